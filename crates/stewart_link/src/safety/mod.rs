//! The link's safety state machine: what may be sent, tick by tick.
//!
//! ```text
//!  DISARMED ──arm──▶ ARMING ──ramp done──▶ ARMED
//!     ▲                 │                    │
//!     │              e-stop               e-stop
//!     │                 ▼                    ▼
//!     └──held / home reached ◀──────── STOPPING ──second stop──▶ DISARMED (emergency)
//! ```
//!
//! Every tick takes the time (seconds, from the caller's clock: the sender's absolute
//! deadlines, or a test's numbers) and the target the motion asks for — six actuator values
//! in their natural units, or why there is none (an unreachable pose). It returns what to
//! send. The values sent always come out of the online trajectory generator
//! ([`crate::generator`]), so they never break the range, speed, acceleration or jerk
//! limits. The rules:
//!
//! - **Disarmed**: nothing moves; the last values are repeated with the armed flag clear.
//! - **Arming** ramps from where the platform is (the values given to [`Supervisor::arm`],
//!   usually the home set-points) to the live target over the ramp time (longer when the
//!   distance needs it, so that the ramp's own motion uses at most a quarter of each limit;
//!   or as long as [`planned_ramp`] found against the whole motion, when it is known), along a
//!   smootherstep (zero speed and acceleration at both ends), then becomes **armed**.
//! - While armed, a target whose motion is within the limits is sent exactly as it is. A
//!   target that would need more (a jump, a motion too fast) is approached time-optimally
//!   at the limits, and the reason is reported. A target outside an actuator's range, or no
//!   target at all (unreachable), is *held*: the platform is brought to rest as fast as the
//!   limits allow and stays there, and the reason is reported.
//! - **E-stop** (a button, Esc, Ctrl-C) goes to **stopping** at once: either hold where it
//!   is and disarm (the e-stop flag set on that frame), or return home no faster than the
//!   home speed, braking first within the limits; the frame that reaches home carries
//!   exactly the home values (armed, home flag), and the next one disarms.
//! - A **second stop** while stopping is an emergency: disarm at once where the platform
//!   is, with the e-stop flag, and say so ([`Supervisor::emergency`]).
//! - A **fault** (the port vanished, a write failed) disarms at once with its message.
//!
//! Nothing here sends anything: the caller encodes what [`Supervisor::tick`] returns.

use crate::generator::{Bounds, Generator, TargetHistory};

use crate::target::{ActuatorMotion, Sample, TargetError};

/// The state of the link.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkState {
    /// Not driving the platform.
    Disarmed,
    /// Ramping from the platform's pose to the target.
    Arming,
    /// Following the target.
    Armed,
    /// Stopping after an e-stop.
    Stopping,
}

/// What an e-stop does after stopping the stream of new targets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StopMode {
    /// Hold the last values and disarm at once.
    Hold,
    /// Return to the home values, each actuator no faster than `speed` (natural units per
    /// second), then disarm.
    Home {
        /// Speed of the return, natural units per second.
        speed: f64,
    },
}

/// The limits every value sent must keep, per actuator, in natural units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActuatorLimits {
    /// Smallest and largest value (stroke in metres, servo range in degrees).
    pub range: [(f64, f64); 6],
    /// Largest speed, units per second (`None`: unlimited).
    pub speed: Option<f64>,
    /// Largest acceleration, units per second squared (`None`: unlimited).
    pub accel: Option<f64>,
    /// Largest jerk, units per second cubed (`None`: unlimited; applies only with an
    /// acceleration limit).
    pub jerk: Option<f64>,
}

impl ActuatorLimits {
    /// The generator's bounds of each actuator.
    fn bounds(&self) -> [Bounds; 6] {
        self.range
            .map(|range| Bounds::new(range, self.speed, self.accel, self.jerk))
    }
}

/// What one tick decided.
#[derive(Clone, Debug, PartialEq)]
pub struct Tick {
    /// The state after the tick.
    pub state: LinkState,
    /// The values to send, natural units.
    pub values: [f64; 6],
    /// Whether the frame goes out armed.
    pub armed: bool,
    /// Whether the frame carries the e-stop flag (the first frame after an e-stop).
    pub estop: bool,
    /// Whether the values lead home after a stop (the frame carries the home flag).
    pub home: bool,
    /// Why the values differ from the target, when they do (held, limited), or why the link
    /// disarmed.
    pub note: Option<String>,
}

/// The safety state machine.
#[derive(Clone, Debug)]
pub struct Supervisor {
    limits: ActuatorLimits,
    ramp_s: f64,
    stop: StopMode,
    home: [f64; 6],
    state: LinkState,
    /// Where the actuators are and how they move: the values sent come from here.
    generator: Generator,
    /// The target's recent positions (its velocity and acceleration).
    history: TargetHistory,
    last_time: Option<f64>,
    /// Start of the arming ramp and where it starts from.
    ramp_from: Option<(f64, [f64; 6])>,
    /// How long this arming's ramp lasts (fixed at its first tick).
    ramp_len: Option<f64>,
    /// The length of the first arming's ramp, planned against the whole motion by the
    /// caller ([`Supervisor::plan_first_ramp`]).
    first_ramp: Option<f64>,
    estop_pending: bool,
    /// The way home has sent the home values; the next tick disarms.
    at_home: bool,
    /// A second stop came during the way home.
    emergency: bool,
    /// Where a held target brings the platform to rest (fixed when the hold begins).
    hold_at: Option<[f64; 6]>,
    fault: Option<String>,
}

impl Supervisor {
    /// A disarmed supervisor whose platform stands at `home`.
    pub fn new(limits: ActuatorLimits, ramp_s: f64, stop: StopMode, home: [f64; 6]) -> Self {
        let mut generator = Generator::new(limits.bounds());
        generator.rest_at(home);
        Self {
            limits,
            ramp_s: ramp_s.max(0.0),
            stop,
            home,
            state: LinkState::Disarmed,
            generator,
            history: TargetHistory::default(),
            last_time: None,
            ramp_from: None,
            ramp_len: None,
            first_ramp: None,
            estop_pending: false,
            at_home: false,
            emergency: false,
            hold_at: None,
            fault: None,
        }
    }

    /// The current state.
    pub fn state(&self) -> LinkState {
        self.state
    }

    /// The limits the values keep.
    pub fn limits(&self) -> &ActuatorLimits {
        &self.limits
    }

    /// The home values the way home leads to.
    pub fn home(&self) -> &[f64; 6] {
        &self.home
    }

    /// The last values sent.
    pub fn last(&self) -> &[f64; 6] {
        &self.generator.state().position
    }

    /// The last values sent with their velocity and acceleration.
    pub fn motion(&self) -> &ActuatorMotion {
        self.generator.state()
    }

    /// Whether a second stop ended the way home (the platform was left where it was).
    pub fn emergency(&self) -> bool {
        self.emergency
    }

    /// Start arming at time `t` from `from` (where the platform is: its last values, or
    /// home). Only from disarmed.
    pub fn arm(&mut self, t: f64, from: [f64; 6]) {
        if self.state == LinkState::Disarmed {
            self.state = LinkState::Arming;
            self.ramp_from = Some((t, from));
            self.ramp_len = self.first_ramp.take();
            self.generator.rest_at(from);
            self.history.clear();
            self.last_time = Some(t);
            self.fault = None;
            self.at_home = false;
            self.emergency = false;
        }
    }

    /// Emergency stop: no new target is followed from now on. A second one while stopping
    /// (on the way home) disarms at once where the platform is.
    pub fn estop(&mut self) {
        match self.state {
            LinkState::Disarmed => {}
            LinkState::Stopping => {
                self.state = LinkState::Disarmed;
                self.estop_pending = true;
                self.emergency = true;
                let here = self.generator.state().position;
                self.generator.rest_at(here);
                self.fault = Some(
                    "second stop: emergency stop on the way home, disarmed where the platform is"
                        .to_owned(),
                );
            }
            LinkState::Arming | LinkState::Armed => {
                self.state = LinkState::Stopping;
                self.estop_pending = true;
            }
        }
    }

    /// Disarm at once (the stream was closed, or a fault), with the reason to show.
    pub fn fault(&mut self, reason: impl Into<String>) {
        self.state = LinkState::Disarmed;
        self.ramp_from = None;
        self.fault = Some(reason.into());
    }

    /// One tick at time `t` with the motion's `target` positions (or why there is none);
    /// the target's velocity and acceleration are estimated from the last targets.
    pub fn tick(&mut self, t: f64, target: Result<[f64; 6], TargetError>) -> Tick {
        self.tick_sample(t, target.map(Sample::At))
    }

    /// One tick at time `t` with the motion's `target` (or why there is none).
    pub fn tick_sample(&mut self, t: f64, target: Result<Sample, TargetError>) -> Tick {
        let dt = self.last_time.map_or(0.0, |t0| (t - t0).max(0.0));
        let mut home = false;
        let note = match self.state {
            LinkState::Disarmed => self.fault.take(),
            LinkState::Arming => self.arming(t, dt, target),
            LinkState::Armed => self.follow(t, dt, target),
            LinkState::Stopping => {
                let (note, leads_home) = self.stopping(dt);
                home = leads_home;
                note
            }
        };
        let estop = std::mem::take(&mut self.estop_pending);
        self.last_time = Some(t);
        Tick {
            state: self.state,
            values: *self.last(),
            armed: home || matches!(self.state, LinkState::Arming | LinkState::Armed),
            estop,
            home,
            note,
        }
    }

    /// Make the first arming's ramp last `ramp_s`, found by [`planned_ramp`] against the
    /// whole motion the target will follow (known in advance: a trajectory from its
    /// start), instead of the length the supervisor would choose without foreseeing it.
    /// The generator keeps every limit whatever the ramp.
    pub fn plan_first_ramp(&mut self, ramp_s: f64) {
        if ramp_s.is_finite() && ramp_s >= 0.0 {
            self.first_ramp = Some(ramp_s);
        }
    }

    /// The ramp from where arming started to the live target.
    fn arming(&mut self, t: f64, dt: f64, target: Result<Sample, TargetError>) -> Option<String> {
        let Some((t0, from)) = self.ramp_from else {
            self.state = LinkState::Armed;
            return self.follow(t, dt, target);
        };
        let target = match self.checked(target) {
            Ok(v) => v,
            // Nowhere safe to ramp to: come to rest where the ramp is.
            Err(why) => return self.hold(dt, why.to_string()),
        };
        let mut lengthened = None;
        let ramp_s = match self.ramp_len {
            Some(len) => len,
            None => {
                let motion = match &target {
                    Sample::At(p) => ActuatorMotion::at_rest(*p),
                    Sample::Moving(m) => *m,
                };
                let len = ramp_needed(self.ramp_s, &from, &motion, &self.limits);
                if len > self.ramp_s {
                    lengthened = Some(format!(
                        "arming over {len:.2} s, longer than the {} s asked: the ramp's own motion stays within a quarter of each limit",
                        self.ramp_s
                    ));
                }
                *self.ramp_len.insert(len)
            }
        };
        let (u, rate) = if ramp_s > 0.0 {
            (((t - t0) / ramp_s).clamp(0.0, 1.0), 1.0 / ramp_s)
        } else {
            (1.0, 0.0)
        };
        let wanted = ramp(&from, &target, u, rate);
        if u >= 1.0 {
            self.state = LinkState::Armed;
            self.ramp_from = None;
        }
        self.track(t, dt, wanted).or(lengthened)
    }

    /// Follow the target while armed.
    fn follow(&mut self, t: f64, dt: f64, target: Result<Sample, TargetError>) -> Option<String> {
        match self.checked(target) {
            Ok(v) => self.track(t, dt, v),
            Err(why) => self.hold(dt, format!("holding the last good set-point: {why}")),
        }
    }

    /// Step towards `wanted` (its motion estimated from the last targets); say why when
    /// it is not reached.
    fn track(&mut self, t: f64, dt: f64, wanted: Sample) -> Option<String> {
        self.hold_at = None;
        let target = self
            .history
            .push_within(t, &wanted, self.generator.bounds());
        match self.generator.step(dt, &target, None) {
            Ok(reached) if reached.all() => None,
            Ok(reached) => Some(format!(
                "approaching the target at the {} limit",
                self.binding_limit(&target, reached.0)
            )),
            Err(e) => self.failed(e.to_string()),
        }
    }

    /// Bring the actuators to rest where they can (a held target), with `why`.
    fn hold(&mut self, dt: f64, why: String) -> Option<String> {
        self.history.clear();
        let here = *self.generator.state();
        let bounds = self.generator.bounds();
        let rest = ActuatorMotion::at_rest(
            *self
                .hold_at
                .get_or_insert_with(|| braking_point(&here, bounds)),
        );
        match self.generator.step(dt, &rest, None) {
            Ok(_) => Some(why),
            Err(e) => self.failed(e.to_string()),
        }
    }

    /// The generator failed (it never should): disarm where the platform is.
    fn failed(&mut self, why: String) -> Option<String> {
        self.fault(why.clone());
        self.fault = None;
        Some(why)
    }

    /// Which limit holds back the actuator furthest from its target (for the note).
    fn binding_limit(&self, target: &ActuatorMotion, reached: [bool; 6]) -> &'static str {
        let m = self.generator.state();
        let Some(k) = (0..6).filter(|&k| !reached[k]).max_by(|&i, &j| {
            let gap = |k: usize| (target.position[k] - m.position[k]).abs();
            gap(i).total_cmp(&gap(j))
        }) else {
            return "speed";
        };
        let b = &self.generator.bounds()[k];
        let near =
            |value: f64, limit: f64| limit.is_finite() && value.abs() >= limit * (1.0 - 1e-6);
        if near(m.velocity[k], b.speed) {
            "speed"
        } else if near(m.acceleration[k], b.accel) {
            "acceleration"
        } else if b.jerk.is_finite() {
            "jerk"
        } else if b.accel.is_finite() {
            "acceleration"
        } else {
            "speed"
        }
    }

    /// After an e-stop: hold and disarm, or go home at the home speed and then disarm.
    /// Returns the note and whether the frame leads home.
    fn stopping(&mut self, dt: f64) -> (Option<String>, bool) {
        match self.stop {
            StopMode::Hold => {
                self.state = LinkState::Disarmed;
                let here = self.generator.state().position;
                self.generator.rest_at(here);
                (
                    Some("e-stop: holding where it is, disarmed".to_owned()),
                    false,
                )
            }
            StopMode::Home { .. } if self.at_home => {
                self.state = LinkState::Disarmed;
                (Some("e-stop: at home, disarmed".to_owned()), false)
            }
            StopMode::Home { speed } => {
                match self.generator.step(
                    dt,
                    &ActuatorMotion::at_rest(self.home),
                    Some(speed.abs()),
                ) {
                    Ok(reached) if reached.all() && self.generator.state().velocity == [0.0; 6] => {
                        self.at_home = true;
                        (Some("e-stop: home reached exactly".to_owned()), true)
                    }
                    Ok(_) => (Some("e-stop: returning home".to_owned()), true),
                    Err(e) => (self.failed(e.to_string()), false),
                }
            }
        }
    }

    /// The target if every value is a finite number inside its range, else why not.
    fn checked(&self, target: Result<Sample, TargetError>) -> Result<Sample, TargetError> {
        let v = target?;
        for (k, (&x, &(lo, hi))) in v.position().iter().zip(&self.limits.range).enumerate() {
            if !x.is_finite() {
                return Err(TargetError::NotFinite {
                    actuator: k + 1,
                    value: x,
                });
            }
            if x < lo || x > hi {
                return Err(TargetError::OutOfRange {
                    actuator: k + 1,
                    value: x,
                    min: lo,
                    max: hi,
                });
            }
        }
        Ok(v)
    }
}

/// The smootherstep `6u⁵ − 15u⁴ + 10u³` the arming ramp blends along (0 to 1, with zero
/// speed and acceleration at both ends).
pub fn smootherstep(u: f64) -> f64 {
    u * u * u * (10.0 + u * (6.0 * u - 15.0))
}

/// The shortest arming ramp, no shorter than `at_least` seconds, along which the blend
/// from `from` toward a target known in advance — `target(t)`, its values at each time of
/// the ramp, `None` where it has none — stays within [`PLANNED_SHARE`] of each speed,
/// acceleration and jerk limit, checked every `step` seconds by finite differences of the
/// blend (what the generator is asked to follow). `None` when the target has no values
/// somewhere along the ramp or no ramp up to ten minutes fits.
pub fn planned_ramp(
    limits: &ActuatorLimits,
    from: &[f64; 6],
    at_least: f64,
    target: impl Fn(f64) -> Option<[f64; 6]>,
    step: f64,
) -> Option<f64> {
    let share = |l: Option<f64>| l.map_or(f64::INFINITY, |l| PLANNED_SHARE * l);
    let (speed, accel) = (share(limits.speed), share(limits.accel));
    let jerk = if accel.is_finite() {
        share(limits.jerk)
    } else {
        f64::INFINITY
    };
    // Whether a ramp of `len` seconds keeps the limits (None: the target has no values).
    let fits = |len: f64| -> Option<bool> {
        let n = (len / step).ceil() as usize + 3;
        let mut blend = Vec::with_capacity(n + 1);
        for k in 0..=n {
            let t = k as f64 * step;
            // The blend starts where the platform is, whatever the length (a ramp of
            // zero jumps at the first step, which the limits then refuse).
            let u = if len > 0.0 {
                (t / len).min(1.0)
            } else if t > 0.0 {
                1.0
            } else {
                0.0
            };
            let s = smootherstep(u);
            let q = target(t)?;
            blend.push(std::array::from_fn::<f64, 6, _>(|j| {
                from[j] + (q[j] - from[j]) * s
            }));
        }
        let h = step;
        let within = (0..6).all(|j| {
            let v = |k: usize| blend[k][j];
            (0..n).all(|k| ((v(k + 1) - v(k)) / h).abs() <= speed)
                && (1..n).all(|k| ((v(k + 1) - 2.0 * v(k) + v(k - 1)) / (h * h)).abs() <= accel)
                && (1..n - 1).all(|k| {
                    ((v(k + 2) - 3.0 * v(k + 1) + 3.0 * v(k) - v(k - 1)) / (h * h * h)).abs()
                        <= jerk
                })
        });
        Some(within)
    };
    shortest_fitting(at_least.max(0.0), fits)
}

/// The longest arming ramp either rule gives, seconds: beyond it a ramp is not planned.
const MAX_RAMP_S: f64 = 600.0;

/// The shortest length, no shorter than `at_least`, that `fits` (to a thousandth, by
/// doubling then bisection: longer ramps fit more easily); `None` when none up to
/// [`MAX_RAMP_S`] does or `fits` cannot tell.
fn shortest_fitting(at_least: f64, fits: impl Fn(f64) -> Option<bool>) -> Option<f64> {
    if fits(at_least)? {
        return Some(at_least);
    }
    let mut low = at_least.max(1e-3);
    let mut high = 2.0 * low;
    while !fits(high)? {
        low = high;
        high *= 2.0;
        if high > MAX_RAMP_S {
            return None;
        }
    }
    while high - low > 1e-3 * high {
        let mid = 0.5 * (low + high);
        if fits(mid)? {
            high = mid;
        } else {
            low = mid;
        }
    }
    Some(high)
}

/// The arming ramp at `u` (0 to 1; `rate` = du/dt): from `from` to the target along a
/// smootherstep, with its velocity and acceleration when the target has them.
fn ramp(from: &[f64; 6], target: &Sample, u: f64, rate: f64) -> Sample {
    let s = smootherstep(u);
    let blend =
        |p: &[f64; 6]| -> [f64; 6] { std::array::from_fn(|k| from[k] + (p[k] - from[k]) * s) };
    match target {
        Sample::At(p) => Sample::At(blend(p)),
        Sample::Moving(m) => {
            // d/dt of from + (p − from)·s(u), with u' = rate.
            let s1 = 30.0 * u * u * (1.0 - u) * (1.0 - u) * rate;
            let s2 = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) * rate * rate;
            Sample::Moving(ActuatorMotion {
                position: blend(&m.position),
                velocity: std::array::from_fn(|k| {
                    m.velocity[k] * s + (m.position[k] - from[k]) * s1
                }),
                acceleration: std::array::from_fn(|k| {
                    m.acceleration[k] * s
                        + 2.0 * m.velocity[k] * s1
                        + (m.position[k] - from[k]) * s2
                }),
            })
        }
    }
}

/// The share of each limit a ramp toward a target it cannot foresee may use itself: the
/// rest is room for the target's own motion, whatever it does during the ramp.
pub const RAMP_SHARE: f64 = 0.25;

/// The share of each limit a ramp planned against the target's whole motion may use,
/// ramp and motion together ([`planned_ramp`]): the rest is room for the generator's
/// discrete steps.
pub const PLANNED_SHARE: f64 = 0.95;

/// The shortest ramp, no shorter than `at_least`, along which the smootherstep's own terms
/// use at most [`RAMP_SHARE`] of each limit, so that the generator follows the ramp itself
/// with room for the target's motion. From `from` to a target at `to` moving with
/// `velocity` and `acceleration`, the blend `from + (p − from)·s(t/T)` adds, per
/// derivative, the distance D times s's peaks (1.875/T, 5.774/T², 60/T³) and the cross
/// terms of the target's velocity v and acceleration a: speed D·1.875/T; acceleration
/// 2v·1.875/T + D·5.774/T²; jerk 3a·1.875/T + 3v·5.774/T² + D·60/T³.
fn ramp_needed(
    at_least: f64,
    from: &[f64; 6],
    to: &ActuatorMotion,
    limits: &ActuatorLimits,
) -> f64 {
    const S1: f64 = 1.875;
    const S2: f64 = 5.773_502_691_896_258;
    const S3: f64 = 60.0;
    let most = |values: &[f64; 6]| values.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
    let gap: [f64; 6] = std::array::from_fn(|k| to.position[k] - from[k]);
    let (d, v, a) = (most(&gap), most(&to.velocity), most(&to.acceleration));
    let share = |limit: Option<f64>| limit.map_or(f64::INFINITY, |l| RAMP_SHARE * l);
    let (speed, accel) = (share(limits.speed), share(limits.accel));
    let jerk = if accel.is_finite() {
        share(limits.jerk)
    } else {
        f64::INFINITY
    };
    let fits = |t: f64| {
        d * S1 / t <= speed
            && 2.0 * v * S1 / t + d * S2 / (t * t) <= accel
            && 3.0 * a * S1 / t + 3.0 * v * S2 / (t * t) + d * S3 / (t * t * t) <= jerk
    };
    if !(d + v + a).is_finite() || fits(at_least.max(1e-9)) {
        return at_least;
    }
    shortest_fitting(at_least, |t| Some(fits(t))).unwrap_or(MAX_RAMP_S)
}

/// Where each actuator comes to rest when it brakes as hard as its limits allow from
/// `here` (kept inside its range).
fn braking_point(here: &ActuatorMotion, bounds: &[Bounds; 6]) -> [f64; 6] {
    std::array::from_fn(|k| {
        let b = &bounds[k];
        let (v, a) = (here.velocity[k], here.acceleration[k]);
        let distance = if b.accel.is_finite() {
            // Second order: v²/2A; with a jerk limit, the acceleration first returns to
            // the braking sign (a bound that is a little long is harmless: the plan to the
            // point is time-optimal and brakes on the way).
            let ramp = if b.jerk.is_finite() {
                (a.abs() / b.jerk) * v.abs() + a.abs().powi(3) / (b.jerk * b.jerk)
            } else {
                0.0
            };
            v * v / (2.0 * b.accel) + ramp
        } else {
            0.0
        };
        (here.position[k] + v.signum() * distance).clamp(b.range.0, b.range.1)
    })
}

#[cfg(test)]
mod tests;
