//! `stewart solve`.

use std::f64::consts::PI;

use crate::{parse_csv, stderr, stdout, stewart, stewart_with_input, tempdir, write};

/// The seed article's script, transcribed independently of the library: 3×3 matrices
/// as arrays, joints at the article's angles, `q = p + R a`, `L = |q − b|`.
fn article_row(t: f64) -> [f64; 13] {
    let x = 0.15 * (2.0 * PI * 0.2 * t).sin();
    let y = 0.15 * (2.0 * PI * 0.2 * t).cos();
    let z = 0.8 + 0.08 * (2.0 * PI * 0.1 * t).sin();
    let roll = 6.0 * (2.0 * PI * 0.1 * t).sin();
    let pitch = 4.0 * (2.0 * PI * 0.15 * t + PI / 4.0).sin();
    let yaw = 8.0 * (2.0 * PI * 0.05 * t).sin();
    let mul = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| {
        let mut c = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                for k in 0..3 {
                    c[i][j] += a[i][k] * b[k][j];
                }
            }
        }
        c
    };
    let (r, p, w) = (roll * PI / 180.0, pitch * PI / 180.0, yaw * PI / 180.0);
    let rx = [
        [1.0, 0.0, 0.0],
        [0.0, r.cos(), -r.sin()],
        [0.0, r.sin(), r.cos()],
    ];
    let ry = [
        [p.cos(), 0.0, p.sin()],
        [0.0, 1.0, 0.0],
        [-p.sin(), 0.0, p.cos()],
    ];
    let rz = [
        [w.cos(), -w.sin(), 0.0],
        [w.sin(), w.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ];
    let rot = mul(mul(rz, ry), rx);
    let mut row = [t, x, y, z, roll, pitch, yaw, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    for i in 0..6 {
        let beta = (60.0 * i as f64) * PI / 180.0;
        let alpha = (30.0 + 60.0 * i as f64) * PI / 180.0;
        let b = [beta.cos(), beta.sin(), 0.0];
        let a = [0.6 * alpha.cos(), 0.6 * alpha.sin(), 0.0];
        let q: Vec<f64> = (0..3)
            .map(|j| [x, y, z][j] + rot[j][0] * a[0] + rot[j][1] * a[1] + rot[j][2] * a[2])
            .collect();
        row[7 + i] = ((q[0] - b[0]).powi(2) + (q[1] - b[1]).powi(2) + (q[2] - b[2]).powi(2)).sqrt();
    }
    row
}

#[test]
fn seed_solution_reproduces_the_article() {
    let o = stewart(&["solve"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(
        header.join(","),
        "t,x,y,z,roll_deg,pitch_deg,yaw_deg,L1,L2,L3,L4,L5,L6"
    );
    assert_eq!(rows.len(), 1001);
    for (k, row) in rows.iter().enumerate() {
        let t = k as f64 * 10.0 / 1000.0;
        let expected = article_row(t);
        // Time and position are the article's formulas to the last bit.
        assert_eq!(&row[..4], &expected[..4], "row {k}");
        // Angles go through radians and back: within a few units in the last place.
        for c in 4..7 {
            assert!((row[c] - expected[c]).abs() < 1e-13, "row {k} column {c}");
        }
        // Leg lengths: an independent evaluation agrees to rounding.
        for c in 7..13 {
            assert!(
                (row[c] - expected[c]).abs() < 1e-13,
                "row {k}: L{} {} vs {}",
                c - 6,
                row[c],
                expected[c]
            );
        }
    }
    // The home-pose hand value: at t = 5 s the seed is not home, but every leg of the
    // home pose is √(2 − 0.6·√3); sanity check of the scale of the numbers.
    let home = (2.0 - 0.6 * 3f64.sqrt()).sqrt();
    assert!(
        rows.iter()
            .all(|r| r[7..].iter().all(|l| (l - home).abs() < 0.25))
    );
}

#[test]
fn preset_and_scenario_file_give_the_same_result_and_out_writes_a_file() {
    let dir = tempdir();
    let out = dir.path().join("legs.csv");
    let o = stewart(&[
        "solve",
        "--preset",
        "paired",
        "--out",
        &out.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let from_preset = std::fs::read_to_string(&out).unwrap_or_else(|e| panic!("{e}"));
    let scenario = write(
        dir.path(),
        "paired.toml",
        stewart_kinematics::io::scenario::presets::text("paired")
            .unwrap_or_else(|| panic!("no preset paired")),
    );
    let o = stewart(&["solve", "--scenario", &scenario]);
    assert_eq!(stdout(&o), from_preset);
    // No temporary file is left behind.
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap_or_else(|e| panic!("{e}"))
        .map(|e| e.map(|e| e.file_name()).unwrap_or_default())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn poses_round_trip_through_solve() {
    // The trajectory's own output, fed back as a pose table (extra L columns ignored),
    // comes back byte for byte: numbers are written so that they read back to the same f64.
    let first = stdout(&stewart(&["solve", "--preset", "sway"]));
    let again = stewart_with_input(
        &["solve", "--preset", "sway", "--poses", "-"],
        first.as_bytes(),
    );
    assert!(again.status.success(), "{}", stderr(&again));
    let again = stdout(&again);
    assert_eq!(again.lines().count(), 802); // header and 801 samples
    for (k, (a, b)) in again.lines().zip(first.lines()).enumerate() {
        assert_eq!(a, b, "line {}", k + 1);
    }
}

#[test]
fn poses_without_time_and_in_any_column_order() {
    let dir = tempdir();
    let poses = write(
        dir.path(),
        "poses.csv",
        "yaw_deg,note,x,y,z,roll_deg,pitch_deg\n0,home,0,0,0.8,0,0\n# a comment line\n\n10,turned,0,0,0.8,0,0\n",
    );
    let o = stewart(&["solve", "--poses", &poses]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(
        header.join(","),
        "x,y,z,roll_deg,pitch_deg,yaw_deg,L1,L2,L3,L4,L5,L6"
    );
    let home = (2.0 - 0.6 * 3f64.sqrt()).sqrt();
    let yawed = (2.0 - 1.2 * 40f64.to_radians().cos()).sqrt();
    for l in &rows[0][6..] {
        assert!((l - home).abs() < 1e-15);
    }
    for l in &rows[1][6..] {
        assert!((l - yawed).abs() < 1e-15);
    }
    assert_eq!(rows[1][5], 10.0);
}

#[test]
fn bad_poses_give_one_located_error_and_no_output() {
    let dir = tempdir();
    let out = dir.path().join("out.csv");
    let out_s = out.display().to_string();
    let cases = [
        (
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,0\n0,0,0.8,NaN,0,0\n",
            "line 3, column `roll_deg`: NaN is not a finite number",
        ),
        (
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,0\n0,0,abc,0,0,0\n",
            "line 3, column `z`: `abc` is not a number",
        ),
        (
            "x,y,z,roll,pitch,yaw\n0,0,0.8,0,0,0\n",
            "line 1: the header has no `roll_deg` column",
        ),
        (
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0\n",
            "line 2: 5 fields where the header has 6",
        ),
        (
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n",
            "the table has a header but no data rows",
        ),
        (
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,1e999\n",
            "line 2, column `yaw_deg`: 1e999 is not a finite number",
        ),
    ];
    for (text, expected) in cases {
        let poses = write(dir.path(), "bad.csv", text);
        let o = stewart(&["solve", "--poses", &poses, "--out", &out_s]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.starts_with(&format!("error: {poses}, "))
                || err.starts_with(&format!("error: {poses}: ")),
            "{err}"
        );
        assert!(err.contains(expected), "{err}");
        assert!(!out.exists(), "an output file was written for bad input");
    }
    // An existing output file is left untouched by a failed run.
    std::fs::write(&out, "precious").unwrap_or_else(|e| panic!("{e}"));
    let o = stewart(&[
        "solve",
        "--poses",
        &dir.path().join("missing.csv").display().to_string(),
        "--out",
        &out_s,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("missing.csv"));
    assert_eq!(
        std::fs::read_to_string(&out).unwrap_or_default(),
        "precious"
    );
    // Not UTF-8.
    let bin = dir.path().join("bin.csv");
    std::fs::write(
        &bin,
        b"x,y,z,roll_deg,pitch_deg,yaw_deg\n\xff\xfe,0,0,0,0,0\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let o = stewart(&["solve", "--poses", &bin.display().to_string()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("line 2, column 1 is not valid UTF-8"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bad_scenarios_and_options_are_refused_with_status_2() {
    let dir = tempdir();
    let scenario = write(dir.path(), "s.toml", "[geometry]\nbase_radius = 0\n");
    let o = stewart(&["solve", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("s.toml, line 1"), "{}", stderr(&o));
    let o = stewart(&["solve", "--preset", "nope"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no preset is called `nope`"));
    let o = stewart(&["solve", "--preset", "seed", "--scenario", &scenario]);
    assert_eq!(o.status.code(), Some(2));
    let o = stewart(&[
        "solve",
        "--out",
        &dir.path().join("no/such/dir/x.csv").display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot write"), "{}", stderr(&o));
}
