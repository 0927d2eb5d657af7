use super::*;
use crate::geometry::StrokeLimits;
use proptest::prelude::*;

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
        prop_assert!(sol.residual <= 1e-12);
        prop_assert!(sol.iterations <= 8, "{} iterations", sol.iterations);
        assert_same_pose(&sol.pose, &truth, 1e-9);
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
        prop_assert!(sol.residual <= 1e-12);
        assert_same_pose(&sol.pose, &truth, 1e-9);
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
