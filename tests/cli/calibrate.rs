//! `stewart calibrate`.

use std::path::Path;

use stewart_kinematics::Scenario;

use crate::{parse_csv, stderr, stdout, stewart, tempdir, write};

/// A file under `tests/cli/`.
fn cli_file(name: &str) -> String {
    format!("{}/cli/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn load(path: &Path) -> Scenario {
    Scenario::load(path).unwrap_or_else(|e| panic!("{e}"))
}

/// The number that follows `after` in the report.
fn report_number(report: &str, after: &str) -> f64 {
    let rest = &report[report
        .find(after)
        .unwrap_or_else(|| panic!("`{after}` in {report}"))
        + after.len()..];
    rest.split_whitespace()
        .next()
        .and_then(|w| w.trim_end_matches(',').parse().ok())
        .unwrap_or_else(|| panic!("a number after `{after}`"))
}

#[test]
fn a_built_paired_platform_is_recovered_from_noisy_measurements_within_the_noise() {
    // The measurements and the truth come from scripts/calibration-example.py (its own
    // kinematics): joints moved by up to 4 mm, offsets up to 3 mm, 10 µm / 0.002° noise.
    let dir = tempdir();
    let out = dir.path().join("calibrated.toml");
    let measurements = cli_file("calibration/paired_measurements.csv");
    let o = stewart(&[
        "calibrate",
        "--preset",
        "paired",
        "--measurements",
        &measurements,
        "--out",
        &out.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = stdout(&o);
    let before = report_number(&report, "before RMS");
    let after = report_number(&report, "after RMS");
    assert!(before > 2.0 && after < 0.03, "{before} mm → {after} mm");
    assert!(
        report.contains("least determined combination: +0.71 offset1"),
        "{report}"
    );
    assert!(report.contains("written:"), "{report}");

    let calibrated = load(&out);
    let nominal = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let (_, truth) = parse_csv(
        &std::fs::read_to_string(cli_file("calibration/paired_as_built.csv"))
            .unwrap_or_else(|e| panic!("{e}")),
    );
    let mut worst: f64 = 0.0;
    for (i, row) in truth.iter().enumerate() {
        let b = calibrated.geometry.base_joints()[i];
        let a = calibrated.geometry.platform_joints()[i];
        let found = [b.x, b.y, b.z, a.x, a.y, a.z, -calibrated.link.offset[i]];
        for (k, value) in found.iter().enumerate() {
            worst = worst.max((value - row[k + 1]).abs());
        }
        // Each joint moved from the nominal by millimetres.
        let moved = (b - nominal.geometry.base_joints()[i]).norm();
        assert!(
            moved > 1e-4 && moved < 0.01,
            "base joint {}: {moved} m",
            i + 1
        );
    }
    // Within 1.2 mm everywhere: three standard uncertainties of the weakest parameters
    // (offset and base height, ±0.4 mm), where the nominal was up to 4 mm off.
    assert!(worst < 1.2e-3, "{worst} m from the truth");
    // Everything else of the scenario is kept, and the calibrated one passes its check.
    assert_eq!(calibrated.name, "paired");
    assert_eq!(calibrated.geometry.stroke(), nominal.geometry.stroke());
    let o = stewart(&["check", "--scenario", &out.display().to_string()]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
}

/// Poses of a small servo platform: 30 of them, about its home, turning in every axis.
fn servo_poses() -> String {
    let mut text = String::from("x,y,z,roll_deg,pitch_deg,yaw_deg\n");
    for k in 0..30 {
        let s = f64::from(k);
        text.push_str(&format!(
            "{},{},{},{},{},{}\n",
            0.005 * (0.7 * s).sin(),
            0.005 * (1.3 * s).cos(),
            0.117 + 0.004 * (0.4 * s).sin(),
            5.0 * (0.9 * s).cos(),
            5.0 * (1.7 * s).sin(),
            6.0 * (0.5 * s).sin()
        ));
    }
    text
}

#[test]
fn a_servo_platform_recovers_moved_joints_and_its_horn_offsets_as_trims() {
    let dir = tempdir();
    let poses = write(dir.path(), "poses.csv", &servo_poses());
    let scenario = &cli_file("rotary.toml");
    // The built platform: two joints off by 2 mm, three horns mounted a few degrees off
    // (what the servos are told for a model angle is the built platform's command).
    let truth = [
        "--set",
        "geometry.platform_joints_m[2][0]=0.012",
        "--set",
        "geometry.base_joints_m[4][1]=-0.0605",
        "--set",
        "actuator.servo_trim_deg[0]=3",
        "--set",
        "actuator.servo_trim_deg[3]=-2",
        "--set",
        "actuator.servo_trim_deg[5]=1.5",
    ];
    let mut args = vec![
        "solve",
        "--scenario",
        scenario,
        "--poses",
        &poses,
        "--commanded",
    ];
    args.extend(truth);
    let o = stewart(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    // Those commands, read as the nominal platform's model angles (its trims are 0).
    let measured = stdout(&o).replacen("cmd", "theta", 6);
    let measurements = write(dir.path(), "measured.csv", &measured);
    let out = dir.path().join("calibrated.toml");
    let o = stewart(&[
        "calibrate",
        "--scenario",
        scenario,
        "--measurements",
        &measurements,
        "--out",
        &out.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("offset1"), "{}", stdout(&o));
    let calibrated = load(&out);
    let servos = calibrated
        .geometry
        .rotary()
        .unwrap_or_else(|| panic!("rotary"));
    let trims: Vec<f64> = servos.trims().iter().map(|t| t.degrees()).collect();
    for (found, want) in trims.iter().zip([3.0, 0.0, 0.0, -2.0, 0.0, 1.5]) {
        assert!((found - want).abs() < 1e-6, "trims {trims:?}");
    }
    assert!((calibrated.geometry.platform_joints()[2].x - 0.012).abs() < 1e-8);
    assert!((calibrated.geometry.base_joints()[4].y + 0.0605).abs() < 1e-8);
    let nominal = load(Path::new(scenario));
    assert!(
        (calibrated.geometry.base_joints()[0] - nominal.geometry.base_joints()[0]).norm() < 1e-8
    );
}

#[test]
fn bad_or_uninformative_measurements_are_refused_with_the_reason_and_nothing_written() {
    let dir = tempdir();
    let out = dir.path().join("calibrated.toml");
    let full = std::fs::read_to_string(cli_file("calibration/paired_measurements.csv"))
        .unwrap_or_else(|e| panic!("{e}"));
    let few: String = full.lines().take(8).map(|l| format!("{l}\n")).collect();
    let translations = {
        let mut t = String::from("x,y,z,roll_deg,pitch_deg,yaw_deg,L1,L2,L3,L4,L5,L6\n");
        let o = stewart(&["solve", "--preset", "paired"]);
        let (_, rows) = parse_csv(&stdout(&o));
        // The paired preset's legs at its positions, with the rotation dropped: poses a
        // rig that only translates would give (the lengths do not matter for the verdict).
        for r in rows.iter().step_by(50) {
            t.push_str(&format!(
                "{},{},{},0,0,0,{},{},{},{},{},{}\n",
                r[1], r[2], r[3], r[7], r[8], r[9], r[10], r[11], r[12]
            ));
        }
        t
    };
    let cases = [
        (
            "missing.csv",
            full.replacen("L3", "L7", 1),
            "missing.csv, line 1: the header has no `L3` column",
        ),
        (
            "nan.csv",
            {
                // Line 3's x measured as NaN.
                let mut lines: Vec<String> = full.lines().map(str::to_owned).collect();
                let rest = lines[2].split_once(',').map_or("", |(_, r)| r).to_owned();
                lines[2] = format!("NaN,{rest}");
                lines.join("\n")
            },
            "nan.csv, line 3, column `x`: NaN is not a finite number",
        ),
        (
            "few.csv",
            few,
            "few.csv: 7 measured poses are too few: each leg has 7 unknowns",
        ),
        (
            "translations.csv",
            translations,
            "cannot tell some parameters apart: for leg 1, moving the parameters together as in any of (base1.x + platform1.x)",
        ),
    ];
    for (name, text, expected) in cases {
        let path = write(dir.path(), name, &text);
        let o = stewart(&[
            "calibrate",
            "--preset",
            "paired",
            "--measurements",
            &path,
            "--out",
            &out.display().to_string(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let message = stderr(&o);
        assert_eq!(message.lines().count(), 1, "{name}: {message}");
        assert!(message.contains(expected), "{name}: {message}");
        assert!(!out.exists(), "{name}: nothing written");
    }
}
