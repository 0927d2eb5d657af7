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
    assert_eq!(header[0], "mode");
    assert!(rows.len() >= 2, "{rows:?}");
    // Numbered from 1, highest platform first, and the mirror of the first is among them.
    assert_eq!(rows[0][0], 1.0);
    assert!(rows[0][3] > 0.0);
    assert!(
        rows.iter()
            .any(|r| (r[3] + rows[0][3]).abs() < 1e-9 && (r[1] - rows[0][1]).abs() < 1e-9)
    );
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
