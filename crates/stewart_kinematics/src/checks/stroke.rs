//! Stroke limits: which leg leaves its stroke, from when to when, and by how much.

use crate::checks::{Finding, FindingKind};
use crate::geometry::StrokeLimits;

/// One finding per leg and per limit passed.
pub fn check(stroke: &StrokeLimits, times: &[f64], lengths: &[[f64; 6]]) -> Vec<Finding> {
    let mut findings = Vec::new();
    for leg in 0..6 {
        if let Some(max) = stroke.max {
            findings.extend(scan(
                FindingKind::StrokeMax,
                leg,
                max,
                times,
                lengths,
                |l| l - max,
            ));
        }
        if let Some(min) = stroke.min {
            findings.extend(scan(
                FindingKind::StrokeMin,
                leg,
                min,
                times,
                lengths,
                |l| min - l,
            ));
        }
    }
    findings
}

/// Collect the samples where `excess(length) > 0` for one leg.
fn scan(
    kind: FindingKind,
    leg: usize,
    limit: f64,
    times: &[f64],
    lengths: &[[f64; 6]],
    excess: impl Fn(f64) -> f64,
) -> Option<Finding> {
    let mut found: Option<Finding> = None;
    for (k, l) in lengths.iter().enumerate() {
        let e = excess(l[leg]);
        if e <= 0.0 {
            continue;
        }
        let f = found.get_or_insert(Finding {
            kind,
            leg: Some(leg + 1),
            first_time: times[k],
            last_time: times[k],
            count: 0,
            worst_time: times[k],
            worst_value: l[leg],
            limit,
            excess: e,
        });
        f.last_time = times[k];
        f.count += 1;
        if e > f.excess {
            f.excess = e;
            f.worst_value = l[leg];
            f.worst_time = times[k];
        }
    }
    found
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
        let f = check(&StrokeLimits::new(0.55, 1.3), &times, &lengths);
        assert_eq!(f.len(), 2);
        assert_eq!(
            (
                f[0].kind,
                f[0].leg,
                f[0].first_time,
                f[0].last_time,
                f[0].count
            ),
            (FindingKind::StrokeMax, Some(3), 1.0, 2.0, 2)
        );
        assert_eq!((f[0].worst_time, f[0].worst_value), (2.0, 1.40));
        assert!((f[0].excess - 0.10).abs() < 1e-15);
        assert_eq!(
            (f[1].kind, f[1].leg, f[1].first_time),
            (FindingKind::StrokeMin, Some(5), 3.0)
        );
        assert!((f[1].excess - 0.05).abs() < 1e-15);
        assert!(f[0].to_string().starts_with("leg L3 is longer than its maximum 1.3000 m from t = 1.000 s to t = 2.000 s (2 samples); worst 1.4000 m at t = 2.000 s, 100.0 mm over"));
        // No limits, no findings.
        assert!(check(&StrokeLimits::default(), &times, &lengths).is_empty());
    }
}
