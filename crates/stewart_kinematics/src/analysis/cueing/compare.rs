//! How well a cued motion reproduces the vehicle's, in the quantities of the cueing
//! literature, computed from the poses alone — the same way for every algorithm:
//!
//! - the **felt specific force** at the reference point, in the platform's axes: the
//!   reference point's acceleration by the second difference of its positions,
//!   `f = Rᵀ (a + g ẑ) − g ẑ`; against the vehicle's scaled force held over the same two
//!   intervals (the mean of the two samples), per axis: the root-mean-square error and
//!   the shape correlation (Pearson's);
//! - the **felt rotation rate**: the body rate that turns `R_{k−1}` into `R_{k+1}`,
//!   against the vehicle's scaled rates;
//! - the **false rotation of tilt**: the largest roll or pitch rate beyond the vehicle's;
//! - the **stroke used**: the largest share of the travel from home to either end taken
//!   by any actuator;
//! - the time the **limiter** held the cue back (washout), the planner's failed solves and
//!   stops (MPC).

use nalgebra::{Rotation3, Vector3};

use super::{CueError, CuedRecording, VehicleMotion, cue_recording};
use crate::model::cueing_settings::{CueingAlgorithm, CueingSettings, GRAVITY};
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// The measures of one cued recording.
#[derive(Clone, Debug, PartialEq)]
pub struct CueMeasures {
    /// The algorithm.
    pub algorithm: CueingAlgorithm,
    /// Felt specific-force error along x, y, z, root mean square, m/s².
    pub force_rmse: [f64; 3],
    /// Surge and sway together: `√(mean(e_x² + e_y²))`, m/s².
    pub force_rmse_xy: f64,
    /// Shape correlation of felt and wanted force along x, y, z (`None` where either does
    /// not vary).
    pub force_correlation: [Option<f64>; 3],
    /// Felt rotation-rate error about x, y, z, root mean square, °/s.
    pub rate_rmse_deg_s: [f64; 3],
    /// The largest roll or pitch rate beyond the vehicle's scaled rate, °/s.
    pub false_tilt_rate_deg_s: f64,
    /// The largest share of the travel from home to an end that an actuator took (1: an
    /// end reached).
    pub stroke_used: f64,
    /// Seconds the workspace limiter held the cue back.
    pub limiter_s: f64,
    /// The planner's solves that found no plan (the last was followed).
    pub failed_solves: u64,
    /// Poses the planner's exact check refused.
    pub stops: u64,
}

/// The felt specific force (platform axes, m/s²) and body rates (rad/s) at each inner
/// sample of a motion, and the vehicle's scaled wishes at the same moments: `(felt force,
/// wanted force, felt rate, wanted rate)` per sample `1..n−1`.
pub type FeltSample = ([f64; 3], [f64; 3], [f64; 3], [f64; 3]);

/// What is felt at the middle of three poses `p` at times `t` (uneven steps allowed), the
/// reference point at `arm` from the rotation centre (platform frame): the specific force
/// in the platform's axes (m/s², the reference point's acceleration by the second
/// difference, `Rᵀ (a + g ẑ) − g ẑ`) and the body rate (rad/s) that turns the first pose's
/// rotation into the last's.
pub fn felt_at(arm: &Vector3<f64>, t: [f64; 3], p: [&Pose; 3]) -> ([f64; 3], [f64; 3]) {
    let head = |p: &Pose| p.position + p.rotation() * arm;
    let up = Vector3::new(0.0, 0.0, GRAVITY);
    let [t0, t1, t2] = t;
    let (h0, h1, h2) = (head(p[0]), head(p[1]), head(p[2]));
    // The second difference on uneven steps.
    let a = 2.0 * ((h2 - h1) / (t2 - t1) - (h1 - h0) / (t1 - t0)) / (t2 - t0);
    let f = p[1].rotation().transpose() * (a + up) - up;
    let w = rotation_vector(&(p[0].rotation().transpose() * p[2].rotation())) / (t2 - t0);
    ([f.x, f.y, f.z], [w.x, w.y, w.z])
}

/// The rotation vector (axis times angle, radians) of rotation matrix `m`, accurate for
/// the small turns between close samples: the angle from its sine (half the skew part's
/// length) and cosine together, where the cosine alone (`acos` of the trace) loses half
/// its digits near 0 and reads 1e-7 rad as 0 or NaN.
pub fn rotation_vector(m: &nalgebra::Matrix3<f64>) -> Vector3<f64> {
    let v = Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    );
    let sin = 0.5 * v.norm();
    let cos = 0.5 * (m.trace() - 1.0);
    if sin == 0.0 {
        return Vector3::zeros();
    }
    // Past a right angle the skew part shrinks again: the rotation's own axis there.
    if cos < 0.0 {
        return Rotation3::from_matrix_unchecked(*m).scaled_axis();
    }
    v * (sin.atan2(cos) / (2.0 * sin))
}

/// What is felt along `poses` (at `times`), the reference point `reference_m` (platform
/// frame), against `samples` scaled by `settings`.
pub fn felt(
    geometry: &Geometry,
    settings: &CueingSettings,
    samples: &[(f64, VehicleMotion)],
    poses: &[Pose],
) -> Vec<FeltSample> {
    let arm = Vector3::from(settings.reference_m) - geometry.pivot();
    let wanted = |m: &VehicleMotion| {
        (
            m.accel.map(|a| settings.translation_scale * a),
            m.rates_deg_s
                .map(|r| settings.rotation_scale * r.to_radians()),
        )
    };
    let mut out = Vec::with_capacity(samples.len().saturating_sub(2));
    for k in 1..samples
        .len()
        .saturating_sub(1)
        .min(poses.len().saturating_sub(1))
    {
        let (t0, t1, t2) = (samples[k - 1].0, samples[k].0, samples[k + 1].0);
        let (f, w) = felt_at(
            &arm,
            [t0, t1, t2],
            [&poses[k - 1], &poses[k], &poses[k + 1]],
        );
        let (f0, w0) = wanted(&samples[k - 1].1);
        let (f1, w1) = wanted(&samples[k].1);
        // Each held sample counts for its interval, as in the second difference.
        let share = (t1 - t0) / (t2 - t0);
        let mean =
            |x: [f64; 3], y: [f64; 3]| std::array::from_fn(|i| share * x[i] + (1.0 - share) * y[i]);
        out.push((f, mean(f0, f1), w, mean(w0, w1)));
    }
    out
}

/// Pearson's correlation of two series, `None` where either is constant.
fn correlation(x: &[f64], y: &[f64]) -> Option<f64> {
    let n = x.len() as f64;
    if x.is_empty() {
        return None;
    }
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx) * (a - mx);
        syy += (b - my) * (b - my);
    }
    let scale = (sxx * syy).sqrt();
    (scale > 1e-12 * n).then(|| sxy / scale)
}

/// The measures of a cued recording.
pub fn measure(
    geometry: &Geometry,
    settings: &CueingSettings,
    samples: &[(f64, VehicleMotion)],
    cued: &CuedRecording,
) -> CueMeasures {
    let counts = cued.planner.map_or((0, 0), |c| (c.failed, c.stops));
    let felt = felt(geometry, settings, samples, &cued.poses);
    let n = felt.len().max(1) as f64;
    let rms = |e: &dyn Fn(&FeltSample) -> f64| {
        (felt.iter().map(|s| e(s).powi(2)).sum::<f64>() / n).sqrt()
    };
    let force_rmse = std::array::from_fn(|i| rms(&|s: &FeltSample| s.0[i] - s.1[i]));
    let force_rmse_xy = (felt
        .iter()
        .map(|s| (s.0[0] - s.1[0]).powi(2) + (s.0[1] - s.1[1]).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    let force_correlation = std::array::from_fn(|i| {
        let x: Vec<f64> = felt.iter().map(|s| s.0[i]).collect();
        let y: Vec<f64> = felt.iter().map(|s| s.1[i]).collect();
        correlation(&x, &y)
    });
    let rate_rmse_deg_s =
        std::array::from_fn(|i| rms(&|s: &FeltSample| s.2[i] - s.3[i]).to_degrees());
    let false_tilt_rate_deg_s = felt
        .iter()
        .flat_map(|s| [(s.2[0] - s.3[0]).abs(), (s.2[1] - s.3[1]).abs()])
        .fold(0.0, f64::max)
        .to_degrees();
    let home = geometry
        .actuator_values_at(&geometry.home_pose())
        .unwrap_or([f64::NAN; 6]);
    let [lo, hi] = geometry.quantity_limits();
    let values = geometry.actuator_values(&cued.poses);
    let mut stroke_used: f64 = 0.0;
    for row in &values {
        for (v, h) in row.iter().zip(&home) {
            let share = if v >= h {
                hi.map_or(0.0, |e| (v - h) / (e - h))
            } else {
                lo.map_or(0.0, |e| (h - v) / (h - e))
            };
            if share.is_finite() {
                stroke_used = stroke_used.max(share);
            }
        }
    }
    let limiter_s = samples
        .windows(2)
        .zip(cued.scales.iter().skip(1))
        .filter(|(_, s)| **s < 1.0)
        .map(|(w, _)| w[1].0 - w[0].0)
        .fold(0.0, |a, b| a + b);
    CueMeasures {
        algorithm: settings.algorithm,
        force_rmse,
        force_rmse_xy,
        force_correlation,
        rate_rmse_deg_s,
        false_tilt_rate_deg_s,
        stroke_used,
        limiter_s,
        failed_solves: counts.0,
        stops: counts.1,
    }
}

/// Both algorithms on one recording, with the same scales, rig and limits: the washout
/// with its limiter on, then the planner. Each with its cued motion.
pub fn compare(
    geometry: &Geometry,
    limits: &Limits,
    checks: &crate::analysis::checks::CheckSettings,
    settings: &CueingSettings,
    samples: &[(f64, VehicleMotion)],
) -> Result<[(CueMeasures, CuedRecording); 2], CueError> {
    if samples.len() < 3 {
        return Err(CueError::TooShort {
            samples: samples.len(),
        });
    }
    let run = |algorithm| -> Result<(CueMeasures, CuedRecording), CueError> {
        let s = CueingSettings {
            algorithm,
            workspace_limiter: settings.workspace_limiter || algorithm == CueingAlgorithm::Washout,
            ..settings.clone()
        };
        let cued = cue_recording(geometry, limits, checks, &s, samples)?;
        Ok((measure(geometry, &s, samples, &cued), cued))
    };
    Ok([run(CueingAlgorithm::Washout)?, run(CueingAlgorithm::Mpc)?])
}
