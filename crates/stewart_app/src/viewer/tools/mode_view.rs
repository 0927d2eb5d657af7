//! The mode viewer: the 3D view shows the platform swinging along one natural mode at a
//! visible amplitude and a visible pace (once a second; the real frequency is written
//! beside it). Only the picture moves: the pose the link sends, the plot and the
//! readouts keep the pose shown without it.

use stewart_kinematics::analysis::dynamics;
use stewart_kinematics::analysis::dynamics::{DynamicsError, Modes};
use stewart_kinematics::{Pose, Scenario};

/// How often the animation swings, Hz (the real modes are far too fast to watch).
pub(crate) const SHOWN_HZ: f64 = 1.0;

/// Why there are no modes to show.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum NoModes {
    /// The scenario has no payload.
    NoPayload,
    /// The dynamics say why.
    Dynamics(DynamicsError),
}

/// The mode viewer's settings and clock.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ModeView {
    /// Whether the 3D view swings along a mode.
    pub(crate) animate: bool,
    /// Which mode, from 0 (the lowest frequency).
    pub(crate) mode: usize,
    /// How far the farthest platform joint swings, as a share of the platform's size.
    pub(crate) amplitude: f64,
    /// Seconds into the current swing.
    phase: f64,
}

impl Default for ModeView {
    fn default() -> Self {
        Self {
            animate: false,
            mode: 0,
            amplitude: 0.06,
            phase: 0.0,
        }
    }
}

impl ModeView {
    /// Move the swing on by `dt` seconds.
    pub(crate) fn advance(&mut self, dt: f64) {
        if self.animate && dt.is_finite() {
            self.phase = (self.phase + dt).rem_euclid(1.0 / SHOWN_HZ);
        }
    }

    /// The modes at `pose`, when the scenario has what they need.
    pub(crate) fn modes(scenario: &Scenario, pose: &Pose) -> Result<Modes, NoModes> {
        let payload = scenario.payload.ok_or(NoModes::NoPayload)?;
        dynamics::modes(&scenario.geometry, pose, &payload, &scenario.dynamics)
            .map_err(NoModes::Dynamics)
    }

    /// What the 3D view draws for the pose shown: `pose` itself, or swung along the
    /// chosen mode when animating (and the modes can be computed there).
    pub(crate) fn shown_pose(&self, scenario: &Scenario, pose: Pose) -> Pose {
        if !self.animate {
            return pose;
        }
        let Ok(modes) = Self::modes(scenario, &pose) else {
            return pose;
        };
        let g = &scenario.geometry;
        let v = modes.modes[self.mode.min(5)];
        let travel = dynamics::joint_travel(g, &pose, &v);
        let moves = travel > 0.0;
        if !moves {
            return pose;
        }
        let reach = self.amplitude * g.characteristic_length() / travel;
        let swing = (std::f64::consts::TAU * SHOWN_HZ * self.phase).sin();
        dynamics::moved_along(g, &pose, &v, reach * swing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn heavy() -> Scenario {
        let text = include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/scenarios/heavy-legs.toml"
        ));
        Scenario::from_toml_str(text, "heavy-legs.toml", None).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn the_swing_moves_the_picture_along_the_mode_by_the_amplitude() {
        let s = heavy();
        let home = s.geometry.home_pose();
        let mut view = ModeView {
            animate: true,
            mode: 2,
            ..ModeView::default()
        };
        // At the start of a swing the platform is where it is.
        assert_eq!(view.shown_pose(&s, home), home);
        // A quarter swing on, the farthest joint is out by the amplitude (to first order).
        view.advance(0.25 / SHOWN_HZ);
        let shown = view.shown_pose(&s, home);
        let before = s.geometry.inverse(&home).platform_joints;
        let after = s.geometry.inverse(&shown).platform_joints;
        let largest = (0..6)
            .map(|i| (after[i] - before[i]).norm())
            .fold(0.0, f64::max);
        let expected = view.amplitude * s.geometry.characteristic_length();
        assert!(
            (largest - expected).abs() < 0.02 * expected,
            "{largest} vs {expected}"
        );
        // Mode 3 of this platform is its heave: the platform only rises.
        assert!((shown.position.z - home.position.z).abs() > 0.5 * expected);
        assert!(shown.position.x.abs() < 1e-9 && shown.yaw.degrees().abs() < 1e-6);
        // Off, or without what the modes need, the pose is left alone.
        view.animate = false;
        assert_eq!(view.shown_pose(&s, home), home);
        view.animate = true;
        assert_eq!(view.shown_pose(&Scenario::seed(), home), home);
    }
}
