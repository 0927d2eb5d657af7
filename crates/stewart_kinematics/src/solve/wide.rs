//! Numbers in lanes: the arithmetic the fast trigonometry needs, for one `f64` or for
//! [`Wide`] arrays of them computed step by step over every lane.
//!
//! A formula written once over [`Real`] is the scalar path for `f64` and the batch's path
//! for `Wide<N>`, with the same operations in the same order, so the same bits. For
//! `Wide<N>` each operation is one short loop over all `N` lanes, which the compiler turns
//! into `N / 4` (AVX2) or `N / 8` (AVX-512) independent vector instructions: a polynomial
//! of 24 lanes advances six registers a step, where eight lanes computed one after the
//! other would wait on each step's latency (measured on AMD Zen 3, where that wait was most
//! of the batch's time).

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A number, or lanes of numbers, with the operations the fast trigonometry uses.
pub(crate) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// A yes or no per lane.
    type Mask: Copy;
    /// The same value in every lane.
    fn splat(value: f64) -> Self;
    /// Rounded to the nearest integer, halves away from zero ([`f64::round`]).
    fn round(self) -> Self;
    /// The magnitude.
    fn abs(self) -> Self;
    /// Where `self > other`.
    fn greater(self, other: Self) -> Self::Mask;
    /// Where the sign bit is set ([`f64::is_sign_negative`]).
    fn sign_negative(self) -> Self::Mask;
    /// `yes` where `mask` holds, else `no`.
    fn select(mask: Self::Mask, yes: Self, no: Self) -> Self;
}

impl Real for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(value: f64) -> Self {
        value
    }
    #[inline(always)]
    fn round(self) -> Self {
        f64::round(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn greater(self, other: Self) -> bool {
        self > other
    }
    #[inline(always)]
    fn sign_negative(self) -> bool {
        self.is_sign_negative()
    }
    #[inline(always)]
    fn select(mask: bool, yes: Self, no: Self) -> Self {
        if mask { yes } else { no }
    }
}

/// `N` numbers, each operation applied lane by lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Wide<const N: usize>(pub [f64; N]);

impl<const N: usize> Wide<N> {
    /// The lanes `f(0)`, `f(1)`, …
    ///
    /// A plain loop rather than [`std::array::from_fn`], whose machinery is not always
    /// inlined: code that is not inlined into the caller compiled for AVX2 or AVX-512 runs
    /// without them.
    #[inline(always)]
    pub fn from_fn(f: impl Fn(usize) -> f64) -> Self {
        let mut lanes = [0.0; N];
        for (l, lane) in lanes.iter_mut().enumerate() {
            *lane = f(l);
        }
        Self(lanes)
    }

    /// `f` of each lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Self::from_fn(|l| f(self.0[l]))
    }

    /// `f` of each pair of lanes.
    #[inline(always)]
    pub fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Self::from_fn(|l| f(self.0[l], other.0[l]))
    }
}

/// Whether every value is within `limit` in magnitude (NaN is not), with no early exit so
/// that it stays a few vector comparisons.
#[inline(always)]
pub(crate) fn all_within(values: &[f64], limit: f64) -> bool {
    values.iter().fold(true, |ok, x| ok & (x.abs() <= limit))
}

/// Lane-by-lane operators for [`Wide`].
macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const N: usize> $trait for Wide<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                self.zip(other, |a, b| a $op b)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<const N: usize> Neg for Wide<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}

impl<const N: usize> Real for Wide<N> {
    type Mask = [bool; N];
    #[inline(always)]
    fn splat(value: f64) -> Self {
        Self([value; N])
    }
    #[inline(always)]
    fn round(self) -> Self {
        self.map(f64::round)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        self.map(f64::abs)
    }
    #[inline(always)]
    fn greater(self, other: Self) -> [bool; N] {
        let mut mask = [false; N];
        for (l, m) in mask.iter_mut().enumerate() {
            *m = self.0[l] > other.0[l];
        }
        mask
    }
    #[inline(always)]
    fn sign_negative(self) -> [bool; N] {
        let mut mask = [false; N];
        for (l, m) in mask.iter_mut().enumerate() {
            *m = self.0[l].is_sign_negative();
        }
        mask
    }
    #[inline(always)]
    fn select(mask: [bool; N], yes: Self, no: Self) -> Self {
        Self::from_fn(|l| if mask[l] { yes.0[l] } else { no.0[l] })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_operation_is_the_scalar_one_lane_by_lane() {
        let a = Wide([1.5, -2.5, 0.1, 7.0]);
        let b = Wide([0.3, 4.0, -0.2, 3.0]);
        for l in 0..4 {
            let (x, y) = (a.0[l], b.0[l]);
            assert_eq!((a + b).0[l], x + y);
            assert_eq!((a - b).0[l], x - y);
            assert_eq!((a * b).0[l], x * y);
            assert_eq!((a / b).0[l], x / y);
            assert_eq!(Real::round(a).0[l], x.round());
            assert_eq!(Real::abs(a).0[l], x.abs());
            assert_eq!((-a).0[l].to_bits(), (-x).to_bits());
            assert_eq!(a.greater(b)[l], x > y);
            assert_eq!(Wide::select(a.greater(b), a, b).0[l], x.max(y));
        }
        // Halves round away from zero, as `f64::round`.
        assert_eq!(Real::round(a).0[..2], [2.0, -3.0]);
        assert_eq!(<Wide<3> as Real>::splat(2.0), Wide([2.0; 3]));
        assert_eq!(Wide([-0.0, 0.0, -1.0]).sign_negative(), [true, false, true]);
    }

    #[test]
    fn all_within_is_false_for_any_lane_outside_or_not_a_number() {
        assert!(all_within(&[1.0, -2.0, 2.0], 2.0));
        assert!(!all_within(&[1.0, -2.5, 0.0], 2.0));
        assert!(!all_within(&[1.0, f64::NAN, 0.0], 2.0));
        assert!(!all_within(&[f64::INFINITY], f64::MAX));
    }
}
