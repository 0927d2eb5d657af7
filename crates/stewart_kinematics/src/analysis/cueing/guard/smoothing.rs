//! Jumps smoothed where they are: a step `check` would call a jump (much larger than the
//! steps around it) is spread over the samples around it.
//!
//! The planner's re-solves can leave a step of a few tenths of a millimetre among steps
//! ten times smaller: within every limit, but a jump by `check`'s rule. The actuator
//! values over a window around it are replaced by the cubic (Hermite) that joins the
//! window's ends with the motion's own values and slopes there, so the steps change
//! gradually; the poses are found from those values by forward kinematics. A window is
//! kept only when every pose keeps every limit, the speeds and accelerations in and
//! around it (as `check` measures them) stay within theirs and no jump is left near it;
//! otherwise a wider window is tried. Nothing outside the window changes, so one
//! smoothing cannot start a jump elsewhere.

use super::ActuatorGuard;
use crate::analysis::checks::jumps::{Jump, jumps_in};
use crate::analysis::checks::rates::{leg_accelerations, leg_speeds};
use crate::model::pose::Pose;

/// Samples on each side of a jump in the narrowest window tried; each wider one doubles.
const NARROWEST: usize = 3;

/// Windows tried per jump.
const WIDENINGS: u32 = 4;

/// Samples on each side of a window judged again for jumps (the jump rule's neighbours).
const JUDGED_AROUND: usize = 4;

impl ActuatorGuard {
    /// The actuator values of `poses` as `check` reads them (from their table rows; NaN
    /// where a row reads back to no pose).
    pub(super) fn values_as_read(&self, poses: &[Pose]) -> Vec<[f64; 6]> {
        (poses.iter())
            .map(|p| self.read_back(p).unwrap_or([f64::NAN; 6]))
            .collect()
    }

    /// Smooth each of `jumps` in `poses` (at `times`) where a window allows; the jumps
    /// left, as `check` would find them.
    pub(super) fn smooth_jumps(&self, times: &[f64], poses: &mut [Pose], jumps: &[Jump]) -> usize {
        for jump in jumps {
            let values = self.values_as_read(poses);
            // Already smoothed with an earlier one.
            if !self
                .jumps_near(times, &values, jump.after, jump.after)
                .is_empty()
            {
                self.smooth_one(times, poses, jump.after);
            }
        }
        let values = self.values_as_read(poses);
        jumps_in(times, &values, self.jump_ratio, self.jump_floor).count()
    }

    /// The jumps of `values` ending within `JUDGED_AROUND` samples of `from ..= to`.
    fn jumps_near(&self, times: &[f64], values: &[[f64; 6]], from: usize, to: usize) -> Vec<Jump> {
        let lo = from.saturating_sub(JUDGED_AROUND);
        let hi = to + JUDGED_AROUND;
        jumps_in(times, values, self.jump_ratio, self.jump_floor)
            .filter(|j| j.after >= lo && j.after <= hi)
            .collect()
    }

    /// Spread the jump ending at sample `after` over the narrowest window that keeps
    /// every limit and leaves no jump near it; `poses` unchanged when none does.
    fn smooth_one(&self, times: &[f64], poses: &mut [Pose], after: usize) {
        let n = poses.len();
        for widening in 0..WIDENINGS {
            let half = NARROWEST << widening;
            // The window's ends a and b stay; a sample before a and after b give the
            // slopes there, and the differences judged reach one sample further.
            // At the start of the motion the window may begin at its first sample (the
            // motion starts from rest there), and at its end finish at its last.
            let a = after.saturating_sub(half);
            let b = (after + half - 1).min(n - 1);
            if b < after || b < a + 2 {
                return;
            }
            // By actuator values, else by pose coordinates; with the motion's own slopes
            // at the ends, else (where samples microseconds apart give those slopes
            // little meaning) the window's mean slope at both.
            let tries = [Ends::Motion, Ends::Mean].into_iter().flat_map(|ends| {
                [
                    self.window_by_values(times, poses, (a, b), ends),
                    self.window_by_coordinates(times, poses, (a, b), ends),
                ]
            });
            for window in tries.flatten() {
                let mut tried = poses.to_vec();
                tried[a + 1..b].copy_from_slice(&window);
                if self.window_keeps_the_limits(times, &tried, a, b) {
                    poses[a + 1..b].copy_from_slice(&window);
                    return;
                }
            }
        }
    }

    /// The poses strictly between samples `a` and `b` whose actuator values follow the
    /// cubic joining the values and slopes at `a` and `b`; `None` when one of them is no
    /// pose within the limits.
    fn window_by_values(
        &self,
        times: &[f64],
        poses: &[Pose],
        (a, b): (usize, usize),
        ends: Ends,
    ) -> Option<Vec<Pose>> {
        let q = |k: usize| self.geometry.actuator_values_at(&poses[k]).ok();
        let mut near = poses[a];
        (hermite(times, (a, b), ends, q)?.into_iter())
            .map(|values| {
                if (values.iter()).any(|v| *v < self.range.0 || *v > self.range.1) {
                    return None;
                }
                near = self.pose_of(&values, &near)?.0;
                Some(near)
            })
            .collect()
    }

    /// The poses strictly between samples `a` and `b` whose coordinates follow the cubic
    /// joining the poses and their rates at `a` and `b` (for a rig whose actuator values
    /// reach no pose in between, as an architecturally singular one's); `None` when one
    /// of them is outside the limits.
    fn window_by_coordinates(
        &self,
        times: &[f64],
        poses: &[Pose],
        (a, b): (usize, usize),
        ends: Ends,
    ) -> Option<Vec<Pose>> {
        let c = |k: usize| Some(poses[k].to_coordinates());
        (hermite(times, (a, b), ends, c)?.into_iter())
            .map(|coordinates| {
                let pose = Pose::from_coordinates(coordinates);
                let read = self.read_back(&pose)?;
                let within = (read.iter()).all(|v| *v >= self.range.0 && *v <= self.range.1);
                (within && self.keeps_the_other_limits(&pose)).then_some(pose)
            })
            .collect()
    }

    /// Whether `poses`, changed between samples `a` and `b`, keep the speed and
    /// acceleration limits wherever the change reaches (as `check` measures them from the
    /// table rows) and leave no jump near the window.
    fn window_keeps_the_limits(&self, times: &[f64], poses: &[Pose], a: usize, b: usize) -> bool {
        let values = self.values_as_read(poses);
        if !self.jumps_near(times, &values, a, b).is_empty() {
            return false;
        }
        // Differences at a − 1 ..= b + 1 (every stencil touching the window), from the
        // samples a − 2 ..= b + 2: interior to that slice, or at an end of the motion,
        // where `check` extrapolates from the same samples.
        let (from, to) = (a.saturating_sub(2), (b + 3).min(times.len()));
        let (t, v) = (&times[from..to], &values[from..to]);
        let first = usize::from(from > 0);
        let within = |series: Vec<[f64; 6]>, limit: Option<f64>| {
            let last = series.len() - usize::from(to < times.len());
            limit.is_none_or(|max| series[first..last].iter().flatten().all(|x| x.abs() <= max))
        };
        within(leg_speeds(t, v), self.speed) && within(leg_accelerations(t, v), self.accel)
    }
}

/// The cubic (Hermite) joining the six numbers `at(a)` and `at(b)`, with the slopes of the
/// intervals before `a` (none at the first sample: from rest) and after `b` (at the last
/// sample: the mean slope from `a`), at the times strictly between; `None` where `at` has
/// no value.
fn hermite(
    times: &[f64],
    (a, b): (usize, usize),
    ends: Ends,
    at: impl Fn(usize) -> Option<[f64; 6]>,
) -> Option<Vec<[f64; 6]>> {
    let (qa, qb) = (at(a)?, at(b)?);
    let (ta, tb) = (times[a], times[b]);
    let h = tb - ta;
    let mean: [f64; 6] = std::array::from_fn(|i| (qb[i] - qa[i]) / h);
    let slope_a: [f64; 6] = match (ends, a.checked_sub(1)) {
        (Ends::Mean, _) => mean,
        (Ends::Motion, Some(before)) => {
            let qa0 = at(before)?;
            std::array::from_fn(|i| (qa[i] - qa0[i]) / (ta - times[before]))
        }
        // From rest at the first sample.
        (Ends::Motion, None) => [0.0; 6],
    };
    // At the last sample, the window's own mean slope.
    let slope_b: [f64; 6] = match times.get(b + 1).filter(|_| ends == Ends::Motion) {
        Some(&tb1) => {
            let qb1 = at(b + 1)?;
            std::array::from_fn(|i| (qb1[i] - qb[i]) / (tb1 - tb))
        }
        None => mean,
    };
    let between = times[a + 1..b].iter().map(|&t| {
        let u = (t - ta) / h;
        let (u2, u3) = (u * u, u * u * u);
        let (h00, h10, h01, h11) = (
            2.0 * u3 - 3.0 * u2 + 1.0,
            u3 - 2.0 * u2 + u,
            -2.0 * u3 + 3.0 * u2,
            u3 - u2,
        );
        std::array::from_fn(|i| {
            h00 * qa[i] + h10 * h * slope_a[i] + h01 * qb[i] + h11 * h * slope_b[i]
        })
    });
    Some(between.collect())
}

/// The slopes a smoothing window's cubic takes at its ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ends {
    /// The motion's own, over the intervals outside (at the first sample: from rest; at
    /// the last: the window's mean).
    Motion,
    /// The window's mean slope at both ends.
    Mean,
}
