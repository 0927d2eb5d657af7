//! One leg's calibration: check that the measurements determine its free parameters,
//! fit them, and say how well each is known.

use nalgebra::DMatrix;

use crate::model::geometry::Geometry;

use super::identifiability::{self, Identification};
use super::least_squares::{self, FitFailure};
use super::leg_model::{LegModel, PARAMETERS, PreparedPose};
use super::{
    CalibrationError, LegCalibration, Measurement, Parameter, ParameterUnit, combination_words,
    parameter_names,
};

/// What one leg's calibration came to.
pub(crate) enum LegOutcome {
    /// Fitted, with its report.
    Fitted(LegCalibration),
    /// Some combinations of its parameters change no residual (in words).
    Undetermined(String),
}

/// The data shared by the six legs' problems.
pub(crate) struct LegProblem<'a> {
    geometry: &'a Geometry,
    poses: &'a [PreparedPose],
    measurements: &'a [Measurement],
    /// The free parameters (indices into the seven).
    free: Vec<usize>,
    /// A servo's horn length (its offset column is scaled to metres of tip travel).
    servo_horn: Option<f64>,
    /// How far each parameter may move from its nominal value before the fit is refused.
    reach: [f64; PARAMETERS],
}

impl<'a> LegProblem<'a> {
    /// The problems of `geometry`'s legs over the measured `poses`, `free` parameters free.
    pub(crate) fn new(
        geometry: &'a Geometry,
        poses: &'a [PreparedPose],
        measurements: &'a [Measurement],
        free: Vec<usize>,
    ) -> Self {
        let servo_horn = geometry.rotary().map(|s| s.horn_length());
        // No joint moves further than the platform's size (nor a servo offset further
        // than a radian): beyond that the fit describes another platform, or none.
        let size = geometry.characteristic_length();
        let reach = std::array::from_fn(|p| {
            if p == 6 && servo_horn.is_some() {
                1.0
            } else {
                size
            }
        });
        Self {
            geometry,
            poses,
            measurements,
            free,
            servo_horn,
            reach,
        }
    }

    /// Leg `leg`'s nominal parameters: the scenario's joints and no offset.
    pub(crate) fn nominal(&self, leg: usize) -> [f64; PARAMETERS] {
        let b = self.geometry.base_joints()[leg];
        let a = self.geometry.platform_joints()[leg];
        [b.x, b.y, b.z, a.x, a.y, a.z, 0.0]
    }

    /// The scale of free column `c`: 1, or 1/horn for a servo's offset (metres of tip travel).
    fn column_scale(&self, c: usize) -> f64 {
        match (self.free[c], self.servo_horn) {
            (6, Some(horn)) => 1.0 / horn,
            _ => 1.0,
        }
    }

    /// The identification Jacobian at `x`, every column in metres per metre.
    fn scaled_jacobian(&self, model: &LegModel, x: &[f64; PARAMETERS]) -> DMatrix<f64> {
        let (mut j, _) = least_squares::linearise(model, x, &self.free);
        for c in 0..self.free.len() {
            j.column_mut(c).scale_mut(self.column_scale(c));
        }
        j
    }

    /// The identification at `x` (`at`: where, in words, for the error when a residual
    /// is not finite there).
    fn identify(
        &self,
        leg: usize,
        model: &LegModel,
        x: &[f64; PARAMETERS],
        at: &'static str,
    ) -> Result<Identification, CalibrationError> {
        identifiability::identify(&self.scaled_jacobian(model, x))
            .ok_or(CalibrationError::NotFinite { leg: leg + 1, at })
    }

    /// The outcome when `id` leaves some combination undetermined.
    fn undetermined(&self, leg: usize, id: &Identification) -> Option<LegOutcome> {
        (!id.undetermined.is_empty())
            .then(|| LegOutcome::Undetermined(combination_words(leg, &self.free, &id.undetermined)))
    }

    /// Calibrate leg `leg` (from 0).
    pub(crate) fn solve(&self, leg: usize) -> Result<LegOutcome, CalibrationError> {
        let model = LegModel::new(self.geometry, leg, self.poses, self.measurements);
        let nominal = self.nominal(leg);
        // Identifiability at the nominal parameters first: a rank-deficient problem is
        // refused before any fit wanders along its free directions.
        let at_nominal = self.identify(leg, &model, &nominal, "at the nominal joints")?;
        if let Some(outcome) = self.undetermined(leg, &at_nominal) {
            return Ok(outcome);
        }
        let fit = least_squares::fit(&model, nominal, &self.free, &self.reach).map_err(|f| {
            CalibrationError::NotConverged {
                leg: leg + 1,
                reason: match f {
                    FitFailure::NotFinite => "a residual became non-finite",
                    FitFailure::TooManySteps => "too many steps",
                    FitFailure::RanAway => {
                        "a parameter ran away, further than the platform's size from the scenario's value: the measurements do not fit this platform"
                    }
                },
            }
        })?;
        let id = self.identify(leg, &model, &fit.x, "at the fitted joints")?;
        if let Some(outcome) = self.undetermined(leg, &id) {
            return Ok(outcome);
        }
        let m = self.measurements.len();
        let cost_after = model.cost(&fit.x);
        let noise_variance = cost_after / (m - self.free.len()) as f64;
        let names = parameter_names(leg);
        let parameters = (0..PARAMETERS)
            .map(|p| {
                let column = self.free.iter().position(|&f| f == p);
                Parameter {
                    name: names[p].clone(),
                    unit: match (p, self.servo_horn) {
                        (6, Some(_)) => ParameterUnit::Radian,
                        _ => ParameterUnit::Metre,
                    },
                    nominal: nominal[p],
                    value: fit.x[p],
                    uncertainty: column.map(|c| {
                        (noise_variance * id.inverse_diagonal[c]).sqrt() * self.column_scale(c)
                    }),
                    held: column.is_none(),
                }
            })
            .collect();
        Ok(LegOutcome::Fitted(LegCalibration {
            parameters,
            weakest_direction: self.weakest_words(leg, &id.weakest),
            singular_values: id.singular_values,
            iterations: fit.iterations,
            rms_before: (model.cost(&nominal) / m as f64).sqrt(),
            rms_after: (cost_after / m as f64).sqrt(),
        }))
    }

    /// The weakest direction's components of magnitude 0.1 or more, largest first, the
    /// first positive.
    fn weakest_words(&self, leg: usize, weakest: &[f64]) -> Vec<(String, f64)> {
        let names = parameter_names(leg);
        let mut words: Vec<(String, f64)> = weakest
            .iter()
            .enumerate()
            .filter(|(_, v)| v.abs() >= 0.1)
            .map(|(c, v)| (names[self.free[c]].clone(), *v))
            .collect();
        words.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
        if words.first().is_some_and(|(_, v)| *v < 0.0) {
            words.iter_mut().for_each(|(_, v)| *v = -*v);
        }
        words
    }
}
