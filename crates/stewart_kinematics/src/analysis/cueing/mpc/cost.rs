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

use super::horizon::{Layout, Quantity};
use crate::model::cueing_settings::{CueingSettings, GRAVITY};

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
}

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
}

/// The residuals of one horizon and their constant rows.
#[derive(Clone, Debug)]
pub struct Cost {
    residuals: Vec<Residual>,
    /// One row per residual, `n` wide, row-major.
    rows: Vec<f64>,
    n: usize,
}

impl Cost {
    /// The residuals of `settings` for `layout`.
    pub fn new(settings: &CueingSettings, layout: &Layout) -> Self {
        let s = settings;
        let mut residuals = Vec::new();
        for step in 0..layout.steps {
            // Each step counts for its length: the sums stand for integrals over time.
            let share = layout.length(step) / layout.step;
            let mut add = |term, axis, weight: f64| {
                if weight > 0.0 {
                    residuals.push(Residual {
                        term,
                        step,
                        axis,
                        weight: weight * share,
                    });
                }
            };
            for axis in 0..3 {
                add(Term::Force, axis, s.mpc_force_weight);
                add(Term::Rate, axis, s.mpc_rate_weight);
            }
            for &axis in &layout.axes {
                add(Term::Input, axis, s.mpc_input_weight);
                let displacement = if axis == 3 || axis == 4 {
                    s.mpc_tilt_weight
                } else {
                    s.mpc_displacement_weight
                };
                add(Term::Displacement, axis, displacement);
                add(Term::Velocity, axis, s.mpc_velocity_weight);
            }
        }
        let n = layout.len();
        let mut rows = vec![0.0; residuals.len() * n];
        for (r, row) in residuals.iter().zip(rows.chunks_mut(n.max(1))) {
            let (k, i) = (r.step, r.axis);
            match r.term {
                Term::Force => {
                    layout.add_quantity(row, Quantity::Acceleration, k, i, 1.0);
                    for j in 0..3 {
                        let g = gravity_slope(i, j);
                        if g != 0.0 {
                            layout.add_quantity(row, Quantity::MidPosition, k, 3 + j, g);
                        }
                    }
                }
                Term::Rate => layout.add_quantity(row, Quantity::MidVelocity, k, 3 + i, 1.0),
                Term::Input => layout.add_quantity(row, Quantity::Acceleration, k, i, 1.0),
                Term::Displacement => layout.add_quantity(row, Quantity::EndPosition, k, i, 1.0),
                Term::Velocity => layout.add_quantity(row, Quantity::EndVelocity, k, i, 1.0),
            }
        }
        Self { residuals, rows, n }
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

    /// The offset of residual `r` (its value for the plan of no acceleration).
    fn offset(r: &Residual, layout: &Layout, now: &Now) -> f64 {
        let (k, i) = (r.step, r.axis);
        let free = |q: Quantity, axis: usize| {
            if layout.axes.contains(&axis) {
                layout.free(q, k, now.s[axis], now.v[axis])
            } else {
                0.0
            }
        };
        match r.term {
            Term::Force => {
                let mut o = now.force[i] - now.a[i] - now.wanted(k, i);
                for j in 0..3 {
                    let g = gravity_slope(i, j);
                    if g != 0.0 {
                        o += g * (free(Quantity::MidPosition, 3 + j) - now.s[3 + j]);
                    }
                }
                o
            }
            Term::Rate => {
                now.rates[i] - now.v[3 + i] + free(Quantity::MidVelocity, 3 + i)
                    - now.wanted(k, 3 + i)
            }
            Term::Input => 0.0,
            Term::Displacement => free(Quantity::EndPosition, i),
            Term::Velocity => free(Quantity::EndVelocity, i),
        }
    }

    /// The linear term `a = 2 Σ w o φ` for the state and wishes `now` (into `out`).
    pub fn gradient(&self, layout: &Layout, now: &Now, out: &mut [f64]) {
        out.iter_mut().for_each(|v| *v = 0.0);
        for (r, row) in self.residuals.iter().zip(self.rows.chunks(self.n.max(1))) {
            let o = Self::offset(r, layout, now);
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
    pub fn value(&self, layout: &Layout, now: &Now, plan: &[f64]) -> f64 {
        self.residuals
            .iter()
            .zip(self.rows.chunks(self.n.max(1)))
            .map(|(r, row)| {
                let e: f64 = Self::offset(r, layout, now)
                    + row.iter().zip(plan).map(|(p, u)| p * u).sum::<f64>();
                r.weight * e * e
            })
            .sum()
    }
}
