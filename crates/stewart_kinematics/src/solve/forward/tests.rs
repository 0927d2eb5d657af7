use super::*;
use crate::model::geometry::StrokeLimits;
use proptest::prelude::*;

/// Normalised condition number above which a pose is taken as near-singular: there two
/// assembly modes can lie within a millimetre of each other with the same leg lengths to
/// 1e-16 (proptest found one at κ ≈ 289), so "the solver returns the original pose" is
/// only a property of well-conditioned poses. Every solution must still reproduce the lengths.
const WELL_CONDITIONED: f64 = 50.0;

/// The solution reproduces `lengths`, and is `truth` itself where the pose is determined.
fn check_solution(g: &Geometry, sol: &ForwardSolution, lengths: &[f64; 6], truth: &Pose) {
    assert!(sol.residual <= 1e-12, "residual {}", sol.residual);
    let found = g.leg_lengths(&sol.pose);
    for i in 0..6 {
        assert!((found[i] - lengths[i]).abs() <= 1e-12);
    }
    if g.conditioning(truth)
        .condition_number
        .is_some_and(|k| k < WELL_CONDITIONED)
    {
        assert_same_pose(&sol.pose, truth, 1e-9);
    }
}

fn assert_same_pose(a: &Pose, b: &Pose, tol: f64) {
    assert!((a.position - b.position).norm() < tol, "{a:?} vs {b:?}");
    assert!((a.rotation() - b.rotation()).amax() < tol, "{a:?} vs {b:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Warm start: from a pose a few millimetres and tenths of a degree away, as along a trajectory.
    #[test]
    fn forward_inverts_inverse_from_a_warm_start(
        x in -0.3f64..0.3, y in -0.3f64..0.3, z in 0.5f64..1.1,
        r in -25.0f64..25.0, p in -25.0f64..25.0, w in -40.0f64..40.0,
        dx in -0.005f64..0.005, dr in -0.5f64..0.5,
    ) {
        let g = crate::test_support::paired_geometry();
        let truth = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
        let lengths = g.leg_lengths(&truth);
        let start = Pose::from_xyz_rpy_deg([x + dx, y - dx, z + dx], [r + dr, p - dr, w + dr]);
        let sol = g.forward(&lengths, &start, &ForwardOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        // Quadratic convergence from a nearby start, where the pose is determined well.
        let kappa = g.conditioning(&truth).condition_number.unwrap_or(f64::INFINITY);
        prop_assert!(sol.iterations <= 8 || kappa >= WELL_CONDITIONED, "{} iterations at κ = {kappa}", sol.iterations);
        check_solution(&g, &sol, &lengths, &truth);
    }

    /// The solver's residual is the inverse kinematics' lengths minus the target, and its
    /// derivative (leg directions and the moments about the turning axes) is the central
    /// difference of the inverse kinematics, for a platform turning about an offset pivot.
    #[test]
    fn residual_derivative_is_the_inverse_kinematics_difference_quotient(
        x in -0.3f64..0.3, y in -0.3f64..0.3, z in 0.5f64..1.1,
        r in -60.0f64..60.0, p in -60.0f64..60.0, w in -180.0f64..180.0,
    ) {
        let mut params = crate::model::geometry::GeometryParams::seed();
        params.pivot = Vector3::new(0.03, -0.02, 0.05);
        let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
        let pose = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
        let coords = coordinates(&pose);
        let target = [0.5; 6];
        let (f, d) = residual_and_derivative(&g, g.base_joints(), &coords, &target);
        let lengths = g.leg_lengths(&pose);
        let h = 1e-6;
        for i in 0..6 {
            prop_assert!((f[i] - (lengths[i] - 0.5)).abs() < 1e-14);
        }
        for k in 0..6 {
            let mut up = coords;
            let mut down = coords;
            up[k] += h;
            down[k] -= h;
            let (lu, ld) = (g.leg_lengths(&pose_of(&up)), g.leg_lengths(&pose_of(&down)));
            for i in 0..6 {
                let quotient = (lu[i] - ld[i]) / (2.0 * h);
                prop_assert!((d[(i, k)] - quotient).abs() < 1e-8, "leg {i} coordinate {k}: {} vs {quotient}", d[(i, k)]);
            }
        }
    }

    /// Cold start: from the home pose, over a wide range of poses.
    #[test]
    fn forward_inverts_inverse_from_home(
        x in -0.25f64..0.25, y in -0.25f64..0.25, z in 0.6f64..1.0,
        r in -15.0f64..15.0, p in -15.0f64..15.0, w in -25.0f64..25.0,
    ) {
        let g = crate::test_support::paired_geometry();
        let truth = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
        let lengths = g.leg_lengths(&truth);
        let sol = g.forward(&lengths, &g.home_pose(), &ForwardOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        check_solution(&g, &sol, &lengths, &truth);
    }
}

#[test]
fn impossible_lengths_fail_with_a_typed_error() {
    let g = crate::test_support::paired_geometry();
    // Every leg 0.1 m: joints 1 and 4 of the base are 2 m apart, of the platform at most
    // 1.2 m, so no platform can be within 0.1 m of both: there is no solution.
    let err = g
        .forward(&[0.1; 6], &g.home_pose(), &ForwardOptions::default())
        .unwrap_err();
    assert!(
        matches!(
            err,
            ForwardError::NotConverged { .. } | ForwardError::Singular { .. }
        ),
        "{err}"
    );
    let text = err.to_string();
    assert!(text.contains("residual"), "{text}");

    assert!(matches!(
        g.forward(&[1.0, 1.0, f64::NAN, 1.0, 1.0, 1.0], &g.home_pose(), &ForwardOptions::default()),
        Err(ForwardError::InvalidLength { leg: 3, value }) if value.is_nan()
    ));
    assert!(matches!(
        g.forward(
            &[1.0, 1.0, -1.0, 1.0, 1.0, 1.0],
            &g.home_pose(),
            &ForwardOptions::default()
        ),
        Err(ForwardError::InvalidLength { leg: 3, .. })
    ));
    let mut params = g.params().clone();
    params.stroke = StrokeLimits::new(0.9, 1.2);
    let limited = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        limited.forward(
            &[1.0, 1.0, 1.0, 1.0, 1.25, 1.0],
            &g.home_pose(),
            &ForwardOptions::default()
        ),
        Err(ForwardError::OutsideStroke {
            leg: 5,
            length: 1.25,
            min: 0.9,
            max: 1.2
        })
    );
}

#[test]
fn a_polished_solution_reproduces_the_lengths_to_rounding() {
    // Started 1 mm off, the solver stops once within 1e-12 m; polished, it goes on to the
    // last few units in the last place of a metre (the guard of a cue differences poses
    // found 1.5 µs apart, where 1e-12 m is an acceleration of hundreds of m/s²).
    let g = crate::test_support::paired_geometry();
    let truth = Pose::from_xyz_rpy_deg([0.05, -0.02, 0.9], [3.0, -2.0, 5.0]);
    let lengths = g.leg_lengths(&truth);
    let start = Pose::from_xyz_rpy_deg([0.051, -0.02, 0.9], [3.0, -2.0, 5.0]);
    let off = |pose: &Pose| {
        let found = g.leg_lengths(pose);
        (0..6).fold(0.0f64, |m, i| m.max((found[i] - lengths[i]).abs()))
    };
    let plain = g.forward(&lengths, &start, &ForwardOptions::default());
    let polished = ForwardOptions {
        polish: true,
        ..ForwardOptions::default()
    };
    let fine = g.forward(&lengths, &start, &polished);
    let (plain, fine) = (
        plain.unwrap_or_else(|e| panic!("{e}")),
        fine.unwrap_or_else(|e| panic!("{e}")),
    );
    assert!(off(&fine.pose) <= 1e-15, "{}", off(&fine.pose));
    // Here the plain solve stops at 6e-14 m, the polished one at 2e-16 m.
    assert!(fine.residual <= 1e-15 && plain.residual > 100.0 * fine.residual);
    assert!(fine.iterations == plain.iterations);
    for (a, b) in fine.pose.to_row().iter().zip(truth.to_row()) {
        assert!((a - b).abs() < 1e-12, "{a} against {b}");
    }
}

#[test]
fn iteration_limit_is_reported() {
    let g = crate::test_support::paired_geometry();
    let truth = Pose::from_xyz_rpy_deg([0.1, 0.1, 0.9], [10.0, -5.0, 20.0]);
    let lengths = g.leg_lengths(&truth);
    let opts = ForwardOptions {
        max_iterations: 1,
        ..ForwardOptions::default()
    };
    match g.forward(&lengths, &g.home_pose(), &opts) {
        Err(ForwardError::NotConverged {
            iterations,
            residual,
        }) => {
            assert_eq!(iterations, 1);
            assert!(residual > 1e-12);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn near_singular_poses_can_share_their_leg_lengths_with_a_neighbour() {
    // The case proptest found: two poses ~1 mm and 0.2° apart with equal leg lengths (to
    // 2e-16) at κ ≈ 289. The warm solver may return either; both reproduce the lengths.
    use crate::model::angle::Angle;
    let g = crate::test_support::paired_geometry();
    let pose = |p: [f64; 3], r: [f64; 3]| {
        Pose::new(
            Vector3::from(p),
            Angle::from_radians(r[0]),
            Angle::from_radians(r[1]),
            Angle::from_radians(r[2]),
        )
    };
    let a = pose(
        [
            0.02486219262462947,
            -0.27281498034371787,
            0.5123279263060075,
        ],
        [
            -0.4173841132556664,
            0.33861497645764804,
            -0.2824340150696038,
        ],
    );
    let b = pose(
        [
            0.024829805658870358,
            -0.2737687672983464,
            0.5108257502122425,
        ],
        [
            -0.4213015228110429,
            0.34078568355085814,
            -0.28385833524806464,
        ],
    );
    let (la, lb) = (g.leg_lengths(&a), g.leg_lengths(&b));
    assert!((0..6).all(|i| (la[i] - lb[i]).abs() < 1e-12));
    assert!((a.position - b.position).norm() > 5e-4);
    assert!(
        g.conditioning(&a)
            .condition_number
            .is_some_and(|k| k > WELL_CONDITIONED)
    );
    let sol = g
        .forward(&la, &a, &ForwardOptions::default())
        .unwrap_or_else(|e| panic!("{e}"));
    check_solution(&g, &sol, &la, &a);
}

#[test]
fn a_near_singular_warm_start_still_converges() {
    // Found by proptest: κ ≈ 159 here, and Newton needs 9 iterations instead of ≤ 8; the
    // iteration bound of the property holds only for well-conditioned poses.
    let g = crate::test_support::paired_geometry();
    let truth = Pose::from_xyz_rpy_deg(
        [-0.21302707904320878, 0.25627429016433, 0.5025641919662236],
        [20.128164901055573, 17.741456521448413, 39.25403373045656],
    );
    let kappa = g
        .conditioning(&truth)
        .condition_number
        .unwrap_or(f64::INFINITY);
    assert!(kappa > WELL_CONDITIONED, "κ = {kappa}");
    let (dx, dr) = (0.0004749692534870331, -0.4664420807893896);
    let [x, y, z] = [truth.position.x, truth.position.y, truth.position.z];
    let [r, p, w] = truth.rpy_degrees();
    let start = Pose::from_xyz_rpy_deg([x + dx, y - dx, z + dx], [r + dr, p - dr, w + dr]);
    let lengths = g.leg_lengths(&truth);
    let sol = g
        .forward(&lengths, &start, &ForwardOptions::default())
        .unwrap_or_else(|e| panic!("{e}"));
    check_solution(&g, &sol, &lengths, &truth);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Servo angles of a pose, then the pose from those angles: the rods close to 1e-12 m
    /// and the pose is the one we started from (warm start a little away, as along a
    /// trajectory; where the pose is well determined).
    #[test]
    fn servo_forward_inverts_servo_inverse(
        x in -0.015f64..0.015, y in -0.015f64..0.015, z in 0.105f64..0.13,
        r in -8.0f64..8.0, p in -8.0f64..8.0, w in -12.0f64..12.0,
        dx in -0.002f64..0.002, dr in -0.5f64..0.5,
    ) {
        let g = crate::test_support::servo_geometry();
        let truth = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
        let Some(Ok(angles)) = g.servo_angles(&truth) else {
            return Ok(()); // unreachable there: nothing to invert
        };
        let start = Pose::from_xyz_rpy_deg([x + dx, y - dx, z + dx], [r + dr, p - dr, w + dr]);
        let sol = g
            .forward_servos(&angles, &start, &ForwardOptions::default())
            .unwrap_or_else(|e| panic!("{e}"));
        prop_assert!(sol.residual <= 1e-12, "residual {}", sol.residual);
        // The found pose holds the servos where they were asked to be.
        let again = g.servo_angles(&sol.pose).and_then(Result::ok);
        prop_assert!(again.is_some());
        if let Some(again) = again {
            for i in 0..6 {
                prop_assert!((again[i].radians() - angles[i].radians()).abs() < 1e-9);
            }
        }
        prop_assert!((sol.pose.position - truth.position).norm() < 1e-9, "{:?} vs {truth:?}", sol.pose);
        prop_assert!((sol.pose.rotation() - truth.rotation()).amax() < 1e-9);
    }
}

#[test]
fn servo_forward_needs_a_rotary_platform_and_finite_angles() {
    let g = crate::test_support::paired_geometry();
    let home = g.home_pose();
    let zero = [Angle::from_degrees(0.0); 6];
    assert_eq!(
        g.forward_servos(&zero, &home, &ForwardOptions::default()),
        Err(ForwardError::NotRotary)
    );
    let g = crate::test_support::servo_geometry();
    let mut bad = zero;
    bad[3] = Angle::from_degrees(f64::NAN);
    assert!(matches!(
        g.forward_servos(&bad, &g.home_pose(), &ForwardOptions::default()),
        Err(ForwardError::InvalidAngle { servo: 4, .. })
    ));
}

/// Every assembly mode of a rotary platform closes every rod at the horn tips of the given
/// servo angles, and the pose those angles were solved from is among them.
#[test]
fn servo_assembly_modes_close_every_rod_and_include_the_pose() {
    let s = crate::io::scenario::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let servos = g.rotary().unwrap_or_else(|| panic!("rotary"));
    let pose = Pose::from_xyz_rpy_deg([0.008, -0.004, 0.115], [3.0, -2.0, 6.0]);
    let angles = g
        .servo_angles(&pose)
        .and_then(Result::ok)
        .unwrap_or_else(|| panic!("reachable"));
    let modes = g
        .servo_assembly_modes(&angles)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(modes.len() >= 2, "{}", modes.len());
    for m in &modes {
        let joints = g.inverse(&m.pose).platform_joints;
        for i in 0..6 {
            let tip = servos.horn_tip(i, &g.base_joints()[i], angles[i]);
            assert!(((joints[i] - tip).norm() - servos.rod_length()).abs() < 1e-9);
        }
    }
    assert!(
        modes
            .iter()
            .any(|m| assembly::same_placement(&m.pose, &pose))
    );
    // The mirror image below the base closes the rods too: the search finds it.
    assert!(modes.iter().any(|m| m.pose.position.z < 0.0));
}
