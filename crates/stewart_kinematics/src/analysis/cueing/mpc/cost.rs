//! The cost of a plan: a weighted sum of squared residuals, each affine in the plan,
//!
//! ```text
//! J(U) = Σ_r w_r (φ_rᵀ U + o_r)² = ½ Uᵀ G U + aᵀ U + const,   G = 2 Σ w φ φᵀ,  a = 2 Σ w o φ
//! ```
//!
//! For each step `k` of the horizon:
//!
//! - **felt specific force** at the reference point, in the platform's axes, against the
//!   vehicle's scaled force `f*`: `f ≈ f₀ + (a_k − a₀) + G_θ (θ_{k+½} − θ₀)`, the exact
//!   force now `f₀ = Rᵀ(a₀ + g ẑ) − g ẑ` plus its change, in which gravity's share
//!   along the tilted platform is `G_θ`: `f_x = −g pitch`, `f_y = +g roll`. Tilt
//!   coordination is what minimising this gives for a sustained force;
//! - **felt rotation rate** against the vehicle's scaled rates: the body rates now plus the
//!   change of the angles' mean rate over the step;
//! - the **acceleration** held over the step (smoothness), the **displacement** from
//!   neutral (translation and yaw; roll and pitch by the tilt weight) and the
//!   **velocity** at the step's end.
//!
//! The slopes are those at neutral (`G_θ`, and body rates equal to the angles' rates), so
//! `G` is the same at every step and is factored once; the value now is exact, so the
//! error is of the order of the change over the horizon times the tilt.

use super::horizon::{Horizon, StepValue};
use super::vestibular::Organ;
use crate::model::cueing_settings::{CueingSettings, GRAVITY, MAX_HORIZON_STEPS};

/// The most steps of a horizon.
const STEPS: usize = MAX_HORIZON_STEPS as usize;

/// One residual: what it measures, in which step, on which axis.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Term {
    /// Felt specific force along platform axis `0..3`.
    Force,
    /// Felt rotation rate about platform axis `0..3`.
    Rate,
    /// Acceleration of axis `0..6`.
    Input,
    /// Position of axis `0..6` at the step's end.
    Displacement,
    /// Velocity of axis `0..6` at the step's end.
    Velocity,
}

#[derive(Clone, Copy, Debug)]
struct Residual {
    term: Term,
    step: usize,
    axis: usize,
    weight: f64,
    /// A force or rate error as the vestibular organs sense it (else as it is).
    sensed: bool,
}

/// With the vestibular model, the share of the force and rate errors' weights kept on the
/// errors as they are: what the organs hardly sense within a step (a jolt of a few
/// milliseconds) must still cost, or the plan would be free to make it.
pub const RAW_SHARE: f64 = 0.1;

/// The slope of felt force `i` in the angle of axis `3 + j` (gravity along the tilt).
fn gravity_slope(i: usize, j: usize) -> f64 {
    match (i, j) {
        (0, 1) => -GRAVITY,
        (1, 0) => GRAVITY,
        _ => 0.0,
    }
}

/// What the offsets need: the state now and what is asked.
#[derive(Clone, Copy, Debug)]
pub struct Now<'a> {
    /// Positions and angles of the six axes.
    pub s: [f64; 6],
    /// Their rates.
    pub v: [f64; 6],
    /// The accelerations held now.
    pub a: [f64; 6],
    /// The felt specific force now (exact).
    pub force: [f64; 3],
    /// The body rates now (exact), rad/s.
    pub rates: [f64; 3],
    /// For each step, the vehicle's scaled specific force (m/s²) and rates (rad/s).
    pub wanted: &'a [[f64; 6]],
    /// The same at each step's end.
    pub wanted_end: &'a [[f64; 6]],
    /// The share of `wanted` asked for (a stalled live input fades it).
    pub fade: f64,
    /// A held input's roll and pitch rates as the vehicle has them now (rad/s, scaled,
    /// before the fade), where `wanted` holds only what is new in them
    /// ([`super::fading`]): the tilt-rate limit's reference in the first step.
    pub tilt_now: Option<[f64; 2]>,
    /// The vestibular filters' states now (otoliths x, y, z, canals roll, pitch, yaw),
    /// driven by the error felt so far (zeros without the vestibular model).
    pub sensed: [[f64; 3]; 6],
}

impl Now<'_> {
    /// The scaled specific force (`i` of `0..3`) or rate (`3..6`) wanted in step `k`.
    pub fn wanted(&self, k: usize, i: usize) -> f64 {
        self.fade * self.wanted[k.min(self.wanted.len() - 1)][i]
    }

    /// The same at the end of step `k`.
    pub fn wanted_end(&self, k: usize, i: usize) -> f64 {
        self.fade * self.wanted_end[k.min(self.wanted_end.len() - 1)][i]
    }

    /// The vehicle's roll (`i` = 3) or pitch (4) rate the tilt-rate limit is kept against
    /// in step `k`: over it and at its end.
    pub fn tilt_reference(&self, k: usize, i: usize) -> [f64; 2] {
        match self.tilt_now {
            Some(r) if k == 0 => [self.fade * r[i - 3]; 2],
            _ => [self.wanted(k, i), self.wanted_end(k, i)],
        }
    }
}

/// The residuals of one horizon and their constant rows.
#[derive(Clone, Debug)]
pub struct Cost {
    residuals: Vec<Residual>,
    /// One row per residual, `n` wide, row-major.
    rows: Vec<f64>,
    n: usize,
    /// With the vestibular model: the otoliths' and the canals' responses over the
    /// horizon's steps (`h[k][j]`, `free[k]`), which the force and rate errors go through.
    sensing: Option<[Responses; 2]>,
}

/// An organ's responses over the horizon: `h[k][j]` and `free[k]`
/// ([`Organ::responses`]).
type Responses = (Vec<Vec<f64>>, Vec<Vec<f64>>);

/// The raw force (`0..3`) and rate (`3..6`) errors of each step for the plan of no
/// acceleration.
type Raw = [[f64; 6]; STEPS];

impl Cost {
    /// The residuals of `settings` for `layout`.
    pub fn new(settings: &CueingSettings, layout: &Horizon) -> Self {
        let s = settings;
        let mut residuals = Vec::new();
        for step in 0..layout.steps {
            // Each step counts for its length: the sums stand for integrals over time.
            let share = layout.length(step) / layout.step;
            let mut add = |term, axis, weight: f64, sensed| {
                if weight > 0.0 {
                    residuals.push(Residual {
                        term,
                        step,
                        axis,
                        weight: weight * share,
                        sensed,
                    });
                }
            };
            for axis in 0..3 {
                for (term, weight) in [
                    (Term::Force, s.mpc_force_weight),
                    (Term::Rate, s.mpc_rate_weight),
                ] {
                    if s.vestibular {
                        add(term, axis, weight, true);
                        add(term, axis, weight * RAW_SHARE, false);
                    } else {
                        add(term, axis, weight, false);
                    }
                }
            }
            for &axis in &layout.axes {
                add(Term::Input, axis, s.mpc_input_weight, false);
                let displacement = if axis == 3 || axis == 4 {
                    s.mpc_tilt_weight
                } else {
                    s.mpc_displacement_weight
                };
                add(Term::Displacement, axis, displacement, false);
                add(Term::Velocity, axis, s.mpc_velocity_weight, false);
            }
        }
        let n = layout.len();
        let mut rows = vec![0.0; residuals.len() * n];
        for (r, row) in residuals.iter().zip(rows.chunks_mut(n.max(1))) {
            raw_row(layout, r.term, r.step, r.axis, row);
        }
        let sensing = settings.vestibular.then(|| {
            let lengths: Vec<f64> = (0..layout.steps).map(|k| layout.length(k)).collect();
            [
                Organ::otolith().responses(&lengths),
                Organ::canal().responses(&lengths),
            ]
        });
        if let Some(organs) = &sensing {
            // What is sensed at the end of step k: the errors of steps j ≤ k through the
            // organ, h[k][j].
            let mut raw = vec![0.0; n];
            for (r, row) in residuals.iter().zip(rows.chunks_mut(n.max(1))) {
                let organ = match r.term {
                    _ if !r.sensed => continue,
                    Term::Force => &organs[0],
                    Term::Rate => &organs[1],
                    _ => continue,
                };
                row.iter_mut().for_each(|v| *v = 0.0);
                for j in 0..=r.step {
                    raw.iter_mut().for_each(|v| *v = 0.0);
                    raw_row(layout, r.term, j, r.axis, &mut raw);
                    let h = organ.0[r.step][j];
                    for (v, w) in row.iter_mut().zip(&raw) {
                        *v += h * w;
                    }
                }
            }
        }
        Self {
            residuals,
            rows,
            n,
            sensing,
        }
    }

    /// `G = 2 Σ w φ φᵀ`, column-major (`n × n`).
    pub fn hessian(&self) -> Vec<f64> {
        let n = self.n;
        let mut g = vec![0.0; n * n];
        for (r, row) in self.residuals.iter().zip(self.rows.chunks(n.max(1))) {
            for (j, rj) in row.iter().enumerate() {
                if *rj == 0.0 {
                    continue;
                }
                for (i, ri) in row.iter().enumerate() {
                    g[j * n + i] += 2.0 * r.weight * ri * rj;
                }
            }
        }
        g
    }

    /// The raw force and rate errors of every step for the plan of no acceleration.
    fn raw(layout: &Horizon, now: &Now) -> Raw {
        let mut raw = [[0.0; 6]; STEPS];
        for (k, errors) in raw.iter_mut().enumerate().take(layout.steps) {
            for (i, e) in errors.iter_mut().enumerate() {
                let (term, axis) = if i < 3 {
                    (Term::Force, i)
                } else {
                    (Term::Rate, i - 3)
                };
                *e = Self::raw_offset(term, k, axis, layout, now);
            }
        }
        raw
    }

    /// The offset of a residual without the vestibular model.
    fn raw_offset(term: Term, k: usize, i: usize, layout: &Horizon, now: &Now) -> f64 {
        let free = |q: StepValue, axis: usize| {
            if layout.axes.contains(&axis) {
                layout.free(q, k, now.s[axis], now.v[axis])
            } else {
                0.0
            }
        };
        match term {
            Term::Force => {
                let mut o = now.force[i] - now.a[i] - now.wanted(k, i);
                for j in 0..3 {
                    let g = gravity_slope(i, j);
                    if g != 0.0 {
                        o += g * (free(StepValue::MidPosition, 3 + j) - now.s[3 + j]);
                    }
                }
                o
            }
            Term::Rate => {
                now.rates[i] - now.v[3 + i] + free(StepValue::MidVelocity, 3 + i)
                    - now.wanted(k, 3 + i)
            }
            Term::Input => 0.0,
            Term::Displacement => free(StepValue::EndPosition, i),
            Term::Velocity => free(StepValue::EndVelocity, i),
        }
    }

    /// The offset of residual `r` (its value for the plan of no acceleration), the raw
    /// errors `raw` at hand.
    fn offset(&self, r: &Residual, layout: &Horizon, now: &Now, raw: &Raw) -> f64 {
        let (organ, channel) = match (r.term, &self.sensing) {
            (Term::Force, Some(o)) if r.sensed => (&o[0], r.axis),
            (Term::Rate, Some(o)) if r.sensed => (&o[1], 3 + r.axis),
            (Term::Force, _) => return raw[r.step][r.axis],
            (Term::Rate, _) => return raw[r.step][3 + r.axis],
            _ => return Self::raw_offset(r.term, r.step, r.axis, layout, now),
        };
        let (h, free) = organ;
        let k = r.step;
        let driven: f64 = (0..=k).map(|j| h[k][j] * raw[j][channel]).sum();
        let held: f64 = free[k]
            .iter()
            .zip(&now.sensed[channel])
            .map(|(f, x)| f * x)
            .sum();
        driven + held
    }

    /// The linear term `a = 2 Σ w o φ` for the state and wishes `now` (into `out`).
    pub fn gradient(&self, layout: &Horizon, now: &Now, out: &mut [f64]) {
        out.iter_mut().for_each(|v| *v = 0.0);
        let raw = Self::raw(layout, now);
        for (r, row) in self.residuals.iter().zip(self.rows.chunks(self.n.max(1))) {
            let o = self.offset(r, layout, now, &raw);
            if o == 0.0 {
                continue;
            }
            let f = 2.0 * r.weight * o;
            for (g, p) in out.iter_mut().zip(row) {
                *g += f * p;
            }
        }
    }

    /// The cost `J(U)` of a plan (for the tests: the programme's objective plus its
    /// constant).
    pub fn value(&self, layout: &Horizon, now: &Now, plan: &[f64]) -> f64 {
        let raw = Self::raw(layout, now);
        self.residuals
            .iter()
            .zip(self.rows.chunks(self.n.max(1)))
            .map(|(r, row)| {
                let e: f64 = self.offset(r, layout, now, &raw)
                    + row.iter().zip(plan).map(|(p, u)| p * u).sum::<f64>();
                r.weight * e * e
            })
            .sum()
    }
}

/// The row of a residual without the vestibular model, added into `row`.
fn raw_row(layout: &Horizon, term: Term, k: usize, i: usize, row: &mut [f64]) {
    match term {
        Term::Force => {
            layout.add_quantity(row, StepValue::Acceleration, k, i, 1.0);
            for j in 0..3 {
                let g = gravity_slope(i, j);
                if g != 0.0 {
                    layout.add_quantity(row, StepValue::MidPosition, k, 3 + j, g);
                }
            }
        }
        Term::Rate => layout.add_quantity(row, StepValue::MidVelocity, k, 3 + i, 1.0),
        Term::Input => layout.add_quantity(row, StepValue::Acceleration, k, i, 1.0),
        Term::Displacement => layout.add_quantity(row, StepValue::EndPosition, k, i, 1.0),
        Term::Velocity => layout.add_quantity(row, StepValue::EndVelocity, k, i, 1.0),
    }
}
