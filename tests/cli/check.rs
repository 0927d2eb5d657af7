//! `stewart check`: the pre-flight report.

use crate::{parse_csv, stderr, stdout, stewart, tempdir, write};

/// The `paired` preset's text.
fn paired() -> &'static str {
    stewart_kinematics::io::scenario::presets::text("paired")
        .unwrap_or_else(|| panic!("no preset paired"))
}

/// A scenario in `dir` on the paired preset's geometry playing `csv` (written beside it as
/// `poses.csv`) as its pose table; its path.
fn paired_playing(dir: &std::path::Path, csv: &str) -> String {
    write(dir, "poses.csv", csv);
    let geometry = paired()
        .split("[trajectory]")
        .next()
        .unwrap_or_default()
        .to_owned();
    write(
        dir,
        "s.toml",
        &(geometry + "[trajectory]\nkind = \"pose_table\"\nfile = \"poses.csv\"\n"),
    )
}

fn json(o: &std::process::Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).unwrap_or_else(|e| panic!("{e}: {}", stdout(o)))
}

#[test]
fn the_seed_is_reported_as_architecturally_singular() {
    let o = stewart(&["check"]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let text = stdout(&o);
    assert!(text.contains("1001 samples"));
    assert!(
        text.contains("This geometry is architecturally singular"),
        "{text}"
    );
    assert!(text.contains("paired layout"), "{text}");
    let doc = json(&stewart(&["check", "--format", "json"]));
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    assert_eq!(findings.len(), 1, "{findings:?}");
    assert_eq!(findings[0]["kind"], "architecture_singular");
    assert_eq!(doc["architecture"]["singular"], true);
    assert_eq!(doc["architecture"]["projective_correspondence"], true);
}

#[test]
fn the_paired_preset_passes_every_limit_with_status_0() {
    let o = stewart(&["check", "--preset", "paired"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("No problem found."));
    let doc = json(&stewart(&[
        "check", "--preset", "paired", "--format", "json",
    ]));
    let limits = doc["limits"].as_array().cloned().unwrap_or_default();
    let kinds: Vec<&str> = limits.iter().filter_map(|l| l["kind"].as_str()).collect();
    assert_eq!(
        kinds,
        [
            "stroke_max",
            "stroke_min",
            "leg_speed",
            "leg_accel",
            "base_cone",
            "platform_cone",
            "leg_collision",
            "near_singular"
        ]
    );
    for l in &limits {
        assert!(l["margin"].as_f64().is_some_and(|m| m > 0.0), "{l}");
        assert!(
            l["worst_time"]
                .as_f64()
                .is_some_and(|t| (0.0..=10.0).contains(&t))
        );
    }
}

#[test]
fn a_leg_over_its_stroke_is_located_with_status_1() {
    let dir = tempdir();
    let scenario = write(
        dir.path(),
        "short.toml",
        &paired().replace("leg_max = 1.30", "leg_max = 1.15"),
    );
    let o = stewart(&["check", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("leg L1 is longer than its maximum 1.1500 m from t = "),
        "{out}"
    );

    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    let doc = json(&o);
    assert_eq!(doc["clean"], false);
    assert_eq!(doc["samples"], 1001);
    assert_eq!(doc["leg_max_m"], 1.15);
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    assert!(!findings.is_empty());
    for f in &findings {
        assert_eq!(f["kind"], "stroke_max");
        assert_eq!(f["unit"], "m");
        let worst = f["worst_value"].as_f64().unwrap_or(0.0);
        let margin = f["margin"].as_f64().unwrap_or(0.0);
        assert!((1.15 - worst - margin).abs() < 1e-12 && margin < 0.0);
        let (first, last) = (
            f["first_time"].as_f64().unwrap_or(-1.0),
            f["last_time"].as_f64().unwrap_or(-1.0),
        );
        assert!((0.0..=10.0).contains(&first) && first <= last);
    }
    // L1 reaches 1.2703 m in the paired motion (see `stewart check --preset paired`).
    assert!(findings.iter().any(|f| f["legs"][0] == 1));
}

#[test]
fn every_kind_of_limit_is_reported_when_passed() {
    let dir = tempdir();
    let text = paired()
        .replace("leg_speed_max_m_s = 0.5", "leg_speed_max_m_s = 0.1")
        .replace("leg_accel_max_m_s2 = 5.0", "leg_accel_max_m_s2 = 0.1")
        .replace("base_cone_deg = 60.0", "base_cone_deg = 45.0")
        .replace("platform_cone_deg = 60.0", "platform_cone_deg = 50.0")
        .replace("leg_radius_m = 0.025", "leg_radius_m = 0.15")
        + "\n[checks]\ncondition_max = 1.9\n";
    let scenario = write(dir.path(), "tight.toml", &text);
    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    let doc = json(&o);
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    for kind in [
        "leg_speed",
        "leg_accel",
        "base_cone",
        "platform_cone",
        "leg_collision",
        "near_singular",
    ] {
        let f = findings
            .iter()
            .find(|f| f["kind"] == kind)
            .unwrap_or_else(|| panic!("no {kind}: {findings:?}"));
        assert!(f["margin"].as_f64().is_some_and(|m| m < 0.0), "{f}");
    }
    let collision = findings
        .iter()
        .find(|f| f["kind"] == "leg_collision")
        .cloned()
        .unwrap_or_default();
    assert_eq!(collision["legs"].as_array().map(Vec::len), Some(2));
    let text = stdout(&stewart(&["check", "--scenario", &scenario]));
    assert!(text.contains("come closer than 300.0 mm"), "{text}");
    assert!(
        text.contains("leans more than 45° from the base normal"),
        "{text}"
    );
}

#[test]
fn a_jump_in_a_pose_table_is_found_and_dated() {
    let dir = tempdir();
    let mut csv = String::from("t,x,y,z,roll_deg,pitch_deg,yaw_deg\n");
    for k in 0..200 {
        let t = k as f64 * 0.01;
        // Smooth heave, then a 3 cm step at t = 1.00 s.
        let z = 0.8 + 0.02 * (t * 2.0).sin() + if k >= 100 { 0.03 } else { 0.0 };
        csv.push_str(&format!("{t},0,0,{z},0,0,0\n"));
    }
    let scenario = paired_playing(dir.path(), &csv);
    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let findings = json(&o)["findings"].as_array().cloned().unwrap_or_default();
    assert_eq!(findings.len(), 6, "every leg jumps: {findings:?}");
    for f in &findings {
        assert_eq!(f["kind"], "jump");
        assert_eq!(f["first_time"], 1.0);
        assert_eq!(f["count"], 1);
    }
}

#[test]
fn a_pose_table_is_judged_at_its_own_rows() {
    // Rows a second apart, and one at t = 5.001 s lifted 0.6 m (beyond every leg's stroke):
    // twelve rows over 10 s, which twelve even times (0, 0.909, …) would step over.
    let dir = tempdir();
    let mut csv = String::from("t,x,y,z,roll_deg,pitch_deg,yaw_deg\n");
    for t in [
        0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.001, 6.0, 7.0, 8.0, 9.0, 10.0,
    ] {
        let z = if t == 5.001 { 1.4 } else { 0.8 };
        csv.push_str(&format!("{t},0,0,{z},0,0,0\n"));
    }
    let scenario = paired_playing(dir.path(), &csv);
    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let findings = json(&o)["findings"].as_array().cloned().unwrap_or_default();
    let stroke: Vec<_> = findings
        .iter()
        .filter(|f| f["kind"] == "stroke_max")
        .collect();
    assert!(!stroke.is_empty(), "{findings:?}");
    for f in stroke {
        assert_eq!(f["first_time"], 5.001, "{f}");
    }
    // `solve` writes the very rows judged.
    let o = stewart(&["solve", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let (_, rows) = parse_csv(&stdout(&o));
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(
        times,
        [
            0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.001, 6.0, 7.0, 8.0, 9.0, 10.0
        ]
    );
}

#[test]
fn unusable_input_gives_status_2() {
    let dir = tempdir();
    let scenario = write(
        dir.path(),
        "s.toml",
        "[geometry]\nbase_radius = 1.0\nplatform_radius = nan\n",
    );
    let o = stewart(&["check", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    let o = stewart(&[
        "check",
        "--scenario",
        &dir.path().join("none.toml").display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("none.toml: cannot be read"),
        "{}",
        stderr(&o)
    );
    let o = stewart(&["check", "--format", "yaml"]);
    assert_eq!(o.status.code(), Some(2));
    let limits = write(
        dir.path(),
        "l.toml",
        &paired().replace("base_cone_deg = 60.0", "base_cone_deg = 200.0"),
    );
    let o = stewart(&["check", "--scenario", &limits]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`limits.base_cone_deg` must be less than 180°, got 200"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn every_pair_of_legs_too_close_is_reported() {
    // The paired layout's three pairs are equally close: all three are findings, not
    // only the closest of each sample.
    let o = stewart(&[
        "check",
        "--preset",
        "paired",
        "--set",
        "limits.leg_radius_m=0.11",
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let report = json(&o);
    let mut pairs: Vec<Vec<u64>> = report["findings"]
        .as_array()
        .map(|f| {
            f.iter()
                .filter(|f| f["kind"] == "leg_collision")
                .map(|f| {
                    f["legs"]
                        .as_array()
                        .map(|l| l.iter().filter_map(serde_json::Value::as_u64).collect())
                        .unwrap_or_default()
                })
                .collect()
        })
        .unwrap_or_default();
    pairs.sort();
    assert_eq!(pairs, vec![vec![1, 2], vec![3, 4], vec![5, 6]]);
}

#[test]
fn a_singular_pose_is_reported_in_words_not_as_inf() {
    // Found by the hostile suite: a keyframe moved to t = 1e6 s makes the spline sweep
    // through singular poses; the condition number there is infinite.
    let dir = tempdir();
    let text = stewart_kinematics::io::scenario::presets::text("keyframes")
        .unwrap_or_else(|| panic!("no preset"))
        .replacen("t_s = 8.0", "t_s = 1e6", 1);
    let file = write(dir.path(), "kf.toml", &text);
    let o = stewart(&["check", "--scenario", &file]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("worst singular at t ="), "{out}");
    assert!(!out.contains("inf"), "{out}");
}

/// A table joined by a cubic spline is judged between its rows too, at every instant the
/// link plays: rows within the stroke whose spline overshoots it are found (they were
/// passed while `link` held at the stroke's end); joined by straight lines, they pass.
#[test]
fn a_spline_through_a_table_is_judged_where_it_plays_between_the_rows() {
    let dir = tempdir();
    let mut csv = String::from("t,x,y,z,roll_deg,pitch_deg,yaw_deg\n");
    for k in 0..25 {
        let z = 0.906 + 0.23 * (60f64 + 60.0 * f64::from(k)).to_radians().sin();
        csv.push_str(&format!("{},0,0,{z:.6},0,0,0\n", 10 * k));
    }
    let linear = paired_playing(dir.path(), &csv);
    let o = stewart(&["check", "--scenario", &linear]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let text = std::fs::read_to_string(&linear).unwrap_or_default();
    let cubic = write(
        dir.path(),
        "cubic.toml",
        &(text + "interpolation = \"cubic\"\n"),
    );
    let o = stewart(&["check", "--scenario", &cubic, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let findings = json(&o)["findings"].as_array().cloned().unwrap_or_default();
    assert!(
        findings.iter().any(|f| f["kind"] == "stroke_max"),
        "{findings:?}"
    );
}
