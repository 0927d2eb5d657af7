use super::*;
use crate::model::geometry::GeometryParams;
use crate::model::layout::Layout;
use nalgebra::Vector3;

#[test]
fn batch_servo_angles_agree_with_the_closed_form_for_every_pose() {
    let g = crate::test_support::servo_geometry();
    let poses: Vec<Pose> = (0..20_000)
        .map(|k| {
            let t = k as f64;
            Pose::from_xyz_rpy_deg(
                [
                    0.02 * (0.37 * t).sin(),
                    0.02 * (0.23 * t).cos(),
                    0.117 + 0.01 * (0.11 * t).sin(),
                ],
                [
                    8.0 * (0.05 * t).sin(),
                    8.0 * (0.07 * t).cos(),
                    20.0 * (0.013 * t).sin(),
                ],
            )
        })
        .collect();
    // The batch form and the closed form agree on which poses are out of reach…
    let solver = ServoBatch::new(&g).unwrap_or_else(|| panic!("not rotary"));
    let mut out_of_reach = 0;
    for pose in &poses {
        let single = g.servo_angles(pose).unwrap_or_else(|| panic!("not rotary"));
        assert_eq!(single.is_err(), solver.angles(pose).is_err(), "{pose:?}");
        out_of_reach += usize::from(single.is_err());
    }
    assert!(
        out_of_reach > 100 && out_of_reach < 10_000,
        "{out_of_reach}"
    );
    // …and on the angles of the others.
    let poses: Vec<Pose> = poses
        .into_iter()
        .filter(|p| g.servo_angles(p).is_some_and(|r| r.is_ok()))
        .collect();
    let batch = g
        .servo_angles_batch(&poses)
        .unwrap_or_else(|| panic!("not rotary"))
        .unwrap_or_else(|e| panic!("unreachable {e:?}"));
    let mut worst: f64 = 0.0;
    for (pose, angles) in poses.iter().zip(&batch) {
        let single = g
            .servo_angles(pose)
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("{pose:?}"));
        for i in 0..6 {
            assert!((single[i].degrees() - angles[i]).abs() < 1e-9, "{pose:?}");
        }
        // The four-lane polynomial atan2 and the scalar fdlibm one agree to rounding.
        let scalar = solver
            .angles_scalar(pose)
            .unwrap_or_else(|i| panic!("servo {i}"));
        let lanes = solver.angles(pose).unwrap_or_else(|i| panic!("servo {i}"));
        for i in 0..6 {
            worst = worst.max((scalar[i] - lanes[i]).abs());
        }
    }
    assert!(worst < 1e-14, "{worst}");
    // An unreachable pose among reachable ones is found, with its servo.
    let mut with_bad = poses[..10].to_vec();
    with_bad[7] = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.5], [0.0, 0.0, 0.0]);
    assert_eq!(g.servo_angles_batch(&with_bad), Some(Err((7, 0))));
    assert!(Geometry::seed().servo_angles_batch(&poses).is_none());
}

#[test]
fn batch_agrees_with_single_pose_solution_for_every_pose() {
    let mut params = GeometryParams::from_layout(0.9, 0.5, 0.7, Layout::paired(24.0));
    params.pivot = Vector3::new(0.05, -0.02, 0.3);
    let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    // A deterministic spread of poses, including large angles in every quadrant.
    let poses: Vec<Pose> = (0..10_000)
        .map(|k| {
            let t = k as f64;
            Pose::from_xyz_rpy_deg(
                [
                    0.3 * (0.37 * t).sin(),
                    0.3 * (0.23 * t).cos(),
                    0.7 + 0.2 * (0.11 * t).sin(),
                ],
                [
                    170.0 * (0.05 * t).sin(),
                    80.0 * (0.07 * t).cos(),
                    359.0 * (0.013 * t).sin(),
                ],
            )
        })
        .collect();
    let batch = g.leg_lengths_batch(&poses);
    for (pose, lengths) in poses.iter().zip(&batch) {
        let single = g.leg_lengths(pose);
        for i in 0..6 {
            assert!((single[i] - lengths[i]).abs() < 1e-14, "{pose:?}");
        }
    }
}

#[test]
fn the_dispatched_batch_gives_the_scalar_paths_bits() {
    let g = Geometry::new(GeometryParams::from_layout(
        0.9,
        0.5,
        0.7,
        Layout::paired(24.0),
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let solver = BatchSolver::new(&g);
    // Random poses over wide ranges, angles near the quadrant boundaries, and angles
    // the fast reduction does not take (beyond its limit, NaN, infinite): a group of
    // eight with one of those falls back to the scalar path whole.
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut random = |scale: f64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        scale * ((seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0)
    };
    let mut poses: Vec<Pose> = (0..20_003)
        .map(|_| {
            let p = Vector3::new(random(2.0), random(2.0), 0.7 + random(1.0));
            let a = [random(720.0), random(720.0), random(720.0)];
            Pose::from_xyz_rpy_deg([p.x, p.y, p.z], a)
        })
        .collect();
    for (k, angle) in [45.0, 90.0, -135.0, 180.0, 1e-300, 0.0, -0.0]
        .into_iter()
        .enumerate()
    {
        poses[100 + k] = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [angle, -angle, angle]);
    }
    for (k, bad) in [2e5, -7e6, f64::NAN, f64::INFINITY].into_iter().enumerate() {
        poses[1000 + 9 * k].roll = crate::model::angle::Angle::from_radians(bad);
    }
    let mut dispatched = vec![[0.0; 6]; poses.len()];
    let mut lanes = vec![[0.0; 6]; poses.len()];
    let mut scalar = vec![[0.0; 6]; poses.len()];
    solver.solve_serial(&poses, &mut dispatched);
    solver.solve_reference(&poses, &mut lanes);
    solver.solve_one_by_one(&poses, &mut scalar);
    for k in 0..poses.len() {
        for i in 0..6 {
            let (d, l, s) = (dispatched[k][i], lanes[k][i], scalar[k][i]);
            assert!(
                d.to_bits() == s.to_bits() && l.to_bits() == s.to_bits(),
                "pose {k} leg {i}: {d} {l} {s}"
            );
        }
    }
    // And the scalar path is the closed form's, to 1e-14 m.
    for (pose, lengths) in poses
        .iter()
        .zip(&scalar)
        .filter(|(p, _)| p.roll.radians().is_finite())
    {
        let single = g.leg_lengths(pose);
        for i in 0..6 {
            assert!((single[i] - lengths[i]).abs() < 1e-14 * single[i].max(1.0));
        }
    }
}

#[test]
fn dispatched_servo_angles_give_the_scalar_paths_bits_and_its_first_unreachable_pose() {
    let g = crate::test_support::servo_geometry();
    let solver = ServoBatch::new(&g).unwrap_or_else(|| panic!("not rotary"));
    let pose = |k: usize, reach: f64| {
        let t = k as f64;
        Pose::from_xyz_rpy_deg(
            [
                reach * 0.02 * (0.37 * t).sin(),
                reach * 0.02 * (0.23 * t).cos(),
                0.117 + reach * 0.01 * (0.11 * t).sin(),
            ],
            [
                reach * 8.0 * (0.05 * t).sin(),
                reach * 8.0 * (0.07 * t).cos(),
                reach * 20.0 * (0.013 * t).sin(),
            ],
        )
    };
    // Reachable poses (a third of the full spread) in whole groups and a ragged end,
    // and angles the fast reduction does not take.
    let mut poses: Vec<Pose> = (0..10_005).map(|k| pose(k, 0.3)).collect();
    // (Whole turns, so still reachable: 40 000 and −1.2 million of them.)
    for (k, turns) in [40_000.0, -1.2e6].into_iter().enumerate() {
        poses[500 + 9 * k].yaw =
            crate::model::angle::Angle::from_radians(std::f64::consts::TAU * turns);
    }
    let reachable = |p: &Pose| solver.angles_scalar(p).is_ok();
    assert!(poses.iter().all(reachable));
    let mut dispatched = vec![[0.0; 6]; poses.len()];
    let mut reference = vec![[0.0; 6]; poses.len()];
    solver
        .solve_parallel(&poses, &mut dispatched)
        .unwrap_or_else(|e| panic!("{e:?}"));
    solver
        .solve_reference(&poses, &mut reference)
        .unwrap_or_else(|e| panic!("{e:?}"));
    for (k, p) in poses.iter().enumerate() {
        let scalar = solver.angles_scalar(p).unwrap_or_else(|e| panic!("{e}"));
        for i in 0..6 {
            assert_eq!(dispatched[k][i].to_bits(), scalar[i].to_bits(), "pose {k}");
            assert_eq!(reference[k][i].to_bits(), scalar[i].to_bits(), "pose {k}");
        }
    }
    // Poses out of reach from a point on: the first one is the error, with its
    // servo, as the scalar path finds it.
    let mut far = poses.clone();
    for (k, p) in far.iter_mut().enumerate().skip(7_777) {
        *p = pose(k, 3.0);
    }
    let first = far
        .iter()
        .enumerate()
        .find_map(|(k, p)| solver.angles_scalar(p).err().map(|servo| (k, servo)))
        .unwrap_or_else(|| panic!("every pose reaches"));
    assert!(first.0 >= 7_777);
    let mut out = vec![[0.0; 6]; far.len()];
    assert_eq!(solver.solve_reference(&far, &mut out), Err(first));
    assert_eq!(g.servo_angles_batch(&far), Some(Err(first)));
}

#[test]
fn absurd_or_degenerate_lanes_go_to_the_scalar_path_which_says_which() {
    // A pose among reachable ones whose joints lie astronomically far (the closure's
    // squares overflow) or on a shaft's axis: the group is left to the scalar path, whose
    // first error is the batch's, on every path.
    let g = crate::test_support::servo_geometry();
    let solver = ServoBatch::new(&g).unwrap_or_else(|| panic!("not rotary"));
    let home = g.home_pose();
    for (x, y, z) in [
        (1e160, 0.0, 0.117),
        (3e150, -2e150, 1e151),
        (0.0, 0.0, -1e-170),
    ] {
        let mut poses = vec![home; 21];
        poses[11].position = Vector3::new(x, y, z);
        let scalar = solver.angles_scalar(&poses[11]).err();
        let first = scalar.map(|servo| (11, servo));
        let mut out = vec![[0.0; 6]; poses.len()];
        let dispatched = solver.solve_parallel(&poses, &mut out).err();
        let reference = solver.solve_reference(&poses, &mut out).err();
        assert_eq!(dispatched, first, "({x}, {y}, {z})");
        assert_eq!(reference, first, "({x}, {y}, {z})");
        if first.is_none() {
            let lone = solver
                .angles_scalar(&poses[11])
                .unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(out[11].map(f64::to_bits), lone.map(f64::to_bits));
        }
    }
}

#[test]
fn a_closure_that_underflows_goes_to_the_scalar_path() {
    // Base and platform joints at the same places (joint 0 at angle 0: exactly (r, 0, 0)),
    // 3 m horns on 5 m rods (rod² − horn² = 16 exactly) and servo 0's shaft at 0°: a pose
    // 4 m up, 1e-170 m high puts leg 0 at (0, 4, 1e-170): its closure's squares underflow
    // to zero and both `atan2` arguments are 0. The scalar path (the standard library's
    // `atan2(0, 0)`) gives 0; the lanes must leave such a pose to it, not give 0/0.
    use crate::model::angle::Angle;
    use crate::model::geometry::PlateJoints;
    let angles = [0.0, 20.0, 120.0, 140.0, 240.0, 260.0].map(Angle::from_degrees);
    let mut p = GeometryParams::from_layout(3.0, 3.0, 4.0, Layout::seed());
    p.base = PlateJoints::Circle {
        radius: 3.0,
        angles,
    };
    p.platform = PlateJoints::Circle {
        radius: 3.0,
        angles,
    };
    p.actuator = crate::model::actuator::Actuator::Rotary(
        crate::model::rotary::RotaryActuators::new(
            3.0,
            5.0,
            [0.0, 20.0, 120.0, 140.0, 240.0, 260.0],
            None,
        )
        .unwrap_or_else(|e| panic!("{e}")),
    );
    let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
    let solver = ServoBatch::new(&g).unwrap_or_else(|| panic!("not rotary"));
    let mut poses = vec![Pose::from_xyz_rpy_deg([0.0, 0.0, 4.0], [0.0; 3]); 16];
    poses[5].position = Vector3::new(0.0, 4.0, 1e-170);
    let lone = solver.angles_scalar(&poses[5]);
    assert_eq!(lone.map(|a| a[0].to_bits()), Ok(0), "{lone:?}");
    let mut out = vec![[f64::NAN; 6]; poses.len()];
    assert_eq!(solver.solve_parallel(&poses, &mut out), Ok(()));
    let mut reference = vec![[f64::NAN; 6]; poses.len()];
    assert_eq!(solver.solve_reference(&poses, &mut reference), Ok(()));
    for (k, pose) in poses.iter().enumerate() {
        let lone = solver.angles_scalar(pose).map(|a| a.map(f64::to_bits));
        assert_eq!(Ok(out[k].map(f64::to_bits)), lone, "pose {k}");
        assert_eq!(Ok(reference[k].map(f64::to_bits)), lone, "pose {k}");
    }
}

#[test]
fn pose_rows_give_the_bits_of_the_pose_batch() {
    // Rows of a pose table (degrees), a ragged count over several chunks: the same
    // bits as the batch of the poses a table reader makes of them, for legs and servos.
    let row = |k: usize, reach: f64, z: f64| {
        let t = k as f64;
        [
            reach * 0.02 * (0.37 * t).sin(),
            reach * 0.02 * (0.23 * t).cos(),
            z + reach * 0.01 * (0.11 * t).sin(),
            reach * 8.0 * (0.05 * t).sin(),
            reach * 8.0 * (0.07 * t).cos(),
            reach * 20.0 * (0.013 * t).sin(),
        ]
    };
    let poses_of = |rows: &[[f64; 6]]| -> Vec<Pose> {
        rows.iter()
            .map(|r| Pose::from_xyz_rpy_deg([r[0], r[1], r[2]], [r[3], r[4], r[5]]))
            .collect()
    };
    for (g, z, reach) in [
        (crate::test_support::paired_geometry(), 0.8, 5.0),
        (crate::test_support::servo_geometry(), 0.117, 0.3),
    ] {
        let rows: Vec<[f64; 6]> = (0..2 * CHUNK + 301).map(|k| row(k, reach, z)).collect();
        let expected = g
            .actuator_values_batch(&poses_of(&rows))
            .unwrap_or_else(|e| panic!("{e:?}"));
        let mut got = vec![[0.0; 6]; rows.len()];
        g.actuator_values_rows(&rows, &mut got)
            .unwrap_or_else(|e| panic!("{e:?}"));
        for (k, (a, b)) in got.iter().zip(&expected).enumerate() {
            assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "row {k}");
        }
    }
    // Out of reach from a row on: that row and its servo, as the pose batch says.
    let g = crate::test_support::servo_geometry();
    let rows: Vec<[f64; 6]> = (0..CHUNK + 50)
        .map(|k| row(k, if k >= 3_001 { 3.0 } else { 0.3 }, 0.117))
        .collect();
    let Some(Err(first)) = g.servo_angles_batch(&poses_of(&rows)) else {
        panic!("every row reaches")
    };
    assert!(first.0 >= 3_001);
    let mut out = vec![[0.0; 6]; rows.len()];
    let unreachable = RowError::Unreachable {
        row: first.0,
        servo: first.1,
    };
    assert_eq!(g.actuator_values_rows(&rows, &mut out), Err(unreachable));
    // A NaN (or infinity) before it is the error instead, with its column.
    let mut bad = rows.clone();
    bad[2_000][4] = f64::NAN;
    bad[2_500][0] = f64::INFINITY;
    let nan = RowError::NotFinite {
        row: 2_000,
        column: 4,
    };
    assert_eq!(g.actuator_values_rows(&bad, &mut out), Err(nan));
    let legs = crate::test_support::paired_geometry();
    assert_eq!(legs.actuator_values_rows(&bad, &mut out), Err(nan));
    // An infinite position alone, in a later chunk; a finite row far out is refused
    // as every pose table refuses it (its lengths would overflow), and so is an angle
    // past ten turns, with their columns; the ranges' ends are accepted.
    let mut far = rows.clone();
    far[CHUNK + 7][1] = f64::NEG_INFINITY;
    let inf = RowError::NotFinite {
        row: CHUNK + 7,
        column: 1,
    };
    assert_eq!(legs.actuator_values_rows(&far, &mut out), Err(inf));
    for (column, value) in [(1, 1e300), (0, 1_000.000_001), (5, -3600.001)] {
        far[CHUNK + 7] = rows[CHUNK + 7];
        far[CHUNK + 7][column] = value;
        let outside = RowError::Outside {
            row: CHUNK + 7,
            column,
        };
        assert_eq!(legs.actuator_values_rows(&far, &mut out), Err(outside));
        // Servos too, before their first unreachable row.
        let mut servo_far = rows.clone();
        servo_far[100][column] = value;
        let outside = RowError::Outside { row: 100, column };
        assert_eq!(g.actuator_values_rows(&servo_far, &mut out), Err(outside));
    }
    far[CHUNK + 7] = [1000.0, -1000.0, 1000.0, 3600.0, -3600.0, 3600.0];
    assert_eq!(legs.actuator_values_rows(&far, &mut out), Ok(()));
    assert!(out[CHUNK + 7].iter().all(|l| l.is_finite()));
}

#[test]
fn results_keep_the_bits_they_had_before_the_kernels_were_tuned_for_avx2() {
    // Digests (FNV-1a over every result's bits) of 100 003 poses about home, taken by
    // `examples/batch_profile.rs`, which makes the same poses, with the kernels of commit
    // 7fd12a7 (before issue #60); the tuned kernels give the very same bits.
    let digest = |out: &[[f64; 6]]| {
        out.as_flattened()
            .iter()
            .fold(0xcbf2_9ce4_8422_2325_u64, |h, v| {
                (h ^ v.to_bits()).wrapping_mul(0x0100_0000_01b3)
            })
    };
    let rows_about = |g: &Geometry| -> Vec<[f64; 6]> {
        let home = g.home_pose().to_row();
        let scale = [0.01, 0.01, 0.005, 4.0, 4.0, 8.0];
        (0..100_003)
            .map(|k| {
                let s = (k as f64 * 0.618_033_988_749_895).fract() - 0.5;
                std::array::from_fn(|c| {
                    home[c] + scale[c] * s * if c % 2 == 0 { 1.0 } else { -1.0 }
                })
            })
            .collect()
    };
    let seed = Geometry::seed();
    let rows = rows_about(&seed);
    let poses: Vec<Pose> = rows.iter().map(Pose::from_row).collect();
    let mut out = vec![[0.0; 6]; rows.len()];
    BatchSolver::new(&seed).solve_serial(&poses, &mut out);
    assert_eq!(digest(&out), 0xce18_a93e_c286_7b05, "leg lengths");
    seed.actuator_values_rows(&rows, &mut out)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(digest(&out), 0xce18_a93e_c286_7b05, "leg lengths of rows");

    let desk = crate::Scenario::preset("servo-desk")
        .unwrap_or_else(|e| panic!("{e}"))
        .geometry;
    let rows = rows_about(&desk);
    let poses: Vec<Pose> = rows.iter().map(Pose::from_row).collect();
    let servos = ServoBatch::new(&desk).unwrap_or_else(|| panic!("servo-desk is rotary"));
    servos
        .solve_serial(&poses, &mut out)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(digest(&out), 0xa7ff_6e4a_cfb1_dc43, "servo angles");
    servos
        .solve_reference(&poses, &mut out)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(
        digest(&out),
        0xa7ff_6e4a_cfb1_dc43,
        "servo angles, baseline build"
    );
}
