//! The generated references of the user guide are current: the settings reference
//! (`stewart settings --format markdown`) and the command-line reference (the program's
//! own help, from clap). `UPDATE_DOCS=1` writes them instead of comparing.

use crate::{stderr, stdout, stewart};

/// The guide's chapter `name`, under docs/guide/.
fn chapter(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../docs/guide/{name}"))
}

/// `text` is what docs/guide/`name` holds, or (with UPDATE_DOCS=1) it is written there.
fn is_current(name: &str, text: &str, how: &str) {
    let path = chapter(name);
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        return;
    }
    let held = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        held == text,
        "docs/guide/{name} is not what {how} writes now: run UPDATE_DOCS=1 cargo test -p stewart_tests --test cli docs"
    );
}

/// The program's help output for `args`, which must succeed.
fn help(args: &[&str]) -> String {
    let o = stewart(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stdout(&o)
}

#[test]
fn the_settings_reference_is_current() {
    let text = help(&["settings", "--format", "markdown"]);
    // Every key the table knows is in the reference, each once.
    let table = help(&["settings"]);
    let keys: Vec<&str> = table
        .lines()
        .skip(2)
        .take_while(|l| !l.is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(keys.len() > 100, "{}", keys.len());
    for key in keys {
        assert_eq!(text.matches(&format!("| `{key}` |")).count(), 1, "{key}");
    }
    is_current("settings.md", &text, "`stewart settings --format markdown`");
}

#[test]
fn the_command_line_reference_is_current() {
    let top = help(&["--help"]);
    let mut text = String::from(
        "# Command-line reference\n\n\
         The program's own help for every subcommand (`stewart SUBCOMMAND --help` prints the \
         same), generated from its command-line definitions; a test keeps this file current. \
         The [command line](command-line.md) chapter shows them at work.\n\n## stewart\n\n```text\n",
    );
    text.push_str(&top);
    text.push_str("```\n");
    let commands: Vec<&str> = top
        .lines()
        .skip_while(|l| *l != "Commands:")
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .collect();
    assert!(commands.len() >= 16, "{commands:?}");
    for name in commands {
        text.push_str(&format!("\n## stewart {name}\n\n```text\n"));
        text.push_str(&help(&[name, "--help"]));
        text.push_str("```\n");
    }
    is_current("cli-reference.md", &text, "the program's help");
}
