//! The edges issue #41's hunt broke, one case each: absurdly light payloads, cues that
//! leave the accepted poses, negative seconds, overflowing simulator settings, arrays with
//! a value too many, one-row pose tables, legs of zero length.

use crate::run::{names, path, run, tempdir, write};

/// A paired platform (its geometry) with `tables` appended.
fn paired_with(tables: &str) -> String {
    format!(
        "[geometry]\nbase_radius = 1.0\nplatform_radius = 0.6\nhome_height = 0.8\n\
         base_angles_deg = [10, 110, 130, 230, 250, 350]\n\
         platform_angles_deg = [50, 70, 170, 190, 290, 310]\n{tables}"
    )
}

#[test]
fn an_absurdly_light_payload_gives_finite_modes_never_nan_as_zero() {
    let dir = tempdir();
    for mass in ["1e-6", "1e-200", "1e-300"] {
        let scenario = write(
            dir.path(),
            "light.toml",
            paired_with(&format!(
                "[payload]\nmass_kg = {mass}\ninertia_kg_m2 = [{mass}, {mass}, {mass}]\n\
                 [dynamics]\nactuator_stiffness = 1e7\n"
            ))
            .as_bytes(),
        );
        for format in ["text", "json"] {
            let o = run(&["modes", "--scenario", &scenario, "--format", format]);
            o.assert_promises();
            assert_eq!(o.code, Some(0), "{}: {}", o.shown(), o.stderr);
            assert!(!o.stdout.contains("null"), "{}: {}", o.shown(), o.stdout);
            assert!(
                !o.stdout.contains(" 0.000 Hz"),
                "{}: {}",
                o.shown(),
                o.stdout
            );
            assert!(
                !o.stdout.contains("singular"),
                "{}: {}",
                o.shown(),
                o.stdout
            );
            // No hundred-digit numbers either.
            assert!(o.stdout.lines().all(|l| l.len() < 400), "{}", o.shown());
        }
    }
}

#[test]
fn modes_at_a_pose_where_a_leg_has_no_length_name_the_leg() {
    // Base and platform joints on the same circle at the same angles: at z = 0 every
    // leg's joints meet.
    let dir = tempdir();
    let scenario = write(
        dir.path(),
        "flat.toml",
        b"[geometry]\nbase_radius = 1.0\nplatform_radius = 1.0\nhome_height = 0.8\n\
          base_angles_deg = [350, 10, 110, 130, 230, 250]\n\
          platform_angles_deg = [350, 10, 110, 130, 230, 250]\n\
          [payload]\nmass_kg = 50\ninertia_kg_m2 = [2, 2, 3]\n\
          [dynamics]\nactuator_stiffness = 1e7\n",
    );
    let o = run(&["modes", "--scenario", &scenario, "--pose", "0,0,0,0,0,0"]);
    o.assert_refused();
    assert!(o.stderr.contains("leg 1 has zero length"), "{}", o.stderr);
}

#[test]
fn negative_seconds_reach_their_options_check() {
    for args in [
        vec![
            "link",
            "--preset",
            "paired",
            "--dry-run",
            "--duration",
            "-1",
        ],
        vec!["link", "--preset", "paired", "--dry-run", "--ramp", "-1"],
        vec!["device-sim", "--udp", "127.0.0.1:0", "--idle", "-1"],
        vec!["device-sim", "--udp", "127.0.0.1:0", "--duration", "-1"],
    ] {
        let o = run(&args);
        o.assert_refused();
        assert!(
            o.stderr.contains("seconds must be between 0 and"),
            "{}: {}",
            o.shown(),
            o.stderr
        );
        assert!(!o.stderr.contains("unexpected argument"), "{}", o.stderr);
    }
}

#[test]
fn the_simulators_model_refuses_overflowing_numbers() {
    for option in ["--lag-s", "--speed-max", "--dead-band"] {
        for value in ["1e308", "-1", "nan"] {
            let o = run(&[
                "device-sim",
                "--udp",
                "127.0.0.1:0",
                "--telemetry",
                option,
                value,
            ]);
            o.assert_refused();
            assert!(o.stderr.contains(option), "{}: {}", o.shown(), o.stderr);
        }
    }
}

#[test]
fn arrays_with_a_value_too_many_and_one_row_tables_are_named() {
    let dir = tempdir();
    for (table, want) in [
        (
            "[pivot]\noffset_m = [0, 0, 0.1, 7]\n",
            "expected 3 values, got 4",
        ),
        (
            "[cueing]\nreference_m = [0, 0, 0.5, 1]\n",
            "expected 3 values, got 4",
        ),
        (
            "[link]\noffset = [0, 0, 0, 0, 0, 0, 0]\n",
            "expected 6 values, got 7",
        ),
    ] {
        let scenario = write(dir.path(), "s.toml", paired_with(table).as_bytes());
        let o = run(&["check", "--scenario", &scenario]);
        o.assert_refused();
        assert!(
            o.stderr.contains(want) && o.stderr.contains("line "),
            "{table}: {}",
            o.stderr
        );
    }
    // What `stewart cue` writes for a one-sample recording, played by a scenario.
    write(
        dir.path(),
        "one.csv",
        b"t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n",
    );
    let scenario = write(
        dir.path(),
        "one.toml",
        paired_with("[trajectory]\nkind = \"pose_table\"\nfile = \"one.csv\"\n").as_bytes(),
    );
    let o = run(&["check", "--scenario", &scenario]);
    o.assert_refused();
    assert!(
        o.stderr.contains("`trajectory.file`") || o.stderr.contains("trajectory.file"),
        "{}",
        o.stderr
    );
    assert!(!o.stderr.contains("trajectory.keys"), "{}", o.stderr);
}

#[test]
fn a_cue_that_would_leave_the_accepted_poses_is_refused_and_writes_nothing() {
    let dir = tempdir();
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    for k in 0..=400 {
        text.push_str(&format!("{},0,0,0,300,0,0\n", f64::from(k) * 0.1));
    }
    let vehicle = write(dir.path(), "roll.csv", text.as_bytes());
    let out = path(dir.path(), "poses.csv");
    // A sustained roll rate with the slowest washout and the largest scale: the platform
    // would turn hundreds of times over.
    let o = run(&[
        "cue",
        "--preset",
        "seed",
        "--input",
        &vehicle,
        "--out",
        &out,
        "--set",
        "cueing.rotation_scale=10",
        "--set",
        "cueing.rotation_hp_wn=0.01",
    ]);
    o.assert_refused();
    assert!(o.stderr.contains("roll.csv, line "), "{}", o.stderr);
    assert_eq!(names(dir.path()), ["roll.csv"]);
}
