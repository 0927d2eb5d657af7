//! A branch-light `sin_cos` for the batch inverse-kinematics hot loop.
//!
//! The C library computes `sin` and `cos` with two calls, each with its own argument
//! reduction and branches; that alone would eat most of the batch budget. This computes
//! both from one reduction with straight-line code that the compiler can inline and
//! schedule. Method (fdlibm's, re-derived here):
//!
//! 1. Reduce: `j = round(x · 2/π)`, `y = x − j·π/2`, with π/2 split in three parts
//!    (Cody–Waite) so that the subtraction is exact for `|j| < 2²⁰`.
//! 2. On `|y| ≤ π/4`, evaluate the minimax polynomials (coefficients are fdlibm's,
//!    written here as the shortest decimals of the same doubles) of fdlibm's `__kernel_sin` and
//!    `__kernel_cos` (degree 13 and 14, error below one unit in the last place).
//! 3. Swap and negate by the quadrant `j mod 4`.
//!
//! Arguments beyond [`REDUCTION_LIMIT`] (or not finite) go to the standard library.
//! A test compares it with the standard library over a wide range.

use std::f64::consts::FRAC_2_PI;

use crate::solve::wide::Real;

/// Beyond this magnitude (radians) the three-part reduction loses exactness.
pub const REDUCTION_LIMIT: f64 = 100000.0;

// π/2 in three parts: the first two have 33 significant bits, so j·PIO2_1 and
// j·PIO2_2 are exact for |j| < 2^20.
const PIO2_1: f64 = 1.5707963267341256;
const PIO2_2: f64 = 6.077100506303966e-11;
const PIO2_3: f64 = 2.0222662487959506e-21;

// Minimax coefficients of sin(y) − y = y³·S(y²) on [−π/4, π/4].
const S1: f64 = -0.16666666666666632;
const S2: f64 = 0.00833333333332249;
const S3: f64 = -0.0001984126982985795;
const S4: f64 = 2.7557313707070068e-06;
const S5: f64 = -2.5050760253406863e-08;
const S6: f64 = 1.58969099521155e-10;

// Minimax coefficients of cos(y) − 1 + y²/2 = y⁴·C(y²) on [−π/4, π/4].
const C1: f64 = 0.0416666666666666;
const C2: f64 = -0.001388888888887411;
const C3: f64 = 2.480158728947673e-05;
const C4: f64 = -2.7557314351390663e-07;
const C5: f64 = 2.087572321298175e-09;
const C6: f64 = -1.1359647557788195e-11;

/// `(sin x, cos x)` for a finite `x`, accurate to about one unit in the last place.
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    // Also taken by NaN, for which the comparison is false.
    if x.abs() > REDUCTION_LIMIT || x.is_nan() {
        return x.sin_cos();
    }
    let (s, c, j) = kernel(x * FRAC_2_PI, x);
    match quadrant(j) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// Steps 1 and 2 for `x` within [`REDUCTION_LIMIT`] (and `scaled = x · 2/π`), for one
/// number or for lanes of them ([`Real`]): the sine and cosine of the reduced argument and
/// `j`, the integer whose low two bits are the quadrant (step 3 is the caller's, with
/// [`quadrant`]), with no branch.
#[inline(always)]
pub(crate) fn kernel<T: Real>(scaled: T, x: T) -> (T, T, T) {
    let c = T::splat;
    let j = scaled.round();
    let y = ((x - j * c(PIO2_1)) - j * c(PIO2_2)) - j * c(PIO2_3);
    let z = y * y;
    let s = y + y * z * (c(S1) + z * (c(S2) + z * (c(S3) + z * (c(S4) + z * (c(S5) + z * c(S6))))));
    let r = z * z * (c(C1) + z * (c(C2) + z * (c(C3) + z * (c(C4) + z * (c(C5) + z * c(C6))))));
    let hz = c(0.5) * z;
    let w = c(1.0) - hz;
    let cos = w + (((c(1.0) - w) - hz) + r);
    (s, cos, j)
}

/// `1.5 · 2⁵²`: an integer `j` with `|j| < 2⁵¹` added to it is exact, and the sum's low
/// mantissa bits are `j` in two's complement.
const INTEGER_BITS: f64 = 6_755_399_441_055_744.0;

/// The quadrant of [`kernel`]'s `j` (`|j|` ≤ 2/π · [`REDUCTION_LIMIT`]) in the low two
/// bits, read from the bits of a float sum rather than converted (`as i64`), which AVX2
/// has no vector instruction for: converted, it took the batch's lanes back to scalar code.
#[inline(always)]
pub(crate) fn quadrant(j: f64) -> u64 {
    (j + INTEGER_BITS).to_bits()
}

// The low parts of π/4 and π/2 (π/4 = FRAC_PI_4 + PI_4_LO), and fdlibm's minimax
// coefficients of (atan(x) − x)/x³ on [−7/16, 7/16].
const PI_4_LO: f64 = 3.061_616_997_868_383e-17;
const PI_2_LO: f64 = 6.123_233_995_736_766e-17;
const AT: [f64; 11] = [
    3.333_333_333_333_293e-1,
    -1.999_999_999_987_648_3e-1,
    1.428_571_427_250_346_6e-1,
    -1.111_111_040_546_235_6e-1,
    9.090_887_133_436_507e-2,
    -7.691_876_205_044_83e-2,
    6.661_073_137_387_531e-2,
    -5.833_570_133_790_573e-2,
    4.976_877_994_615_932e-2,
    -3.653_157_274_421_691_5e-2,
    1.628_582_011_536_578_2e-2,
];
/// π's low part: π = `PI` + `PI_LO`.
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// `atan(t)` on |t| ≤ 7/16 with a low part added at the base angle `hi + lo`:
/// `hi + lo + atan(t)`, fdlibm's polynomial and its way of adding the parts.
#[inline(always)]
fn atan_reduced<T: Real>(t: T, hi: T, lo: T) -> T {
    let c = |k: usize| T::splat(AT[k]);
    let z = t * t;
    let w = z * z;
    let s1 = z * (c(0) + w * (c(2) + w * (c(4) + w * (c(6) + w * (c(8) + w * c(10))))));
    let s2 = w * (c(1) + w * (c(3) + w * (c(5) + w * (c(7) + w * c(9)))));
    hi - ((t * (s1 + s2) - lo) - t)
}

/// `atan2(y, x)` for finite `y`, `x` not both zero, in (−π, π], to about one unit in
/// the last place: the batch servo-angle loop's one transcendental. Branch-light (the
/// choices compile to selects): the ratio `a = min/max` of `|y|`, `|x|` lies in [0, 1];
/// above tan(π/8) it is reduced by `(a − 1)/(a + 1)` around π/4, so fdlibm's `atan`
/// polynomial (valid on |t| ≤ 7/16) covers it; then octant and quadrant symmetries.
#[inline(always)]
pub fn atan2(y: f64, x: f64) -> f64 {
    if !(y.is_finite() && x.is_finite()) || (y == 0.0 && x == 0.0) {
        return y.atan2(x);
    }
    atan2_finite(y, x)
}

/// [`atan2`] of finite `y`, `x`, not both zero, with no branch (selects only), for one
/// number or for lanes of them ([`Real`]). Each division's operands are chosen first, so
/// that there are two divisions whichever way a lane goes (`a / 1` is `a` exactly). (One
/// division, `(near − far)/(near + far)`, was measured 3 ns a servo pose faster on Zen 3,
/// but it is up to three units in the last place from this form's results, which issue
/// #60 keeps; fused multiply–adds in the polynomial were left for the same reason.)
#[inline(always)]
pub(crate) fn atan2_finite<T: Real>(y: T, x: T) -> T {
    let k = T::splat;
    let (ay, ax) = (y.abs(), x.abs());
    let steep = ay.greater(ax);
    let a = T::select(steep, ax, ay) / T::select(steep, ay, ax);
    let big = a.greater(k(std::f64::consts::SQRT_2 - 1.0));
    let t = T::select(big, a - k(1.0), a) / T::select(big, a + k(1.0), k(1.0));
    let hi = T::select(big, k(std::f64::consts::FRAC_PI_4), k(0.0));
    let lo = T::select(big, k(PI_4_LO), k(0.0));
    let r = atan_reduced(t, hi, lo);
    // Past 45°: π/2 − r, with π/2's low part.
    let r = T::select(steep, (k(std::f64::consts::FRAC_PI_2) - r) + k(PI_2_LO), r);
    let r = T::select(
        k(0.0).greater(x),
        k(std::f64::consts::PI) - (r - k(PI_LO)),
        r,
    );
    T::select(y.sign_negative(), -r, r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_the_standard_library() {
        let mut worst: f64 = 0.0;
        let mut x = -2.0e4;
        // Irregular stride so that many quadrants and reduced arguments are hit.
        while x < 2.0e4 {
            let (s, c) = sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
            x += 0.137_931_034_482_758_6;
        }
        assert!(worst < 3e-16, "worst difference {worst:e}");
    }

    #[test]
    fn atan2_agrees_with_the_standard_library() {
        let mut worst: f64 = 0.0;
        let mut k = 0u64;
        // A deterministic spread of angles and magnitudes over all four quadrants.
        for i in 0..200_000 {
            k = k
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let angle = (k >> 11) as f64 / (1u64 << 53) as f64 * std::f64::consts::TAU
                - std::f64::consts::PI;
            let r = 10f64.powi((i % 13) - 6);
            let (y, x) = (r * angle.sin(), r * angle.cos());
            let d = (atan2(y, x) - y.atan2(x)).abs();
            worst = worst.max(d / y.atan2(x).abs().max(1e-300) * y.atan2(x).abs().max(1.0));
        }
        for (y, x) in [
            (0.0, 1.0),
            (1.0, 0.0),
            (0.0, -1.0),
            (-1.0, 0.0),
            (1.0, 1.0),
            (-1e-300, -1.0),
        ] {
            assert_eq!(atan2(y, x), y.atan2(x), "({y}, {x})");
        }
        assert!(worst < 5e-16, "worst difference {worst:e}");
    }

    #[test]
    fn exact_at_special_points_and_sensible_far_out() {
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        let (s, c) = sin_cos(std::f64::consts::FRAC_PI_2);
        assert!((s - 1.0).abs() < 1e-16 && c.abs() < 1e-16);
        let far = 3.0e7;
        assert_eq!(sin_cos(far), far.sin_cos());
        assert!(sin_cos(f64::NAN).0.is_nan());
    }
}
