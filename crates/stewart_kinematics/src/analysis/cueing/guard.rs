//! The actuator guard: what model-predictive cueing promises — every actuator (leg or
//! servo) within its range, its speed and its acceleration limit, as `check` measures
//! them (finite differences of the values at the samples) — kept after the planner, in
//! the actuators' own space.
//!
//! The planner keeps these limits on its linearisation; where the rig is strongly
//! nonlinear (a servo near the end of its travel) the exact motion can leave them. Each
//! pose the planner gives is therefore judged by its actuator values against the last two
//! given: the slope over the new interval must lie within the speed limit (less what the
//! acceleration can add at the ends of a table, where `check` extrapolates), within the
//! acceleration limit of the slope before, and slow enough to stop before the range's end
//! at the acceleration limit. A pose outside is replaced by the pose whose actuator values
//! are the nearest allowed (each actuator's slope clamped; the pose found by forward
//! kinematics from the planner's), and counted: the planner's own state goes on, and the
//! guard lets the motion back onto it as fast as the limits allow.

use crate::analysis::workspace;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// The guard of one rig.
#[derive(Clone, Debug)]
pub struct ActuatorGuard {
    geometry: Geometry,
    limits: Limits,
    /// The range, the margin taken off (`±∞` where unset).
    range: (f64, f64),
    /// Speed and acceleration limits, the margin taken off.
    speed: Option<f64>,
    accel: Option<f64>,
    /// The last two values given and their times, newest last.
    history: Vec<(f64, [f64; 6], Pose)>,
    /// Poses replaced to keep the limits.
    pub held: usize,
    /// Poses for which no allowed pose was found: the last pose given again.
    pub stopped: usize,
}

impl ActuatorGuard {
    /// The guard of `geometry` within `limits`, each kept `margin` (a share) inside.
    pub fn new(geometry: &Geometry, limits: &Limits, margin: f64) -> Self {
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
            range: (
                lo.map_or(f64::NEG_INFINITY, |l| l + keep),
                hi.map_or(f64::INFINITY, |h| h - keep),
            ),
            // Half the planner's margin: the guard acts only where the exact motion left
            // the planner's envelope by more than half of it.
            speed: speed.map(|v| v * (1.0 - 0.5 * margin)),
            accel: accel.map(|a| a * (1.0 - 0.5 * margin)),
            history: Vec::with_capacity(3),
            held: 0,
            stopped: 0,
        }
    }

    /// The pose to give at time `t` for the planner's `pose`.
    pub fn pass(&mut self, t: f64, pose: Pose) -> Pose {
        let Ok(wanted) = self.geometry.actuator_values_at(&pose) else {
            return self.stop(t, pose);
        };
        let Some(&(t1, q1, last)) = self.history.last() else {
            self.remember(t, wanted, pose);
            return pose;
        };
        let dt = t - t1;
        if dt.is_nan() || dt <= 0.0 {
            self.remember(t, wanted, pose);
            return pose;
        }
        let before = match self.history.as_slice() {
            [(t0, q0, _), _] => Some((t1 - t0, *q0)),
            _ => None,
        };
        let mut allowed = [(0.0, 0.0); 6];
        let mut inside = true;
        for i in 0..6 {
            let previous = before.map(|(h0, q0)| ((q1[i] - q0[i]) / h0, h0));
            allowed[i] = self.slopes(q1[i], dt, previous);
            let s = (wanted[i] - q1[i]) / dt;
            inside &= s >= allowed[i].0 && s <= allowed[i].1;
        }
        if inside {
            self.remember(t, wanted, pose);
            return pose;
        }
        // The nearest allowed to what the planner wants, else to half of it, else the
        // motion going on as it was, at half its speed, or braking (each clamped to what
        // is allowed): the first whose pose keeps every other limit too.
        let going_on: [f64; 6] =
            std::array::from_fn(|i| before.map_or(0.0, |(h0, q0)| (q1[i] - q0[i]) / h0));
        // Last, braking as hard as allowed.
        let candidates = [(1.0, 1.0), (0.5, 1.0), (0.0, 1.0), (0.0, 0.5), (0.0, 0.0)];
        for (blend, keep_going) in candidates {
            let values: [f64; 6] = std::array::from_fn(|i| {
                let wanted_slope = (wanted[i] - q1[i]) / dt;
                let s = blend * wanted_slope + (1.0 - blend) * keep_going * going_on[i];
                q1[i] + s.clamp(allowed[i].0, allowed[i].1) * dt
            });
            // Found from the last pose given, whose values these are close to.
            if let Some(found) = self.pose_of(&values, &last) {
                self.held += 1;
                self.remember(t, values, found);
                return found;
            }
        }
        self.stop(t, pose)
    }

    /// The pose whose actuator values are `values`, found from `near`, when it keeps every
    /// limit as written.
    fn pose_of(&self, values: &[f64; 6], near: &Pose) -> Option<Pose> {
        let found = self.geometry.pose_from_actuator_values(values, near).ok()?;
        let exact = self
            .geometry
            .actuator_values_at(&found)
            .is_ok_and(|q| q.iter().zip(values).all(|(a, b)| (a - b).abs() < 1e-6));
        (exact && workspace::pose_within_limits_as_written(&self.geometry, &self.limits, &found))
            .then_some(found)
    }

    /// The slopes allowed over the next interval of `dt` from value `q`, after the slope
    /// `previous` over an interval of `h0` (none: the first interval, from rest).
    fn slopes(&self, q: f64, dt: f64, previous: Option<(f64, f64)>) -> (f64, f64) {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        if let Some(a) = self.accel {
            let (s0, h0) = previous.unwrap_or((0.0, dt));
            let change = a * 0.5 * (h0 + dt);
            (lo, hi) = (s0 - change, s0 + change);
        }
        let mut keep = |l: f64, h: f64| {
            lo = lo.max(l);
            hi = hi.min(h);
        };
        if let Some(v) = self.speed {
            keep(-v, v);
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
        if lo > hi {
            // The limits cannot all hold (a margin already used up): the acceleration's
            // bound nearest the others, which keeps the motion smooth.
            let mid = 0.5 * (lo + hi);
            (mid, mid)
        } else {
            (lo, hi)
        }
    }

    /// The last pose given again (none: `pose`).
    fn stop(&mut self, t: f64, pose: Pose) -> Pose {
        self.stopped += 1;
        let Some(&(_, q, last)) = self.history.last() else {
            return pose;
        };
        self.remember(t, q, last);
        last
    }

    fn remember(&mut self, t: f64, q: [f64; 6], pose: Pose) {
        if self.history.len() == 2 {
            self.history.remove(0);
        }
        self.history.push((t, q, pose));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::checks::rates::leg_accelerations;
    use crate::io::scenario::Scenario;

    #[test]
    fn a_motion_within_the_limits_passes_untouched_and_a_sudden_stop_is_braked() {
        let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let limits = Limits {
            leg_speed_max: Some(0.5),
            leg_accel_max: Some(2.0),
            ..s.limits
        };
        let mut guard = ActuatorGuard::new(&s.geometry, &limits, 0.0);
        let home = s.geometry.home_pose();
        let at = |z: f64| home.with_position(home.position + nalgebra::Vector3::new(0.0, 0.0, z));
        // Heaving at 0.1 m/s from rest after a gentle start (legs well inside the limits),
        // then stopping dead: the guard leaves the first part as it is and brakes the stop.
        let dt = 0.01;
        let mut z = 0.0;
        let mut v: f64 = 0.0;
        let mut times = Vec::new();
        let mut given = Vec::new();
        for k in 0..80 {
            let t = k as f64 * dt;
            if k < 40 {
                v = (v + 1.0 * dt).min(0.1);
                z += v * dt;
            }
            let planned = at(z);
            let out = guard.pass(t, planned);
            if k < 40 {
                assert_eq!(out, planned, "{k}");
            }
            times.push(t);
            given.push(s.geometry.leg_lengths(&out));
        }
        assert!(guard.held > 0 && guard.stopped == 0, "{guard:?}");
        let worst = leg_accelerations(&times, &given)
            .iter()
            .flatten()
            .fold(0.0f64, |m, a| m.max(a.abs()));
        assert!(worst <= 2.0 + 1e-6, "{worst}");
    }
}
