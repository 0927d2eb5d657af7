//! Leg-to-leg clearance: legs as cylinders of the given radius around their axes.

use super::FindingKind;
use super::scan::{Bound, Collected, scan_one};
use crate::inverse::LegSolution;
use crate::limits::{Limits, closest_legs};

/// A finding when two legs come closer than twice the leg radius; the summary gives the
/// smallest axis distance and the pair.
pub(crate) fn check(
    limits: &Limits,
    times: &[f64],
    solutions: &[LegSolution],
    out: &mut Collected,
) {
    let Some(radius) = limits.leg_radius else {
        return;
    };
    let series = solutions.iter().map(|s| {
        let c = closest_legs(s);
        (c.distance, vec![c.legs.0, c.legs.1])
    });
    scan_one(
        FindingKind::LegCollision,
        "m",
        Bound::AtLeast(2.0 * radius),
        times,
        series,
        out,
    );
}
