//! `stewart check`.

use crate::{stderr, stdout, stewart, tempdir, write};

#[test]
fn the_seed_passes_with_status_0() {
    let o = stewart(&["check"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let text = stdout(&o);
    assert!(text.contains("1001 samples"));
    assert!(text.contains("No problem found"));
}

#[test]
fn a_leg_over_its_stroke_is_located_with_status_1() {
    let dir = tempdir();
    // Seed motion with a shorter maximum: legs pass 1.15 m somewhere.
    let text =
        include_str!("../../assets/presets/seed.toml").replace("leg_max = 1.30", "leg_max = 1.15");
    let scenario = write(dir.path(), "short.toml", &text);
    let o = stewart(&["check", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("leg L1 is longer than its maximum 1.1500 m from t = "),
        "{out}"
    );

    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    let doc: serde_json::Value =
        serde_json::from_slice(&o.stdout).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(doc["clean"], false);
    assert_eq!(doc["samples"], 1001);
    assert_eq!(doc["leg_max_m"], 1.15);
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    assert!(!findings.is_empty());
    for f in &findings {
        assert_eq!(f["kind"], "stroke_max");
        let worst = f["worst_value"].as_f64().unwrap_or(0.0);
        let excess = f["excess"].as_f64().unwrap_or(0.0);
        assert!((worst - 1.15 - excess).abs() < 1e-12 && excess > 0.0);
        let (first, last) = (
            f["first_time"].as_f64().unwrap_or(-1.0),
            f["last_time"].as_f64().unwrap_or(-1.0),
        );
        assert!((0.0..=10.0).contains(&first) && first <= last);
    }
    // L1 reaches 1.196 m in the seed motion (see `stewart check`): it must be among them.
    assert!(findings.iter().any(|f| f["leg"] == 1));
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
    write(dir.path(), "poses.csv", &csv);
    let scenario = write(
        dir.path(),
        "s.toml",
        &(include_str!("../../assets/presets/seed.toml")
            .split("[trajectory]")
            .next()
            .unwrap_or_default()
            .to_owned()
            + "[trajectory]\nkind = \"pose_table\"\nfile = \"poses.csv\"\n"),
    );
    let o = stewart(&["check", "--scenario", &scenario, "--format", "json"]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let doc: serde_json::Value =
        serde_json::from_slice(&o.stdout).unwrap_or_else(|e| panic!("{e}"));
    let findings = doc["findings"].as_array().cloned().unwrap_or_default();
    assert_eq!(findings.len(), 6, "every leg jumps: {findings:?}");
    for f in &findings {
        assert_eq!(f["kind"], "jump");
        assert_eq!(f["first_time"], 1.0);
        assert_eq!(f["count"], 1);
    }
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
}
