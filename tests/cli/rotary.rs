//! Rotary-servo scenarios (`[actuator] kind = "rotary"`) through every command: servo
//! angles, forward kinematics, checks, torques, workspace, plots and frames.

use crate::{parse_csv, stderr, stdout, stewart, tempdir, write};

/// A desktop platform with hobby servos (the test scenario next to this file).
fn scenario() -> String {
    format!("{}/cli/rotary.toml", env!("CARGO_MANIFEST_DIR"))
}

/// The test scenario's numbers, transcribed: base and platform joints, horn directions.
const RB: f64 = 0.08;
const RP: f64 = 0.06;
const HORN: f64 = 0.025;
const ROD: f64 = 0.12;
const BASE_DEG: [f64; 6] = [350.0, 10.0, 110.0, 130.0, 230.0, 250.0];
const PLATFORM_DEG: [f64; 6] = [345.0, 15.0, 105.0, 135.0, 225.0, 255.0];
const HORN_DEG: [f64; 6] = [255.0, 105.0, 15.0, 225.0, 135.0, 345.0];

/// Distance from horn tip `i` at servo angle `theta_deg` to platform joint `i` of the pose
/// (x, y, z, yaw only — the test motion has no roll or pitch): the rod's length when the
/// angle is right. Written from the model's definition, not from the solver's formula.
fn rod(i: usize, pose: [f64; 4], theta_deg: f64) -> f64 {
    let [x, y, z, yaw] = pose;
    let (b, p, h, t) = (
        BASE_DEG[i].to_radians(),
        PLATFORM_DEG[i].to_radians(),
        HORN_DEG[i].to_radians(),
        theta_deg.to_radians(),
    );
    let tip = [
        RB * b.cos() + HORN * t.cos() * h.cos(),
        RB * b.sin() + HORN * t.cos() * h.sin(),
        HORN * t.sin(),
    ];
    let (ax, ay) = (RP * p.cos(), RP * p.sin());
    let (s, c) = yaw.to_radians().sin_cos();
    let joint = [x + c * ax - s * ay, y + s * ax + c * ay, z];
    (0..3)
        .map(|k| (joint[k] - tip[k]).powi(2))
        .sum::<f64>()
        .sqrt()
}

#[test]
fn solve_gives_servo_angles_that_close_every_rod() {
    let o = stewart(&["solve", "--scenario", &scenario()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(
        header,
        [
            "t",
            "x",
            "y",
            "z",
            "roll_deg",
            "pitch_deg",
            "yaw_deg",
            "theta1",
            "theta2",
            "theta3",
            "theta4",
            "theta5",
            "theta6"
        ]
    );
    assert_eq!(rows.len(), 101);
    for row in &rows {
        assert_eq!((row[4], row[5]), (0.0, 0.0));
        let pose = [row[1], row[2], row[3], row[6]];
        for i in 0..6 {
            let theta = row[7 + i];
            assert!((-80.0..=80.0).contains(&theta), "{row:?}");
            let error = rod(i, pose, theta) - ROD;
            assert!(
                error.abs() < 1e-12,
                "servo {}: rod off by {error} m in {row:?}",
                i + 1
            );
        }
    }
    // At home the six servos are alike (the layout is three-fold symmetric) and near zero.
    let home = &rows[0][7..13];
    assert!(
        home.iter()
            .all(|t| (t - home[0]).abs() < 1e-9 && t.abs() < 0.1),
        "{home:?}"
    );
}

#[test]
fn an_unreachable_pose_is_one_located_error_and_nothing_is_written() {
    let dir = tempdir();
    let poses = write(
        dir.path(),
        "poses.csv",
        "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.117,0,0,0\n0,0,0.5,0,0,0\n",
    );
    let out = dir.path().join("angles.csv");
    let o = stewart(&[
        "solve",
        "--scenario",
        &scenario(),
        "--poses",
        &poses,
        "--out",
        &out.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("poses.csv, line 3: servo 1 cannot reach its platform joint"),
        "{err}"
    );
    assert!(!out.exists());
}

#[test]
fn rotary_keys_are_checked_and_located() {
    let dir = tempdir();
    let text = std::fs::read_to_string(scenario()).unwrap_or_else(|e| panic!("{e}"));
    for (from, to, expected) in [
        (
            "rod_length_m = 0.12",
            "rod_length_m = 0.02",
            "line 12, column 17: `actuator.horn_length_m` (0.025 m) must be shorter than `actuator.rod_length_m` (0.02 m)",
        ),
        (
            "home_height = 0.117",
            "home_height = 0.117\nleg_max = 0.2",
            "line 7, column 11: `leg_max` belongs to linear legs",
        ),
        (
            "horn_angles_deg = [255, 105, 15, 225, 135, 345]",
            "horn_angles_deg = [255, 105, 15]",
            "`actuator.horn_angles_deg` must list 6 angles (one per servo), got 3",
        ),
        (
            "servo_max_deg = 80.0",
            "servo_max_deg = -90.0",
            "the servo range must lie in (-180, 180] degrees with min < max, got -80 … -90",
        ),
        (
            "kind = \"rotary\"",
            "kind = \"linear\"",
            "`actuator.horn_length_m` belongs to rotary servos, not to `kind = \"linear\"`",
        ),
        (
            "horn_length_m = 0.025\n",
            "",
            "`actuator.horn_length_m` is required by `kind = \"rotary\"` but missing",
        ),
    ] {
        assert!(text.contains(from), "{from}");
        let file = write(dir.path(), "r.toml", &text.replacen(from, to, 1));
        let o = stewart(&["solve", "--scenario", &file]);
        assert_eq!(o.status.code(), Some(2), "{to}");
        assert!(stderr(&o).contains(expected), "{to}: {}", stderr(&o));
    }
}

#[test]
fn workspace_of_a_servo_platform_has_volume_and_orientation_ranges() {
    let o = stewart(&["workspace", "--preset", "servo-desk", "--resolution", "32"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(
        text.contains("servo reach, range, rod cones exact per column; rod clearance by branch"),
        "{text}"
    );
    assert!(text.contains("extent x"), "{text}");
    assert!(!text.contains("not reachable"), "{text}");
}

#[test]
fn fk_turns_servo_angles_back_into_the_poses() {
    let dir = tempdir();
    let angles = dir.path().join("angles.csv");
    let o = stewart(&[
        "solve",
        "--scenario",
        &scenario(),
        "--out",
        &angles.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, solved) = parse_csv(&std::fs::read_to_string(&angles).unwrap_or_default());
    for cold in [false, true] {
        let mut args = vec!["fk", "--scenario"];
        let s = scenario();
        args.push(&s);
        let a = angles.display().to_string();
        args.extend(["--legs", &a]);
        if cold {
            args.push("--cold");
        }
        let o = stewart(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let (header, rows) = parse_csv(&stdout(&o));
        assert_eq!(
            header[..7],
            ["t", "x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"]
        );
        assert_eq!(rows.len(), solved.len());
        for (row, want) in rows.iter().zip(&solved) {
            assert!(row[8] <= 1e-12, "residual {}", row[8]);
            for c in 0..4 {
                assert!((row[c] - want[c]).abs() < 1e-9, "{row:?} vs {want:?}");
            }
            for c in 4..7 {
                assert!((row[c] - want[c]).abs() < 1e-7, "{row:?} vs {want:?}");
            }
        }
    }
    // Three rows are enough for the (400-start) assembly-mode search.
    let text = std::fs::read_to_string(&angles).unwrap_or_default();
    let first: String = text.lines().take(4).map(|l| format!("{l}\n")).collect();
    let few = write(dir.path(), "few.csv", &first);
    let solved = &solved[..3];
    let o = stewart(&[
        "fk",
        "--scenario",
        &scenario(),
        "--legs",
        &few,
        "--assembly-modes",
    ]);
    // Every row's own pose is among its assembly modes.
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(header[..4], ["t", "row", "mode", "x"]);
    for want in solved {
        let same_time: Vec<&Vec<f64>> = rows.iter().filter(|r| r[0] == want[0]).collect();
        assert!(same_time.len() >= 2, "{}", same_time.len());
        assert!(
            same_time
                .iter()
                .any(|r| (1..4).all(|c| (r[c + 2] - want[c]).abs() < 1e-7)),
            "{want:?} not among {same_time:?}"
        );
    }
}

#[test]
fn settings_lists_the_actuator_and_offers_the_level_home_height() {
    let o = stewart(&["settings", "--scenario", &scenario()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for key in [
        "actuator.horn_length_m",
        "actuator.horn_angles_deg[5]",
        "actuator.servo_max_deg",
    ] {
        assert!(text.lines().any(|l| l.starts_with(key)), "{key} in\n{text}");
    }
    let line = text
        .lines()
        .find(|l| l.starts_with("Automatic home height"))
        .unwrap_or_else(|| panic!("{text}"));
    let h: f64 = line
        .split("home_height=")
        .nth(1)
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("{line}"));
    // Set it: the servos then stand level at home.
    let o = stewart(&[
        "solve",
        "--scenario",
        &scenario(),
        "--set",
        &format!("geometry.home_height={h}"),
        "--set",
        &format!("trajectory.z.offset_m={h}"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = parse_csv(&stdout(&o));
    assert!(
        rows[0][7..13].iter().all(|t| t.abs() < 1e-3),
        "{:?}",
        &rows[0]
    );
}

#[test]
fn commanded_angles_apply_reversal_and_trim() {
    let dir = tempdir();
    let text = std::fs::read_to_string(scenario()).unwrap_or_else(|e| panic!("{e}"));
    let mounted = text.replacen(
        "servo_max_deg = 80.0",
        "servo_max_deg = 80.0\nservo_reversed = [false, true, false, false, false, false]\nservo_trim_deg = [5.0, -3.0, 0, 0, 0, 0]",
        1,
    );
    let file = write(dir.path(), "mounted.toml", &mounted);
    let model = stewart(&["solve", "--scenario", &file]);
    let cmd = stewart(&["solve", "--scenario", &file, "--commanded"]);
    assert!(
        model.status.success() && cmd.status.success(),
        "{}",
        stderr(&cmd)
    );
    let (_, m) = parse_csv(&stdout(&model));
    let (header, c) = parse_csv(&stdout(&cmd));
    assert_eq!(
        header[7..],
        ["cmd1", "cmd2", "cmd3", "cmd4", "cmd5", "cmd6"]
    );
    for (m, c) in m.iter().zip(&c) {
        assert!((c[7] - (m[7] + 5.0)).abs() < 1e-9, "{m:?} {c:?}");
        assert!((c[8] - (-m[8] - 3.0)).abs() < 1e-9, "{m:?} {c:?}");
        assert!((c[9] - m[9]).abs() < 1e-9);
    }
    let o = stewart(&["solve", "--commanded"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--commanded applies to rotary servo platforms"));
    let bad = write(
        dir.path(),
        "bad.toml",
        &text.replacen(
            "servo_max_deg = 80.0",
            "servo_max_deg = 80.0\nservo_trim_deg = [1, 2]",
            1,
        ),
    );
    let o = stewart(&["solve", "--scenario", &bad]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`actuator.servo_trim_deg` must list 6 values (one per servo), got 2"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn check_reports_servo_angles_and_names_the_servo_past_its_range() {
    let s = scenario();
    let o = stewart(&["check", "--scenario", &s]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("Servo angles over the motion:"), "{text}");
    assert!(text.contains("servo reach"), "{text}");
    assert!(text.contains("No problem found."), "{text}");
    // A narrow range and a speed limit: exit 1, each servo named, JSON says the same.
    let o = stewart(&[
        "check",
        "--scenario",
        &s,
        "--set",
        "actuator.servo_max_deg=12",
        "--set",
        "limits.servo_speed_max_deg_s=10",
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let doc: serde_json::Value =
        serde_json::from_str(&stdout(&o)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(doc["actuator"], "rotary");
    assert_eq!(doc["servo_max_deg"], 12.0);
    assert!(doc.get("leg_max_m").is_none());
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    let kinds: Vec<&str> = findings.iter().filter_map(|f| f["kind"].as_str()).collect();
    assert!(
        kinds.contains(&"servo_max") && kinds.contains(&"servo_speed"),
        "{kinds:?}"
    );
    let ranges = doc["servo_ranges_deg"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert_eq!(ranges.len(), 6);
    // Servo 5 turns furthest (17.7°, see the plain report), so it is over the 12° top.
    assert!(
        findings
            .iter()
            .any(|f| f["kind"] == "servo_max" && f["legs"][0] == 5)
    );
    let o = stewart(&[
        "check",
        "--scenario",
        &s,
        "--set",
        "actuator.servo_max_deg=12",
    ]);
    let text = stdout(&o);
    assert!(
        text.contains("servo S5 turns past its maximum 12°"),
        "{text}"
    );
    assert!(
        text.contains("servo angle (max)    worst 17.7287 deg (S5)"),
        "{text}"
    );
}

#[test]
fn plot_and_render_draw_servo_angles_and_servos() {
    let dir = tempdir();
    let s = scenario();
    let svg = dir.path().join("servos.svg");
    let o = stewart(&[
        "plot",
        "--scenario",
        &s,
        "--out",
        &svg.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{e}"));
    assert!(text.contains("Servo angle θ (°)") && text.contains("θmax = 80°"));
    assert_eq!(text.matches(r#"class="leg S"#).count(), 6);
    let frames = dir.path().join("frames");
    let o = stewart(&[
        "render",
        "--scenario",
        &s,
        "--out",
        &frames.display().to_string(),
        "--size",
        "320x180",
        "--frames",
        "0..2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_dir(&frames).map(|d| d.count()).unwrap_or(0),
        2
    );
}

#[test]
fn forces_gives_servo_torques_that_hold_the_payload() {
    let o = stewart(&["forces", "--preset", "crank-rig"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(header[1], "T1_static");
    assert_eq!(header[12], "T6");
    assert_eq!(rows.len(), 1201);
    // A 120 kg seat on 150 mm cranks: every crank holds a torque of the order of
    // m g a / 6 ≈ 29 N·m (more on some, less on others), never NaN.
    for row in &rows {
        assert!(row.iter().all(|v| v.is_finite()));
    }
    let total: f64 = rows[0][1..7].iter().map(|t| t.abs()).sum();
    assert!(total > 60.0 && total < 1000.0, "{total}");
}
