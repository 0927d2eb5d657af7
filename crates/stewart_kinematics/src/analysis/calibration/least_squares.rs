//! Levenberg–Marquardt for one leg's parameters: each step solves the damped linear
//! least-squares problem `[J; √λ D] δ ≈ [−r; 0]` by a QR factorisation (no normal
//! equations, so a weakly determined direction keeps its precision), with Marquardt's
//! scaling `D` = the column norms of `J`.

use nalgebra::{DMatrix, DVector};

use super::leg_model::{LegModel, PARAMETERS};

/// Most steps tried (accepted or not) before giving up.
const MAX_STEPS: usize = 200;
/// A step shorter than this (relative to the parameters' size) has converged.
const STEP_TOLERANCE: f64 = 1e-13;
/// A step changing the cost by less than this fraction of it has converged.
const COST_TOLERANCE: f64 = 1e-12;

/// A converged fit.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fit {
    /// The parameters.
    pub x: [f64; PARAMETERS],
    /// Steps taken.
    pub iterations: usize,
}

/// Why a fit did not converge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum FitFailure {
    /// A residual became NaN or infinite (a joint on its anchor, for example).
    NotFinite,
    /// [`MAX_STEPS`] steps without converging.
    TooManySteps,
    /// A parameter went further than the allowed reach from its start: the measurements
    /// are best fitted by a platform unlike the scenario's (or by none: a joint at
    /// infinity).
    RanAway,
}

/// The Jacobian (free columns only) and residuals of `model` at `x`.
pub(crate) fn linearise(
    model: &LegModel,
    x: &[f64; PARAMETERS],
    free: &[usize],
) -> (DMatrix<f64>, DVector<f64>) {
    let m = model.len();
    let mut jacobian = DMatrix::zeros(m, free.len());
    let mut residuals = DVector::zeros(m);
    let mut g = [0.0; PARAMETERS];
    for k in 0..m {
        residuals[k] = model.residual(x, k, Some(&mut g));
        for (c, &p) in free.iter().enumerate() {
            jacobian[(k, c)] = g[p];
        }
    }
    (jacobian, residuals)
}

/// Least-squares parameters of `model` from `start`, changing only the `free` ones, none
/// by more than its `reach` (in its unit).
pub(crate) fn fit(
    model: &LegModel,
    start: [f64; PARAMETERS],
    free: &[usize],
    reach: &[f64; PARAMETERS],
) -> Result<Fit, FitFailure> {
    let mut x = start;
    let mut cost = model.cost(&x);
    let mut lambda: f64 = 1e-3;
    let n = free.len();
    let m = model.len();
    for iteration in 1..=MAX_STEPS {
        if !cost.is_finite() {
            return Err(FitFailure::NotFinite);
        }
        if cost == 0.0 || n == 0 {
            return Ok(Fit {
                x,
                iterations: iteration - 1,
            });
        }
        let (jacobian, residuals) = linearise(model, &x, free);
        let scale: Vec<f64> = (0..n)
            .map(|c| jacobian.column(c).norm().max(1e-300))
            .collect();
        let mut augmented = DMatrix::zeros(m + n, n);
        augmented.rows_mut(0, m).copy_from(&jacobian);
        let mut rhs = DVector::zeros(m + n);
        rhs.rows_mut(0, m).copy_from(&(-&residuals));
        for c in 0..n {
            augmented[(m + c, c)] = lambda.sqrt() * scale[c];
        }
        let qr = augmented.qr();
        qr.q_tr_mul(&mut rhs);
        let r = qr.r();
        let Some(step) = r.solve_upper_triangular(&rhs.rows(0, n).into_owned()) else {
            lambda *= 10.0;
            continue;
        };
        let mut trial = x;
        for (c, &p) in free.iter().enumerate() {
            trial[p] += step[c];
        }
        let trial_cost = model.cost(&trial);
        let size = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let tiny_step = step.norm() <= STEP_TOLERANCE * (1.0 + size);
        // A cost that changes by less than rounding does is flat: at the minimum.
        let flat = (trial_cost - cost).abs() <= COST_TOLERANCE * cost;
        if trial_cost.is_finite() && trial_cost <= cost {
            x = trial;
            cost = trial_cost;
            lambda = (lambda / 5.0).max(1e-12);
            if (0..PARAMETERS).any(|p| (x[p] - start[p]).abs() > reach[p]) {
                return Err(FitFailure::RanAway);
            }
            if tiny_step || flat {
                return Ok(Fit {
                    x,
                    iterations: iteration,
                });
            }
        } else if tiny_step || flat {
            return Ok(Fit {
                x,
                iterations: iteration,
            });
        } else {
            lambda *= 4.0;
        }
    }
    Err(FitFailure::TooManySteps)
}
