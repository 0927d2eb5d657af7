//! A continuous linear system `ẋ = A x + B u` stepped exactly for an input held constant
//! between samples (zero-order hold): over a step `h`, `x ← Φ x + Γ u` with
//! `[[Φ, Γ], [0, 1]] = exp([[A, B], [0, 0]] h)` (Van Loan's block exponential). For a
//! piecewise-constant input the states at the sample times are those of the continuous
//! system, to the matrix exponential's rounding; `Φ` and `Γ` are kept for the last step
//! length, so a stream at a fixed rate computes them once.

use nalgebra::{DMatrix, SMatrix, SVector};

/// A system of `N` states driven by one input.
#[derive(Clone, Debug)]
pub struct Lti<const N: usize> {
    a: SMatrix<f64, N, N>,
    b: SVector<f64, N>,
    state: SVector<f64, N>,
    /// The step length `phi` and `gamma` were computed for (NaN before the first).
    step: f64,
    phi: SMatrix<f64, N, N>,
    gamma: SVector<f64, N>,
}

impl<const N: usize> Lti<N> {
    /// The system `ẋ = A x + B u` at rest.
    pub fn new(a: SMatrix<f64, N, N>, b: SVector<f64, N>) -> Self {
        Self {
            a,
            b,
            state: SVector::zeros(),
            step: f64::NAN,
            phi: SMatrix::identity(),
            gamma: SVector::zeros(),
        }
    }

    /// The companion form of `1 / (sᴺ + c[N-1] sᴺ⁻¹ + … + c[0])`: state `i` is the output's
    /// `i`-th derivative, so `sⁱ / den` is state `i`.
    pub fn companion(c: [f64; N]) -> Self {
        let mut a = SMatrix::<f64, N, N>::zeros();
        for i in 0..N.saturating_sub(1) {
            a[(i, i + 1)] = 1.0;
        }
        for (j, cj) in c.iter().enumerate() {
            a[(N - 1, j)] = -cj;
        }
        let mut b = SVector::<f64, N>::zeros();
        b[N - 1] = 1.0;
        Self::new(a, b)
    }

    /// Advance by `h` seconds with the input held at `u`.
    pub fn advance(&mut self, h: f64, u: f64) {
        if h != self.step {
            self.discretise(h);
        }
        self.state = self.phi * self.state + self.gamma * u;
    }

    /// The states now.
    pub fn state(&self) -> &SVector<f64, N> {
        &self.state
    }

    /// The states' derivatives now, with the input at `u`.
    pub fn derivative(&self, u: f64) -> SVector<f64, N> {
        self.a * self.state + self.b * u
    }

    /// Back to rest.
    pub fn reset(&mut self) {
        self.state = SVector::zeros();
    }

    fn discretise(&mut self, h: f64) {
        let mut m = DMatrix::<f64>::zeros(N + 1, N + 1);
        m.view_mut((0, 0), (N, N)).copy_from(&(self.a * h));
        m.view_mut((0, N), (N, 1)).copy_from(&(self.b * h));
        let e = m.exp();
        self.phi.copy_from(&e.view((0, 0), (N, N)));
        self.gamma.copy_from(&e.view((0, N), (N, 1)));
        self.step = h;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_first_order_lag_steps_to_its_exact_response() {
        // ẋ = −2x + u, a unit step from rest: x(t) = (1 − e^{−2t}) / 2, at uneven steps.
        let mut f = Lti::<1>::companion([2.0]);
        let mut t = 0.0;
        for h in [0.01, 0.3, 0.001, 1.7, 0.05] {
            f.advance(h, 1.0);
            t += h;
            let exact = (1.0 - (-2.0 * t).exp()) / 2.0;
            assert!((f.state()[0] - exact).abs() < 1e-15, "{t}");
        }
    }

    #[test]
    fn a_double_integrator_holds_its_input_between_samples() {
        // ẍ = u with u = 3 for 0.5 s then −1 for 0.25 s: x = 3·0.25/2·… exactly.
        let mut f = Lti::<2>::companion([0.0, 0.0]);
        f.advance(0.5, 3.0);
        f.advance(0.25, -1.0);
        let v1 = 3.0 * 0.5;
        let x1 = 0.5 * 3.0 * 0.25;
        let exact = [x1 + v1 * 0.25 - 0.5 * 0.0625, v1 - 0.25];
        for (got, want) in f.state().iter().zip(exact) {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
    }
}
