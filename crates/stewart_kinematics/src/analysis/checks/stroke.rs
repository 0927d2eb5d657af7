//! Stroke limits: which leg leaves its stroke, from when to when, and by how much.

use super::FindingKind;
use super::scan::{Bound, Collected, scan_legs};
use crate::model::geometry::StrokeLimits;

/// One finding per leg and per limit passed; a summary per limit set.
pub(crate) fn check(
    stroke: &StrokeLimits,
    times: &[f64],
    lengths: &[[f64; 6]],
    out: &mut Collected,
) {
    if let Some(max) = stroke.max {
        scan_legs(
            FindingKind::StrokeMax,
            "m",
            Bound::AtMost(max),
            times,
            lengths,
            out,
        );
    }
    if let Some(min) = stroke.min {
        scan_legs(
            FindingKind::StrokeMin,
            "m",
            Bound::AtLeast(min),
            times,
            lengths,
            out,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_leg_first_last_and_worst() {
        let times = [0.0, 1.0, 2.0, 3.0];
        let mut lengths = [[1.0; 6]; 4];
        lengths[1][2] = 1.35;
        lengths[2][2] = 1.40;
        lengths[3][4] = 0.5;
        let mut out = Collected::default();
        check(&StrokeLimits::new(0.55, 1.3), &times, &lengths, &mut out);
        let f = &out.findings;
        assert_eq!(f.len(), 2);
        assert_eq!(
            (
                f[0].kind,
                f[0].legs.clone(),
                f[0].first_time,
                f[0].last_time,
                f[0].count
            ),
            (FindingKind::StrokeMax, vec![3], 1.0, 2.0, 2)
        );
        assert_eq!((f[0].worst_time, f[0].worst_value), (2.0, 1.40));
        assert!((f[0].margin + 0.10).abs() < 1e-15);
        assert_eq!(
            (f[1].kind, f[1].legs.clone(), f[1].first_time),
            (FindingKind::StrokeMin, vec![5], 3.0)
        );
        assert!((f[1].margin + 0.05).abs() < 1e-15);
        // The limit it is over (its sentence, in every language, is the app's catalogues').
        assert_eq!(f[0].limit, 1.30);
        // A summary per limit, with the worst leg.
        assert_eq!(out.limits.len(), 2);
        assert_eq!(out.limits[0].legs, vec![3]);
        // No limits, nothing.
        let mut out = Collected::default();
        check(&StrokeLimits::default(), &times, &lengths, &mut out);
        assert!(out.findings.is_empty() && out.limits.is_empty());
    }
}
