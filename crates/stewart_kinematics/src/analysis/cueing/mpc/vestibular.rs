//! The vestibular organs as linear filters, for the planner to track what is sensed
//! rather than the specific force and rates themselves (`[cueing] vestibular = true`):
//!
//! - **otoliths** (specific force, per axis): `K (τa s + 1) / ((τL s + 1)(τS s + 1))`
//!   with `K = 0.4`, `τa = 13.2 s`, `τL = 5.33 s`, `τS = 0.66 s` — Young and Meiry's
//!   model as Reid and Nahon use it (UTIAS Report 296, 1985); its gain is 0.4 for a
//!   sustained force and about 1 from 0.2 to 1 Hz, where a change of force is felt best;
//! - **semicircular canals** (rotation rate, per axis):
//!   `τa τL s² / ((τa s + 1)(τL s + 1)(τS s + 1))` with `τL = 5.73 s`, `τS = 0.005 s`,
//!   `τa = 80 s` (the canal's long time constant and its adaptation, as in Telban and
//!   Cardullo's models, NASA CR-2005-213747, and Rader, Oman and Merfeld 2009); its gain
//!   is about 1 from 0.03 to 30 Hz and 0 for a sustained rate, which is not felt.
//!
//! Each is stepped exactly for an input held over a step (the block matrix exponential).

use nalgebra::{DMatrix, DVector};

/// The otolith model's gain and time constants (s): `K`, `τa`, `τL`, `τS`.
pub const OTOLITH: [f64; 4] = [0.4, 13.2, 5.33, 0.66];
/// The canal model's time constants (s): `τa`, `τL`, `τS`.
pub const CANAL: [f64; 3] = [80.0, 5.73, 0.005];

/// A single-input, single-output filter `ẋ = A x + b u`, `y = c·x`.
#[derive(Clone, Debug)]
pub struct Organ {
    a: DMatrix<f64>,
    b: DVector<f64>,
    c: DVector<f64>,
}

impl Organ {
    /// The otolith filter of one axis (specific force in, sensed force out, m/s²).
    pub fn otolith() -> Self {
        let [k, ta, tl, ts] = OTOLITH;
        // K (τa s + 1) / (τL τS s² + (τL + τS) s + 1), made monic.
        let (a0, a1) = (1.0 / (tl * ts), (tl + ts) / (tl * ts));
        Self {
            a: DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -a0, -a1]),
            b: DVector::from_vec(vec![0.0, 1.0]),
            c: DVector::from_vec(vec![k / (tl * ts), k * ta / (tl * ts)]),
        }
    }

    /// The canal filter of one axis (rotation rate in, sensed rate out, rad/s).
    pub fn canal() -> Self {
        let [ta, tl, ts] = CANAL;
        let p = ta * tl * ts;
        let (d0, d1, d2) = (
            1.0 / p,
            (ta + tl + ts) / p,
            (ta * tl + ta * ts + tl * ts) / p,
        );
        Self {
            a: DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -d0, -d1, -d2]),
            b: DVector::from_vec(vec![0.0, 0.0, 1.0]),
            // τa τL s² / (τa τL τS (s³ + …)) = s² / (τS (s³ + …)).
            c: DVector::from_vec(vec![0.0, 0.0, 1.0 / ts]),
        }
    }

    /// The number of states.
    pub fn order(&self) -> usize {
        self.b.len()
    }

    /// The output of state `x`.
    pub fn output(&self, x: &[f64]) -> f64 {
        self.c.iter().zip(x).map(|(c, x)| c * x).sum()
    }

    /// `(Φ, Γ)` of a step of `h` seconds with the input held: `x ← Φ x + Γ u`.
    pub fn step(&self, h: f64) -> (DMatrix<f64>, DVector<f64>) {
        let n = self.order();
        let mut m = DMatrix::<f64>::zeros(n + 1, n + 1);
        m.view_mut((0, 0), (n, n)).copy_from(&(&self.a * h));
        m.view_mut((0, n), (n, 1)).copy_from(&(&self.b * h));
        let e = m.exp();
        (
            e.view((0, 0), (n, n)).into_owned(),
            e.view((0, n), (n, 1)).column(0).into_owned(),
        )
    }

    /// Along steps of `lengths`: `h[k][j]`, the output at the end of step `k` per unit
    /// input held over step `j` (0 for `j > k`), and `free[k]`, the output at the end of
    /// step `k` per unit of each initial state.
    pub fn responses(&self, lengths: &[f64]) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        let n = lengths.len();
        let steps: Vec<_> = lengths.iter().map(|&h| self.step(h)).collect();
        let mut h = vec![vec![0.0; n]; n];
        for j in 0..n {
            let mut v = steps[j].1.clone();
            for k in j..n {
                h[k][j] = self.c.dot(&v);
                if k + 1 < n {
                    v = &steps[k + 1].0 * v;
                }
            }
        }
        // c Φ_k ⋯ Φ_0, row by row.
        let mut free = Vec::with_capacity(n);
        let mut m = DMatrix::<f64>::identity(self.order(), self.order());
        for (phi, _) in &steps {
            m = phi * m;
            free.push((self.c.transpose() * &m).iter().copied().collect());
        }
        (h, free)
    }
}

/// The six organs' states over time (otoliths x, y, z; canals roll, pitch, yaw), stepped
/// once per solve interval with the error felt then held: what the planner's cost starts
/// from. Fixed-size, no allocation.
#[derive(Clone, Debug)]
pub struct Sensed {
    /// `Φ`, `Γ` of a solve interval, the otolith's then the canal's, padded to 3 states.
    phi: [[[f64; 3]; 3]; 2],
    gamma: [[f64; 3]; 2],
    /// The states now.
    pub states: [[f64; 3]; 6],
    /// The error held since the last step (felt minus wanted: force, then rates).
    held: [f64; 6],
}

impl Sensed {
    /// At rest, stepped every `interval` seconds.
    pub fn new(interval: f64) -> Self {
        let mut phi = [[[0.0; 3]; 3]; 2];
        let mut gamma = [[0.0; 3]; 2];
        for (k, organ) in [Organ::otolith(), Organ::canal()].iter().enumerate() {
            let (p, g) = organ.step(interval);
            for i in 0..organ.order() {
                gamma[k][i] = g[i];
                for j in 0..organ.order() {
                    phi[k][i][j] = p[(i, j)];
                }
            }
        }
        Self {
            phi,
            gamma,
            states: [[0.0; 3]; 6],
            held: [0.0; 6],
        }
    }

    /// The states one interval on with `held` through it.
    pub fn next(&self) -> [[f64; 3]; 6] {
        let mut out = [[0.0; 3]; 6];
        for (c, (x, o)) in self.states.iter().zip(out.iter_mut()).enumerate() {
            let k = usize::from(c >= 3);
            for (i, value) in o.iter_mut().enumerate() {
                *value = (0..3).map(|j| self.phi[k][i][j] * x[j]).sum::<f64>()
                    + self.gamma[k][i] * self.held[c];
            }
        }
        out
    }

    /// Step one interval and hold `error` from now on.
    pub fn step(&mut self, error: [f64; 6]) {
        self.states = self.next();
        self.held = error;
    }

    /// Back to rest.
    pub fn reset(&mut self) {
        self.states = [[0.0; 3]; 6];
        self.held = [0.0; 6];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fine fourth-order Runge–Kutta integration of the filter, independent of the
    /// matrix exponential: the output after `t` seconds of a unit step from rest.
    fn integrated(organ: &Organ, t: f64) -> f64 {
        let n = organ.order();
        let steps = 200_000;
        let h = t / f64::from(steps);
        let f = |x: &DVector<f64>| &organ.a * x + &organ.b;
        let mut x = DVector::zeros(n);
        for _ in 0..steps {
            let k1 = f(&x);
            let k2 = f(&(&x + &k1 * (h / 2.0)));
            let k3 = f(&(&x + &k2 * (h / 2.0)));
            let k4 = f(&(&x + &k3 * h));
            x += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
        }
        organ.output(x.as_slice())
    }

    #[test]
    fn the_otolith_s_step_response_is_its_closed_form() {
        // K (τa s + 1)/((τL s + 1)(τS s + 1)) · 1/s, by residues:
        // y(t) = K [1 + (τa − τL)/(τL − τS) e^{−t/τL} − (τa − τS)/(τL − τS) e^{−t/τS}].
        let [k, ta, tl, ts] = OTOLITH;
        let closed = |t: f64| {
            k * (1.0 + (ta - tl) / (tl - ts) * (-t / tl).exp()
                - (ta - ts) / (tl - ts) * (-t / ts).exp())
        };
        let organ = Organ::otolith();
        for t in [0.01, 0.1, 1.0, 5.0, 40.0] {
            let (h, _) = organ.responses(&[t]);
            assert!(
                (h[0][0] - closed(t)).abs() < 1e-12,
                "{t}: {} vs {}",
                h[0][0],
                closed(t)
            );
        }
        // A sustained force is sensed at 0.4 of itself.
        let (h, _) = organ.responses(&[200.0]);
        assert!((h[0][0] - 0.4).abs() < 1e-9);
    }

    #[test]
    fn the_canal_s_step_response_is_its_integrated_ode_and_fades() {
        let organ = Organ::canal();
        for t in [0.02, 0.5, 3.0] {
            let (h, _) = organ.responses(&[t]);
            let reference = integrated(&organ, t);
            assert!(
                (h[0][0] - reference).abs() < 1e-8,
                "{t}: {} vs {reference}",
                h[0][0]
            );
        }
        // A step of rate is sensed at once near its size, then fades: adaptation.
        let (h, _) = organ.responses(&[0.05]);
        assert!(h[0][0] > 0.9 && h[0][0] < 1.0, "{}", h[0][0]);
        let (h, _) = organ.responses(&[400.0]);
        assert!(h[0][0].abs() < 0.01, "{}", h[0][0]);
    }

    #[test]
    fn responses_over_uneven_steps_compose() {
        // Steps of 0.01 then 0.1 s: the response to an input over step 0 seen at the end
        // of step 2 is that of a state stepped by each in turn.
        let organ = Organ::otolith();
        let (h, free) = organ.responses(&[0.01, 0.1, 0.1]);
        let (p0, g0) = organ.step(0.01);
        let (p1, _) = organ.step(0.1);
        let x = &p1 * (&p1 * &g0);
        assert!((h[2][0] - organ.output(x.as_slice())).abs() < 1e-14);
        assert_eq!(h[0][2], 0.0);
        let e0 = DVector::from_vec(vec![1.0, 0.0]);
        let x = &p1 * (&p1 * (&p0 * e0));
        assert!((free[2][0] - organ.output(x.as_slice())).abs() < 1e-14);
    }
}
