//! `stewart fk`.

use crate::{parse_csv, stderr, stdout, stewart, stewart_with_input, tempdir, write};

/// Leg lengths of the paired preset's trajectory, from `stewart solve`.
fn paired_solution() -> String {
    let o = stewart(&["solve", "--preset", "paired"]);
    assert!(o.status.success(), "{}", stderr(&o));
    stdout(&o)
}

#[test]
fn fk_recovers_the_trajectory_warm_and_cold() {
    let solved = paired_solution();
    let (_, rows) = parse_csv(&solved);
    for extra in [None, Some("--cold")] {
        let mut args = vec!["fk", "--preset", "paired", "--legs", "-"];
        args.extend(extra);
        let o = stewart_with_input(&args, solved.as_bytes());
        assert!(o.status.success(), "{}", stderr(&o));
        let (header, poses) = parse_csv(&stdout(&o));
        assert_eq!(
            header.join(","),
            "t,x,y,z,roll_deg,pitch_deg,yaw_deg,iterations,residual"
        );
        assert_eq!(poses.len(), rows.len());
        for (p, r) in poses.iter().zip(&rows) {
            assert_eq!(p[0], r[0]);
            for c in 1..4 {
                assert!((p[c] - r[c]).abs() < 1e-9, "{p:?} vs {r:?}");
            }
            for c in 4..7 {
                assert!((p[c] - r[c]).abs() < 1e-7, "{p:?} vs {r:?}");
            }
            assert!(p[8] <= 1e-12, "residual {}", p[8]);
        }
        let iterations: f64 = poses.iter().map(|p| p[7]).sum();
        let mean = iterations / poses.len() as f64;
        if extra.is_none() {
            assert!(mean <= 4.5, "warm starts take a few iterations, got {mean}");
        }
    }
}

#[test]
fn assembly_modes_lists_several_solutions_per_row() {
    let dir = tempdir();
    let legs = write(
        dir.path(),
        "legs.csv",
        "note,L1,L2,L3,L4,L5,L6\nhome,1,1,1,1,1,1\n",
    );
    let o = stewart(&[
        "fk",
        "--preset",
        "paired",
        "--legs",
        &legs,
        "--assembly-modes",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(header[..2], ["row", "mode"]);
    assert!(rows.len() >= 2, "{rows:?}");
    // All of input row 1; numbered from 1, highest platform first, and the mirror of the
    // first is among them.
    assert!(rows.iter().all(|r| r[0] == 1.0));
    assert_eq!(rows[0][1], 1.0);
    assert!(rows[0][4] > 0.0);
    assert!(
        rows.iter()
            .any(|r| (r[4] + rows[0][4]).abs() < 1e-9 && (r[2] - rows[0][2]).abs() < 1e-9)
    );
}

/// Dietmaier's published platform and legs (`dietmaier.toml`, `dietmaier_legs.csv`).
const DIETMAIER_BASE: [[f64; 3]; 6] = [
    [0.0, 0.0, 0.0],
    [1.107915, 0.0, 0.0],
    [0.549094, 0.756063, 0.0],
    [0.735077, -0.223935, 0.525991],
    [0.514188, -0.526063, -0.368418],
    [0.590473, 0.094733, -0.205018],
];
const DIETMAIER_PLATFORM: [[f64; 3]; 6] = [
    [0.0, 0.0, 0.0],
    [0.542805, 0.0, 0.0],
    [0.956919, -0.528915, 0.0],
    [0.665885, -0.353482, 1.402538],
    [0.478359, 1.158742, 0.107672],
    [-0.137087, -0.235121, 0.353913],
];
const DIETMAIER_LEGS: [f64; 6] = [1.0, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071];

/// The legs of a pose row `x, y, z, roll, pitch, yaw` (degrees), computed here from
/// the rotation `Rz(yaw)·Ry(pitch)·Rx(roll)` written out by hand.
fn dietmaier_legs_at(row: &[f64]) -> [f64; 6] {
    let [r, p, y] = [row[3], row[4], row[5]].map(f64::to_radians);
    let (sr, cr, sp, cp, sy, cy) = (r.sin(), r.cos(), p.sin(), p.cos(), y.sin(), y.cos());
    let m = [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ];
    std::array::from_fn(|i| {
        let a = DIETMAIER_PLATFORM[i];
        let b = DIETMAIER_BASE[i];
        let d: Vec<f64> = (0..3)
            .map(|k| row[k] + m[k][0] * a[0] + m[k][1] * a[1] + m[k][2] * a[2] - b[k])
            .collect();
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    })
}

#[test]
fn dietmaiers_platform_has_forty_real_assembly_modes() {
    let scenario = format!("{}/cli/dietmaier.toml", env!("CARGO_MANIFEST_DIR"));
    let legs = scenario.replace("dietmaier.toml", "dietmaier_legs.csv");
    let o = stewart(&[
        "fk",
        "--scenario",
        &scenario,
        "--legs",
        &legs,
        "--assembly-modes",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(
        header.join(","),
        "row,mode,x,y,z,roll_deg,pitch_deg,yaw_deg,iterations,residual"
    );
    assert_eq!(rows.len(), 40);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!((row[0], row[1]), (1.0, (k + 1) as f64));
        assert!(row[9] < 1e-12, "mode {}: residual {}", k + 1, row[9]);
        // Each pose really has Dietmaier's legs (to the printed precision).
        let l = dietmaier_legs_at(&row[2..8]);
        for i in 0..6 {
            assert!(
                (l[i] - DIETMAIER_LEGS[i]).abs() < 1e-12,
                "mode {}: {l:?}",
                k + 1
            );
        }
    }
    // Forty different placements: any two differ by more than a millimetre somewhere.
    for i in 0..40 {
        for j in i + 1..40 {
            let apart = (2..8).any(|c| (rows[i][c] - rows[j][c]).abs() > 1e-3);
            assert!(apart, "modes {} and {} coincide", i + 1, j + 1);
        }
    }
    // The preset has those legs at home, so its modes are the same forty.
    let dir = tempdir();
    let home = write(
        dir.path(),
        "legs.csv",
        "L1,L2,L3,L4,L5,L6\n1.0,0.645275,1.086284,1.503439,1.281933,0.771071\n",
    );
    let o = stewart(&[
        "fk",
        "--preset",
        "dietmaier",
        "--legs",
        &home,
        "--assembly-modes",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, preset_rows) = parse_csv(&stdout(&o));
    assert_eq!(preset_rows.len(), 40);
    assert!(preset_rows.iter().any(|r| {
        r[2..8]
            .iter()
            .zip([0.0, 0.0, 0.372525366226035, 0.0, 0.0, 0.0])
            .all(|(a, b)| (a - b).abs() < 1e-9)
    }));
}

#[test]
fn fk_refuses_an_architecturally_singular_geometry_and_bad_rows() {
    let dir = tempdir();
    let legs = write(dir.path(), "legs.csv", "L1,L2,L3,L4,L5,L6\n1,1,1,1,1,1\n");
    let o = stewart(&["fk", "--preset", "seed", "--legs", &legs]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("the pose is not determined by the leg lengths"),
        "{err}"
    );
    assert!(err.contains("architecturally singular"), "{err}");
    assert!(err.contains("paired layout"), "{err}");

    let out = dir.path().join("poses.csv");
    let cases = [
        (
            "L1,L2,L3,L4,L5,L6\n1,1,1,1,1,1\n1,1,inf,1,1,1\n",
            "legs.csv, line 3, column `L3`: inf is not a finite number",
        ),
        (
            "L1,L2,L3,L4,L5,L6\n1,1,1,1,1,1\n0.1,0.1,0.1,0.1,0.1,0.1\n",
            "legs.csv, line 3: leg L1 length 0.1 m is outside the stroke [0.55 m, 1.3 m]",
        ),
        (
            "L1,L2,L3,L4,L5,L6\n1,1,1,1,1,1\n0.56,0.56,1.29,1.29,0.56,1.29\n",
            "legs.csv, line 3: forward kinematics",
        ),
        (
            "L1,L2,L3,L4,L6\n1,1,1,1,1\n",
            "legs.csv, line 1: the header has no `L5` column",
        ),
    ];
    for (text, expected) in cases {
        let legs = write(dir.path(), "legs.csv", text);
        let o = stewart(&[
            "fk",
            "--preset",
            "paired",
            "--legs",
            &legs,
            "--out",
            &out.display().to_string(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        assert!(stderr(&o).contains(expected), "{}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1);
        assert!(!out.exists());
    }
}
