//! `stewart robot`: an MJCF or URDF file from any rig, and one located refusal (exit 2,
//! nothing written) for input it cannot describe. The descriptions' numbers are checked
//! in MuJoCo and yourdfpy by `scripts/robot-check.sh`, and composed from the XML alone by
//! the app's unit tests.

use crate::{stderr, stewart, tempdir};

#[test]
fn writes_mjcf_and_urdf_with_the_joint_states_for_linear_and_rotary_rigs() {
    let dir = tempdir();
    for (preset, keys) in [("paired", 11), ("crank-rig", 13)] {
        let xml = dir.path().join(format!("{preset}.xml"));
        let out = stewart(&[
            "robot",
            "--preset",
            preset,
            "--format",
            "mjcf",
            "--out",
            xml.to_str().unwrap(),
            "--every",
            "100",
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let text = std::fs::read_to_string(&xml).unwrap();
        assert!(text.starts_with("<mujoco model=\""), "{}", &text[..80]);
        // 1001 and 1201 samples, every 100th from the first.
        assert_eq!(text.matches("<key ").count(), keys, "{preset}");
        let said = format!("with {keys} samples");
        assert!(stderr(&out).contains(&said), "{}", stderr(&out));

        let urdf = dir.path().join(format!("{preset}.urdf"));
        let states = dir.path().join(format!("{preset}.csv"));
        let out = stewart(&[
            "robot",
            "--preset",
            preset,
            "--format",
            "urdf",
            "--out",
            urdf.to_str().unwrap(),
            "--joint-states",
            states.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let table = std::fs::read_to_string(&states).unwrap();
        let header = table.lines().next().unwrap();
        assert!(header.starts_with("t,x,y,z,yaw,pitch,roll,"), "{header}");
        assert_eq!(header.split(',').count(), 1 + 6 + 18);
        assert!(
            std::fs::read_to_string(&urdf)
                .unwrap()
                .contains("<robot name=\"")
        );
    }
}

/// Exit status 2, one sentence containing `words`, and no file at `out`.
fn refused(args: &[&str], words: &[&str], out: &std::path::Path) {
    let o = stewart(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    for w in words {
        assert!(
            stderr(&o).contains(w),
            "{args:?}: {w} not in {}",
            stderr(&o)
        );
    }
    assert!(!out.exists(), "{args:?} wrote {}", out.display());
}

#[test]
fn what_cannot_be_described_is_refused_where_it_lies_and_nothing_is_written() {
    let dir = tempdir();
    let xml = dir.path().join("rig.xml");
    let x = xml.to_str().unwrap();
    // A pose no servo reaches, located by its time.
    refused(
        &[
            "robot",
            "--preset",
            "servo-desk",
            "--set",
            "trajectory.z.offset_m=1",
            "--format",
            "mjcf",
            "--out",
            x,
        ],
        &[
            "preset `servo-desk`: the trajectory at t = 0 s",
            "cannot reach",
        ],
        &xml,
    );
    // A leg beyond its stroke.
    refused(
        &[
            "robot",
            "--preset",
            "paired",
            "--set",
            "geometry.leg_max=0.9",
            "--format",
            "urdf",
            "--out",
            x,
        ],
        &["the trajectory at t = ", "beyond its stroke"],
        &xml,
    );
    refused(
        &["robot", "--preset", "paired", "--format", "sdf", "--out", x],
        &["sdf"],
        &xml,
    );
    refused(
        &[
            "robot", "--preset", "paired", "--format", "mjcf", "--out", x, "--every", "0",
        ],
        &["--every"],
        &xml,
    );
    let csv = dir.path().join("states.csv");
    refused(
        &[
            "robot",
            "--preset",
            "paired",
            "--format",
            "mjcf",
            "--out",
            x,
            "--joint-states",
            csv.to_str().unwrap(),
        ],
        &["--joint-states applies to --format urdf"],
        &xml,
    );
    refused(
        &[
            "robot",
            "--preset",
            "paired",
            "--format",
            "urdf",
            "--out",
            x,
            "--joint-states",
            x,
        ],
        &["own file"],
        &xml,
    );
    // The output over the scenario's own file leaves it as it was.
    let scenario = dir.path().join("mine.toml");
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/presets/paired.toml"),
        &scenario,
    )
    .unwrap();
    let before = std::fs::read(&scenario).unwrap();
    let o = stewart(&[
        "robot",
        "--scenario",
        scenario.to_str().unwrap(),
        "--format",
        "mjcf",
        "--out",
        scenario.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("it is the scenario file"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(&scenario).unwrap(), before);
}

#[test]
fn the_joint_states_never_land_on_the_description_or_a_parts_material_file() {
    let dir = tempdir();
    let urdf = dir.path().join("rig.urdf");
    let u = urdf.to_str().unwrap();
    // A joint-state file that cannot be written leaves no description either.
    let missing = dir.path().join("missing").join("s.csv");
    refused(
        &[
            "robot",
            "--preset",
            "paired",
            "--format",
            "urdf",
            "--out",
            u,
            "--joint-states",
            missing.to_str().unwrap(),
        ],
        &["cannot write"],
        &urdf,
    );
    // The description's own file, reached through `..` or a link.
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    let around = dir.path().join("sub").join("..").join("rig.urdf");
    refused(
        &[
            "robot",
            "--preset",
            "paired",
            "--format",
            "urdf",
            "--out",
            u,
            "--joint-states",
            around.to_str().unwrap(),
        ],
        &["own file"],
        &urdf,
    );
    std::fs::write(&urdf, "mine").unwrap();
    let link = dir.path().join("link.csv");
    std::os::unix::fs::symlink(&urdf, &link).unwrap();
    let o = stewart(&[
        "robot",
        "--preset",
        "paired",
        "--format",
        "urdf",
        "--out",
        u,
        "--joint-states",
        link.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&urdf).unwrap(), "mine");
    // The material file an OBJ part reads is an input too.
    let cad = dir.path().join("cad");
    std::fs::create_dir(&cad).unwrap();
    let examples = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/cad");
    for f in std::fs::read_dir(examples).unwrap() {
        let f = f.unwrap();
        std::fs::copy(f.path(), cad.join(f.file_name())).unwrap();
    }
    let mtl = cad.join("platform.mtl");
    let before = std::fs::read(&mtl).unwrap();
    let scenario = cad.join("seed-cad.toml");
    let out = cad.join("x.urdf");
    let o = stewart(&[
        "robot",
        "--scenario",
        scenario.to_str().unwrap(),
        "--format",
        "urdf",
        "--out",
        out.to_str().unwrap(),
        "--joint-states",
        mtl.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("a file of the scenario's CAD parts"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(&mtl).unwrap(), before);
    assert!(!out.exists());
}
