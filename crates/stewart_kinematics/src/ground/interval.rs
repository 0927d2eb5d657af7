//! Interval arithmetic on `f64` with outward rounding: every operation's result contains
//! every real result of the operation on points of its operands, so that a bound computed
//! over a box of poses holds for every pose in it — what certified analysis stands on.
//!
//! Each bound is rounded away from the inside by one step ([`f64::next_down`] below,
//! [`f64::next_up`] above) after the nearest-rounded operation, which covers its error of
//! at most half a step. The sine, cosine, arcsine and arctangent of the platform's library
//! are not correctly rounded; their bounds are widened by four steps (their error is below
//! one) and kept within their ranges.

use std::f64::consts::{FRAC_PI_2, TAU};
use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` of reals, `lo ≤ hi`, both finite or infinite (never NaN).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

/// One step below `x` (itself when it is −∞).
fn down(x: f64) -> f64 {
    x.next_down()
}

/// One step above `x` (itself when it is +∞).
fn up(x: f64) -> f64 {
    x.next_up()
}

impl Interval {
    /// `[lo, hi]`; `None` when either is NaN or `lo > hi`.
    pub fn new(lo: f64, hi: f64) -> Option<Self> {
        (lo <= hi).then_some(Self { lo, hi })
    }

    /// The single point `x` (NaN: the whole line, which contains any value it stood for).
    pub fn point(x: f64) -> Self {
        if x.is_nan() {
            Self::ENTIRE
        } else {
            Self { lo: x, hi: x }
        }
    }

    /// The whole real line.
    pub const ENTIRE: Self = Self {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// `[mid − r, mid + r]` for `r ≥ 0`, rounded outward.
    pub fn around(mid: f64, r: f64) -> Self {
        Self::point(mid) + Self::new(-r.abs(), r.abs()).unwrap_or(Self::ENTIRE)
    }

    /// The lower bound.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The upper bound.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The midpoint (a finite value inside for a bounded interval).
    pub fn mid(&self) -> f64 {
        let m = 0.5 * self.lo + 0.5 * self.hi;
        m.clamp(self.lo, self.hi)
    }

    /// `hi − lo`, rounded up (0 for a point).
    pub fn width(&self) -> f64 {
        let w = self.hi - self.lo;
        if w == 0.0 { 0.0 } else { up(w) }
    }

    /// `hi − lo`, rounded down: at most the real width.
    pub fn width_below(&self) -> f64 {
        let w = self.hi - self.lo;
        if w == 0.0 { 0.0 } else { down(w).max(0.0) }
    }

    /// The largest absolute value of a point inside.
    pub fn mag(&self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The smallest absolute value of a point inside (0 when it contains 0).
    pub fn mig(&self) -> f64 {
        if self.contains(0.0) {
            0.0
        } else {
            self.lo.abs().min(self.hi.abs())
        }
    }

    /// Whether `x` lies inside.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether every point of `self` lies in `other`.
    pub fn within(&self, other: &Self) -> bool {
        other.lo <= self.lo && self.hi <= other.hi
    }

    /// The two halves at the midpoint.
    pub fn split(&self) -> [Self; 2] {
        let m = self.mid();
        [Self { lo: self.lo, hi: m }, Self { lo: m, hi: self.hi }]
    }

    /// The smallest interval holding both.
    pub fn hull(&self, other: &Self) -> Self {
        Self {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// `self²`: not below 0, tighter than `self · self` when it contains 0.
    pub fn sqr(&self) -> Self {
        let (a, b) = (self.lo * self.lo, self.hi * self.hi);
        if self.contains(0.0) {
            Self {
                lo: 0.0,
                hi: up(a.max(b)),
            }
        } else {
            Self {
                lo: down(a.min(b)).max(0.0),
                hi: up(a.max(b)),
            }
        }
    }

    /// `√self` over its non-negative part; `None` when it is all negative.
    pub fn sqrt(&self) -> Option<Self> {
        (self.hi >= 0.0).then(|| Self {
            lo: down(self.lo.max(0.0).sqrt()).max(0.0),
            hi: up(self.hi.sqrt()),
        })
    }

    /// `self / other`; `None` when `other` contains 0.
    pub fn div(&self, other: &Self) -> Option<Self> {
        if other.contains(0.0) {
            return None;
        }
        let q = [
            self.lo / other.lo,
            self.lo / other.hi,
            self.hi / other.lo,
            self.hi / other.hi,
        ];
        Some(hull_of(q))
    }

    /// The sine over the interval.
    pub fn sin(&self) -> Self {
        self.cos_shifted(-FRAC_PI_2)
    }

    /// The cosine over the interval.
    pub fn cos(&self) -> Self {
        self.cos_shifted(0.0)
    }

    /// `cos(x + shift)` over the interval (`sin x = cos(x − π/2)`): the values at the
    /// ends, and ±1 where a maximum (`x + shift = 2kπ`) or a minimum (`= π + 2kπ`) may lie
    /// inside — decided with a margin, so that a rounding error only ever widens.
    fn cos_shifted(&self, shift: f64) -> Self {
        // Beyond a million radians the shift's rounding could outgrow the margin below:
        // the whole range, which holds whatever lies inside.
        let far = self.lo.abs().max(self.hi.abs()) > 1e6;
        if far || !(self.lo.is_finite() && self.hi.is_finite()) || self.hi - self.lo >= TAU {
            return Self { lo: -1.0, hi: 1.0 };
        }
        let at = |x: f64| if shift == 0.0 { x.cos() } else { x.sin() };
        let (a, b) = (at(self.lo), at(self.hi));
        let mut lo = a.min(b);
        let mut hi = a.max(b);
        // Turns from the shifted start, with a margin for the shift's own rounding.
        let margin = 1e-9;
        let start = (self.lo + shift) / TAU;
        let end = (self.hi + shift) / TAU;
        if (start - margin).ceil() <= end + margin {
            hi = 1.0;
        }
        if (start - 0.5 - margin).ceil() <= end - 0.5 + margin {
            lo = -1.0;
        }
        // Four steps for the library's sine and cosine (their error is below one).
        let (lo, hi) = widened(lo, hi);
        Self {
            lo: lo.max(-1.0),
            hi: hi.min(1.0),
        }
    }

    /// The arcsine over the part of the interval within [−1, 1] (`None` when no part is).
    pub fn asin(&self) -> Option<Self> {
        let (lo, hi) = (self.lo.max(-1.0), self.hi.min(1.0));
        if lo > hi {
            return None;
        }
        // Increasing: the ends' values, widened, within [−π/2, π/2] enclosed.
        let (a, b) = widened(lo.asin(), hi.asin());
        let half = up(FRAC_PI_2);
        Some(Self {
            lo: a.max(-half),
            hi: b.min(half),
        })
    }

    /// The arctangent over the interval (increasing, within ±π/2).
    pub fn atan(&self) -> Self {
        let (a, b) = widened(self.lo.atan(), self.hi.atan());
        let half = up(FRAC_PI_2);
        Self {
            lo: a.max(-half),
            hi: b.min(half),
        }
    }
}

/// Four steps below `x`, and above `y`: a bound of the library's sine, cosine, arcsine or
/// arctangent (each within a step of the real value) made safe.
fn widened(x: f64, y: f64) -> (f64, f64) {
    let four = |v: f64, f: fn(f64) -> f64| f(f(f(f(v))));
    (four(x, down), four(y, up))
}

/// The smallest interval holding four values rounded to nearest, widened a step each way.
fn hull_of(v: [f64; 4]) -> Interval {
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if lo.is_nan() || hi.is_nan() {
        return Interval::ENTIRE;
    }
    Interval {
        lo: down(lo),
        hi: up(hi),
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, other: Interval) -> Interval {
        let (lo, hi) = (self.lo + other.lo, self.hi + other.hi);
        if lo.is_nan() || hi.is_nan() {
            return Interval::ENTIRE;
        }
        Interval {
            lo: down(lo),
            hi: up(hi),
        }
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, other: Interval) -> Interval {
        self + (-other)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, other: Interval) -> Interval {
        // 0 · ∞ is taken as 0: a bounded factor of 0 keeps the product 0.
        let p = |a: f64, b: f64| if a == 0.0 || b == 0.0 { 0.0 } else { a * b };
        hull_of([
            p(self.lo, other.lo),
            p(self.lo, other.hi),
            p(self.hi, other.lo),
            p(self.hi, other.hi),
        ])
    }
}

impl Mul<f64> for Interval {
    type Output = Interval;
    fn mul(self, k: f64) -> Interval {
        self * Interval::point(k)
    }
}

impl Add<f64> for Interval {
    type Output = Interval;
    fn add(self, k: f64) -> Interval {
        self + Interval::point(k)
    }
}

/// π as an interval holding the real π.
pub const PI_INTERVAL: Interval = Interval {
    lo: std::f64::consts::PI,
    hi: 3.141_592_653_589_793_6,
};

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    /// An interval from two values and a point inside it chosen by `t` in [0, 1].
    fn interval_and_point(a: f64, b: f64, t: f64) -> (Interval, f64) {
        let (lo, hi) = (a.min(b), a.max(b));
        let x = (lo + (hi - lo) * t).clamp(lo, hi);
        (Interval::new(lo, hi).expect("ordered"), x)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn every_operation_holds_the_results_of_its_points(
            a in -1e3f64..1e3, b in -1e3f64..1e3, c in -1e3f64..1e3, d in -1e3f64..1e3,
            s in 0f64..=1.0, t in 0f64..=1.0,
        ) {
            let (x, p) = interval_and_point(a, b, s);
            let (y, q) = interval_and_point(c, d, t);
            prop_assert!((x + y).contains(p + q));
            prop_assert!((x - y).contains(p - q));
            prop_assert!((x * y).contains(p * q));
            prop_assert!((-x).contains(-p));
            prop_assert!(x.sqr().contains(p * p));
            if let Some(r) = x.sqrt()
                && p >= 0.0
            {
                prop_assert!(r.contains(p.sqrt()));
            }
            match x.div(&y) {
                Some(r) => prop_assert!(r.contains(p / q)),
                None => prop_assert!(y.contains(0.0)),
            }
            prop_assert!(x.sin().contains(p.sin()), "sin {x:?} {p}");
            prop_assert!(x.cos().contains(p.cos()), "cos {x:?} {p}");
        }

        #[test]
        fn narrow_sines_and_cosines_hold_their_points(
            a in -20f64..20.0, w in 0f64..0.5, t in 0f64..=1.0,
        ) {
            let (x, p) = interval_and_point(a, a + w, t);
            prop_assert!(x.sin().contains(p.sin()), "sin {x:?} {p}");
            prop_assert!(x.cos().contains(p.cos()), "cos {x:?} {p}");
            prop_assert!(x.sin().width() <= w + 1e-12 && x.cos().width() <= w + 1e-12);
        }

        #[test]
        fn arcsines_and_arctangents_hold_their_points(
            a in -1.2f64..1.2, b in -1.2f64..1.2, t in 0f64..=1.0, big in -1e12f64..1e12,
        ) {
            let (x, p) = interval_and_point(a, b, t);
            match x.asin() {
                Some(y) if (-1.0..=1.0).contains(&p) => prop_assert!(y.contains(p.asin()), "asin {x:?} {p}"),
                Some(_) => {}
                None => prop_assert!(!(-1.0..=1.0).contains(&p), "asin {x:?} refused {p}"),
            }
            prop_assert!(x.atan().contains(p.atan()), "atan {x:?} {p}");
            let (x, p) = interval_and_point(big, big * 1.001, t);
            prop_assert!(x.atan().contains(p.atan()), "atan {x:?} {p}");
        }

        #[test]
        fn far_angles_hold_their_points_too(a in -1e10f64..1e10, w in 0f64..2.0, t in 0f64..=1.0) {
            let (x, p) = interval_and_point(a, a + w, t);
            prop_assert!(x.sin().contains(p.sin()), "sin {x:?} {p}");
            prop_assert!(x.cos().contains(p.cos()), "cos {x:?} {p}");
        }
    }

    #[test]
    fn sines_and_cosines_reach_their_extremes_inside() {
        let i = |a: f64, b: f64| Interval::new(a, b).expect("ordered");
        // The cosine's maximum at 0, its minimum at π; the sine's at ±π/2.
        assert_eq!(i(-0.1, 0.1).cos().hi(), 1.0);
        assert_eq!(i(3.0, 3.3).cos().lo(), -1.0);
        assert_eq!(i(1.5, 1.6).sin().hi(), 1.0);
        assert_eq!(i(-1.6, -1.5).sin().lo(), -1.0);
        assert!(i(0.2, 0.3).cos().hi() < 0.99);
        assert!(i(7.0, 7.5).sin().lo() > 0.6, "{:?}", i(7.0, 7.5).sin());
        assert_eq!(i(0.0, 7.0).sin(), i(-1.0, 1.0));
        // A real peak the shifted turn count would round past (found by review).
        let far = i(4_374_695_819.833_795, 4_374_695_820.833_795).sin();
        assert_eq!(far.hi(), 1.0);
        assert_eq!(Interval::point(2.5).width(), 0.0);
    }

    #[test]
    fn bounds_are_rounded_outward() {
        // 0.1 + 0.2 is not 0.3 in f64: the interval holds the real sum 0.3 exactly.
        let s = Interval::point(0.1) + Interval::point(0.2);
        assert!(s.lo() < 0.1 + 0.2 && 0.1 + 0.2 < s.hi());
        assert!(PI_INTERVAL.contains(PI));
        assert!(PI_INTERVAL.lo() < PI_INTERVAL.hi());
        // √2 squared straddles 2.
        let r = Interval::point(2.0).sqrt().expect("non-negative");
        let back = r.sqr();
        assert!(back.lo() < 2.0 && 2.0 < back.hi(), "{back:?}");
    }
}
