//! `stewart cue`: vehicle motion in, a pose table out that the other commands take.

use crate::{parse_csv, stderr, stdout, stewart, tempdir, write};

/// A braking manoeuvre with a turn: 6 m/s² from 1 to 3 s, 20°/s of yaw from 2 to 4 s,
/// sampled every 10 ms for `seconds`.
fn braking(seconds: f64) -> String {
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    let n = (seconds * 100.0).round() as usize;
    for k in 0..=n {
        let t = k as f64 * 0.01;
        let ax = if (1.0..3.0).contains(&t) { -6.0 } else { 0.0 };
        let ay = if (2.0..4.0).contains(&t) { 3.0 } else { 0.0 };
        let wz = if (2.0..4.0).contains(&t) { 20.0 } else { 0.0 };
        text.push_str(&format!("{t},{ax},{ay},0,0,0,{wz}\n"));
    }
    text
}

#[test]
fn a_manoeuvre_becomes_a_pose_table_that_solve_check_and_link_take() {
    let dir = tempdir();
    let vehicle = write(dir.path(), "vehicle.csv", &braking(6.0));
    let poses = dir.path().join("poses.csv");
    let o = stewart(&[
        "cue",
        "--preset",
        "seed",
        "--input",
        &vehicle,
        "--out",
        &poses.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).starts_with("cue: 601 poses over 6.000 s"),
        "{}",
        stderr(&o)
    );
    let text = std::fs::read_to_string(&poses).unwrap_or_else(|e| panic!("{e}"));
    let (header, rows) = parse_csv(&text);
    assert_eq!(
        header,
        ["t", "x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"]
    );
    assert_eq!(rows.len(), 601);
    // At rest until the braking: home (the seed's 0.8 m), level.
    assert_eq!(rows[0][1..], [0.0, 0.0, 0.8, 0.0, 0.0, 0.0]);
    assert_eq!(rows[100][1..], [0.0, 0.0, 0.8, 0.0, 0.0, 0.0]);
    // Braking: the platform surges backwards and pitches nose down (gravity pushes the
    // occupant forward, as braking does); the turn yaws it.
    let during = &rows[200];
    assert!(during[1] < -0.01, "x {}", during[1]);
    assert!(during[5] > 0.5, "pitch {}", during[5]);
    assert!(rows[300][6] > 1.0, "yaw {}", rows[300][6]);
    // solve takes it.
    let solved = stewart(&[
        "solve",
        "--preset",
        "seed",
        "--poses",
        &poses.display().to_string(),
    ]);
    assert_eq!(solved.status.code(), Some(0), "{}", stderr(&solved));
    assert_eq!(stdout(&solved).lines().count(), 602);
    // A scenario playing it: check and a dry-run link take it.
    let scenario = write(
        dir.path(),
        "cued.toml",
        "[geometry]\nbase_radius = 1.0\nplatform_radius = 0.6\nhome_height = 0.8\nbase_angles_deg = [0, 60, 120, 180, 240, 300]\nplatform_angles_deg = [30, 90, 150, 210, 270, 330]\n[trajectory]\nkind = \"pose_table\"\nfile = \"poses.csv\"\n",
    );
    let check = stewart(&["check", "--scenario", &scenario]);
    assert!(
        matches!(check.status.code(), Some(0 | 1)),
        "{}",
        stderr(&check)
    );
    let link = stewart(&[
        "link",
        "--scenario",
        &scenario,
        "--dry-run",
        "--duration",
        "1",
        "--ramp",
        "0.2",
    ]);
    assert_eq!(link.status.code(), Some(0), "{}", stderr(&link));
}

#[test]
fn the_workspace_limiter_keeps_a_hard_manoeuvre_within_the_stroke() {
    let dir = tempdir();
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    for k in 0..=800 {
        let t = f64::from(k) * 0.005;
        let sign = if (t / 1.0) as i64 % 2 == 0 { 1.0 } else { -1.0 };
        text.push_str(&format!(
            "{t},{},{},3,{},-30,{}\n",
            9.0 * sign,
            -7.0 * sign,
            50.0 * sign,
            80.0 * sign
        ));
    }
    let vehicle = write(dir.path(), "hard.csv", &text);
    let stroke = [
        "--set",
        "geometry.leg_min=0.9",
        "--set",
        "geometry.leg_max=1.1",
    ];
    let cue = |limiter: &str| {
        let mut args = vec!["cue", "--preset", "seed", "--input", &vehicle];
        args.extend(stroke);
        args.extend(["--set", "cueing.translation_scale=1", "--set", limiter]);
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        (stdout(&o), stderr(&o))
    };
    let legs = |poses: &str| {
        let mut args = vec!["solve", "--preset", "seed", "--poses", "-"];
        args.extend(stroke);
        let o = crate::stewart_with_input(&args, poses.as_bytes());
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let (header, rows) = parse_csv(&stdout(&o));
        let l1 = header.iter().position(|c| c == "L1").unwrap_or(7);
        rows.iter()
            .flat_map(|r| r[l1..l1 + 6].to_vec())
            .collect::<Vec<f64>>()
    };
    let (free, _) = cue("cueing.workspace_limiter=false");
    let outside = legs(&free)
        .iter()
        .filter(|&&l| !(0.9..=1.1).contains(&l))
        .count();
    assert!(
        outside > 50,
        "the manoeuvre must leave the stroke: {outside}"
    );
    let (limited, said) = cue("cueing.workspace_limiter=true");
    assert!(
        said.contains("the workspace limiter scaled the cue back"),
        "{said}"
    );
    let lengths = legs(&limited);
    assert_eq!(lengths.len(), 801 * 6);
    assert!(lengths.iter().all(|l| (0.9..=1.1).contains(l)));
}

#[test]
fn bad_vehicle_motion_is_one_located_error_and_writes_nothing() {
    let dir = tempdir();
    let out = dir.path().join("poses.csv");
    let run = |name: &str, text: &str, extra: &[&str]| {
        let input = write(dir.path(), name, text);
        let mut args = vec!["cue", "--preset", "seed", "--input", &input];
        let out = out.display().to_string();
        args.extend(["--out", &out]);
        args.extend(extra);
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        assert!(
            !std::path::Path::new(&out).exists(),
            "{name} left an output"
        );
        assert!(stdout(&o).is_empty());
        stderr(&o)
    };
    let e = run("missing.csv", "t,ax,ay,az,wx,wy\n0,0,0,0,0,0\n", &[]);
    assert!(e.contains("missing.csv") && e.contains("wz"), "{e}");
    let e = run(
        "nan.csv",
        "t,ax,ay,az,wx,wy,wz\n0,0,0,0,0,0,0\n0.1,NaN,0,0,0,0,0\n",
        &[],
    );
    assert!(e.contains("nan.csv, line 3") && e.contains("ax"), "{e}");
    let e = run(
        "time.csv",
        "t,ax,ay,az,wx,wy,wz\n0,0,0,0,0,0,0\n0.1,1,0,0,0,0,0\n0.1,1,0,0,0,0,0\n",
        &[],
    );
    assert!(
        e.contains("time.csv, line 4, column `t`: t = 0.1 s does not come after"),
        "{e}"
    );
    let e = run(
        "fine.csv",
        "t,ax,ay,az,wx,wy,wz\n0,0,0,0,0,0,0\n",
        &["--set", "cueing.tilt_lp_wn=0"],
    );
    assert!(e.contains("cueing.tilt_lp_wn"), "{e}");
}
