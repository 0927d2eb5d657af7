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
    let examples = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/cad/base.stl");
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
