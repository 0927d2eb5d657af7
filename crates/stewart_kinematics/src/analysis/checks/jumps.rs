//! Discontinuities in leg length between consecutive samples.
//!
//! A smooth motion sampled finely changes each leg by about the same amount from one
//! step to the next. A step is a jump when it is more than `jump_ratio` times the
//! median of the (up to eight) steps around it and more than `jump_floor`. The median
//! keeps a one-sample spike (a jump up and straight back down) from hiding itself.

use crate::analysis::checks::{CheckSettings, Finding, FindingKind};

/// Steps on each side compared with a step.
const NEIGHBOURS: usize = 4;

/// On an uneven grid, each interval's factor to the median interval (`None`: the intervals
/// are equal, as a sampled motion's are, to rounding).
fn interval_scales(times: &[f64]) -> Option<Vec<f64>> {
    let intervals: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    let (lo, hi) = intervals
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), &h| {
            (lo.min(h), hi.max(h))
        });
    if lo.is_nan() || lo <= 0.0 || hi <= lo * (1.0 + 1e-6) {
        return None;
    }
    let typical = typical_interval(times)?;
    Some(intervals.iter().map(|h| typical / h).collect())
}

/// The interval at which [`jumps_in`] judges every step: the median of `times`' intervals
/// (`None` for fewer than two times).
pub(crate) fn typical_interval(times: &[f64]) -> Option<f64> {
    let mut sorted: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    sorted.sort_by(f64::total_cmp);
    sorted.get(sorted.len() / 2).copied()
}

/// One finding per leg that jumps, with the first and last jump and the largest.
pub fn check(times: &[f64], lengths: &[[f64; 6]], settings: &CheckSettings) -> Vec<Finding> {
    check_series(
        FindingKind::Jump,
        "m",
        times,
        lengths,
        settings.jump_ratio,
        settings.jump_floor,
    )
}

/// One finding of `kind` per column of `values` (in `unit`) that jumps: a step more than
/// `ratio` times the median of its neighbours and more than `floor`. Steps next to a
/// missing (NaN) value are not judged.
pub(crate) fn check_series(
    kind: FindingKind,
    unit: &str,
    times: &[f64],
    values: &[[f64; 6]],
    ratio: f64,
    floor: f64,
) -> Vec<Finding> {
    let mut findings = Vec::new();
    for leg in 0..6 {
        let mut found: Option<Finding> = None;
        for jump in jumps_in(times, values, ratio, floor).filter(|j| j.column == leg) {
            // The jump happens between samples k and k + 1; it is dated at k + 1.
            let (t, step, limit) = (times[jump.after], jump.step, jump.limit);
            let f = found.get_or_insert_with(|| Finding {
                kind,
                legs: vec![leg + 1],
                first_time: t,
                last_time: t,
                count: 0,
                worst_time: t,
                worst_value: step,
                limit,
                margin: limit - step,
                unit: unit.to_owned(),
            });
            f.last_time = t;
            f.count += 1;
            if step > f.worst_value {
                f.worst_value = step;
                f.worst_time = t;
                f.limit = limit;
                f.margin = f.limit - step;
            }
        }
        findings.extend(found);
    }
    findings
}

/// One step judged a jump: in which column, the sample it ends at, its size over its own
/// interval and the most the steps around it allow over that interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Jump {
    pub column: usize,
    pub after: usize,
    pub step: f64,
    pub limit: f64,
}

/// Every step of `values` more than `ratio` times the median of its neighbours and more
/// than `floor`, column by column (the rule of [`check_series`]).
pub(crate) fn jumps_in<'a>(
    times: &'a [f64],
    values: &'a [[f64; 6]],
    ratio: f64,
    floor: f64,
) -> impl Iterator<Item = Jump> + 'a {
    let n = values.len();
    // On an uneven grid (a pose table's own rows) a step is judged as the step it would
    // be at the typical interval: a motion sampled more sparsely is no jump.
    let scale = if n < 2 { None } else { interval_scales(times) };
    (0..6).flat_map(move |column| {
        let factor = |k: usize| scale.as_ref().map_or(1.0, |c| c[k]);
        let steps: Vec<f64> = values
            .windows(2)
            .enumerate()
            .map(|(k, pair)| (pair[1][column] - pair[0][column]).abs() * factor(k))
            .collect();
        (0..steps.len())
            .filter_map(|k| {
                let step = steps[k];
                // A NaN step (or neighbourhood) is never a jump.
                if step.is_nan() || step <= floor {
                    return None;
                }
                let limit = ratio * median_of_neighbours(&steps, k);
                // Judged at the typical interval, told as the step really taken over
                // its own interval and the most the steps around allow over it.
                (!limit.is_nan() && step > limit).then(|| Jump {
                    column,
                    after: k + 1,
                    step: step / factor(k),
                    limit: limit.max(floor) / factor(k),
                })
            })
            .collect::<Vec<_>>()
    })
}

fn median_of_neighbours(steps: &[f64], k: usize) -> f64 {
    let mut around = [0.0; 2 * NEIGHBOURS];
    let mut m = 0;
    let lo = k.saturating_sub(NEIGHBOURS);
    let hi = (k + NEIGHBOURS + 1).min(steps.len());
    for (j, &s) in steps.iter().enumerate().take(hi).skip(lo) {
        if j != k {
            around[m] = s;
            m += 1;
        }
    }
    if m == 0 {
        return 0.0;
    }
    let around = &mut around[..m];
    around.sort_by(f64::total_cmp);
    if m % 2 == 1 {
        around[m / 2]
    } else {
        0.5 * (around[m / 2 - 1] + around[m / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn smooth(n: usize) -> (Vec<f64>, Vec<[f64; 6]>) {
        let times: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
        let lengths = times
            .iter()
            .map(|&t| std::array::from_fn(|i| 1.0 + 0.1 * (2.0 * t + i as f64).sin()))
            .collect();
        (times, lengths)
    }

    #[test]
    fn smooth_motion_has_no_jumps_even_at_turning_points() {
        let (times, lengths) = smooth(2000);
        assert!(check(&times, &lengths, &CheckSettings::default()).is_empty());
    }

    #[test]
    fn a_step_and_a_spike_are_found_and_dated() {
        let (times, mut lengths) = smooth(500);
        // Leg 2 steps up by 5 cm from sample 200 on.
        for l in lengths.iter_mut().skip(200) {
            l[1] += 0.05;
        }
        // Leg 6 has one wrong sample at 300 (a spike: up then straight down).
        lengths[300][5] += 0.02;
        let f = check(&times, &lengths, &CheckSettings::default());
        assert_eq!(f.len(), 2);
        assert_eq!(
            (f[0].legs.clone(), f[0].count, f[0].first_time),
            (vec![2], 1, times[200])
        );
        assert!((f[0].worst_value - 0.05).abs() < 2e-3);
        assert_eq!(
            (
                f[1].legs.clone(),
                f[1].count,
                f[1].first_time,
                f[1].last_time
            ),
            (vec![6], 2, times[300], times[301])
        );
    }
}

#[cfg(test)]
mod uneven_tests {
    use super::*;

    #[test]
    fn a_smooth_motion_sampled_unevenly_does_not_jump_and_a_real_jump_still_does() {
        // 0.05·sin(t) at rows 0.01 s apart, then 0.2 s apart (a table's own rows).
        let mut times: Vec<f64> = (0..120).map(|k| k as f64 * 0.01).collect();
        times.extend((1..20).map(|k| 1.19 + k as f64 * 0.2));
        let values: Vec<[f64; 6]> = times.iter().map(|t| [0.05 * t.sin(); 6]).collect();
        let settings = CheckSettings::default();
        assert!(check(&times, &values, &settings).is_empty());
        // A 10 cm step between two of the sparse rows (10 times what the motion moves
        // there) is still a jump.
        let mut jumped = values.clone();
        for v in jumped.iter_mut().skip(130) {
            for x in v.iter_mut() {
                *x += 0.1;
            }
        }
        let found = check(&times, &jumped, &settings);
        assert_eq!(found.len(), 6, "{found:?}");
        assert!(found.iter().all(|f| f.first_time == times[130]));
    }

    #[test]
    fn a_jump_over_a_short_interval_is_told_as_the_step_it_really_is() {
        // Rows 10 ms apart and one row 0.5 ms after another, 6 cm off: judged at the
        // typical interval (20 times the step), but told as the 6 cm it is, beside the
        // most the steps around allow over 0.5 ms.
        let mut times: Vec<f64> = (0..100).map(|k| k as f64 * 0.01).collect();
        times.insert(51, 0.5005);
        let mut values: Vec<[f64; 6]> = times.iter().map(|t| [0.01 * t; 6]).collect();
        values[51] = [0.01 * 0.5005 + 0.06; 6];
        let found = check(&times, &values, &CheckSettings::default());
        assert_eq!(found.len(), 6, "{found:?}");
        let f = &found[0];
        assert_eq!(f.worst_time, 0.5005);
        assert!((f.worst_value - 0.06).abs() < 1e-5, "{}", f.worst_value);
        // 5 × the 0.1 mm the steps around move in 10 ms, over a twentieth of that
        // interval: 25 µm.
        assert!((f.limit - 2.5e-5).abs() < 1e-9, "{}", f.limit);
    }
}
