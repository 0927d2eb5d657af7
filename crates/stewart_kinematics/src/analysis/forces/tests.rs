use super::*;
use crate::model::angle::Angle;
use crate::model::pose::Pose;
use proptest::prelude::*;

fn payload(mass: f64, com: [f64; 3]) -> Payload {
    Payload::new(
        mass,
        Vector3::from(com),
        Matrix3::from_diagonal(&Vector3::new(2.0, 2.5, 4.0)),
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// The resultant force and moment (about the base origin) the legs exert.
fn resultant(g: &Geometry, pose: &Pose, f: &[f64; 6]) -> (Vector3<f64>, Vector3<f64>) {
    let sol = g.inverse(pose);
    let mut force = Vector3::zeros();
    let mut moment = Vector3::zeros();
    for (i, &fi) in f.iter().enumerate() {
        let fi = sol.unit(i) * fi;
        force += fi;
        moment += sol.platform_joints[i].cross(&fi);
    }
    (force, moment)
}

proptest! {
    /// Statics: the leg forces carry the weight, force and moment, at any pose.
    #[test]
    fn static_forces_balance_the_weight(
        x in -0.2f64..0.2, y in -0.2f64..0.2, z in 0.65f64..1.0,
        r in -15.0f64..15.0, p in -15.0f64..15.0, w in -25.0f64..25.0,
        m in 1.0f64..500.0, cx in -0.2f64..0.2, cy in -0.2f64..0.2, cz in 0.0f64..0.4,
    ) {
        let g = crate::test_support::paired_geometry();
        let pose = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
        let load = payload(m, [cx, cy, cz]);
        let f = static_forces(&g, &pose, &load).unwrap_or_else(|| panic!("singular"));
        let (force, moment) = resultant(&g, &pose, &f);
        let weight = Vector3::new(0.0, 0.0, -m * STANDARD_GRAVITY);
        // Σ f_i u_i = −weight, and the moments about the base origin cancel too.
        prop_assert!((force + weight).norm() < 1e-9 * m);
        let com = pose.position + pose.rotation() * Vector3::new(cx, cy, cz);
        prop_assert!((moment + com.cross(&weight)).norm() < 1e-9 * m);
    }
}

#[test]
fn a_centred_load_on_the_level_platform_is_shared_equally() {
    // By the three-fold symmetry of the paired layout, a load on the axis at home splits
    // equally: each leg carries m·g / (6 · u_z), with u_z = 0.8 / L.
    let g = crate::test_support::paired_geometry();
    let home = g.home_pose();
    let f = static_forces(&g, &home, &payload(60.0, [0.0, 0.0, 0.0]))
        .unwrap_or_else(|| panic!("singular"));
    let l = g.leg_lengths(&home)[0];
    let expected = 60.0 * STANDARD_GRAVITY / (6.0 * 0.8 / l);
    for fi in f {
        assert!((fi - expected).abs() < 1e-9, "{fi} vs {expected}");
    }
}

#[test]
fn dynamics_adds_mass_times_acceleration_in_a_vertical_lift() {
    // z = 0.8 + ½·a·t²: the legs must carry m·(g + a).
    let g = crate::test_support::paired_geometry();
    let a = 2.0;
    let times: Vec<f64> = (0..41).map(|k| k as f64 * 0.005).collect();
    let poses = times
        .iter()
        .map(|&t| Pose::level_at(0.8 + 0.5 * a * t * t))
        .collect();
    let samples = Samples { times, poses };
    let load = payload(50.0, [0.0, 0.0, 0.1]);
    let series = forces_along(&g, &samples, &load).unwrap_or_else(|e| panic!("{e}"));
    for k in 1..40 {
        let (force, _) = resultant(&g, &samples.poses[k], &series.dynamics[k]);
        assert!(
            (force.z - 50.0 * (STANDARD_GRAVITY + a)).abs() < 1e-6,
            "{}",
            force.z
        );
        let (still, _) = resultant(&g, &samples.poses[k], &series.statics[k]);
        assert!((still.z - 50.0 * STANDARD_GRAVITY).abs() < 1e-9);
    }
}

#[test]
fn dynamics_adds_inertia_times_angular_acceleration_in_a_yaw_spin_up() {
    // yaw = ½·α·t² about the centre, load centred: moment about z = I_zz·α, no net force
    // beyond the weight (the gyroscopic term vanishes for a spin about a principal axis).
    let g = crate::test_support::paired_geometry();
    let alpha = 3.0;
    let times: Vec<f64> = (0..41).map(|k| k as f64 * 0.005).collect();
    let poses = times
        .iter()
        .map(|&t| {
            Pose::new(
                Vector3::new(0.0, 0.0, 0.8),
                Angle::ZERO,
                Angle::ZERO,
                Angle::from_radians(0.5 * alpha * t * t),
            )
        })
        .collect();
    let samples = Samples { times, poses };
    let load = payload(50.0, [0.0, 0.0, 0.0]);
    let series = forces_along(&g, &samples, &load).unwrap_or_else(|e| panic!("{e}"));
    for k in 1..40 {
        let (force, moment) = resultant(&g, &samples.poses[k], &series.dynamics[k]);
        assert!((force - Vector3::new(0.0, 0.0, 50.0 * STANDARD_GRAVITY)).norm() < 1e-6);
        // Central differences of R(t) err by O(h²): 1e-5 relative at h = 5 ms.
        assert!((moment.z - 4.0 * alpha).abs() < 1e-4, "{}", moment.z);
    }
}

#[test]
fn bad_payloads_and_singular_geometry_are_refused() {
    assert!(Payload::new(0.0, Vector3::zeros(), Matrix3::zeros()).is_err());
    assert!(Payload::new(1.0, Vector3::new(f64::NAN, 0.0, 0.0), Matrix3::zeros()).is_err());
    assert!(
        Payload::new(
            1.0,
            Vector3::zeros(),
            Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, 1.0))
        )
        .is_err()
    );
    // Principal moments 1, 1, 5 break the triangle inequality: no rigid body has them.
    let moments = |m: [f64; 3]| {
        Payload::new(
            1.0,
            Vector3::zeros(),
            Matrix3::from_diagonal(&Vector3::from(m)),
        )
    };
    let e = moments([1.0, 1.0, 5.0])
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        e.contains("each principal moment at most the sum of the other two"),
        "{e}"
    );
    // A thin plate (Izz = Ixx + Iyy), a rod (0, 1, 1) and a point mass (zeros) are possible.
    for m in [[1.0, 1.0, 2.0], [0.0, 1.0, 1.0], [0.0; 3], [2.0, 2.5, 4.0]] {
        assert!(moments(m).is_ok(), "{m:?}");
    }
    // Rotated off its principal axes, the same impossible body is refused too.
    let r = nalgebra::Rotation3::from_euler_angles(0.3, -0.2, 0.7);
    let rotated = r * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 5.0)) * r.transpose();
    assert!(Payload::new(1.0, Vector3::zeros(), rotated).is_err());
    let seed = Geometry::seed();
    assert_eq!(
        static_forces(&seed, &seed.home_pose(), &payload(10.0, [0.0; 3])),
        None
    );
}

/// Static servo torques by virtual work through the forward kinematics alone: turning
/// servo i by δ moves the platform (found by the forward solver) and with it the load;
/// the torque that holds the load is the work of its weight per radian,
/// τ_i = m g Δz_c / δ (central difference). No Jacobian is involved.
#[test]
fn servo_torques_are_the_weights_work_per_radian() {
    let s = crate::io::scenario::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let load = payload(0.8, [0.01, -0.005, 0.03]);
    for pose in [
        g.home_pose(),
        Pose::from_xyz_rpy_deg([0.01, -0.006, 0.118], [4.0, -3.0, 7.0]),
    ] {
        let tau = static_forces(g, &pose, &load).unwrap_or_else(|| panic!("singular"));
        let angles = g
            .servo_angles(&pose)
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("reachable"));
        let com_height = |p: &Pose| (p.position + p.rotation() * load.centre_of_mass).z;
        let delta = 1e-6;
        for i in 0..6 {
            let moved = |d: f64| {
                let mut a = angles;
                a[i] = Angle::from_radians(a[i].radians() + d);
                g.forward_servos(&a, &pose, &crate::solve::forward::ForwardOptions::default())
                    .unwrap_or_else(|e| panic!("{e}"))
                    .pose
            };
            let dz = com_height(&moved(delta)) - com_height(&moved(-delta));
            let expected = load.mass * STANDARD_GRAVITY * dz / (2.0 * delta);
            assert!(
                (tau[i] - expected).abs() < 1e-6 * (1.0 + expected.abs()),
                "servo {}: {} vs {expected}",
                i + 1,
                tau[i]
            );
        }
    }
}

#[test]
fn a_servo_out_of_reach_is_named_in_the_torque_error() {
    let s = crate::io::scenario::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let samples = Samples {
        times: vec![0.0, 0.1, 0.2],
        poses: vec![
            g.home_pose(),
            Pose::from_xyz_rpy_deg([0.0, 0.0, 0.3], [0.0; 3]),
            g.home_pose(),
        ],
    };
    let e = forces_along(g, &samples, &payload(1.0, [0.0; 3])).unwrap_err();
    assert_eq!(
        e.to_string(),
        "at t = 0.1 s servo 1 cannot reach its platform joint: no torque holds it"
    );
}
