//! Near-singular poses along the motion, and the architecture verdict.

use super::scan::{Bound, Collected, scan_one};
use super::{CheckSettings, Finding, FindingKind};
use crate::analysis::architecture::ArchitectureReport;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// An architecture-singular geometry gives one finding for the whole motion (every pose
/// is singular, so per-pose findings would say nothing more); otherwise the normalised
/// condition number (of the servo Jacobian for a rotary platform) is scanned against
/// `condition_max` (a singular pose counts as infinite).
pub(crate) fn check(
    geometry: &Geometry,
    architecture: &ArchitectureReport,
    times: &[f64],
    poses: &[Pose],
    settings: &CheckSettings,
    out: &mut Collected,
) {
    if architecture.singular {
        out.findings.push(Finding {
            kind: FindingKind::ArchitectureSingular,
            legs: Vec::new(),
            first_time: times.first().copied().unwrap_or(0.0),
            last_time: times.last().copied().unwrap_or(0.0),
            count: times.len(),
            worst_time: times.first().copied().unwrap_or(0.0),
            worst_value: f64::INFINITY,
            limit: settings.condition_max,
            margin: f64::NEG_INFINITY,
            unit: String::new(),
        });
        return;
    }
    // A pose a servo cannot reach has no conditioning (NaN, skipped): the reach check
    // reports it.
    let series = poses.iter().map(|p| {
        let value = geometry
            .actuated_conditioning(p)
            .map_or(f64::NAN, |c| c.condition_number.unwrap_or(f64::INFINITY));
        (value, Vec::new())
    });
    scan_one(
        FindingKind::NearSingular,
        "",
        Bound::AtMost(settings.condition_max),
        times,
        series,
        out,
    );
}
