//! The shared scan of a per-sample quantity against a limit.

use super::{Finding, FindingKind, LimitSummary};

/// Findings and limit summaries gathered by the checks.
#[derive(Default)]
pub(crate) struct Collected {
    pub findings: Vec<Finding>,
    pub limits: Vec<LimitSummary>,
}

/// Which side of the limit is allowed.
#[derive(Clone, Copy)]
pub(crate) enum Bound {
    /// Values must not exceed the limit.
    AtMost(f64),
    /// Values must not fall below the limit.
    AtLeast(f64),
}

impl Bound {
    fn limit(self) -> f64 {
        match self {
            Bound::AtMost(l) | Bound::AtLeast(l) => l,
        }
    }

    /// How far inside the bound `v` is (negative outside).
    fn margin(self, v: f64) -> f64 {
        match self {
            Bound::AtMost(l) => l - v,
            Bound::AtLeast(l) => v - l,
        }
    }
}

/// Scan one series (`values[k]` at `times[k]`, attributed to `legs[k]`): a finding for the
/// samples outside the bound, and the summary of the worst sample.
pub(crate) fn scan(
    kind: FindingKind,
    unit: &str,
    bound: Bound,
    times: &[f64],
    values: impl Iterator<Item = (f64, Vec<usize>)>,
) -> (Option<Finding>, Option<LimitSummary>) {
    let mut summary: Option<LimitSummary> = None;
    let mut finding: Option<Finding> = None;
    for (k, (v, legs)) in values.enumerate() {
        // A missing value (a pose a servo cannot reach) is reported by its own check.
        if v.is_nan() {
            continue;
        }
        let margin = bound.margin(v);
        if summary.as_ref().is_none_or(|s| margin < s.margin) {
            summary = Some(LimitSummary {
                kind,
                legs: legs.clone(),
                worst_value: v,
                worst_time: times[k],
                limit: bound.limit(),
                margin,
                unit: unit.to_owned(),
            });
        }
        if margin >= 0.0 {
            continue;
        }
        let f = finding.get_or_insert_with(|| Finding {
            kind,
            legs: legs.clone(),
            first_time: times[k],
            last_time: times[k],
            count: 0,
            worst_time: times[k],
            worst_value: v,
            limit: bound.limit(),
            margin,
            unit: unit.to_owned(),
        });
        f.last_time = times[k];
        f.count += 1;
        if margin < f.margin {
            f.margin = margin;
            f.worst_value = v;
            f.worst_time = times[k];
            f.legs = legs;
        }
    }
    (finding, summary)
}

/// Scan six per-leg series: one finding per leg outside the bound, one summary overall.
pub(crate) fn scan_legs(
    kind: FindingKind,
    unit: &str,
    bound: Bound,
    times: &[f64],
    values: &[[f64; 6]],
    out: &mut Collected,
) {
    scan_columns(kind, unit, bound, times, values, |leg| vec![leg + 1], out);
}

/// Scan `N` series stored column-wise (`values[k][c]` is series `c` at sample `k`,
/// attributed to the legs `legs_of(c)`): one finding per series outside the bound, one
/// summary of the worst sample overall.
pub(crate) fn scan_columns<const N: usize>(
    kind: FindingKind,
    unit: &str,
    bound: Bound,
    times: &[f64],
    values: &[[f64; N]],
    legs_of: impl Fn(usize) -> Vec<usize>,
    out: &mut Collected,
) {
    let mut overall: Option<LimitSummary> = None;
    for c in 0..N {
        let legs = legs_of(c);
        let series = values.iter().map(|v| (v[c], legs.clone()));
        let (finding, summary) = scan(kind, unit, bound, times, series);
        out.findings.extend(finding);
        if let Some(s) = summary
            && overall.as_ref().is_none_or(|o| s.margin < o.margin)
        {
            overall = Some(s);
        }
    }
    out.limits.extend(overall);
}

/// Scan one whole-platform series.
pub(crate) fn scan_one(
    kind: FindingKind,
    unit: &str,
    bound: Bound,
    times: &[f64],
    values: impl Iterator<Item = (f64, Vec<usize>)>,
    out: &mut Collected,
) {
    let (finding, summary) = scan(kind, unit, bound, times, values);
    out.findings.extend(finding);
    out.limits.extend(summary);
}
