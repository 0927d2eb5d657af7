//! Leg speed, acceleration and jerk, by finite differences of the sampled leg lengths.
//!
//! Interior samples use central differences on the (possibly uneven) time grid; at the
//! end samples one-sided differences of the same order (see [`crate::analysis::differences`]).

use nalgebra::Vector6;

use super::FindingKind;
use super::scan::{Bound, Collected, scan_legs};
use crate::analysis::differences::{first_difference, second_difference, third_difference};
use crate::model::limits::Limits;

/// Leg speeds dL/dt (m/s) at every sample (see [`crate::analysis::differences`]).
pub fn leg_speeds(times: &[f64], lengths: &[[f64; 6]]) -> Vec<[f64; 6]> {
    per_sample(times, lengths, first_difference)
}

/// Leg accelerations d²L/dt² (m/s²) at every sample (see [`crate::analysis::differences`]).
pub fn leg_accelerations(times: &[f64], lengths: &[[f64; 6]]) -> Vec<[f64; 6]> {
    per_sample(times, lengths, second_difference)
}

/// Leg jerks d³L/dt³ (m/s³) at every sample (see [`crate::analysis::differences`]).
pub fn leg_jerks(times: &[f64], lengths: &[[f64; 6]]) -> Vec<[f64; 6]> {
    per_sample(times, lengths, third_difference)
}

/// A finite-difference rule of [`crate::analysis::differences`] on six-vectors.
pub(crate) type Difference = fn(&[f64], &[Vector6<f64>], usize) -> Option<Vector6<f64>>;

/// `difference` of the six lengths at every sample (zero where there are too few samples).
pub(crate) fn per_sample(
    times: &[f64],
    lengths: &[[f64; 6]],
    difference: Difference,
) -> Vec<[f64; 6]> {
    let values: Vec<Vector6<f64>> = lengths.iter().map(|l| Vector6::from(*l)).collect();
    (0..values.len())
        .map(|k| difference(times, &values, k).map_or([0.0; 6], Into::into))
        .collect()
}

/// Findings and summaries for the speed, acceleration and jerk limits that are set.
pub(crate) fn check(limits: &Limits, times: &[f64], lengths: &[[f64; 6]], out: &mut Collected) {
    let rules: [(Option<f64>, FindingKind, &str, Difference); 3] = [
        (
            limits.leg_speed_max,
            FindingKind::LegSpeed,
            "m/s",
            first_difference,
        ),
        (
            limits.leg_accel_max,
            FindingKind::LegAccel,
            "m/s²",
            second_difference,
        ),
        (
            limits.leg_jerk_max,
            FindingKind::LegJerk,
            "m/s³",
            third_difference,
        ),
    ];
    scan_rates(&rules, times, lengths, out);
}

/// Each rule whose limit is set: `|difference|` of the values against it, as findings of
/// its kind in its unit.
pub(crate) fn scan_rates(
    rules: &[(Option<f64>, FindingKind, &str, Difference)],
    times: &[f64],
    values: &[[f64; 6]],
    out: &mut Collected,
) {
    for &(limit, kind, unit, difference) in rules {
        if let Some(max) = limit {
            let rates: Vec<[f64; 6]> = per_sample(times, values, difference)
                .into_iter()
                .map(|r| r.map(f64::abs))
                .collect();
            scan_legs(kind, unit, Bound::AtMost(max), times, &rates, out);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differences_of_a_parabola_are_exact() {
        // L = 1 + 0.3 t + 0.5·2 t² on an uneven grid: speed 0.3 + 2t, acceleration 2.
        let times = [0.0, 0.1, 0.25, 0.3, 0.5];
        let lengths: Vec<[f64; 6]> = times.iter().map(|&t| [1.0 + 0.3 * t + t * t; 6]).collect();
        let a = leg_accelerations(&times, &lengths);
        for row in &a {
            assert!((row[0] - 2.0).abs() < 1e-12, "{row:?}");
        }
        let v = leg_speeds(&times, &lengths);
        // Central difference over an uneven pair: exact for the mean slope.
        let expected = (lengths[3][0] - lengths[1][0]) / (0.3 - 0.1);
        assert!((v[2][0] - expected).abs() < 1e-15);
    }

    #[test]
    fn limits_are_checked_only_when_set() {
        let times: Vec<f64> = (0..101).map(|k| k as f64 * 0.01).collect();
        let lengths: Vec<[f64; 6]> = times
            .iter()
            .map(|&t| [1.0 + 0.1 * (10.0 * t).sin(); 6])
            .collect();
        let mut out = Collected::default();
        check(&Limits::default(), &times, &lengths, &mut out);
        assert!(out.limits.is_empty());
        // Peak speed 1 m/s, peak acceleration 10 m/s².
        let limits = Limits {
            leg_speed_max: Some(0.8),
            leg_accel_max: Some(20.0),
            ..Limits::default()
        };
        check(&limits, &times, &lengths, &mut out);
        assert_eq!(out.limits.len(), 2);
        assert!((out.limits[0].worst_value - 1.0).abs() < 5e-3); // central differences: 0.1·sin(0.1)/0.01
        assert!((out.limits[1].worst_value - 10.0).abs() < 1e-2);
        assert!(out.limits[1].margin > 9.0);
        assert_eq!(out.findings.len(), 6); // every leg is too fast
        assert!(
            out.findings
                .iter()
                .all(|f| f.kind == FindingKind::LegSpeed && f.first_time == 0.0)
        );
    }

    #[test]
    fn a_jerk_limit_finds_the_legs_whose_acceleration_changes_too_fast() {
        // L = 1 + 0.1 sin(10 t): peak jerk 100 m/s³ (at t = 0, π/10, …).
        let times: Vec<f64> = (0..101).map(|k| k as f64 * 0.01).collect();
        let lengths: Vec<[f64; 6]> = times
            .iter()
            .map(|&t| [1.0 + 0.1 * (10.0 * t).sin(); 6])
            .collect();
        let j = leg_jerks(&times, &lengths);
        for (t, row) in times.iter().zip(&j).skip(1).take(98) {
            // Four samples k−1 … k+2 centre on t + h/2: off by about h/2 times the fourth
            // derivative (1000 m/s⁴ here), at most 5 m/s³.
            assert!(
                (row[0] + 100.0 * (10.0 * t).cos()).abs() < 6.0,
                "{t}: {}",
                row[0]
            );
        }
        let mut out = Collected::default();
        let limits = Limits {
            leg_jerk_max: Some(150.0),
            ..Limits::default()
        };
        check(&limits, &times, &lengths, &mut out);
        assert!(out.findings.is_empty());
        assert!((out.limits[0].worst_value - 100.0).abs() < 6.0);
        let mut out = Collected::default();
        let limits = Limits {
            leg_jerk_max: Some(80.0),
            ..Limits::default()
        };
        check(&limits, &times, &lengths, &mut out);
        assert_eq!(out.findings.len(), 6);
        assert!(out.findings.iter().all(|f| f.kind == FindingKind::LegJerk));
    }
}
