//! Building the firmware examples with the system C (or C++) compiler and running a small
//! harness program on bytes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// `examples/firmware/`, or a folder inside it.
pub fn firmware_dir(inside: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/firmware")
        .join(inside)
}

/// Build `harness` (source text) with `compiler` and `flags` (warnings are errors), with
/// `include` on the include path and `extra` sources beside it; run it on `input` and
/// return what it printed.
pub fn build_and_run(
    compiler: &str,
    flags: &[&str],
    include: &Path,
    extra: &[PathBuf],
    harness: &str,
    input: &[u8],
) -> String {
    let dir = std::env::temp_dir().join(format!(
        "stewart-firmware-{}-{compiler}-{}",
        std::process::id(),
        include
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default()
    ));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let source = dir.join(if compiler == "c++" {
        "harness.cpp"
    } else {
        "harness.c"
    });
    std::fs::write(&source, harness).unwrap_or_else(|e| panic!("{e}"));
    let program = dir.join("harness");
    let built = Command::new(compiler)
        .args(flags)
        .args(["-Wall", "-Wextra", "-Wpedantic", "-Werror", "-I"])
        .arg(include)
        .arg("-o")
        .arg(&program)
        .arg(&source)
        .args(extra)
        .output()
        .unwrap_or_else(|e| panic!("{compiler}: {e}"));
    assert!(
        built.status.success(),
        "{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let mut child = Command::new(&program)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    child
        .stdin
        .take()
        .map(|mut s| s.write_all(input))
        .unwrap_or_else(|| panic!("no stdin"))
        .unwrap_or_else(|e| panic!("{e}"));
    let out = child.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    let _ = std::fs::remove_dir_all(&dir);
    String::from_utf8_lossy(&out.stdout).into_owned()
}
