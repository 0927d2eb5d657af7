//! CAD parts and the glTF animation from the command line: a broken or absurd mesh refused
//! with the key and file at fault (exit 2, nothing written), the export written and valid
//! by the layout glTF binaries have, the parts listed by `stewart settings`.

use std::path::{Path, PathBuf};

use crate::stewart;

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/cad")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn a_broken_mesh_is_refused_naming_the_key_and_file_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    // A binary STL cut short, beside a copy of the example scenario.
    let stl = std::fs::read(examples().join("base.stl")).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(dir.path().join("cut.stl"), &stl[..5000]).unwrap_or_else(|e| panic!("{e}"));
    let scenario = std::fs::read_to_string(examples().join("seed-cad.toml"))
        .unwrap_or_else(|e| panic!("{e}"))
        .replace("base.stl", "cut.stl");
    let file = dir.path().join("s.toml");
    std::fs::write(&file, scenario).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.path().join("x.gif");
    let run = stewart(&[
        "render",
        "--scenario",
        &file.to_string_lossy(),
        "--out",
        &out.to_string_lossy(),
        "--frames",
        "0..2",
    ]);
    assert_eq!(run.status.code(), Some(2));
    let err = text(&run.stderr);
    assert!(err.contains("`appearance.base.file` (cut.stl): "), "{err}");
    assert!(err.contains("promises 1608 facets"), "{err}");
    assert!(!out.exists());
    // A unit that makes the base 2.9 km across, in the glTF export too.
    let glb = dir.path().join("x.glb");
    let run = stewart(&[
        "render",
        "--scenario",
        &examples().join("seed-cad.toml").to_string_lossy(),
        "--set",
        "appearance.base.scale=m",
        "--out",
        &glb.to_string_lossy(),
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(text(&run.stderr).contains("is the file in millimetres?"));
    assert!(!glb.exists());
}

#[test]
fn render_writes_a_glb_or_a_gltf_with_its_bin_and_settings_list_the_parts() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let glb = dir.path().join("seed.glb");
    let run = stewart(&[
        "render",
        "--scenario",
        &examples().join("seed-cad.toml").to_string_lossy(),
        "--out",
        &glb.to_string_lossy(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run.stderr));
    assert!(text(&run.stderr).contains("1001 keys for 13 moving parts"));
    let bytes = std::fs::read(&glb).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(&bytes[..4], b"glTF");
    assert_eq!(
        u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize,
        bytes.len()
    );
    let gltf = dir.path().join("servo.gltf");
    let run = stewart(&[
        "render",
        "--preset",
        "servo-desk",
        "--out",
        &gltf.to_string_lossy(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run.stderr));
    let json = std::fs::read_to_string(&gltf).unwrap_or_else(|e| panic!("{e}"));
    assert!(json.contains("\"uri\":\"servo.bin\"") && json.contains("servo1_horn"));
    assert!(dir.path().join("servo.bin").is_file());
    let run = stewart(&[
        "settings",
        "--scenario",
        &examples().join("seed-cad.toml").to_string_lossy(),
    ]);
    let listed = text(&run.stdout);
    assert!(
        listed.contains("base.file") && listed.contains("base.stl"),
        "{listed}"
    );
    assert!(listed.contains("horn.file") && listed.contains("off"));
}
