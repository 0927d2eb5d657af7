//! A dense, strictly convex quadratic programme solved by the dual active-set method of
//! Goldfarb and Idnani (Math. Programming 27, 1983, pp. 1–33):
//!
//! ```text
//! minimise ½ xᵀ G x + aᵀ x   subject to   lᵢ ≤ cᵢᵀ x ≤ uᵢ   (lᵢ = uᵢ for the first rows: equalities)
//! ```
//!
//! It starts from the unconstrained minimum `−G⁻¹ a` and adds one violated constraint at a
//! time, dropping one whose multiplier would turn negative, each step keeping the
//! solution optimal for the constraints added so far; it ends when none is violated (the
//! optimum, exactly: primal feasible, dual feasible and complementary) or proves that
//! none can be met. `G = L Lᵀ` is factored once; `J = L⁻ᵀ Q` and the triangle `R` of the
//! active normals (`Jᵀ N = [R; 0]`) are updated by Givens rotations.
//!
//! **Warm start.** The constraints active at the last solve are tried first: a stream of
//! close problems (one per cueing step) adds them again without the detours.
//!
//! Every buffer is allocated when the solver is made; a solve allocates nothing.

/// Why a programme has no solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QpFailure {
    /// No point meets every constraint.
    Infeasible,
    /// The iteration limit was reached (a degenerate programme cycling): treated as no
    /// solution.
    Iterations,
}

/// Linear constraints `l ≤ c x ≤ u` on `n` variables, row by row; the first
/// [`Constraints::equalities`] rows are equalities.
#[derive(Clone, Debug)]
pub struct Constraints {
    n: usize,
    rows: Vec<f64>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    equalities: usize,
}

impl Constraints {
    /// No constraints on `n` variables, room for `capacity` rows.
    pub fn new(n: usize, capacity: usize) -> Self {
        Self {
            n,
            rows: Vec::with_capacity(n * capacity),
            lower: Vec::with_capacity(capacity),
            upper: Vec::with_capacity(capacity),
            equalities: 0,
        }
    }

    /// Remove every row (the room is kept).
    pub fn clear(&mut self) {
        self.rows.clear();
        self.lower.clear();
        self.upper.clear();
        self.equalities = 0;
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.lower.len()
    }

    /// Whether there is no row.
    pub fn is_empty(&self) -> bool {
        self.lower.is_empty()
    }

    /// The number of equality rows (the first ones).
    pub fn equalities(&self) -> usize {
        self.equalities
    }

    /// Add the equality row `c x = value`, its coefficients zero, returned to be filled.
    /// Equalities come first: one after an inequality is refused (`None`).
    pub fn push_equality(&mut self, value: f64) -> Option<&mut [f64]> {
        if self.equalities != self.len() {
            return None;
        }
        self.equalities += 1;
        Some(self.push_row(value, value))
    }

    /// Add the inequality row `l ≤ c x ≤ u` (infinite bounds for a one-sided row; equal
    /// bounds are still an inequality's two sides), its coefficients zero, returned to be
    /// filled.
    pub fn push(&mut self, lower: f64, upper: f64) -> &mut [f64] {
        self.push_row(lower, upper)
    }

    fn push_row(&mut self, lower: f64, upper: f64) -> &mut [f64] {
        self.lower.push(lower);
        self.upper.push(upper);
        let start = self.rows.len();
        self.rows.resize(start + self.n, 0.0);
        &mut self.rows[start..]
    }

    /// Scale every row to unit length (bounds with it): the same constraints, better
    /// conditioned for the solver. A zero row is left as it is.
    pub fn normalise(&mut self) {
        for i in 0..self.len() {
            let row = &mut self.rows[i * self.n..(i + 1) * self.n];
            let norm = dot(row, row).sqrt();
            if norm > 0.0 && norm.is_finite() {
                row.iter_mut().for_each(|v| *v /= norm);
                self.lower[i] /= norm;
                self.upper[i] /= norm;
            }
        }
    }

    /// Row `i`'s coefficients.
    pub fn row(&self, i: usize) -> &[f64] {
        &self.rows[i * self.n..(i + 1) * self.n]
    }

    /// Row `i`'s bounds.
    pub fn bounds(&self, i: usize) -> (f64, f64) {
        (self.lower[i], self.upper[i])
    }
}

/// One side of a row: `+1` for `c x ≥ l`, `−1` for `c x ≤ u` (as `−c x ≥ −u`).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Side {
    row: usize,
    sign: f64,
}

impl Side {
    /// `±c x ∓ bound`: negative when violated.
    fn slack(&self, c: &Constraints, x: &[f64]) -> f64 {
        let v = dot(c.row(self.row), x);
        let (l, u) = c.bounds(self.row);
        if self.sign > 0.0 { v - l } else { u - v }
    }
}

/// The solver for one `G`: its factor and its work space.
#[derive(Clone, Debug)]
pub struct DenseQp {
    n: usize,
    /// `L⁻ᵀ` of `G = L Lᵀ`, column-major.
    j0: Vec<f64>,
    /// `J`, column-major, updated as constraints come and go.
    j: Vec<f64>,
    /// The upper triangle `R`, column-major in an `n × n` block.
    r: Vec<f64>,
    x: Vec<f64>,
    d: Vec<f64>,
    z: Vec<f64>,
    step: Vec<f64>,
    normal: Vec<f64>,
    multipliers: Vec<f64>,
    active: Vec<Side>,
    /// The inequality sides active at the last solve, tried first next time.
    previous: Vec<Side>,
    iterations: usize,
}

/// The `G` of a solver is not symmetric positive definite.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NotPositiveDefinite;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl DenseQp {
    /// The solver of `½ xᵀ G x + aᵀ x` for the symmetric positive definite `G` (`n × n`,
    /// column-major), with room for `rows` constraint rows.
    pub fn new(g: &[f64], n: usize, rows: usize) -> Result<Self, NotPositiveDefinite> {
        let gm = nalgebra::DMatrix::from_column_slice(n, n, g);
        let l = gm.cholesky().ok_or(NotPositiveDefinite)?.l();
        // L⁻ᵀ: the transpose of the lower triangle's inverse.
        let mut inverse = nalgebra::DMatrix::identity(n, n);
        if !l.solve_lower_triangular_mut(&mut inverse) {
            return Err(NotPositiveDefinite);
        }
        let j0: Vec<f64> = inverse.transpose().as_slice().to_vec();
        if j0.iter().any(|v| !v.is_finite()) {
            return Err(NotPositiveDefinite);
        }
        Ok(Self {
            n,
            j: j0.clone(),
            j0,
            r: vec![0.0; n * n],
            x: vec![0.0; n],
            d: vec![0.0; n],
            z: vec![0.0; n],
            step: vec![0.0; n],
            normal: vec![0.0; n],
            multipliers: Vec::with_capacity(n),
            active: Vec::with_capacity(n),
            previous: Vec::with_capacity(rows.max(n)),
            iterations: 0,
        })
    }

    /// The number of variables.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether there are no variables.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The iterations (constraints added or dropped) of the last solve.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The number of constraints active at the last solution.
    pub fn active_count(&self) -> usize {
        self.active.len()
    }

    /// The multipliers of the last solution, one per row (0 for an inactive row; for a
    /// row active at its upper bound, the multiplier of `−c x ≥ −u`, reported negative),
    /// so that `G x + a = Σ λᵢ cᵢ`.
    pub fn row_multipliers(&self, rows: usize, out: &mut [f64]) {
        out[..rows].iter_mut().for_each(|v| *v = 0.0);
        for (side, m) in self.active.iter().zip(&self.multipliers) {
            out[side.row] += side.sign * m;
        }
    }

    fn jcol(&self, i: usize) -> &[f64] {
        &self.j[i * self.n..(i + 1) * self.n]
    }

    /// The minimiser of `½ xᵀ G x + aᵀ x` within `c`, or why there is none.
    pub fn solve(&mut self, a: &[f64], c: &Constraints) -> Result<&[f64], QpFailure> {
        let n = self.n;
        debug_assert_eq!(c.n, n);
        self.j.copy_from_slice(&self.j0);
        self.active.clear();
        self.multipliers.clear();
        self.iterations = 0;
        // x = −G⁻¹ a = −J (Jᵀ a).
        for i in 0..n {
            self.d[i] = dot(self.jcol(i), a);
        }
        self.x.iter_mut().for_each(|v| *v = 0.0);
        for i in 0..n {
            let di = self.d[i];
            let col = &self.j[i * n..(i + 1) * n];
            for (xv, jv) in self.x.iter_mut().zip(col) {
                *xv -= di * jv;
            }
        }
        let limit = 20 * (n + c.len()) + 50;
        // Equalities first, each on the side it is violated from.
        for row in 0..c.equalities() {
            let v = dot(c.row(row), &self.x);
            let sign = if v <= c.bounds(row).0 { 1.0 } else { -1.0 };
            self.add(Side { row, sign }, c, true, limit)?;
        }
        while let Some(side) = self.most_violated(c) {
            self.add(side, c, false, limit)?;
        }
        self.previous.clear();
        let equalities = c.equalities();
        self.previous
            .extend(self.active.iter().filter(|s| s.row >= equalities));
        Ok(&self.x)
    }

    /// The violated side to add: the most violated of those active last time, else the
    /// most violated of all (by distance, the row's norm dividing), or `None`.
    fn most_violated(&self, c: &Constraints) -> Option<Side> {
        let tolerance = |side: &Side| {
            let (l, u) = c.bounds(side.row);
            let bound = if side.sign > 0.0 { l } else { u };
            1e-9 * (1.0 + bound.abs())
        };
        let is_active = |s: &Side| self.active.iter().any(|a| a.row == s.row);
        let mut best: Option<(f64, Side)> = None;
        for s in &self.previous {
            if s.row < c.len() && !is_active(s) {
                let slack = s.slack(c, &self.x);
                if slack < -tolerance(s) && best.is_none_or(|(b, _)| slack < b) {
                    best = Some((slack, *s));
                }
            }
        }
        if let Some((_, s)) = best {
            return Some(s);
        }
        let mut best: Option<(f64, Side)> = None;
        for row in c.equalities()..c.len() {
            let v = dot(c.row(row), &self.x);
            let (l, u) = c.bounds(row);
            let (slack, sign, bound) = if v < l {
                (v - l, 1.0, l)
            } else {
                (u - v, -1.0, u)
            };
            if slack >= -1e-9 * (1.0 + bound.abs()) {
                continue;
            }
            let norm = dot(c.row(row), c.row(row)).sqrt().max(f64::MIN_POSITIVE);
            let distance = slack / norm;
            let side = Side { row, sign };
            if is_active(&side) {
                continue;
            }
            if best.is_none_or(|(b, _)| distance < b) {
                best = Some((distance, side));
            }
        }
        best.map(|(_, s)| s)
    }

    /// Make `side` hold (as an equality when `equality`), dropping the inequalities whose
    /// multipliers would turn negative on the way.
    fn add(
        &mut self,
        side: Side,
        c: &Constraints,
        equality: bool,
        limit: usize,
    ) -> Result<(), QpFailure> {
        let n = self.n;
        for (nv, cv) in self.normal.iter_mut().zip(c.row(side.row)) {
            *nv = side.sign * cv;
        }
        let mut added_multiplier = 0.0;
        loop {
            self.iterations += 1;
            if self.iterations > limit {
                return Err(QpFailure::Iterations);
            }
            let q = self.active.len();
            // d = Jᵀ n⁺; z = J₂ d₂ (the primal step); step = R⁻¹ d₁ (minus the dual step).
            for i in 0..n {
                self.d[i] = dot(self.jcol(i), &self.normal);
            }
            self.z.iter_mut().for_each(|v| *v = 0.0);
            for i in q..n {
                let di = self.d[i];
                let col = &self.j[i * n..(i + 1) * n];
                for (zv, jv) in self.z.iter_mut().zip(col) {
                    *zv += di * jv;
                }
            }
            for i in (0..q).rev() {
                let mut s = self.d[i];
                for k in i + 1..q {
                    s -= self.r[k * n + i] * self.step[k];
                }
                self.step[i] = s / self.r[i * n + i];
            }
            // The longest dual step that keeps the inequality multipliers non-negative.
            let mut partial: Option<(f64, usize)> = None;
            for k in 0..q {
                if self.step[k] > 0.0 && self.active[k].row >= c.equalities() {
                    // A multiplier rounded just below 0 is 0.
                    let t = (self.multipliers[k] / self.step[k]).max(0.0);
                    if partial.is_none_or(|(b, _)| t < b) {
                        partial = Some((t, k));
                    }
                }
            }
            let zn = dot(&self.z, &self.normal);
            let scale = dot(&self.normal, &self.normal).max(f64::MIN_POSITIVE);
            let full = if zn > 1e-14 * scale {
                let slack = dot(&self.normal, &self.x)
                    - side.sign * {
                        let (l, u) = c.bounds(side.row);
                        if side.sign > 0.0 { l } else { u }
                    };
                Some(-slack / zn)
            } else {
                None
            };
            match (full, partial) {
                (None, None) => return Err(QpFailure::Infeasible),
                (None, Some((t, k))) => {
                    // A dual step only: drop constraint k and try again.
                    if equality && t.is_infinite() {
                        return Err(QpFailure::Infeasible);
                    }
                    for i in 0..q {
                        self.multipliers[i] -= t * self.step[i];
                    }
                    added_multiplier += t;
                    self.drop(k);
                }
                (Some(tf), partial) => {
                    let (t, drop) = match partial {
                        Some((tp, k)) if tp < tf => (tp, Some(k)),
                        _ => (tf, None),
                    };
                    for (xv, zv) in self.x.iter_mut().zip(&self.z) {
                        *xv += t * zv;
                    }
                    for i in 0..q {
                        self.multipliers[i] -= t * self.step[i];
                    }
                    added_multiplier += t;
                    match drop {
                        Some(k) => self.drop(k),
                        None => {
                            self.push_active(side, added_multiplier);
                            return Ok(());
                        }
                    }
                }
            }
        }
    }

    /// Add `side` to the active set: rotate `d = Jᵀ n⁺` so that its tail is zero, and
    /// append it to `R`.
    fn push_active(&mut self, side: Side, multiplier: f64) {
        let n = self.n;
        let q = self.active.len();
        for i in (q + 1..n).rev() {
            let (a, b) = (self.d[i - 1], self.d[i]);
            if b == 0.0 {
                continue;
            }
            let h = a.hypot(b);
            let (cs, sn) = (a / h, b / h);
            self.d[i - 1] = h;
            self.d[i] = 0.0;
            self.rotate_columns(i - 1, cs, sn);
        }
        for i in 0..=q {
            self.r[q * n + i] = self.d[i];
        }
        self.active.push(side);
        self.multipliers.push(multiplier);
    }

    /// Columns `i`, `i + 1` of `J` ← `(c Jᵢ + s Jᵢ₊₁, −s Jᵢ + c Jᵢ₊₁)`.
    fn rotate_columns(&mut self, i: usize, cs: f64, sn: f64) {
        let n = self.n;
        let (left, right) = self.j.split_at_mut((i + 1) * n);
        let a = &mut left[i * n..];
        let b = &mut right[..n];
        for (x, y) in a.iter_mut().zip(b.iter_mut()) {
            let (u, v) = (*x, *y);
            *x = cs * u + sn * v;
            *y = -sn * u + cs * v;
        }
    }

    /// Drop active constraint `k`: remove its column of `R` and bring `R` back to a
    /// triangle by rotations, applied to `J` too.
    fn drop(&mut self, k: usize) {
        let n = self.n;
        let q = self.active.len();
        for col in k..q - 1 {
            for i in 0..=col + 1 {
                self.r[col * n + i] = self.r[(col + 1) * n + i];
            }
        }
        for col in k..q - 1 {
            let (a, b) = (self.r[col * n + col], self.r[col * n + col + 1]);
            if b != 0.0 {
                let h = a.hypot(b);
                let (cs, sn) = (a / h, b / h);
                for c2 in col..q - 1 {
                    let (u, v) = (self.r[c2 * n + col], self.r[c2 * n + col + 1]);
                    self.r[c2 * n + col] = cs * u + sn * v;
                    self.r[c2 * n + col + 1] = -sn * u + cs * v;
                }
                self.rotate_columns(col, cs, sn);
            }
            self.r[col * n + col + 1] = 0.0;
        }
        self.active.remove(k);
        self.multipliers.remove(k);
    }
}

#[cfg(test)]
mod tests;
