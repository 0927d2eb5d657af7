//! Real roots of polynomials of degree at most four in an interval: the points where a
//! column's constraints (a cone, a servo's reach or range end) can change along `z`.
//!
//! **Method.** Degree one and two in closed form (the quadratic in its cancellation-free
//! form, which also degrades gracefully to a line when the leading coefficient vanishes).
//! Degree three and four by isolation: the derivative's roots (found the same way) cut the
//! interval into pieces on which the polynomial is monotone, so each piece holds a root
//! exactly when its ends differ in sign, and that root is found by Newton's method kept
//! inside its bracket (bisection whenever a Newton step would leave it).

/// A polynomial `c[0] + c[1] z + … + c[4] z⁴` (coefficients beyond the degree are zero).
pub(super) type Poly = [f64; 5];

/// `p(z)` by Horner's rule.
pub(super) fn eval(p: &Poly, z: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, &k| acc * z + k)
}

/// The product of two polynomials whose degrees sum to at most four.
pub(super) fn mul(a: &Poly, b: &Poly) -> Poly {
    let mut out = [0.0; 5];
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            if x != 0.0 && y != 0.0 {
                out[i + j] += x * y;
            }
        }
    }
    out
}

/// `a − b`.
pub(super) fn sub(a: &Poly, b: &Poly) -> Poly {
    std::array::from_fn(|k| a[k] - b[k])
}

/// The derivative.
fn derivative(p: &Poly) -> Poly {
    [p[1], 2.0 * p[2], 3.0 * p[3], 4.0 * p[4], 0.0]
}

/// The degree, ignoring zero leading coefficients (0 for a constant or zero polynomial).
fn degree(p: &Poly) -> usize {
    (0..5).rev().find(|&k| p[k] != 0.0).unwrap_or(0)
}

/// The real roots of `p` in `[lo, hi]`, ascending, appended to `out` (a polynomial that is
/// identically zero has none: it never changes sign).
pub(super) fn roots_in(p: &Poly, lo: f64, hi: f64, out: &mut Vec<f64>) {
    if lo.partial_cmp(&hi).is_none_or(|o| o.is_gt()) {
        return;
    }
    match degree(p) {
        0 => {}
        1 => push_within(-p[0] / p[1], lo, hi, out),
        2 => quadratic(p[2], p[1], p[0], lo, hi, out),
        _ => isolated(p, lo, hi, out),
    }
}

/// `z` when it lies in `[lo, hi]`.
fn push_within(z: f64, lo: f64, hi: f64, out: &mut Vec<f64>) {
    if (lo..=hi).contains(&z) {
        out.push(z);
    }
}

/// Roots of `a z² + b z + c` in `[lo, hi]`, ascending.
fn quadratic(a: f64, b: f64, c: f64, lo: f64, hi: f64, out: &mut Vec<f64>) {
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return;
    }
    // q = −(b + sign(b)√D)/2 avoids subtracting nearly equal numbers; the roots are q/a and
    // c/q (with a = 0 the first is infinite and the second the line's root).
    let q = -0.5 * (b + b.signum() * discriminant.sqrt());
    let (r0, r1) = (q / a, c / q);
    let (r0, r1) = if r0 <= r1 { (r0, r1) } else { (r1, r0) };
    push_within(r0, lo, hi, out);
    if r1 != r0 {
        push_within(r1, lo, hi, out);
    }
}

/// Roots of a cubic or quartic in `[lo, hi]`: monotone pieces between the derivative's
/// roots, each bracketing at most one root.
fn isolated(p: &Poly, lo: f64, hi: f64, out: &mut Vec<f64>) {
    let dp = derivative(p);
    let mut cuts = Vec::with_capacity(5);
    cuts.push(lo);
    roots_in(&dp, lo, hi, &mut cuts);
    cuts.push(hi);
    let mut last: Option<f64> = None;
    let mut push = |z: f64, out: &mut Vec<f64>| {
        if last != Some(z) {
            out.push(z);
            last = Some(z);
        }
    };
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (fa, fb) = (eval(p, a), eval(p, b));
        if fa == 0.0 {
            push(a, out);
        }
        if fa * fb < 0.0 {
            push(bracketed(p, &dp, a, b, fa), out);
        }
    }
    if eval(p, hi) == 0.0 {
        push(hi, out);
    }
}

/// The root of `p` in `[a, b]` (monotone there, `p(a)` = `fa` and `p(b)` of opposite
/// signs): Newton steps that stay inside the shrinking bracket, else bisection.
fn bracketed(p: &Poly, dp: &Poly, mut a: f64, mut b: f64, fa: f64) -> f64 {
    let mut z = 0.5 * (a + b);
    for _ in 0..200 {
        let f = eval(p, z);
        if f == 0.0 {
            return z;
        }
        if (f < 0.0) == (fa < 0.0) {
            a = z;
        } else {
            b = z;
        }
        let newton = z - f / eval(dp, z);
        let next = if newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if (next - z).abs() <= 4.0 * f64::EPSILON * z.abs().max(1e-300) || b - a <= 0.0 {
            return next;
        }
        z = next;
    }
    z
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The monic polynomial with the given roots.
    fn with_roots(roots: &[f64]) -> Poly {
        roots.iter().fold([1.0, 0.0, 0.0, 0.0, 0.0], |p, &r| {
            mul(&p, &[-r, 1.0, 0.0, 0.0, 0.0])
        })
    }

    fn roots(p: &Poly, lo: f64, hi: f64) -> Vec<f64> {
        let mut out = Vec::new();
        roots_in(p, lo, hi, &mut out);
        out
    }

    #[test]
    fn hand_cases() {
        // 2z − 1; z² − 2; (z − 1)(z − 2)(z − 3); z⁴ − 5z² + 4 = (z² − 1)(z² − 4).
        assert_eq!(roots(&[-1.0, 2.0, 0.0, 0.0, 0.0], -5.0, 5.0), vec![0.5]);
        let r = roots(&[-2.0, 0.0, 1.0, 0.0, 0.0], -5.0, 5.0);
        assert!((r[0] + 2f64.sqrt()).abs() < 1e-15 && (r[1] - 2f64.sqrt()).abs() < 1e-15);
        let r = roots(&[-6.0, 11.0, -6.0, 1.0, 0.0], 0.0, 10.0);
        assert_eq!(r.len(), 3);
        for (got, want) in r.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-14, "{r:?}");
        }
        let r = roots(&[4.0, 0.0, -5.0, 0.0, 1.0], -10.0, 10.0);
        assert_eq!(r.len(), 4, "{r:?}");
        for (got, want) in r.iter().zip([-2.0, -1.0, 1.0, 2.0]) {
            assert!((got - want).abs() < 1e-14, "{r:?}");
        }
        // Only those inside the interval; none for z² + 1 or a constant.
        assert_eq!(roots(&[4.0, 0.0, -5.0, 0.0, 1.0], 0.0, 1.5).len(), 1);
        assert!(roots(&[1.0, 0.0, 1.0, 0.0, 0.0], -9.0, 9.0).is_empty());
        assert!(roots(&[3.0, 0.0, 0.0, 0.0, 0.0], -9.0, 9.0).is_empty());
        // A vanishing leading coefficient leaves the line's root.
        assert_eq!(roots(&[-1.0, 2.0, 0.0, 0.0, 0.0], 0.0, 1.0), vec![0.5]);
    }

    proptest! {
        /// Quartics and cubics built from known distinct roots give back every root in the
        /// interval, in order, to 1e-9 of the interval's scale, and no other.
        #[test]
        fn known_roots_are_found(
            mut r in prop::collection::vec(-1.0f64..1.0, 3..=4),
            scale in 0.01f64..10.0,
        ) {
            r.sort_by(f64::total_cmp);
            prop_assume!(r.windows(2).all(|w| w[1] - w[0] > 1e-3));
            let r: Vec<f64> = r.iter().map(|x| x * scale).collect();
            let p = with_roots(&r);
            let (lo, hi) = (-0.8 * scale, 0.9 * scale);
            let want: Vec<f64> = r.iter().copied().filter(|z| (lo..=hi).contains(z)).collect();
            let got = roots(&p, lo, hi);
            prop_assert_eq!(got.len(), want.len(), "{:?} vs {:?}", got, want);
            for (g, w) in got.iter().zip(&want) {
                prop_assert!((g - w).abs() < 1e-9 * scale, "{:?} vs {:?}", got, want);
            }
        }

        /// Every root found is a root: the polynomial changes sign across it or vanishes.
        #[test]
        fn found_roots_are_sign_changes(c in prop::array::uniform5(-3.0f64..3.0)) {
            for z in roots(&c, -4.0, 4.0) {
                let h = 1e-7;
                let (a, b) = (eval(&c, z - h), eval(&c, z + h));
                prop_assert!(a * b <= 0.0 || eval(&c, z).abs() < 1e-9, "{c:?} at {z}");
            }
        }
    }
}
