//! The link's safety state machine: what may be sent, tick by tick.
//!
//! ```text
//!  DISARMED ──arm──▶ ARMING ──ramp done──▶ ARMED
//!     ▲                 │                    │
//!     │              e-stop               e-stop
//!     │                 ▼                    ▼
//!     └──held / home reached ◀──────── STOPPING
//! ```
//!
//! Every tick takes the time (seconds, from the caller's clock: the sender's absolute
//! deadlines, or a test's numbers) and the target the motion asks for — six actuator values
//! in their natural units, or why there is none (an unreachable pose). It returns what to
//! send. The rules:
//!
//! - **Disarmed**: nothing moves; the last values are repeated with the armed flag clear.
//! - **Arming** ramps from where the platform is (the values given to [`Supervisor::arm`],
//!   usually the home set-points) to the live target over the ramp time, along a smoothstep
//!   (zero speed at both ends), then becomes **armed**.
//! - While armed, a target outside an actuator's range, or no target at all (unreachable),
//!   is *held*: the platform stays at the last good values — brought to rest there within
//!   the acceleration limit when it was moving — and the reason is reported. A target that
//!   would need more than the speed or acceleration limit is approached at the limit,
//!   slowing in time to stop at it (the values sent never break a limit; the range is the
//!   hard one), and the reason is reported.
//! - **E-stop** (a button, Esc, Ctrl-C) goes to **stopping** at once: either hold where it
//!   is and disarm (the e-stop flag set on that frame), or return home no faster than the
//!   home speed, then disarm.
//! - A **fault** (the port vanished, a write failed) disarms at once with its message.
//!
//! Nothing here sends anything: the caller encodes what [`Supervisor::tick`] returns.

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
    /// Last values sent, their time, and their speed per actuator.
    last: [f64; 6],
    last_time: Option<f64>,
    velocity: [f64; 6],
    /// Start of the arming ramp and where it starts from.
    ramp_from: Option<(f64, [f64; 6])>,
    estop_pending: bool,
    fault: Option<String>,
}

impl Supervisor {
    /// A disarmed supervisor whose platform stands at `home`.
    pub fn new(limits: ActuatorLimits, ramp_s: f64, stop: StopMode, home: [f64; 6]) -> Self {
        Self {
            limits,
            ramp_s: ramp_s.max(0.0),
            stop,
            home,
            state: LinkState::Disarmed,
            last: home,
            last_time: None,
            velocity: [0.0; 6],
            ramp_from: None,
            estop_pending: false,
            fault: None,
        }
    }

    /// The current state.
    pub fn state(&self) -> LinkState {
        self.state
    }

    /// The last values sent.
    pub fn last(&self) -> &[f64; 6] {
        &self.last
    }

    /// Start arming at time `t` from `from` (where the platform is: its last values, or
    /// home). Only from disarmed.
    pub fn arm(&mut self, t: f64, from: [f64; 6]) {
        if self.state == LinkState::Disarmed {
            self.state = LinkState::Arming;
            self.ramp_from = Some((t, from));
            self.last = from;
            self.last_time = Some(t);
            self.velocity = [0.0; 6];
            self.fault = None;
        }
    }

    /// Emergency stop: no new target is followed from now on.
    pub fn estop(&mut self) {
        if self.state != LinkState::Disarmed {
            self.state = LinkState::Stopping;
            self.estop_pending = true;
        }
    }

    /// Disarm at once (the stream was closed, or a fault), with the reason to show.
    pub fn fault(&mut self, reason: impl Into<String>) {
        self.state = LinkState::Disarmed;
        self.ramp_from = None;
        self.fault = Some(reason.into());
    }

    /// One tick at time `t` with the motion's `target` (or why there is none).
    pub fn tick(&mut self, t: f64, target: Result<[f64; 6], String>) -> Tick {
        let dt = self.last_time.map_or(0.0, |t0| (t - t0).max(0.0));
        let (values, note) = match self.state {
            LinkState::Disarmed => (self.last, self.fault.take()),
            LinkState::Arming => self.arming(t, dt, target),
            LinkState::Armed => self.follow(dt, target),
            LinkState::Stopping => self.stopping(dt),
        };
        let estop = std::mem::take(&mut self.estop_pending);
        if dt > 0.0 {
            self.velocity = std::array::from_fn(|k| (values[k] - self.last[k]) / dt);
        }
        self.last = values;
        self.last_time = Some(t);
        // On the way home the controller must follow the values: the frames stay armed.
        let home = self.state == LinkState::Stopping && matches!(self.stop, StopMode::Home { .. });
        Tick {
            state: self.state,
            values,
            armed: home || matches!(self.state, LinkState::Arming | LinkState::Armed),
            estop,
            home,
            note,
        }
    }

    /// The ramp from where arming started to the live target.
    fn arming(
        &mut self,
        t: f64,
        dt: f64,
        target: Result<[f64; 6], String>,
    ) -> ([f64; 6], Option<String>) {
        let Some((t0, from)) = self.ramp_from else {
            self.state = LinkState::Armed;
            return self.follow(dt, target);
        };
        let target = match self.checked(target) {
            Ok(v) => v,
            // Nowhere safe to ramp to: hold where the ramp is.
            Err(why) => return (self.limited(dt, self.last).0, Some(why)),
        };
        let u = if self.ramp_s > 0.0 {
            ((t - t0) / self.ramp_s).clamp(0.0, 1.0)
        } else {
            1.0
        };
        let s = u * u * (3.0 - 2.0 * u);
        let wanted = std::array::from_fn(|k| from[k] + (target[k] - from[k]) * s);
        if u >= 1.0 {
            self.state = LinkState::Armed;
            self.ramp_from = None;
        }
        self.limited(dt, wanted)
    }

    /// Follow the target while armed.
    fn follow(&mut self, dt: f64, target: Result<[f64; 6], String>) -> ([f64; 6], Option<String>) {
        match self.checked(target) {
            Ok(v) => self.limited(dt, v),
            Err(why) => (
                self.limited(dt, self.last).0,
                Some(format!("holding the last good set-point: {why}")),
            ),
        }
    }

    /// After an e-stop: hold and disarm, or go home at the home speed and then disarm.
    fn stopping(&mut self, dt: f64) -> ([f64; 6], Option<String>) {
        match self.stop {
            StopMode::Hold => {
                self.state = LinkState::Disarmed;
                (
                    self.last,
                    Some("e-stop: holding where it is, disarmed".to_owned()),
                )
            }
            StopMode::Home { speed } => {
                let step = speed.abs() * dt;
                let next: [f64; 6] = std::array::from_fn(|k| {
                    let d = self.home[k] - self.last[k];
                    self.last[k] + d.clamp(-step, step)
                });
                if next == self.home {
                    self.state = LinkState::Disarmed;
                    (next, Some("e-stop: home reached, disarmed".to_owned()))
                } else {
                    (next, Some("e-stop: returning home".to_owned()))
                }
            }
        }
    }

    /// The target if every value is a finite number inside its range, else why not.
    fn checked(&self, target: Result<[f64; 6], String>) -> Result<[f64; 6], String> {
        let v = target?;
        for (k, (&x, &(lo, hi))) in v.iter().zip(&self.limits.range).enumerate() {
            if !x.is_finite() {
                return Err(format!("actuator {} has no value ({x})", k + 1));
            }
            if x < lo || x > hi {
                return Err(format!(
                    "actuator {} would go to {x:.6}, outside its range {lo} … {hi}",
                    k + 1
                ));
            }
        }
        Ok(v)
    }

    /// Move from the last values towards `wanted` no faster and with no more acceleration
    /// than the limits allow.
    fn limited(&self, dt: f64, wanted: [f64; 6]) -> ([f64; 6], Option<String>) {
        if dt <= 0.0 {
            return (self.last, None);
        }
        let mut out = wanted;
        let mut limited = None;
        for k in 0..6 {
            let distance = wanted[k] - self.last[k];
            let mut v = distance / dt;
            if let Some(a) = self.limits.accel {
                // No faster than the speed from which it can still stop at the target.
                let stoppable = (2.0 * a * distance.abs()).sqrt();
                v = v.clamp(-stoppable, stoppable);
                let dv = (v - self.velocity[k]).clamp(-a * dt, a * dt);
                if self.velocity[k] + dv != v {
                    limited = Some("acceleration");
                }
                v = self.velocity[k] + dv;
            }
            if let Some(s) = self.limits.speed
                && v.abs() > s
            {
                v = v.clamp(-s, s);
                limited = Some("speed");
            }
            out[k] = self.last[k] + v * dt;
        }
        // The range is the hard limit: an approach carried past the target by its speed is
        // stopped at the range's end.
        for (v, &(lo, hi)) in out.iter_mut().zip(&self.limits.range) {
            if *v < lo || *v > hi {
                *v = v.clamp(lo, hi);
                limited = Some("range");
            }
        }
        let note = limited.map(|what| format!("approaching the target at the {what} limit"));
        (out, note)
    }
}

#[cfg(test)]
mod tests;
