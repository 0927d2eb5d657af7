//! What moves the platform joints, as one abstraction: the actuator (linear legs, or rotary
//! servos with their horns and rods), its kind, and every fact that differs between kinds in
//! how the driven quantity is named, shown, bounded, rate-limited and sent. Code elsewhere
//! asks the kind for these facts instead of deciding on it. A new kind is a variant here
//! (the compiler then points at each exhaustive `match` on it: this module, the solvers'
//! dispatch in `solve/actuation.rs`, the file format, calibration and drawing), its solver
//! file, and its words in the interface's catalogues (keys ending in the kind's name).

use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;
use crate::model::limits::Limits;
use crate::model::link_settings::LinkOutput;
use crate::model::rotary::RotaryActuators;

/// What moves the platform joints: linear legs (the seed's), or rotary servos with horns
/// and rods.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum Actuator {
    /// Legs whose length changes (stroke limits in the geometry).
    #[default]
    Linear,
    /// Servos turning horns, with fixed-length rods to the platform.
    Rotary(RotaryActuators),
}

/// The actuator kinds, as scenario files name them (`linear`, `rotary`) and settings
/// belong to them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ActuatorKind {
    /// Linear legs (stroke, leg speed, acceleration and jerk).
    Linear,
    /// Rotary servos (horns, rods, servo range and rates).
    Rotary,
}

impl Actuator {
    /// Its kind.
    pub fn kind(&self) -> ActuatorKind {
        match self {
            Actuator::Linear => ActuatorKind::Linear,
            Actuator::Rotary(_) => ActuatorKind::Rotary,
        }
    }

    /// The kind as scenario files write it: `linear` or `rotary`.
    pub fn kind_name(&self) -> &'static str {
        self.kind().name()
    }

    /// The servos' range, `None` for linear legs or servos without one.
    pub fn servo_range(&self) -> Option<(Angle, Angle)> {
        self.rotary().and_then(RotaryActuators::range)
    }

    /// Model values (leg lengths in metres or servo angles in degrees) as the actuators are
    /// commanded them: servo directions and trims applied. `None` for kinds commanded their
    /// model values as they are.
    pub fn commanded_values(&self, model: &[f64; 6]) -> Option<[f64; 6]> {
        match self {
            Actuator::Linear => None,
            Actuator::Rotary(servos) => Some(std::array::from_fn(|i| {
                servos.commanded(i, Angle::from_degrees(model[i])).degrees()
            })),
        }
    }

    /// The servos' parameters, `None` for linear legs.
    pub fn rotary(&self) -> Option<&RotaryActuators> {
        match self {
            Actuator::Rotary(r) => Some(r),
            Actuator::Linear => None,
        }
    }
}

impl ActuatorKind {
    /// Every kind, in the order the viewer offers them.
    pub const ALL: [ActuatorKind; 2] = [ActuatorKind::Linear, ActuatorKind::Rotary];

    /// The kind as scenario files write it (`linear`, `rotary`); the interface's words for
    /// a kind are catalogue keys ending in it.
    pub fn name(self) -> &'static str {
        match self {
            ActuatorKind::Linear => "linear",
            ActuatorKind::Rotary => "rotary",
        }
    }

    /// The quantity that drives each joint: leg length or servo angle.
    pub fn quantity(self) -> Quantity {
        match self {
            ActuatorKind::Linear => LEG_LENGTH,
            ActuatorKind::Rotary => SERVO_ANGLE,
        }
    }

    /// Whether a home height stands the actuators level (the servos' horns horizontal,
    /// with the most travel both ways), which [`crate::model::geometry::Geometry::servo_home_height`]
    /// finds; linear legs' mid-stroke follows from their lengths instead.
    pub fn has_level_home(self) -> bool {
        match self {
            ActuatorKind::Linear => false,
            ActuatorKind::Rotary => true,
        }
    }

    /// The speed, acceleration and jerk limits of the actuator values (m/s… or °/s…),
    /// from `limits`' keys for this kind.
    pub fn rate_limits(self, limits: &Limits) -> [Option<f64>; 3] {
        match self {
            ActuatorKind::Linear => [
                limits.leg_speed_max,
                limits.leg_accel_max,
                limits.leg_jerk_max,
            ],
            ActuatorKind::Rotary => [
                limits.servo_speed_max,
                limits.servo_accel_max,
                limits.servo_jerk_max,
            ],
        }
    }

    /// What the link can send for this kind: the native unit (µm of leg length or 0.01° of
    /// servo angle) always, hobby-servo pulse widths for servos.
    pub fn link_outputs(self) -> &'static [LinkOutput] {
        match self {
            ActuatorKind::Linear => &[LinkOutput::Native],
            ActuatorKind::Rotary => &[LinkOutput::Native, LinkOutput::Pulse],
        }
    }
}

/// The quantity that drives each joint, in words and numbers: everything that differs
/// between actuator kinds in how their values are named, shown and bounded. Code that
/// needs such a difference reads it here instead of asking which kind it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantity {
    /// `leg length` or `servo angle`.
    pub name: &'static str,
    /// `L` or `θ`: with the actuator's number, the curve's label (`L1`, `θ1`).
    pub symbol: &'static str,
    /// What each actuator is called, for labels such as `leg L3` / `servo S3`.
    pub part: &'static str,
    /// `L` or `S`: with the number, the actuator's name (`L3`, `S3`).
    pub letter: &'static str,
    /// `m` or `°`.
    pub unit: &'static str,
    /// The same unit in ASCII, for files: `m` or `deg`.
    pub ascii_unit: &'static str,
    /// The kind in words: `linear legs` or `rotary servos`.
    pub kind: &'static str,
    /// The six values' CSV columns: `L1…L6` or `theta1…theta6`.
    pub columns: [&'static str; 6],
    /// What the actuators exert, by letter and unit: forces `F` (N) or torques `T` (N·m).
    pub effort: (&'static str, &'static str),
    /// Decimals that show a value to about a micrometre or a thousandth of a degree.
    pub decimals: usize,
    /// The widest sane range of a value when the scenario sets no limit.
    pub widest: (f64, f64),
    /// A small error in the value as people read it: millimetres or degrees (the factor
    /// from the natural unit, and the unit).
    pub fine: (f64, &'static str),
    /// The value in SI units (metres, radians) of one unit as shown: 1 for metres, π/180
    /// for degrees.
    pub si_per_unit: f64,
    /// The actuator kind it belongs to.
    pub actuator: ActuatorKind,
}

/// Linear legs: lengths in metres.
pub const LEG_LENGTH: Quantity = Quantity {
    name: "leg length",
    symbol: "L",
    part: "leg",
    letter: "L",
    unit: "m",
    ascii_unit: "m",
    kind: "linear legs",
    columns: ["L1", "L2", "L3", "L4", "L5", "L6"],
    effort: ("F", "N"),
    decimals: 6,
    widest: (0.0, crate::ground::bounds::LENGTH_M),
    fine: (1e3, "mm"),
    si_per_unit: 1.0,
    actuator: ActuatorKind::Linear,
};

/// Rotary servos: angles in degrees.
pub const SERVO_ANGLE: Quantity = Quantity {
    name: "servo angle",
    symbol: "θ",
    part: "servo",
    letter: "S",
    unit: "°",
    ascii_unit: "deg",
    kind: "rotary servos",
    columns: ["theta1", "theta2", "theta3", "theta4", "theta5", "theta6"],
    effort: ("T", "N·m"),
    decimals: 3,
    widest: (-180.0, 180.0),
    fine: (1.0, "°"),
    si_per_unit: std::f64::consts::PI / 180.0,
    actuator: ActuatorKind::Rotary,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_answers_for_itself() {
        for kind in ActuatorKind::ALL {
            let q = kind.quantity();
            assert_eq!(q.actuator, kind);
            // The name is the word scenario files use for the kind.
            let word: ActuatorKind = toml::Value::String(kind.name().to_owned())
                .try_into()
                .unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(word, kind);
            assert_eq!(kind.link_outputs()[0], LinkOutput::Native);
            // One unit shown is `si_per_unit` in SI: 1 m, or π/180 rad for 1°.
            let one = if q.unit == "°" {
                1f64.to_radians()
            } else {
                1.0
            };
            assert_eq!(q.si_per_unit, one);
        }
        assert!(!ActuatorKind::Linear.has_level_home() && ActuatorKind::Rotary.has_level_home());
    }

    #[test]
    fn servos_are_commanded_through_their_mounting_and_legs_as_they_are() {
        assert_eq!(Actuator::Linear.commanded_values(&[0.5; 6]), None);
        let servos = RotaryActuators::new(0.03, 0.15, [0.0; 6], None)
            .and_then(|s| {
                s.with_mounting(
                    [true, false, false, false, false, false],
                    [5.0, 0.0, 0.0, 0.0, 0.0, -2.0],
                )
            })
            .unwrap_or_else(|e| panic!("{e}"));
        let commanded = Actuator::Rotary(servos)
            .commanded_values(&[10.0, 10.0, 0.0, 0.0, 0.0, 10.0])
            .unwrap_or_else(|| panic!("servos have a commanded form"));
        // Reversed: −10 + 5; plain: 10 + 0; trimmed: 10 − 2.
        for (got, want) in commanded.iter().zip([-5.0, 10.0, 0.0, 0.0, 0.0, 8.0]) {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
    }
}
