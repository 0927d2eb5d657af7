//! No command writes over a file the scenario reads (its pose table, its CAD parts) or a
//! folder, and every refusal comes before any work, naming both files.

use crate::{stderr, stewart, tempdir, write};

/// A scenario on the seed's geometry playing `poses.csv`, with the example CAD base.
fn scenario_with_table_and_part(
    dir: &std::path::Path,
) -> (String, std::path::PathBuf, std::path::PathBuf) {
    let table = "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n1,0.05,0,0.8,0,0,0\n";
    let table_path = dir.join("poses.csv");
    std::fs::write(&table_path, table).unwrap_or_else(|e| panic!("{e}"));
    let part = dir.join("base.stl");
    let examples = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/cad/base.stl");
    std::fs::copy(examples, &part).unwrap_or_else(|e| panic!("{e}"));
    let scenario = write(
        dir,
        "s.toml",
        "[geometry]\nbase_radius = 1.0\nplatform_radius = 0.6\nhome_height = 0.8\nbase_angles_deg = [0, 60, 120, 180, 240, 300]\nplatform_angles_deg = [30, 90, 150, 210, 270, 330]\n[trajectory]\nkind = \"pose_table\"\nfile = \"poses.csv\"\n[appearance.base]\nfile = \"base.stl\"\nscale = \"mm\"\n",
    );
    (scenario, table_path, part)
}

#[test]
fn no_command_writes_over_the_scenarios_own_files() {
    let dir = tempdir();
    let (scenario, table, part) = scenario_with_table_and_part(dir.path());
    let table_before = std::fs::read(&table).unwrap_or_default();
    let part_before = std::fs::read(&part).unwrap_or_default();
    let (t, p) = (table.display().to_string(), part.display().to_string());
    let cases: [(&[&str], &str, &str); 6] = [
        (&["solve", "--out", &t], "pose table", "poses.csv"),
        (
            &["forces", "--mass", "10", "--out", &t],
            "pose table",
            "poses.csv",
        ),
        (
            &["settings", "--as-coordinates", "--out", &t],
            "pose table",
            "poses.csv",
        ),
        (&["render", "--out", &p], "CAD parts", "base.stl"),
        (&["plot", "--out", &p], "CAD parts", "base.stl"),
        (
            &["link", "--dry-run", "--out", &t],
            "pose table",
            "poses.csv",
        ),
    ];
    for (args, what, name) in cases {
        let mut all = vec![args[0], "--scenario", &scenario];
        all.extend(&args[1..]);
        let o = stewart(&all);
        let said = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {said}");
        assert!(
            said.contains("refusing to write") && said.contains(what) && said.contains(name),
            "{args:?}: {said}"
        );
    }
    assert_eq!(std::fs::read(&table).unwrap_or_default(), table_before);
    assert_eq!(std::fs::read(&part).unwrap_or_default(), part_before);
}

#[test]
fn telemetry_refuses_a_folder_before_it_listens() {
    let dir = tempdir();
    let o = stewart(&[
        "telemetry",
        "--listen",
        "udp:127.0.0.1:0",
        "--duration",
        "30",
        "--out",
        &dir.path().display().to_string(),
    ]);
    let said = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{said}");
    assert!(
        said.contains("it is a folder") && !said.contains("listening"),
        "{said}"
    );
}

/// A named pipe as the output is opened before the work, waiting for its reader (said),
/// so a session recorded for minutes is never lost waiting at the end; with the reader
/// there, every row arrives.
#[test]
fn a_named_pipe_output_is_opened_before_listening() {
    let dir = tempdir();
    let fifo = dir.path().join("rows.fifo");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let port = crate::link::free_port();
    let telemetry = crate::watched::Watched::spawn(
        std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["telemetry", "--listen", &format!("udp:{port}")])
            .args(["--duration", "2", "--out"])
            .arg(&fifo),
    );
    // Nothing is listened to until the pipe has a reader.
    telemetry.wait_for("waiting for a reader of");
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap_or_default())
    };
    telemetry.wait_for("telemetry: listening");
    let socket = std::net::UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    for k in 0..20 {
        let line = format!("{},-3,0.5,0,0,0,10", f64::from(k) * 0.01);
        socket
            .send_to(line.as_bytes(), &port)
            .unwrap_or_else(|e| panic!("{e}"));
    }
    let o = telemetry.finish();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows = reader.join().unwrap_or_default();
    assert_eq!(rows.lines().count(), 21, "{rows}");
}

/// Standard input redirected from a file is that file: writing the output over it is
/// refused before any work, as naming it would be.
#[test]
fn standard_input_redirected_from_the_output_file_is_refused() {
    let dir = tempdir();
    let table = dir.path().join("table.csv");
    let o = stewart(&[
        "solve",
        "--preset",
        "paired",
        "--out",
        &table.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let before = std::fs::read(&table).unwrap_or_default();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["solve", "--preset", "paired", "--poses", "-", "--out"])
        .arg(&table)
        .stdin(std::fs::File::open(&table).unwrap_or_else(|e| panic!("{e}")))
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("standard input, redirected from it"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(&table).unwrap_or_default(), before);
}

/// A named pipe as the output of a short command is opened when the output is ready: a
/// refusal before that (a missing input) is said at once, not after a reader came.
#[test]
fn a_refusal_does_not_wait_for_a_named_pipes_reader() {
    let dir = tempdir();
    let fifo = dir.path().join("out.fifo");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let missing = dir.path().join("missing.csv");
    let cue = crate::watched::Watched::spawn(
        std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["cue", "--preset", "paired", "--input"])
            .arg(&missing)
            .arg("--out")
            .arg(&fifo),
    );
    let o = cue.finish();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("cannot be read"), "{}", stderr(&o));
    assert!(
        !stderr(&o).contains("waiting for a reader"),
        "{}",
        stderr(&o)
    );
}
