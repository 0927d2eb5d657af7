//! The Orientation reach panel and the manual sliders' reach bars: the numbers shown are
//! the core's ranges at the pose, and they follow the pose.

use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::{Pose, Scenario};

fn manual_at(pose: Pose) -> egui_kittest::Harness<'static, ViewerState> {
    let mut state = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
    state.look.expand_panels = true;
    state.playback.mode = MotionMode::Manual;
    state.playback.manual = pose;
    super::harness_with(state, 4200.0)
}

/// The line the panel writes for angle `k` (3 roll, 4 pitch, 5 yaw) at `pose`, from the
/// core's range over ±90° around the pose's own angle.
fn range_line(pose: &Pose, k: usize, name: &str) -> String {
    let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let c = pose.to_coordinates()[k];
    let span = std::f64::consts::FRAC_PI_2;
    let [lo, hi] =
        workspace::coordinate_range(&s.geometry, &s.limits, pose, k, [c - span, c + span], 120)
            .unwrap_or_else(|| panic!("out of reach"));
    format!("{name} {:.1}° … {:.1}°", lo.to_degrees(), hi.to_degrees())
}

#[test]
fn each_angle_alone_and_the_map_follow_the_pose() {
    let home = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0; 3]);
    let mut h = manual_at(home);
    for (k, name) in [(3, "roll"), (4, "pitch"), (5, "yaw")] {
        let line = range_line(&home, k, name);
        assert!(h.query_by_label(&line).is_some(), "no `{line}`");
    }
    assert!(
        h.query_by_label_contains("Roll and pitch together at yaw 0.0° (±45°): ")
            .is_some()
    );
    // Higher up the legs are longer: less room to tilt.
    let high = Pose::from_xyz_rpy_deg([0.0, 0.0, 1.05], [0.0; 3]);
    h.state_mut().playback.manual = high;
    h.run();
    let before = range_line(&home, 3, "roll");
    let after = range_line(&high, 3, "roll");
    assert_ne!(before, after);
    assert!(h.query_by_label(&after).is_some(), "no `{after}`");
    assert!(h.query_by_label(&before).is_none());
    let reach = h.state_mut().orientation_reach();
    let count = reach.map.reachable.iter().filter(|&&r| r).count();
    assert!(count > 0 && count < reach.map.reachable.len());
    let words = format!("{count} of {} cells reachable", reach.map.reachable.len());
    assert!(h.query_by_label_contains(&words).is_some(), "no `{words}`");
}

#[test]
fn a_pose_out_of_reach_says_so() {
    let h = manual_at(Pose::from_xyz_rpy_deg([0.0, 0.0, 1.8], [0.0; 3]));
    assert!(
        h.query_by_label("The pose shown is out of reach: no orientation range.")
            .is_some()
    );
}

#[test]
fn the_sliders_know_their_reachable_part() {
    let pose = Pose::from_xyz_rpy_deg([0.05, 0.0, 0.9], [5.0, 0.0, 10.0]);
    let mut h = manual_at(pose);
    let s = h.state().scenario().clone();
    let home = s.geometry.home_pose().to_coordinates();
    let bounds: [[f64; 2]; 6] = std::array::from_fn(|k| {
        let reach = [
            0.3,
            0.3,
            0.3,
            30f64.to_radians(),
            30f64.to_radians(),
            45f64.to_radians(),
        ][k];
        [home[k] - reach, home[k] + reach]
    });
    let ranges = h.state_mut().slider_reach(bounds);
    let c = pose.to_coordinates();
    for k in 0..6 {
        let [lo, hi] = ranges[k].unwrap_or_else(|| panic!("coordinate {k}"));
        // The pose lies inside; each end is a bound or a limit (a hair beyond is out).
        assert!(lo <= c[k] && c[k] <= hi, "{k}: {lo} {} {hi}", c[k]);
        for (end, bound, outward) in [(lo, bounds[k][0], -1.0), (hi, bounds[k][1], 1.0)] {
            if (end - bound).abs() > 1e-12 {
                let mut beyond = c;
                beyond[k] = end + outward * 1e-6;
                assert!(!workspace::pose_within_limits(
                    &s.geometry,
                    &s.limits,
                    &Pose::from_coordinates(beyond)
                ));
            }
        }
    }
    // z is limited by the stroke well within the slider at 0.9 m with this tilt.
    assert!(ranges[2].is_some_and(|[_, hi]| hi < bounds[2][1]));
}
