//! Calibration: the joint coordinates and actuator offsets of a built platform, identified
//! from measured poses and the leg lengths (or servo angles) commanded for them.
//!
//! With the pose measured, every leg's closure equation involves that leg's parameters
//! only: its base joint (3 coordinates), its platform joint (3) and its actuator offset
//! (the length a linear leg really has beyond its commanded length, metres; or the angle
//! a servo's horn really stands beyond its commanded model angle, radians). So the 42
//! unknowns split into six independent problems of seven, each solved by nonlinear least
//! squares ([`least_squares`]) from the scenario's nominal values. Each leg's
//! identification Jacobian tells what the measurements determine ([`identifiability`]):
//! its singular values, the parameter combinations no measurement changes (refused, with
//! their names), and each parameter's standard uncertainty.
//!
//! The measured poses are taken in the scenario's frames: the base frame of the base
//! joints and the platform frame of the platform joints (a measuring system's frames must
//! be registered to those first).

mod apply;
mod identifiability;
mod least_squares;
mod leg_model;
mod leg_problem;

use thiserror::Error;

use crate::model::actuator::Actuator;
use crate::model::geometry::{Geometry, GeometryError, PlateJoints};
use crate::model::pose::Pose;
use crate::model::rotary::RotaryError;

use leg_model::{LegModel, PARAMETERS, PreparedPose};
use leg_problem::{LegOutcome, LegProblem};

pub use apply::{calibrated_scenario, offsets_folded_into};

/// One measured pose and what the actuators were commanded for it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measurement {
    /// The platform's pose as measured.
    pub pose: Pose,
    /// Commanded leg lengths (metres) of a linear platform, or model servo angles
    /// (radians, as `stewart solve` gives them) of a rotary one.
    pub commanded: [f64; 6],
}

/// Which groups of parameters keep their nominal values (known from elsewhere, or not
/// determined by the measurements).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Held {
    /// The base joints.
    pub base: bool,
    /// The platform joints.
    pub platform: bool,
    /// The actuator offsets.
    pub offsets: bool,
}

impl Held {
    /// Whether parameter `p` (0–2 base, 3–5 platform, 6 offset) is held.
    fn holds(&self, p: usize) -> bool {
        match p {
            0..=2 => self.base,
            3..=5 => self.platform,
            _ => self.offsets,
        }
    }
}

/// The unit a parameter is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParameterUnit {
    /// Metres.
    Metre,
    /// Radians (shown in degrees).
    Radian,
}

/// One identified parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    /// Its name: `base3.x`, `platform3.z`, `offset3`.
    pub name: String,
    /// Its unit.
    pub unit: ParameterUnit,
    /// The scenario's value (an offset's nominal is 0).
    pub nominal: f64,
    /// The calibrated value.
    pub value: f64,
    /// Its standard uncertainty from the residual noise, when free and determined.
    pub uncertainty: Option<f64>,
    /// Whether it was held at its nominal value.
    pub held: bool,
}

/// What was found for one leg.
#[derive(Clone, Debug, PartialEq)]
pub struct LegCalibration {
    /// Its seven parameters: base joint x, y, z, platform joint x, y, z, offset.
    pub parameters: Vec<Parameter>,
    /// Singular values of the leg's identification Jacobian divided by √(poses), largest
    /// first, with the offset column in metres of horn-tip travel for a servo: the RMS
    /// change of the residuals (m) per metre of parameter change along each direction.
    pub singular_values: Vec<f64>,
    /// The parameter combination the measurements see least (the smallest singular
    /// value's direction): its components of magnitude 0.1 or more, largest first, as
    /// (parameter name, component of a unit vector).
    pub weakest_direction: Vec<(String, f64)>,
    /// Least-squares steps taken.
    pub iterations: usize,
    /// RMS residual with the nominal parameters, metres.
    pub rms_before: f64,
    /// RMS residual with the calibrated parameters, metres.
    pub rms_after: f64,
}

/// Size of the residuals (each a closure error in metres) over every leg and pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Residuals {
    /// Root mean square, metres.
    pub rms: f64,
    /// Largest magnitude, metres.
    pub max: f64,
    /// The measurement (index) holding the largest.
    pub worst_measurement: usize,
    /// The leg (from 0) holding the largest.
    pub worst_leg: usize,
}

/// A calibration's result.
#[derive(Clone, Debug, PartialEq)]
pub struct Calibration {
    /// The calibrated geometry: both plates' joints as coordinates, servo trims adjusted
    /// by the identified angle offsets.
    pub geometry: Geometry,
    /// The identified actuator offsets: metres (linear: real length − commanded) or
    /// radians (rotary: real horn angle − commanded model angle).
    pub offsets: [f64; 6],
    /// Per leg: parameters, singular values, residuals.
    pub legs: Vec<LegCalibration>,
    /// Residuals with the nominal parameters.
    pub before: Residuals,
    /// Residuals with the calibrated parameters.
    pub after: Residuals,
    /// Per measurement, the largest residual over its six legs after calibration, metres.
    pub row_residuals: Vec<f64>,
}

/// Why a calibration was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum CalibrationError {
    /// Too few measured poses for the unknowns.
    #[error(
        "{count} measured poses are too few: each leg has {unknowns} unknowns ({which}), so at least {needed} poses are needed (one more than the unknowns, to see the measurement noise; 20 or more spread over the workspace are better)"
    )]
    TooFew {
        /// Poses given.
        count: usize,
        /// Free parameters per leg.
        unknowns: usize,
        /// Their names in words.
        which: String,
        /// Poses needed.
        needed: usize,
    },
    /// Every parameter is held: nothing to calibrate.
    #[error("every parameter is held: nothing is left to calibrate")]
    NothingFree,
    /// Some parameter combinations do not change any residual.
    #[error(
        "the measurements cannot tell some parameters apart: for leg {leg}, moving the parameters together as in {combinations} leaves every residual unchanged{others}. {hint}"
    )]
    Undetermined {
        /// The first such leg, from 1.
        leg: usize,
        /// The combinations in words.
        combinations: String,
        /// Which other legs are alike, in words (empty when none).
        others: String,
        /// What would help.
        hint: String,
    },
    /// The least-squares fit of a leg did not converge.
    #[error(
        "leg {leg}: the least-squares fit did not converge ({reason}); check that the measured poses are in the scenario's frames (metres, degrees) and that the commanded values belong to them, in the scenario's leg order"
    )]
    NotConverged {
        /// The leg, from 1.
        leg: usize,
        /// What happened.
        reason: &'static str,
    },
    /// A residual is not a finite number (a platform joint on its anchor).
    #[error(
        "leg {leg}: a residual is not a finite number {at} (a platform joint exactly on its base joint or horn tip)"
    )]
    NotFinite {
        /// The leg, from 1.
        leg: usize,
        /// Where: at the nominal or at the fitted joints.
        at: &'static str,
    },
    /// The calibrated joints are not a valid platform.
    #[error("the calibrated geometry is not a valid platform: {0}")]
    Invalid(GeometryError),
    /// A servo trim the offsets lead to is refused.
    #[error("the calibrated servo trims are refused: {0}")]
    Trim(RotaryError),
}

/// The names of leg `leg`'s (from 0) parameters, in the order of [`LegCalibration::parameters`].
pub fn parameter_names(leg: usize) -> [String; PARAMETERS] {
    let n = leg + 1;
    [
        format!("base{n}.x"),
        format!("base{n}.y"),
        format!("base{n}.z"),
        format!("platform{n}.x"),
        format!("platform{n}.y"),
        format!("platform{n}.z"),
        format!("offset{n}"),
    ]
}

/// Identify the joints and actuator offsets of `geometry`'s platform from `measurements`,
/// keeping the `held` groups at their nominal values.
pub fn calibrate(
    geometry: &Geometry,
    measurements: &[Measurement],
    held: Held,
) -> Result<Calibration, CalibrationError> {
    let free: Vec<usize> = (0..PARAMETERS).filter(|&p| !held.holds(p)).collect();
    if free.is_empty() {
        return Err(CalibrationError::NothingFree);
    }
    if measurements.len() <= free.len() {
        return Err(CalibrationError::TooFew {
            count: measurements.len(),
            unknowns: free.len(),
            which: free_words(&held),
            needed: free.len() + 1,
        });
    }
    let pivot = geometry.pivot();
    let poses: Vec<PreparedPose> = measurements
        .iter()
        .map(|m| PreparedPose::new(m, &pivot))
        .collect();
    let problem = LegProblem::new(geometry, &poses, measurements, free);
    let mut legs = Vec::with_capacity(6);
    let mut undetermined: Vec<(usize, String)> = Vec::new();
    for leg in 0..6 {
        match problem.solve(leg)? {
            LegOutcome::Fitted(fit) => legs.push(fit),
            LegOutcome::Undetermined(words) => undetermined.push((leg, words)),
        }
    }
    if let Some((leg, combinations)) = undetermined.first() {
        return Err(CalibrationError::Undetermined {
            leg: leg + 1,
            combinations: combinations.clone(),
            others: others_words(&undetermined),
            hint: hint(&held),
        });
    }
    let nominal: [[f64; PARAMETERS]; 6] = std::array::from_fn(|leg| problem.nominal(leg));
    let fitted: [[f64; PARAMETERS]; 6] =
        std::array::from_fn(|leg| std::array::from_fn(|p| legs[leg].parameters[p].value));
    let models: Vec<LegModel> = (0..6)
        .map(|leg| LegModel::new(geometry, leg, &poses, measurements))
        .collect();
    let residuals_of = |params: &[[f64; PARAMETERS]; 6]| -> Vec<[f64; 6]> {
        (0..measurements.len())
            .map(|k| std::array::from_fn(|leg| models[leg].residual(&params[leg], k, None)))
            .collect()
    };
    let before_rows = residuals_of(&nominal);
    let after_rows = residuals_of(&fitted);
    Ok(Calibration {
        geometry: calibrated_geometry(geometry, &fitted)?,
        offsets: fitted.map(|x| x[6]),
        legs,
        before: summarise(&before_rows),
        after: summarise(&after_rows),
        row_residuals: after_rows
            .iter()
            .map(|row| row.iter().fold(0.0f64, |m, r| m.max(r.abs())))
            .collect(),
    })
}

/// The geometry with the fitted joints as coordinates and, for servos, the angle offsets
/// folded into the trims.
fn calibrated_geometry(
    geometry: &Geometry,
    fitted: &[[f64; PARAMETERS]; 6],
) -> Result<Geometry, CalibrationError> {
    let mut params = geometry.params().clone();
    params.base = PlateJoints::Points(fitted.map(|x| nalgebra::Vector3::new(x[0], x[1], x[2])));
    params.platform = PlateJoints::Points(fitted.map(|x| nalgebra::Vector3::new(x[3], x[4], x[5])));
    if let Actuator::Rotary(servos) = &params.actuator {
        let retrimmed =
            apply::retrimmed(servos, &fitted.map(|x| x[6])).map_err(CalibrationError::Trim)?;
        params.actuator = Actuator::Rotary(retrimmed);
    }
    Geometry::new(params).map_err(CalibrationError::Invalid)
}

/// RMS, largest and where, of per-row residuals.
fn summarise(rows: &[[f64; 6]]) -> Residuals {
    let mut sum = 0.0;
    let mut worst = (0.0f64, 0, 0);
    for (k, row) in rows.iter().enumerate() {
        for (leg, r) in row.iter().enumerate() {
            sum += r * r;
            if r.abs() > worst.0 {
                worst = (r.abs(), k, leg);
            }
        }
    }
    Residuals {
        rms: (sum / (6 * rows.len()).max(1) as f64).sqrt(),
        max: worst.0,
        worst_measurement: worst.1,
        worst_leg: worst.2,
    }
}

/// The free parameter groups in words.
fn free_words(held: &Held) -> String {
    let mut words = Vec::new();
    if !held.base {
        words.push("base joint x, y, z");
    }
    if !held.platform {
        words.push("platform joint x, y, z");
    }
    if !held.offsets {
        words.push("actuator offset");
    }
    words.join(", ")
}

/// Null-space combinations in words: `base1.x + platform1.x`, ….
fn combination_words(leg: usize, free: &[usize], combos: &[Vec<(usize, f64)>]) -> String {
    let names = parameter_names(leg);
    let words: Vec<String> = combos
        .iter()
        .map(|combo| {
            let mut text = String::new();
            for (i, (c, v)) in combo.iter().enumerate() {
                let name = &names[free[*c]];
                let sign = if *v < 0.0 { "−" } else { "+" };
                let size = v.abs();
                let factor = if (size - 1.0).abs() < 1e-6 {
                    String::new()
                } else {
                    format!("{size:.3}·")
                };
                if i == 0 {
                    let lead = if *v < 0.0 { "−" } else { "" };
                    text.push_str(&format!("{lead}{factor}{name}"));
                } else {
                    text.push_str(&format!(" {sign} {factor}{name}"));
                }
            }
            format!("({text})")
        })
        .collect();
    match words.len() {
        1 => words[0].clone(),
        _ => format!("any of {}", words.join(", ")),
    }
}

/// The other undetermined legs in words.
fn others_words(undetermined: &[(usize, String)]) -> String {
    let rest: Vec<String> = undetermined[1..]
        .iter()
        .map(|(leg, _)| (leg + 1).to_string())
        .collect();
    if rest.is_empty() {
        String::new()
    } else {
        format!(" (and likewise for leg {})", rest.join(", "))
    }
}

/// What would make the parameters determined.
fn hint(held: &Held) -> String {
    let mut hint =
        "Measure poses that differ in every rotation (roll, pitch and yaw) as well as in position"
            .to_owned();
    if !(held.base || held.platform) {
        hint.push_str(
            ", or keep joints known from elsewhere with `--hold base` or `--hold platform`",
        );
    } else if !held.offsets {
        hint.push_str(", or keep the offsets with `--hold offsets`");
    }
    hint.push('.');
    hint
}

#[cfg(test)]
mod tests;
