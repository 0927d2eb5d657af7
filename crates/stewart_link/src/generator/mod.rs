//! Online trajectory generation: each actuator follows a moving target as closely as its
//! speed, acceleration and jerk limits allow, inside its range.
//!
//! Every tick, each actuator plans the time-optimal, jerk-limited motion from its current
//! state (position, velocity, acceleration) to the target's state at the tick's time and
//! steps one tick along it — Ruckig's algorithm (Berscheid & Kröger, RSS 2021), through the
//! pure-Rust port `rsruckig`. Three cases, in this order:
//!
//! 1. **On the target.** A target whose motion is within the limits is reached within one
//!    tick: the value sent *is* the target (its own numbers, not recomputed).
//! 2. **Catching up a target that moves within the limits** (after the arming ramp, a hold,
//!    a jump): the gap to the target is planned to zero in the target's own frame, within
//!    nine tenths of what the target's motion leaves of each limit, and the actuator steps
//!    towards the target plus that shrinking gap — it closes in without overshooting and
//!    then stays on the target (a plan that only chased the target's present state would
//!    circle a fast-turning target for ever).
//! 3. **A target beyond the limits** (a jump, a motion too fast): approached as fast as the
//!    limits allow, along the plan that meets the target earliest where it will be
//!    (extrapolated at its acceleration; the meeting time found by doubling and bisection),
//!    or straight after it when no meeting is possible.
//!
//! Every step is a Ruckig plan from the actuator's own state, with the range as position
//! limits, so whatever the case the values never break a limit and the plan brakes in time
//! at the end of the range.
//!
//! A limit that is not set is not a limit: no jerk limit gives an acceleration-limited
//! (second-order) plan, no acceleration limit a speed-limited one; an unset speed limit is
//! replaced by a speed that crosses the whole range in 0.1 ms, faster than any tick.
//!
//! The target's velocity and acceleration come with it (a trajectory, differentiated) or from
//! its last three positions (see [`TargetHistory`]), so any source works: a sampled
//! trajectory, a teleoperated pose, a live signal. Exactness under a jerk limit needs the
//! first kind.

use rsruckig::prelude::{
    ControlInterface, DataArrayOrVec, IgnoreErrorHandler, InputParameter, OutputParameter,
    RuckigResult, Synchronization, TargetState, Trackig,
};
use thiserror::Error;

use crate::target::{ActuatorMotion, Sample};

/// Whether `m` needs more than twice the speed or acceleration of `bounds` on any actuator:
/// such a target jumped (a step of teleoperation, a seek, a wrap of a looping motion).
pub fn jumped(m: &ActuatorMotion, bounds: &[Bounds; 6]) -> bool {
    (0..6).any(|k| {
        m.velocity[k].abs() > 2.0 * bounds[k].speed
            || m.acceleration[k].abs() > 2.0 * bounds[k].accel
    })
}

/// The limits of one actuator as the generator uses them: finite speed, acceleration and
/// jerk that may be infinite (no limit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest and largest position.
    pub range: (f64, f64),
    /// Largest speed (finite).
    pub speed: f64,
    /// Largest acceleration (`f64::INFINITY`: none).
    pub accel: f64,
    /// Largest jerk (`f64::INFINITY`: none).
    pub jerk: f64,
}

impl Bounds {
    /// The bounds for optional limits (`None`: no limit; see the module's note on speed).
    pub fn new(
        range: (f64, f64),
        speed: Option<f64>,
        accel: Option<f64>,
        jerk: Option<f64>,
    ) -> Self {
        let width = (range.1 - range.0).abs().max(f64::MIN_POSITIVE);
        Self {
            range,
            speed: speed.unwrap_or(1e4 * width),
            accel: accel.unwrap_or(f64::INFINITY),
            // Ruckig plans a jerk limit only with an acceleration limit.
            jerk: if accel.is_some() {
                jerk.unwrap_or(f64::INFINITY)
            } else {
                f64::INFINITY
            },
        }
    }
}

/// The generator could not plan (it never should: the tests run it over thousands of
/// random sequences).
#[derive(Clone, Debug, PartialEq, Error)]
#[error("the trajectory generator failed for actuator {actuator} ({result}); disarmed")]
pub struct GeneratorError {
    /// Actuator number, from 1.
    pub actuator: usize,
    /// Ruckig's result code, in words.
    pub result: String,
}

/// The solver could not make a plan: its result code, in words.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("{0}")]
struct PlanFailed(String);

/// How a tick ended, per actuator.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Reached(pub [bool; 6]);

impl Reached {
    /// Whether every actuator is at its target.
    pub fn all(self) -> bool {
        self.0.iter().all(|&r| r)
    }
}

/// One Ruckig plan's buffers (allocation-free once built).
struct Planner {
    tracker: Trackig<1, IgnoreErrorHandler>,
    input: InputParameter<1>,
    output: OutputParameter<1>,
    target: TargetState<1>,
}

impl Planner {
    fn new() -> Self {
        let mut input = InputParameter::new(None);
        // One actuator per generator: `Time` only makes it honour a minimum duration.
        input.synchronization = Synchronization::Time;
        Self {
            tracker: Trackig::new(None, 0.001),
            input,
            output: OutputParameter::new(None),
            target: TargetState::new(None),
        }
    }

    /// Plan from `now` to `goal` (arriving no sooner than `minimum`) and step `dt` along
    /// it: the new state and the plan's duration.
    fn step(
        &mut self,
        dt: f64,
        now: State,
        goal: State,
        minimum: Option<f64>,
    ) -> Result<(State, f64), PlanFailed> {
        self.tracker.delta_time = dt;
        self.tracker.reset();
        // Without a jerk limit the plan is second order: accelerations may jump, and the
        // solver takes none at either end (a braking acceleration left in would make it
        // fail on the exact braking distance).
        let third_order = self.input.max_jerk[0].is_finite();
        let acceleration = |a: f64| if third_order { a } else { 0.0 };
        self.input.current_position[0] = now.0;
        self.input.current_velocity[0] = now.1;
        self.input.current_acceleration[0] = acceleration(now.2);
        self.input.minimum_duration = minimum;
        self.target.position[0] = goal.0;
        self.target.velocity[0] = goal.1;
        self.target.acceleration[0] = acceleration(goal.2);
        let result = self
            .tracker
            .update(&self.target, &self.input, &mut self.output)
            .unwrap_or(RuckigResult::Error);
        let next = (
            self.output.new_position[0],
            self.output.new_velocity[0],
            self.output.new_acceleration[0],
        );
        match result {
            RuckigResult::Working | RuckigResult::Finished
                if next.0.is_finite() && next.1.is_finite() && next.2.is_finite() =>
            {
                Ok((next, self.output.trajectory.get_duration()))
            }
            other => Err(PlanFailed(format!("{other:?}"))),
        }
    }
}

/// One actuator's tracking generator: the plan in its own coordinates (with the range as
/// position limits), the plan of its error from the target, and the previous target.
struct Axis {
    own: Planner,
    error: Planner,
    last_goal: Option<State>,
}

impl Axis {
    fn new(bounds: &Bounds) -> Self {
        let mut own = Planner::new();
        own.input.max_velocity[0] = bounds.speed;
        own.input.max_acceleration[0] = bounds.accel;
        own.input.max_jerk[0] = bounds.jerk;
        own.input.min_position = Some(DataArrayOrVec::Stack([bounds.range.0]));
        own.input.max_position = Some(DataArrayOrVec::Stack([bounds.range.1]));
        Self {
            own,
            error: Planner::new(),
            last_goal: None,
        }
    }

    /// One plan from `now` towards `goal` (the target at the end of the step, moving on
    /// with its velocity and acceleration), arriving `dt + ahead` seconds from now (the
    /// earliest the limits allow when `ahead` is `None`); steps `dt` along it. Returns the
    /// new state, and the plan's total duration.
    fn plan(
        &mut self,
        dt: f64,
        now: State,
        goal: State,
        ahead: Option<f64>,
    ) -> Result<(State, f64), PlanFailed> {
        let tau = ahead.unwrap_or(0.0);
        let (p, v, a) = goal;
        // Where the target will be `tau` after the step, were its acceleration constant.
        let a_max = self.own.input.max_acceleration[0];
        let a_held = if a_max.is_finite() {
            a.clamp(-a_max, a_max)
        } else {
            0.0
        };
        let ahead_goal = (
            p + v * tau + 0.5 * a_held * tau * tau,
            v + a_held * tau,
            a_held,
        );
        // Never sooner than the tick: a plan that ended within it would be extrapolated
        // past its end by the step.
        self.own.step(dt, now, ahead_goal, Some(dt + tau))
    }

    /// The step that closes the gap in the target's own frame: the error (`now` minus the
    /// previous target) planned to zero within what the target's motion leaves of each
    /// limit (nine tenths of it), stepped one tick and added to `goal` — a target moving
    /// within the limits is caught up without overshooting it. The step itself is the plan
    /// in the actuator's own coordinates towards that candidate, so it keeps the limits
    /// whatever the candidate. `None` when the target's own motion leaves no margin (it
    /// moves beyond the limits).
    fn converge(&mut self, dt: f64, now: State, goal: State) -> Result<Option<State>, PlanFailed> {
        // A target at rest is reached time-optimally by the plain plan.
        let Some(prev) = self.last_goal.filter(|&prev| prev != goal || goal.1 != 0.0) else {
            return Ok(None);
        };
        let limits = &self.own.input;
        let spare = |limit: f64, used: f64| 0.9 * (limit - used);
        let speed = spare(limits.max_velocity[0], prev.1.abs().max(goal.1.abs()));
        let accel = spare(limits.max_acceleration[0], prev.2.abs().max(goal.2.abs()));
        let jerk = spare(limits.max_jerk[0], ((goal.2 - prev.2) / dt).abs());
        if !(speed > 0.0 && accel > 0.0 && jerk > 0.0) {
            return Ok(None);
        }
        self.error.input.max_velocity[0] = speed;
        self.error.input.max_acceleration[0] = accel;
        self.error.input.max_jerk[0] = jerk;
        let gap = (now.0 - prev.0, now.1 - prev.1, now.2 - prev.2);
        let (e, _) = self.error.step(dt, gap, (0.0, 0.0, 0.0), None)?;
        let candidate = (goal.0 + e.0, goal.1 + e.1, goal.2 + e.2);
        // Onto the candidate within the tick when the limits allow it, else as close as
        // they do (the target's jerk changed within the tick more than the margin).
        let (next, _) = self.own.step(dt, now, candidate, Some(dt))?;
        Ok(Some(next))
    }

    /// Step `dt` from `now` towards the moving `goal`: onto it when the limits allow it
    /// within the step (then exactly its position), else along the time-optimal plan that
    /// meets the target where it will be (the earliest meeting the limits allow, found by
    /// doubling and bisection on the meeting time), or — a target that runs away faster
    /// than the limits — straight after it.
    fn step(&mut self, dt: f64, now: State, goal: State) -> Result<(State, bool), PlanFailed> {
        let result = self.follow(dt, now, goal);
        self.last_goal = Some(goal);
        result
    }

    /// A plan the solver could not make on the exact edge of a case (a braking distance
    /// that is exactly the distance left): made again with the acceleration and jerk
    /// limits a millionth lower, which moves it off the edge and keeps within the limits.
    /// Should that fail too (a gap of a few nanometres with a little speed left), the
    /// actuator brakes to rest as fast as the limits allow (Ruckig's velocity interface:
    /// no position target, so no edge case), and the next ticks start from rest.
    fn degenerate(&mut self, dt: f64, now: State, goal: State) -> Result<(State, f64), PlanFailed> {
        let input = &mut self.own.input;
        let (accel, jerk) = (input.max_acceleration[0], input.max_jerk[0]);
        input.max_acceleration[0] = accel * (1.0 - 1e-6);
        input.max_jerk[0] = jerk * (1.0 - 1e-6);
        let plan = self.own.step(dt, now, goal, None);
        self.own.input.max_acceleration[0] = accel;
        self.own.input.max_jerk[0] = jerk;
        if plan.is_ok() {
            return plan;
        }
        self.own.input.control_interface = ControlInterface::Velocity;
        let braked = self.own.step(dt, now, (now.0, 0.0, 0.0), None);
        self.own.input.control_interface = ControlInterface::Position;
        braked
    }

    fn follow(&mut self, dt: f64, now: State, goal: State) -> Result<(State, bool), PlanFailed> {
        // The solver may fail on a hair-thin case (a plan of exactly one tick): each stage
        // below then gives way to the next, and only a target no plan reaches fails.
        let plain = self.plan(dt, now, goal, None);
        // Onto the target within the tick: the target's own numbers (the plan's end differs
        // by the solver's precision only).
        if let Ok((next, duration)) = plain
            && duration <= dt * (1.0 + 1e-9)
            && close(next.0, goal.0)
        {
            let v = if close(next.1, goal.1) {
                goal.1
            } else {
                next.1
            };
            let a = if close(next.2, goal.2) {
                goal.2
            } else {
                next.2
            };
            return Ok(((goal.0, v, a), true));
        }
        if let Ok(Some(next)) = self.converge(dt, now, goal) {
            // On the target to the solver's precision (a plan of a tick that the solver found
            // a hair longer than the tick): counted as reached.
            let on_target = close(next.0, goal.0);
            return Ok((next, on_target));
        }
        let meets = |axis: &mut Self, tau: f64| {
            axis.plan(dt, now, goal, Some(tau))
                .ok()
                .filter(|&(_, duration)| duration <= dt + tau + 1e-12)
        };
        // Doubling: the first meeting time the limits allow.
        let mut low = 0.0;
        let mut high = dt;
        let mut found = None;
        while high <= MEETING_HORIZON_S {
            if let Some(plan) = meets(self, high) {
                found = Some((high, plan));
                break;
            }
            low = high;
            high *= 2.0;
        }
        let Some((mut high, mut best)) = found else {
            // It runs away: chase it at the limits (straight at it, no tick minimum, if the
            // plain plan failed).
            let (next, _) = match plain {
                Ok(plan) => plan,
                Err(_) => self.degenerate(dt, now, goal)?,
            };
            return Ok((next, false));
        };
        // Bisection down to a tenth of a tick (re-planned every tick anyway).
        while high - low > 0.1 * dt {
            let mid = 0.5 * (low + high);
            match meets(self, mid) {
                Some(plan) => {
                    high = mid;
                    best = plan;
                }
                None => low = mid,
            }
        }
        Ok((best.0, false))
    }
}

/// Position, velocity and acceleration of one actuator.
type State = (f64, f64, f64);

/// Whether `x` is `y` to the solver's precision (Ruckig's plans end on their target to about
/// 1e-8 relative): then `y`'s own numbers are sent.
fn close(x: f64, y: f64) -> bool {
    (x - y).abs() <= 1e-8 * (1.0 + y.abs())
}

/// The furthest ahead a meeting with a moving target is looked for, seconds.
const MEETING_HORIZON_S: f64 = 20.0;

/// Six actuators following their targets.
pub struct Generator {
    axes: [Axis; 6],
    bounds: [Bounds; 6],
    state: ActuatorMotion,
}

impl std::fmt::Debug for Generator {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Generator")
            .field("bounds", &self.bounds)
            .field("state", &self.state)
            .finish_non_exhaustive()
    }
}

impl Clone for Generator {
    fn clone(&self) -> Self {
        let mut copy = Self::new(self.bounds);
        copy.state = self.state;
        copy
    }
}

impl Generator {
    /// At rest at the middle of each range.
    pub fn new(bounds: [Bounds; 6]) -> Self {
        Self {
            axes: std::array::from_fn(|k| Axis::new(&bounds[k])),
            bounds,
            state: ActuatorMotion::at_rest(bounds.map(|b| 0.5 * (b.range.0 + b.range.1))),
        }
    }

    /// The bounds of each actuator.
    pub fn bounds(&self) -> &[Bounds; 6] {
        &self.bounds
    }

    /// Where the actuators are and how they move (the last values stepped to).
    pub fn state(&self) -> &ActuatorMotion {
        &self.state
    }

    /// Put the actuators at rest at `position` (arming, a disarmed platform standing there).
    pub fn rest_at(&mut self, position: [f64; 6]) {
        self.state = ActuatorMotion::at_rest(position);
        for axis in &mut self.axes {
            axis.last_goal = None;
        }
    }

    /// Step `dt` seconds towards `target` (the state the actuators should be in at the end
    /// of the step), no faster than `speed_cap` where given (the way home). Returns which
    /// actuators are exactly at their target's position after the step.
    pub fn step(
        &mut self,
        dt: f64,
        target: &ActuatorMotion,
        speed_cap: Option<f64>,
    ) -> Result<Reached, GeneratorError> {
        let mut reached = [false; 6];
        if dt <= 0.0 {
            for (k, r) in reached.iter_mut().enumerate() {
                *r = self.state.position[k] == target.position[k];
            }
            return Ok(Reached(reached));
        }
        for (k, axis) in self.axes.iter_mut().enumerate() {
            let b = &self.bounds[k];
            axis.own.input.max_velocity[0] = speed_cap.map_or(b.speed, |c| c.min(b.speed));
            let now = (
                self.state.position[k],
                self.state.velocity[k],
                self.state.acceleration[k],
            );
            let goal = (
                target.position[k],
                target.velocity[k],
                target.acceleration[k],
            );
            let (next, at_target) = axis.step(dt, now, goal).map_err(|failed| GeneratorError {
                actuator: k + 1,
                result: failed.0,
            })?;
            self.state.position[k] = next.0;
            self.state.velocity[k] = next.1;
            self.state.acceleration[k] = next.2;
            reached[k] = at_target;
        }
        Ok(Reached(reached))
    }
}

/// The target's last positions and their times, from which its velocity and acceleration
/// are estimated: with three samples, the derivatives at the newest of the parabola through
/// them (exact for a parabola, on uneven ticks too); with two, of the parabola that left the
/// first at rest; with one, rest.
#[derive(Clone, Copy, Debug, Default)]
pub struct TargetHistory {
    samples: [(f64, [f64; 6]); 3],
    len: usize,
}

impl TargetHistory {
    /// Forget the past (a held target, a new arming).
    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// Add the target at time `t` and return its motion — the sample's own, or estimated —
    /// unless that motion [`jumped`]: then it is taken as a target at rest where it now is
    /// (the past forgotten). A time not after the newest replaces the newest.
    pub fn push_within(&mut self, t: f64, sample: &Sample, bounds: &[Bounds; 6]) -> ActuatorMotion {
        let m = match sample {
            Sample::At(p) => self.push(t, *p),
            Sample::Moving(m) => {
                self.push(t, m.position);
                *m
            }
        };
        if jumped(&m, bounds) {
            self.clear();
            return self.push(t, *sample.position());
        }
        m
    }

    /// Add the target at time `t` and return its estimated motion. A time not after the
    /// newest replaces the newest.
    pub fn push(&mut self, t: f64, position: [f64; 6]) -> ActuatorMotion {
        if self.len > 0 && t <= self.samples[self.len - 1].0 {
            self.len -= 1;
        }
        if self.len == 3 {
            self.samples.rotate_left(1);
            self.len = 2;
        }
        self.samples[self.len] = (t, position);
        self.len += 1;
        let mut m = ActuatorMotion::at_rest(position);
        match &self.samples[..self.len] {
            [(t1, p1), (t2, p2), (t3, p3)] => {
                let (h1, h2) = (t2 - t1, t3 - t2);
                for k in 0..6 {
                    let (d1, d2) = ((p2[k] - p1[k]) / h1, (p3[k] - p2[k]) / h2);
                    let second = 2.0 * (d2 - d1) / (h1 + h2);
                    m.acceleration[k] = second;
                    m.velocity[k] = d2 + 0.5 * h2 * second;
                }
            }
            // Two samples: the parabola that left the first at rest (a ramp's start, a
            // platform that was held).
            [(t1, p1), (t2, p2)] => {
                let h = t2 - t1;
                for k in 0..6 {
                    m.velocity[k] = 2.0 * (p2[k] - p1[k]) / h;
                    m.acceleration[k] = 2.0 * (p2[k] - p1[k]) / (h * h);
                }
            }
            _ => {}
        }
        m
    }
}

#[cfg(test)]
mod tests;
