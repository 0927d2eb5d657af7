//! Leg-to-leg clearance: legs as cylinders of the given radius around their axes.

use super::FindingKind;
use super::scan::{Bound, Collected, scan_columns};
use crate::model::leg_solution::LegSolution;
use crate::model::limits::{LEG_PAIRS, Limits, pair_distances};

/// A finding for every pair of legs that comes closer than twice the leg radius (pairs
/// that are as close as each other are all reported); the summary gives the smallest
/// axis distance and its pair.
pub(crate) fn check(
    limits: &Limits,
    times: &[f64],
    solutions: &[LegSolution],
    out: &mut Collected,
) {
    let Some(radius) = limits.leg_radius else {
        return;
    };
    let distances: Vec<[f64; 15]> = solutions.iter().map(pair_distances).collect();
    scan_columns(
        FindingKind::LegCollision,
        "m",
        Bound::AtLeast(2.0 * radius),
        times,
        &distances,
        |pair| {
            let (i, j) = LEG_PAIRS[pair];
            vec![i + 1, j + 1]
        },
        out,
    );
}
