//! The plan's target against closed forms: a heave sinusoid's leg speeds and
//! accelerations, computed from the joints by hand.

use super::*;

#[test]
fn a_heave_target_carries_the_legs_exact_speed_and_acceleration() {
    let geometry = Geometry::seed();
    let z0 = geometry.home_height();
    // z(t) = z0 + A sin(ωt), no rotation: leg i is p_i − b_i + (0, 0, z).
    let (amp, omega) = (0.02, 2.0 * std::f64::consts::PI * 0.7);
    let pose_at =
        |t: f64| Pose::from_xyz_rpy_deg([0.0, 0.0, z0 + amp * (omega * t).sin()], [0.0; 3]);
    for (t, speed) in [(0.13, 1.0), (1.7, 1.0), (0.4, 2.5)] {
        let Ok(Sample::Moving(m)) = moving_sample(&geometry, pose_at, t, speed) else {
            panic!("no motion at {t}");
        };
        let z = z0 + amp * (omega * t).sin();
        let zd = speed * amp * omega * (omega * t).cos();
        let zdd = -speed * speed * amp * omega * omega * (omega * t).sin();
        for i in 0..6 {
            let d = geometry.platform_joints()[i] - geometry.base_joints()[i];
            let h = d.z + z;
            let length = (d.x * d.x + d.y * d.y + h * h).sqrt();
            let velocity = h * zd / length;
            let accel = (zd * zd + h * zdd) / length - h * h * zd * zd / length.powi(3);
            assert!((m.position[i] - length).abs() < 1e-12, "{i}");
            assert!(
                (m.velocity[i] - velocity).abs() < 1e-9,
                "{i}: {} vs {velocity}",
                m.velocity[i]
            );
            assert!(
                (m.acceleration[i] - accel).abs() < 1e-6,
                "{i}: {} vs {accel}",
                m.acceleration[i]
            );
        }
    }
    // A still pose is at rest.
    let Ok(Sample::Moving(m)) = moving_sample(&geometry, pose_at, 0.3, 0.0) else {
        panic!("no motion");
    };
    assert_eq!((m.velocity, m.acceleration), ([0.0; 6], [0.0; 6]));
}

#[test]
fn the_trajectory_target_rests_at_the_last_pose_after_the_end() {
    let scenario = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let plan = LinkPlan::new(&scenario).unwrap_or_else(|e| panic!("{e}"));
    let mut target = plan.trajectory_target(false);
    let end = plan.span.1;
    let last = scenario
        .geometry
        .actuator_values_at(&scenario.motion.trajectory.pose_at(plan.span.0 + end))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        target(end + 3.0).ok(),
        Some(Sample::Moving(ActuatorMotion::at_rest(last)))
    );
    // Inside, the values are the trajectory's own.
    let Ok(sample) = target(0.5 * end) else {
        panic!("no target");
    };
    let inside = scenario
        .geometry
        .actuator_values_at(&scenario.motion.trajectory.pose_at(plan.span.0 + 0.5 * end))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(*sample.position(), inside);
}
