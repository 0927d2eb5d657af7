//! The actuator guard: what model-predictive cueing promises — every actuator (leg or
//! servo) within its range, its speed and its acceleration limit, as `check` measures
//! them (finite differences of the values at the samples), every pose within the joint
//! cones and clearances and under the check's condition-number limit — kept after the
//! planner, in the actuators' own space.
//!
//! The planner keeps these limits on its linearisation; where the rig is strongly
//! nonlinear (a servo near the end of its travel, a rig near a singular pose) the exact
//! motion can leave them. Each pose the planner gives is therefore judged by its actuator
//! values against the last two given: the slope over the new interval must lie within the
//! speed limit, within the acceleration limit of the slope before, and slow enough to stop
//! before the range's end at the acceleration limit; the pose itself must keep every
//! other limit. A pose outside is replaced by the pose whose actuator values are the
//! nearest allowed (each actuator's slope clamped; the pose found by forward kinematics
//! from the last), and counted.
//!
//! A motion heading fast into a cone or a singular pose may find no allowed pose at all
//! (it cannot stop within one sample). The guard sees the whole recording, so it then goes
//! back — two samples, then four, eight … — and brakes from there as hard as the limits
//! allow, until the motion stops short of what it could not keep; at rest, staying put is
//! always allowed. The planner's own state goes on throughout, and the guard lets the
//! motion back onto it as fast as the limits allow.

use crate::analysis::checks::CheckSettings;
mod smoothing;
mod steering;

use steering::{along, clamped};

use crate::analysis::checks::jumps::{Jump, jumps_in, typical_interval};
use crate::analysis::workspace;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;
use crate::solve::forward::ForwardOptions;

/// The guard of one rig.
#[derive(Clone, Debug)]
pub struct ActuatorGuard {
    geometry: Geometry,
    limits: Limits,
    /// The check's largest condition number (none on a geometry singular at every pose,
    /// which `check` judges once, as the rig's, not pose by pose).
    condition_max: Option<f64>,
    /// The check's jump rule: ratio, and floor in the actuators' unit.
    jump_ratio: f64,
    jump_floor: f64,
    /// The range, the margin taken off (`±∞` where unset).
    range: (f64, f64),
    /// Speed and acceleration limits, the margin taken off.
    speed: Option<f64>,
    accel: Option<f64>,
}

/// One pose given: its time, actuator values and pose.
type Given = (f64, [f64; 6], Pose);

/// One actuator's recent motion: its slope over the last interval and that interval,
/// and its acceleration at the last sample, where the poses given so far have them.
#[derive(Clone, Copy, Debug)]
struct Recent {
    previous: Option<(f64, f64)>,
    accel: Option<f64>,
}

/// Where a pose lies in the motion (its index in `times`), and whether it is to brake
/// rather than follow.
#[derive(Clone, Copy, Debug)]
struct Place<'a> {
    index: usize,
    times: &'a [f64],
    braking: bool,
    /// Near a jump found before (how many times): every acceleration changes smoothly,
    /// more slowly each time.
    careful: u8,
    /// The interval at which `check` judges every step for jumps (a step over a shorter
    /// interval counts for more).
    typical: f64,
}

/// What became of a planned pose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Outcome {
    /// Given as planned.
    Kept,
    /// Replaced by an allowed pose.
    Replaced,
    /// No allowed pose was found: the last pose given again.
    Stopped,
}

/// A pass of [`ActuatorGuard::step`]: the planner's pose taken as it is, or a
/// replacement steered towards it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Pass {
    Accept,
    Steer,
}

/// The samples over which a smooth motion's acceleration may go from nought to its limit.
const SMOOTH_SAMPLES: f64 = 4.0;

/// The share of a limit the guard uses at most, even with no margin asked for: the poses
/// are judged again from their table rows, whose rounding must not carry a value kept
/// exactly on a limit over it.
const ROUNDING_KEPT: f64 = 1.0 - 1e-6;

/// The rounding the actuator values of a pose found by forward kinematics carry once
/// read back from its table row, as a share of the value (at least of 1): slopes are aimed
/// this far inside their limits over the interval.
const VALUE_ROUNDING: f64 = 1e-13;

/// The most a sample's smoothing is doubled around the jumps found near it.
const MOST_CAREFUL: u8 = 4;

/// The most times a motion is guarded again around the jumps found in it.
const JUMP_PASSES: usize = 16;

/// What the guard did to a whole motion.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Guarded {
    /// The poses given, one per pose planned.
    pub poses: Vec<Pose>,
    /// Poses replaced to keep the limits.
    pub held: usize,
    /// Times the guard went back to brake earlier.
    pub rewound: usize,
    /// Poses for which no allowed pose was found even so (the last pose given again):
    /// none unless the motion starts outside the limits.
    pub stopped: usize,
    /// Steps `check` would still call jumps when the guard's passes ran out.
    pub jumps_left: usize,
}

/// The most times the guard steps through the motion, per pose planned, before it gives
/// the last pose again where it finds no allowed one (a bound on the work, never reached
/// by a motion that starts within the limits).
const WORK_PER_POSE: usize = 64;

impl ActuatorGuard {
    /// The guard of `geometry` within `limits` and the thresholds of `checks` (the
    /// condition number, jumps), each limit kept `margin` (a share) inside.
    pub fn new(geometry: &Geometry, limits: &Limits, checks: &CheckSettings, margin: f64) -> Self {
        let [lo, hi] = geometry.quantity_limits();
        let width = match (lo, hi) {
            (Some(l), Some(h)) => h - l,
            _ => 0.0,
        };
        let keep = 0.5 * margin * width;
        let [speed, accel, _] = geometry.actuator_rate_limits(limits);
        Self {
            geometry: geometry.clone(),
            limits: *limits,
            condition_max: (!crate::analysis::architecture::architecture(geometry).singular)
                .then_some(checks.condition_max),
            jump_ratio: checks.jump_ratio,
            // As `check` judges servo angles: a jump of the horn tip by the floor.
            jump_floor: geometry.rotary().map_or(checks.jump_floor, |servos| {
                (checks.jump_floor / servos.horn_length()).to_degrees()
            }),
            range: (
                lo.map_or(f64::NEG_INFINITY, |l| l + keep),
                hi.map_or(f64::INFINITY, |h| h - keep),
            ),
            // Half the planner's margin: the guard acts only where the exact motion left
            // the planner's envelope by more than half of it.
            speed: speed.map(|v| v * (1.0 - 0.5 * margin).min(ROUNDING_KEPT)),
            accel: accel.map(|a| a * (1.0 - 0.5 * margin).min(ROUNDING_KEPT)),
        }
    }

    /// The poses to give for the planner's `planned` poses at `times` (as many): each
    /// limit kept, and no step `check` would call a jump (where one is found, the motion
    /// around it is guarded again, its acceleration changed smoothly there).
    pub fn guard_all(&self, times: &[f64], planned: &[Pose]) -> Guarded {
        let n = planned.len().min(times.len());
        let mut careful = vec![0u8; n];
        let times = &times[..n];
        let mut out = self.guard_with(times, planned, &careful);
        for pass in 0..=JUMP_PASSES {
            // Judged as `check` will read them: from their table rows. Each jump is first
            // smoothed where it is; only where that cannot keep the limits is the motion
            // around it guarded again.
            let jumps: Vec<_> = self.jumps_of(times, &out.poses);
            let left = if jumps.is_empty() {
                0
            } else {
                self.smooth_jumps(times, &mut out.poses, &jumps)
            };
            if left == 0 || pass == JUMP_PASSES {
                out.jumps_left = left;
                break;
            }
            for jump in self.jumps_of(times, &out.poses) {
                let from = jump.after.saturating_sub(3 * SMOOTH_SAMPLES as usize);
                let to = (jump.after + 3 * SMOOTH_SAMPLES as usize).min(n);
                for c in &mut careful[from..to] {
                    *c = (*c + 1).min(MOST_CAREFUL);
                }
            }
            out = self.guard_with(times, planned, &careful);
        }
        // Every pose given otherwise than planned, the ones smoothed included.
        let changed = (out.poses.iter().zip(planned))
            .filter(|(a, b)| a != b)
            .count();
        out.held = changed.saturating_sub(out.stopped);
        out
    }

    /// The steps of `poses` at `times` that `check` would call jumps.
    fn jumps_of(&self, times: &[f64], poses: &[Pose]) -> Vec<Jump> {
        let values = self.values_as_read(poses);
        jumps_in(times, &values, self.jump_ratio, self.jump_floor).collect()
    }

    /// [`ActuatorGuard::guard_all`] once, each sample marked in `careful` guarded
    /// smoothly.
    fn guard_with(&self, times: &[f64], planned: &[Pose], careful: &[u8]) -> Guarded {
        let n = planned.len().min(times.len());
        let mut given: Vec<(Given, Outcome)> = Vec::with_capacity(n);
        let mut out = Guarded::default();
        // Samples before this one are braked rather than steered towards the plan.
        let mut brake_until = 0;
        // How far the last failure went back, and where it happened.
        let (mut span, mut failed_at) = (0usize, 0usize);
        let budget = WORK_PER_POSE * n + 1000;
        let typical = typical_interval(&times[..n]).unwrap_or(0.0);
        let mut work = 0;
        let mut k = 0;
        while k < n {
            work += 1;
            let history: [Option<Given>; 3] =
                std::array::from_fn(|back| given.len().checked_sub(3 - back).map(|i| given[i].0));
            let place = Place {
                index: k,
                times: &times[..n],
                braking: k < brake_until,
                careful: careful[k],
                typical,
            };
            let wanted_before = (k > 0)
                .then(|| self.geometry.actuator_values_at(&planned[k - 1]).ok())
                .flatten();
            match self.step(times[k], planned[k], wanted_before, history, place) {
                Some((g, replaced)) => {
                    let outcome = if replaced {
                        Outcome::Replaced
                    } else {
                        Outcome::Kept
                    };
                    given.push((g, outcome));
                    k += 1;
                }
                None if k > 0 && work < budget => {
                    // Go back and brake earlier: twice as far as last time when this
                    // failure is no later than the last.
                    span = if k <= failed_at { (span * 2).max(2) } else { 2 };
                    failed_at = k;
                    brake_until = brake_until.max(k + 1);
                    let to = k.saturating_sub(span);
                    given.truncate(to);
                    k = to;
                    out.rewound += 1;
                }
                None => {
                    let last = history[2].unwrap_or_else(|| {
                        let q = self
                            .geometry
                            .actuator_values_at(&planned[k])
                            .unwrap_or([0.0; 6]);
                        (times[k], q, planned[k])
                    });
                    given.push(((times[k], last.1, last.2), Outcome::Stopped));
                    k += 1;
                }
            }
        }
        // Counted from what was given in the end (a rewind takes back what it passes).
        let count = |o: Outcome| given.iter().filter(|(_, x)| *x == o).count();
        (out.held, out.stopped) = (count(Outcome::Replaced), count(Outcome::Stopped));
        out.poses = given.into_iter().map(|((_, _, pose), _)| pose).collect();
        out
    }

    /// The pose to give at `t` for the planner's `pose` (whose actuator values at the
    /// sample before were `wanted_before`) after the `history` (the last three given,
    /// newest last), and whether it replaced the planner's; `None` when no allowed pose
    /// was found.
    fn step(
        &self,
        t: f64,
        pose: Pose,
        wanted_before: Option<[f64; 6]>,
        history: [Option<Given>; 3],
        place: Place,
    ) -> Option<(Given, bool)> {
        let wanted = self.read_back(&pose);
        let Some((t1, q1, last)) = history[2] else {
            // The first pose: where the motion starts (at rest).
            return Some(((t, wanted?, pose), false));
        };
        let dt = t - t1;
        if dt.is_nan() || dt <= 0.0 {
            return Some(((t, wanted?, pose), false));
        }
        // Each actuator's slope over the last interval and its acceleration at the last
        // sample, where the history has them.
        let slope = |a: &Given, b: &Given, i: usize| (b.1[i] - a.1[i]) / (b.0 - a.0);
        let motion: [Recent; 6] = std::array::from_fn(|i| Recent {
            previous: history[1].map(|g| (slope(&g, &history[2].unwrap_or(g), i), t1 - g.0)),
            accel: match (history[0], history[1], history[2]) {
                (Some(a), Some(b), Some(c)) => {
                    Some((slope(&b, &c, i) - slope(&a, &b, i)) / (0.5 * (c.0 - a.0)))
                }
                _ => None,
            },
        });
        let going_on: [f64; 6] = std::array::from_fn(|i| motion[i].previous.map_or(0.0, |p| p.0));
        let steering: &[(f64, f64)] = match (place.braking, wanted) {
            (false, Some(_)) => &[(1.0, 1.0), (0.5, 1.0), (0.0, 1.0), (0.0, 0.5), (0.0, 0.0)],
            (false, None) => &[(0.0, 1.0), (0.0, 0.5), (0.0, 0.0)],
            (true, _) => &[(0.0, 0.0)],
        };
        // The planner's pose as it is when it keeps the limits (changing the
        // acceleration smoothly, where a jump was found before); else a replacement that
        // changes the acceleration smoothly (over a few samples, as a motion without jumps
        // does), else as hard as the limits allow.
        let passes = [
            (Pass::Accept, place.careful > 0),
            (Pass::Steer, true),
            (Pass::Steer, false),
        ];
        // Near a jump found before, smoothly or not at all (then the guard goes back).
        let passes = if place.careful > 0 {
            &passes[..2]
        } else {
            &passes[..]
        };
        for &(pass, smooth) in passes {
            let mut allowed = [(0.0, 0.0); 6];
            let mut possible = true;
            for (i, a) in allowed.iter_mut().enumerate() {
                match self.slopes(q1[i], dt, motion[i], place, smooth) {
                    Some(range) => *a = range,
                    None => possible = false,
                }
            }
            if !possible {
                continue;
            }
            if pass == Pass::Accept {
                if !place.braking
                    && let Some(w) = wanted
                    && (0..6).all(|i| {
                        let s = (w[i] - q1[i]) / dt;
                        s >= allowed[i].0 && s <= allowed[i].1
                    })
                    && self.keeps_the_other_limits(&pose)
                {
                    return Some(((t, w, pose), false));
                }
                continue;
            }
            // The nearest allowed to what the planner wants, else to half of it, else
            // the motion going on as it was, at half its speed, or braking (each clamped
            // to what is allowed): the first whose pose keeps every other limit too.
            let target = wanted.unwrap_or(q1);
            // First back onto the plan gently: the plan's own slope, and a quarter of the
            // way the motion has strayed from it, so that it settles without overshoot.
            let tracking = match (place.braking, wanted, wanted_before) {
                (false, Some(w), Some(before)) => Some(std::array::from_fn::<f64, 6, _>(|i| {
                    (w[i] - before[i]) / dt + (before[i] - q1[i]) / (SMOOTH_SAMPLES * dt)
                })),
                _ => None,
            };
            let slopes_of = |entries: &[(f64, f64)]| -> Vec<[f64; 6]> {
                (entries.iter())
                    .map(|&(blend, keep_going)| {
                        std::array::from_fn(|i| {
                            let wanted_slope = (target[i] - q1[i]) / dt;
                            blend * wanted_slope + (1.0 - blend) * keep_going * going_on[i]
                        })
                    })
                    .collect()
            };
            // Each slope aimed inside what is allowed by the rounding the values found
            // carry; first along its own direction from the motion going on (all
            // actuators cut back together, so the values stay those of a pose), then
            // each clamped alone; what is found judged as `check` reads it.
            let aim: [(f64, f64); 6] = std::array::from_fn(|i| {
                let room = VALUE_ROUNDING * q1[i].abs().max(1.0) / dt;
                let (lo, hi) = allowed[i];
                if hi - lo > 2.0 * room {
                    (lo + room, hi - room)
                } else {
                    let mid = 0.5 * (lo + hi);
                    (mid, mid)
                }
            });
            let by_values = |slopes: Vec<[f64; 6]>| {
                (slopes.into_iter())
                    .flat_map(|slope| [along(&going_on, &slope, &aim), clamped(&slope, &aim)])
                    .find_map(|slope| {
                        let values: [f64; 6] = std::array::from_fn(|i| q1[i] + slope[i] * dt);
                        let (found, read) = if values == q1 {
                            // Staying put: the last pose, already judged.
                            (last, q1)
                        } else {
                            self.pose_of(&values, &last)?
                        };
                        (0..6)
                            .all(|i| {
                                let s = (read[i] - q1[i]) / dt;
                                s >= allowed[i].0 && s <= allowed[i].1
                            })
                            .then_some(((t, read, found), true))
                    })
            };
            // Where no pose has the values wanted (on a rig whose leg lengths reach only
            // some values together, as an architecturally singular one's), on the way
            // between poses instead: from the motion going on, or from the last pose,
            // towards the plan's pose, or the last (braking). The last resort (braking,
            // or staying put) comes after.
            let going_pose = history[1]
                .filter(|(t0, _, _)| t1 > *t0)
                .map(|(t0, _, before)| {
                    let (a, b) = (before.to_coordinates(), last.to_coordinates());
                    let r = dt / (t1 - t0);
                    Pose::from_coordinates(std::array::from_fn(|j| b[j] + (b[j] - a[j]) * r))
                });
            let towards: &[Pose] = if place.braking || wanted.is_none() {
                &[last]
            } else {
                &[pose, last]
            };
            let between = || {
                (going_pose.iter().chain([&last]))
                    .flat_map(|from| towards.iter().map(move |to| (from, to)))
                    .find_map(|(from, to)| self.between(t, (dt, &q1), from, to, (&allowed, &aim)))
                    .map(|g| (g, true))
            };
            let (resort, moving) = steering.split_last()?;
            let found = by_values(tracking.into_iter().chain(slopes_of(moving)).collect())
                .or_else(between)
                .or_else(|| by_values(slopes_of(std::slice::from_ref(resort))));
            if found.is_some() {
                return found;
            }
        }
        None
    }

    /// Whether `pose` keeps the joint cones, clearances and (as its table row reads back)
    /// the condition-number limit.
    pub(super) fn keeps_the_other_limits(&self, pose: &Pose) -> bool {
        workspace::pose_within_limits_as_written(&self.geometry, &self.limits, pose)
            && self.condition_max.is_none_or(|max| {
                self.geometry
                    .actuated_conditioning(&Pose::from_row(&pose.to_row()))
                    .and_then(|c| c.condition_number)
                    .is_some_and(|c| c <= max)
            })
    }

    /// The pose whose actuator values are `values`, found from `near` (to rounding), and
    /// its values as `check` reads them, when it keeps every limit as written.
    pub(super) fn pose_of(&self, values: &[f64; 6], near: &Pose) -> Option<(Pose, [f64; 6])> {
        let polished = ForwardOptions {
            polish: true,
            ..ForwardOptions::default()
        };
        let found = (self.geometry)
            .pose_from_actuator_values_with(values, near, &polished)
            .ok()?;
        let read = self.read_back(&found)?;
        let exact = read.iter().zip(values).all(|(a, b)| (a - b).abs() < 1e-6);
        (exact && self.keeps_the_other_limits(&found)).then_some((found, read))
    }

    /// The actuator values of `pose` as `check` reads them: from its table row.
    pub(super) fn read_back(&self, pose: &Pose) -> Option<[f64; 6]> {
        let read = Pose::from_row(&pose.to_row());
        self.geometry.actuator_values_at(&read).ok()
    }

    /// The slopes allowed over the next interval of `dt` from value `q` after the
    /// `recent` motion (none: from rest) at `place`; `None` when none keeps every limit.
    /// `smooth`: the acceleration may change by a quarter of its limit a sample.
    fn slopes(
        &self,
        q: f64,
        dt: f64,
        recent: Recent,
        place: Place,
        smooth: bool,
    ) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let (s0, h0) = recent.previous.unwrap_or((0.0, dt));
        let tau = 0.5 * (h0 + dt);
        let (k, times) = (place.index, place.times);
        let n = times.len();
        if let Some(a) = self.accel {
            let (mut least, mut most) = (-a, a);
            if let Some(a0) = recent.accel {
                if smooth {
                    let change = a / (SMOOTH_SAMPLES * f64::from(1u8 << place.careful));
                    (least, most) = (least.max(a0 - change), most.min(a0 + change));
                }
                // `check` extrapolates each end of a table from the two accelerations
                // inside it, a₁(1 + w) − a₂·w with w from the four end samples' times:
                // the second of them keeps that within the limit too.
                let ends = |w: f64, known: f64, new_is_first: bool| {
                    if new_is_first {
                        // a_end = new·(1 + w) − known·w
                        ((known * w - a) / (1.0 + w), (known * w + a) / (1.0 + w))
                    } else {
                        // a_end = known·(1 + w) − new·w
                        ((known * (1.0 + w) - a) / w, (known * (1.0 + w) + a) / w)
                    }
                };
                let mut keep_accel = |(l, h): (f64, f64)| {
                    least = least.max(l);
                    most = most.min(h);
                };
                if n >= 4 && k == 3 {
                    let w = (2.0 * (times[1] - times[0]) + (times[2] - times[1]))
                        / (times[3] - times[0]);
                    keep_accel(ends(w, a0, false));
                }
                if n >= 4 && k + 1 == n {
                    let w = (2.0 * (times[n - 1] - times[n - 2]) + (times[n - 2] - times[n - 3]))
                        / (times[n - 1] - times[n - 4]);
                    keep_accel(ends(w, a0, true));
                }
            }
            if least > most {
                return None;
            }
            (lo, hi) = (s0 + least * tau, s0 + most * tau);
        }
        let mut keep = |l: f64, h: f64| {
            lo = lo.max(l);
            hi = hi.min(h);
        };
        if place.careful > 0 {
            // Near a jump found before, each step at most twice the last (or the check's
            // floor, as `check` judges a step: at the typical interval): a motion that
            // grows so is no jump, whatever limits are set.
            let judged_over = if place.typical > 0.0 {
                place.typical
            } else {
                dt
            };
            let grow = (ROUNDING_KEPT * self.jump_floor / judged_over).max(2.0 * s0.abs());
            keep(-grow, grow);
        }
        if let Some(v) = self.speed {
            keep(-v, v);
            // The speed `check` extrapolates at each end: at the start from the first two
            // slopes, s₀ − (s₁ − s₀)·h₀/(h₀ + h₁); at the end s + (s − s₀)·h/(h₀ + h).
            if k == 2 {
                let r = h0 / (h0 + dt);
                keep((s0 * (1.0 + r) - v) / r, (s0 * (1.0 + r) + v) / r);
            }
            if k + 1 == n && k >= 2 {
                let r = dt / (h0 + dt);
                keep((s0 * r - v) / (1.0 + r), (s0 * r + v) / (1.0 + r));
            }
        }
        let (bottom, top) = self.range;
        // Slow enough to stop before the end: s·dt to the next sample, one more interval
        // as the deceleration starts, then s²/2a.
        let reach = |room: f64| match self.accel {
            _ if room <= 0.0 => room / dt,
            Some(a) => a * (-2.0 * dt + (4.0 * dt * dt + 2.0 * room / a).sqrt()),
            None => room / dt,
        };
        keep(
            if bottom.is_finite() {
                -reach(q - bottom)
            } else {
                f64::NEG_INFINITY
            },
            if top.is_finite() {
                reach(top - q)
            } else {
                f64::INFINITY
            },
        );
        (lo <= hi).then_some((lo, hi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::checks::rates::{leg_accelerations, leg_speeds};
    use crate::io::scenario::Scenario;
    use crate::model::angle::Angle;
    use crate::model::limits::joint_angles;

    fn worst(series: &[[f64; 6]]) -> f64 {
        series.iter().flatten().fold(0.0f64, |m, a| m.max(a.abs()))
    }

    #[test]
    fn a_motion_within_the_limits_passes_untouched_and_a_sudden_stop_is_braked() {
        let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let limits = Limits {
            leg_speed_max: Some(0.5),
            leg_accel_max: Some(2.0),
            ..s.limits
        };
        let guard = ActuatorGuard::new(&s.geometry, &limits, &CheckSettings::default(), 0.0);
        let home = s.geometry.home_pose();
        let at = |z: f64| home.with_position(home.position + nalgebra::Vector3::new(0.0, 0.0, z));
        // Heaving at 0.1 m/s from rest after a gentle start (legs well inside the limits),
        // then stopping dead: the guard leaves the first part as it is and brakes the stop.
        let dt = 0.01;
        let (mut z, mut v) = (0.0, 0.0f64);
        let mut times = Vec::new();
        let mut planned = Vec::new();
        for k in 0..80 {
            if k < 40 {
                v = (v + 1.0 * dt).min(0.1);
                z += v * dt;
            }
            times.push(k as f64 * dt);
            planned.push(at(z));
        }
        let out = guard.guard_all(&times, &planned);
        assert_eq!(out.poses[..40], planned[..40]);
        let counts = (out.held, out.rewound, out.stopped);
        assert!(out.held > 0 && out.stopped == 0, "{counts:?}");
        let given: Vec<_> = out
            .poses
            .iter()
            .map(|p| s.geometry.leg_lengths(p))
            .collect();
        assert!(worst(&leg_accelerations(&times, &given)) <= 2.0 + 1e-6);
    }

    #[test]
    fn a_motion_heading_fast_into_a_cone_is_braked_in_time_by_going_back() {
        // Sliding sideways at 0.3 m/s into a base-joint cone set where the platform is
        // 4 cm over: no pose within one sample of the cone keeps it, so the guard must
        // have started braking earlier — it goes back and does.
        let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let home = s.geometry.home_pose();
        let at = |x: f64| home.with_position(home.position + nalgebra::Vector3::new(x, 0.0, 0.0));
        let cone_at = |x: f64| {
            let p = at(x);
            let angles = joint_angles(&p, &s.geometry.inverse(&p));
            angles.iter().fold(0.0f64, |m, a| m.max(a[0]))
        };
        let wall = cone_at(0.04);
        assert!(wall > cone_at(0.0), "the cone grows as the platform slides");
        let limits = Limits {
            leg_speed_max: Some(0.5),
            leg_accel_max: Some(2.0),
            base_cone: Some(Angle::from_radians(wall)),
            platform_cone: None,
            ..s.limits
        };
        let guard = ActuatorGuard::new(&s.geometry, &limits, &CheckSettings::default(), 0.0);
        let dt = 0.01;
        let (mut x, mut v) = (0.0, 0.0f64);
        let mut times = Vec::new();
        let mut planned = Vec::new();
        for k in 0..100 {
            v = (v + 1.0 * dt).min(0.3);
            x += v * dt;
            times.push(k as f64 * dt);
            planned.push(at(x));
        }
        let out = guard.guard_all(&times, &planned);
        let counts = (out.held, out.rewound, out.stopped);
        assert!(out.rewound > 0 && out.stopped == 0, "{counts:?}");
        for p in &out.poses {
            assert!(workspace::pose_within_limits_as_written(
                &s.geometry,
                &limits,
                p
            ));
        }
        let given: Vec<_> = out
            .poses
            .iter()
            .map(|p| s.geometry.leg_lengths(p))
            .collect();
        assert!(worst(&leg_speeds(&times, &given)) <= 0.5 + 1e-9);
        assert!(worst(&leg_accelerations(&times, &given)) <= 2.0 + 1e-6);
        // What was planned broke the cone; what is given does not.
        assert!((planned.iter()).any(|p| !workspace::pose_within_limits(&s.geometry, &limits, p)));
    }
}
