//! Joint cone angles: how far each leg leans from the base normal at its base joint and
//! from the platform normal at its platform joint.

use super::FindingKind;
use super::scan::{Bound, Collected, scan_legs};
use crate::model::leg_solution::LegSolution;
use crate::model::limits::{Limits, joint_angles};
use crate::model::pose::Pose;

/// Findings and summaries for the cone limits that are set (angles in degrees).
pub(crate) fn check(
    limits: &Limits,
    times: &[f64],
    poses: &[Pose],
    solutions: &[LegSolution],
    out: &mut Collected,
) {
    if limits.base_cone.is_none() && limits.platform_cone.is_none() {
        return;
    }
    let angles: Vec<[[f64; 2]; 6]> = poses
        .iter()
        .zip(solutions)
        .map(|(p, s)| joint_angles(p, s))
        .collect();
    let at = |k: usize| -> Vec<[f64; 6]> {
        angles
            .iter()
            .map(|a| a.map(|leg| leg[k].to_degrees()))
            .collect()
    };
    if let Some(max) = limits.base_cone {
        scan_legs(
            FindingKind::BaseCone,
            "deg",
            Bound::AtMost(max.degrees()),
            times,
            &at(0),
            out,
        );
    }
    if let Some(max) = limits.platform_cone {
        scan_legs(
            FindingKind::PlatformCone,
            "deg",
            Bound::AtMost(max.degrees()),
            times,
            &at(1),
            out,
        );
    }
}
