//! Switching a scenario between linear legs and rotary servos, keeping the plates.

use thiserror::Error;

use super::target::ActuatorKind;
use crate::io::scenario::Scenario;
use crate::model::actuator::Actuator;
use crate::model::geometry::{Geometry, GeometryError};
use crate::model::rotary::{RotaryActuators, RotaryError};

/// Why a switch of actuator kind was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SwitchError {
    /// The servos sized for the plates are not sound.
    #[error(transparent)]
    Servos(#[from] RotaryError),
    /// The geometry with the new actuators is not sound.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
}

/// Give `scenario` actuators of `kind`. Linear legs become servos sized for the plates:
/// horns 0.3 base radii long, pointing along the base circle (alternately one way and the
/// other, so that the servos of a pair turn away from each other), and rods as long as
/// the distance from a level horn's tip to its platform joint at home, so the servos
/// start level. Servos become legs without a stroke. Limits of the other kind (stroke,
/// leg or servo rates) are dropped. A refused switch leaves the scenario unchanged.
pub fn switch_actuator(scenario: &mut Scenario, kind: ActuatorKind) -> Result<(), SwitchError> {
    if scenario.geometry.actuator().kind() == kind {
        return Ok(());
    }
    let mut params = scenario.geometry.params().clone();
    let mut limits = scenario.limits;
    match kind {
        ActuatorKind::Linear => {
            params.actuator = Actuator::Linear;
            limits.servo_speed_max = None;
            limits.servo_accel_max = None;
            limits.servo_jerk_max = None;
        }
        ActuatorKind::Rotary => {
            params.stroke = Default::default();
            params.actuator = Actuator::Rotary(fitted_servos(&scenario.geometry)?);
            limits.leg_speed_max = None;
            limits.leg_accel_max = None;
            limits.leg_jerk_max = None;
        }
    }
    scenario.geometry = Geometry::new(params)?;
    scenario.limits = limits;
    Ok(())
}

/// Servos sized for `geometry`'s plates (see [`switch_actuator`]).
fn fitted_servos(geometry: &Geometry) -> Result<RotaryActuators, RotaryError> {
    let horn = 0.3 * geometry.plate_radius(crate::model::geometry::Plate::Base);
    // Each horn at right angles to its joint's direction from the base centre.
    let directions: [f64; 6] = std::array::from_fn(|i| {
        let turn = if i % 2 == 0 { -90.0 } else { 90.0 };
        let b = geometry.base_joints()[i];
        (b.y.atan2(b.x).to_degrees() + turn).rem_euclid(360.0)
    });
    let joints = geometry.inverse(&geometry.home_pose()).platform_joints;
    let rods: Vec<f64> = (0..6)
        .map(|i| {
            let beta = directions[i].to_radians();
            let tip = geometry.base_joints()[i]
                + horn * nalgebra::Vector3::new(beta.cos(), beta.sin(), 0.0);
            (joints[i] - tip).norm()
        })
        .collect();
    let rod = rods.iter().sum::<f64>() / 6.0;
    RotaryActuators::new(horn, rod.max(1.01 * horn), directions, None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::checks::{CheckSettings, check_motion};

    #[test]
    fn legs_become_level_servos_and_back() {
        let mut s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        assert!(s.limits.leg_speed_max.is_some() && s.geometry.stroke().max.is_some());
        switch_actuator(&mut s, ActuatorKind::Rotary).unwrap_or_else(|e| panic!("{e}"));
        let servos = s.geometry.rotary().unwrap_or_else(|| panic!("rotary"));
        assert!((servos.horn_length() - 0.3).abs() < 1e-12);
        assert_eq!(s.geometry.stroke(), Default::default());
        assert_eq!(s.limits.leg_speed_max, None);
        // The paired layout is symmetric: every level horn reaches its joint with the same
        // rod, so every servo stands at zero at home.
        let angles = s
            .geometry
            .servo_angles(&s.geometry.home_pose())
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("home reachable"));
        for a in angles {
            assert!(a.degrees().abs() < 1e-9, "{}", a.degrees());
        }
        // The switched scenario checks and writes like any other.
        let report = check_motion(
            &s.geometry,
            &s.limits,
            &s.motion.sample(),
            &CheckSettings::default(),
        );
        assert!(report.servo_ranges_deg.is_some());
        let back =
            Scenario::from_toml_str(&s.to_toml(), "x.toml", None).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(back.geometry, s.geometry);
        switch_actuator(&mut s, ActuatorKind::Linear).unwrap_or_else(|e| panic!("{e}"));
        assert!(s.geometry.rotary().is_none());
        assert_eq!(s.limits.servo_speed_max, None);
    }
}
