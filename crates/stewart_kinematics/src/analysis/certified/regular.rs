//! Proving that every matrix of an interval matrix is regular: precondition by the inverse
//! `C` of its midpoint and bound `‖I − C·J‖∞` from above over the whole interval matrix;
//! below 1, every `C·J` is regular (a Neumann series converges), so every `J` is.

use nalgebra::Matrix6;

use crate::ground::interval::Interval;

/// Whether every matrix in `j` is proven regular (`false` also when the proof fails
/// without the matrix being singular: a box too wide, a midpoint too near singular).
pub fn proven_regular(j: &[[Interval; 6]; 6]) -> bool {
    let mid = Matrix6::from_fn(|r, c| j[r][c].mid());
    let Some(inverse) = mid.try_inverse() else {
        return false;
    };
    if !inverse.iter().all(|v| v.is_finite()) {
        return false;
    }
    (0..6).all(|r| {
        let mut row = Interval::point(0.0);
        for k in 0..6 {
            // (C·J)[r][k], then its distance from the identity's entry.
            let mut e = Interval::point(0.0);
            for (m, jm) in j.iter().enumerate() {
                e = e + jm[k] * inverse[(r, m)];
            }
            let d = if r == k { Interval::point(1.0) - e } else { e };
            row = row + Interval::point(d.mag());
        }
        row.hi() < 1.0
    })
}

/// The same test with every entry taken at its midpoint and rounded to nearest, as a
/// computation without intervals would make it: what outward rounding guards against.
#[cfg(test)]
pub fn naive_regular(j: &[[Interval; 6]; 6]) -> bool {
    let mid = Matrix6::from_fn(|r, c| j[r][c].mid());
    let Some(inverse) = mid.try_inverse() else {
        return false;
    };
    let product = inverse * mid;
    (0..6).all(|r| {
        (0..6)
            .map(|k| (product[(r, k)] - if r == k { 1.0 } else { 0.0 }).abs())
            .sum::<f64>()
            < 1.0
    })
}
