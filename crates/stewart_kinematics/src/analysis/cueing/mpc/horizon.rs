//! The horizon of the model-predictive cueing: each cued axis (`x, y, z` of the reference
//! point, roll, pitch, yaw) a double integrator driven by its acceleration `u_j`, held
//! over each step `j` of the horizon. The first step is the solve interval — what is
//! followed until the next plan, so every limit set on its end holds for the motion
//! given — and the others are `mpc_step_s` long. Every quantity the cost or the limits
//! use — a position or velocity at a step's end or middle, a step's acceleration — is
//! affine in the plan `U = (u₀, …, u_{N−1})` and the state now `(s₀, ṡ₀)`; this module
//! gives both parts. With `τ_k` the start of step `k` and `T_k` its length:
//!
//! ```text
//! ṡ(τ_k)             = ṡ₀ + Σ_{j<k} T_j u_j
//! s(τ_k)             = s₀ + τ_k ṡ₀ + Σ_{j<k} T_j (τ_k − τ_j − T_j/2) u_j
//! s(τ_k + T_k/2)     = s₀ + (τ_k + T_k/2) ṡ₀ + Σ_{j<k} T_j (τ_k + T_k/2 − τ_j − T_j/2) u_j + T_k²/8 u_k
//! ṡ(τ_k + T_k/2)     = ṡ₀ + Σ_{j<k} T_j u_j + T_k/2 u_k
//! ```

/// A value of one axis at a step of the horizon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepValue {
    /// The position at the end of step `k`.
    EndPosition,
    /// The velocity at the end of step `k`.
    EndVelocity,
    /// The position in the middle of step `k`.
    MidPosition,
    /// The velocity in the middle of step `k` (its mean over the step).
    MidVelocity,
    /// The acceleration held over step `k`.
    Acceleration,
}

/// The horizon and the plan laid out on it: which axes are cued (the others stay at neutral and have no
/// variables), the steps, and where each variable sits (step-major).
#[derive(Clone, Debug, PartialEq)]
pub struct Horizon {
    /// The cued axes, of `0..6` (x, y, z, roll, pitch, yaw).
    pub axes: Vec<usize>,
    /// Steps.
    pub steps: usize,
    /// The first step's length (the solve interval), seconds.
    pub first: f64,
    /// The other steps' length, seconds.
    pub step: f64,
    /// Extra variables after the plan (slacks).
    pub extra: usize,
}

impl Horizon {
    /// The number of plan variables (accelerations).
    pub fn plan_len(&self) -> usize {
        self.axes.len() * self.steps
    }

    /// The number of variables.
    pub fn len(&self) -> usize {
        self.plan_len() + self.extra
    }

    /// Whether there is no variable.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The length of step `k`, seconds.
    pub fn length(&self, k: usize) -> f64 {
        if k == 0 { self.first } else { self.step }
    }

    /// The start of step `k` (`τ_k`), seconds from now.
    pub fn start(&self, k: usize) -> f64 {
        if k == 0 {
            0.0
        } else {
            self.first + (k - 1) as f64 * self.step
        }
    }

    /// The step that holds the moment `age` seconds from the plan's start, or `None`
    /// after the horizon.
    pub fn step_at(&self, age: f64) -> Option<usize> {
        if age < self.first {
            return Some(0);
        }
        // In floats first: a plan long over may be any age.
        let k = 1.0 + ((age - self.first) / self.step).floor();
        (k < self.steps as f64).then_some(k as usize)
    }

    /// The moment (from the step's start) at which `quantity` of step `k` is taken.
    fn moment(quantity: StepValue, length: f64) -> f64 {
        match quantity {
            StepValue::EndPosition | StepValue::EndVelocity => length,
            StepValue::MidPosition | StepValue::MidVelocity => 0.5 * length,
            StepValue::Acceleration => 0.0,
        }
    }

    /// The coefficient of `u_j` in `quantity` of step `k`.
    pub fn coefficient(&self, quantity: StepValue, k: usize, j: usize) -> f64 {
        if j > k {
            return 0.0;
        }
        let tk = self.length(k);
        let at = self.start(k) + Self::moment(quantity, tk);
        if j == k {
            let m = Self::moment(quantity, tk);
            return match quantity {
                StepValue::Acceleration => 1.0,
                StepValue::EndPosition | StepValue::MidPosition => 0.5 * m * m,
                StepValue::EndVelocity | StepValue::MidVelocity => m,
            };
        }
        let tj = self.length(j);
        let end_j = self.start(j) + tj;
        match quantity {
            StepValue::Acceleration => 0.0,
            StepValue::EndPosition | StepValue::MidPosition => tj * (0.5 * tj + at - end_j),
            StepValue::EndVelocity | StepValue::MidVelocity => tj,
        }
    }

    /// `quantity` of step `k` with no acceleration at all, from position `s` and velocity
    /// `v` now.
    pub fn free(&self, quantity: StepValue, k: usize, s: f64, v: f64) -> f64 {
        let at = self.start(k) + Self::moment(quantity, self.length(k));
        match quantity {
            StepValue::EndPosition | StepValue::MidPosition => s + at * v,
            StepValue::EndVelocity | StepValue::MidVelocity => v,
            StepValue::Acceleration => 0.0,
        }
    }

    /// Add `factor` × (the coefficients of `quantity` of `axis` in step `k`) to `row`.
    pub fn add_quantity(
        &self,
        row: &mut [f64],
        quantity: StepValue,
        k: usize,
        axis: usize,
        factor: f64,
    ) {
        let Some(slot) = self.axes.iter().position(|&a| a == axis) else {
            return;
        };
        for j in 0..=k.min(self.steps - 1) {
            let c = self.coefficient(quantity, k, j);
            if c != 0.0 {
                row[j * self.axes.len() + slot] += factor * c;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Integrate a double integrator finely under a plan of uneven steps and compare
    /// every quantity with its affine form.
    #[test]
    fn the_affine_forms_are_the_integrated_motion() {
        let layout = Horizon {
            axes: vec![2],
            steps: 4,
            first: 0.01,
            step: 0.1,
            extra: 0,
        };
        let plan = [1.5, -2.0, 0.25, 3.0];
        let (s0, v0) = (0.2, -0.7);
        let substeps = 1000;
        let (mut s, mut v) = (s0, v0);
        for (k, &u) in plan.iter().enumerate() {
            let h = layout.length(k) / substeps as f64;
            let mut mid = (0.0, 0.0);
            for i in 0..substeps {
                if i == substeps / 2 {
                    mid = (s, v);
                }
                // Exact for a held acceleration.
                s += v * h + 0.5 * u * h * h;
                v += u * h;
            }
            let value = |q: StepValue| {
                let mut row = [0.0; 4];
                layout.add_quantity(&mut row, q, k, 2, 1.0);
                layout.free(q, k, s0, v0) + row.iter().zip(&plan).map(|(c, u)| c * u).sum::<f64>()
            };
            assert!((value(StepValue::EndPosition) - s).abs() < 1e-12);
            assert!((value(StepValue::EndVelocity) - v).abs() < 1e-12);
            assert!((value(StepValue::MidPosition) - mid.0).abs() < 1e-12);
            assert!((value(StepValue::MidVelocity) - mid.1).abs() < 1e-12);
            assert_eq!(value(StepValue::Acceleration), u);
        }
        assert_eq!(layout.step_at(0.005), Some(0));
        assert_eq!(layout.step_at(0.05), Some(1));
        assert_eq!(layout.step_at(0.25), Some(3));
        assert_eq!(layout.step_at(0.32), None);
    }
}
