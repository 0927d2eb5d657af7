//! Model-predictive motion cueing: every `mpc_solve_interval_s`, the accelerations of the
//! six axes over the next `mpc_horizon_steps` steps of `mpc_step_s` that best reproduce
//! what the occupant feels — the specific force at the reference point in the platform's
//! axes, gravity included, and the body rates — against the vehicle's scaled ones, within
//! the rig's limits ([`cost`], [`rig`]); the plan is followed until the next.
//!
//! - **Model.** Each axis (`x, y, z` of the reference point, roll, pitch, yaw) is a double
//!   integrator, exact; only the felt force's and the limits' slopes are linearised
//!   ([`horizon`]). The vehicle's motion is held over the horizon (a live input knows no
//!   more), but for its heave and rates, which no platform can sustain: what is new in
//!   them, fading ([`fading`]).
//! - **Constraints, all hard**: every actuator within its stroke (range) and each joint
//!   within its cone at the end of every step, linearised about the pose now and kept
//!   `mpc_margin` inside; actuator speed and acceleration limits; at rest at the
//!   horizon's end (so the last plan is always a way to stop within the limits). The
//!   tilt-rate limit — roll and pitch turning no faster than `tilt_rate_max_deg_s` more
//!   than the vehicle asks — is kept by an exact penalty: met whenever it can be.
//! - **Solver**: the dense dual active-set method of [`qp`], its matrix factored once,
//!   warm-started from the last active set.
//! - **Safety.** A solve that fails (no plan within the limits, or the iteration limit)
//!   keeps the last plan, which brakes to rest within them; a pose the exact check
//!   ([`workspace::pose_within_limits`]) refuses is never given: the platform stops at the
//!   last pose that passed.

pub mod cost;
pub mod fading;
pub mod horizon;
pub mod qp;
pub mod remote;
pub mod rig;
pub mod vestibular;

use nalgebra::Vector3;

use crate::analysis::cueing::{Cue, VehicleMotion};
use crate::analysis::workspace;
use crate::model::cueing_settings::CueingSettings;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;
use cost::{Cost, Now};
use fading::{FADING, Fading};
use horizon::{Horizon, StepValue};
use qp::{Constraints, DenseQp};
use rig::{Rig, pose_of};

/// The linear and quadratic cost of the tilt-rate slack: large enough that the penalty is
/// exact (no slack while the limit can be met).
const SLACK_LINEAR: f64 = 1e6;
const SLACK_QUADRATIC: f64 = 10.0;

/// The time constants of a held heave's and rates' fading (heave, roll, pitch, yaw), as
/// shares of the horizon: roll and pitch fade in a quarter of it, as a roll or pitch rate
/// held longer tilts the platform so far that gravity's false force outweighs the rate.
pub const FADE_SHARES: [f64; 4] = [1.0, 0.25, 0.25, 1.0];

/// How the planner has fared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MpcCounts {
    /// Plans made.
    pub solves: u64,
    /// Solves that found no plan within the limits (the last plan was kept).
    pub failed: u64,
    /// Poses the exact check refused (the platform held the last good pose instead).
    pub stops: u64,
    /// Constraints active in the last plan.
    pub active: usize,
    /// Planning elsewhere: solve instants whose plan had not come (the last went on).
    pub late: u64,
    /// Poses of a recording the actuator guard replaced to keep the actuators' range,
    /// speed and acceleration limits where the plan's linearisation did not
    /// ([`super::guard`]).
    pub guarded: u64,
    /// Times the guard went back in a recording to brake earlier, as no allowed pose
    /// followed where it was.
    pub guard_rewinds: u64,
    /// Poses of a recording for which the guard found no allowed pose even so (the last
    /// was given again).
    pub guard_stops: u64,
    /// Steps of a recording that `check` would still call jumps when the guard's passes
    /// ran out.
    pub guard_jumps_left: u64,
}

/// The planner and its state, in the parts it is made of.
#[derive(Clone, Debug)]
pub struct Mpc {
    problem: Problem,
    plant: Plant,
    plan: Plan,
    wanted: Wanted,
    remote: RemotePlanning,
    counts: MpcCounts,
    /// With the vestibular model: the organs' states.
    sensed: Option<vestibular::Sensed>,
}

/// The optimisation problem, fixed at the start: the rig, its limits, the horizon's
/// layout, the cost and the solver with its work space.
#[derive(Clone, Debug)]
struct Problem {
    settings: CueingSettings,
    geometry: Geometry,
    limits: Limits,
    /// The reference point from the rotation centre.
    arm: Vector3<f64>,
    layout: Horizon,
    cost: Cost,
    rig: Rig,
    qp: DenseQp,
    constraints: Constraints,
    gradient: Vec<f64>,
}

/// The platform as the planner moves it.
#[derive(Clone, Debug)]
struct Plant {
    /// Positions and angles, and their rates.
    s: [f64; 6],
    v: [f64; 6],
    /// The last state whose pose passed the exact check.
    last_good: [f64; 6],
}

/// The plan being followed.
#[derive(Clone, Debug)]
struct Plan {
    /// Step-major accelerations of the cued axes.
    accelerations: Vec<f64>,
    /// How long it has run, seconds.
    age: f64,
    /// Seconds since the last solve (`∞` before the first).
    since_solve: f64,
}

/// What the vehicle asks for over the horizon.
#[derive(Clone, Debug)]
struct Wanted {
    /// The vehicle's motion in each step of the horizon, scaled (m/s², rad/s), before the
    /// fade.
    mean: Vec<[f64; 6]>,
    /// The same at each step's end.
    at_end: Vec<[f64; 6]>,
    /// A recording's samples from the last one given on (times from it), and how long
    /// ago it was given (empty: the motion is held).
    ahead: Vec<(f64, VehicleMotion)>,
    ahead_age: f64,
    /// The share of the vehicle's motion asked for (0 to 1).
    fade: f64,
    /// A held motion's heave and rates, cued as what is new in them ([`fading`]).
    fading: [Fading; 4],
    /// A held motion's roll and pitch rates as they are (none with a recording ahead).
    tilt_now: Option<[f64; 2]>,
}

/// Planning elsewhere ([`remote`]).
#[derive(Clone, Debug)]
struct RemotePlanning {
    /// Whether plans come from elsewhere.
    on: bool,
    /// The solve instants so far.
    instant: u64,
    /// Bumped by a stop, a reset or a skipped gap: replies asked for before are dropped.
    epoch: u64,
    /// The request left for the next instant, and the reply offered.
    request: Option<remote::PlanRequest>,
    reply: Option<remote::PlanReply>,
}

/// Why a planner cannot be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BadCost;

impl Mpc {
    /// The planner of `settings` for `geometry` within `limits`, at rest at neutral.
    pub fn new(
        geometry: &Geometry,
        limits: &Limits,
        settings: &CueingSettings,
    ) -> Result<Self, BadCost> {
        let axes: Vec<usize> = (0..6).filter(|&i| settings.axes()[i]).collect();
        let tilts = axes.iter().filter(|&&a| a == 3 || a == 4).count();
        let layout = Horizon {
            axes,
            steps: settings.mpc_horizon_steps as usize,
            first: settings.mpc_solve_interval_s,
            step: settings.mpc_step_s,
            extra: tilts,
        };
        let arm = Vector3::from(settings.reference_m) - geometry.pivot();
        let cost = Cost::new(settings, &layout);
        let n = layout.len();
        let mut g = cost.hessian();
        for e in 0..layout.extra {
            let i = layout.plan_len() + e;
            g[i * n + i] += SLACK_QUADRATIC;
        }
        let rig = Rig::new(geometry, limits, arm, settings.mpc_margin);
        let rows = layout.axes.len() + rig.rows(layout.steps) + 4 * layout.steps * tilts + tilts;
        let qp = DenseQp::new(&g, n, rows).map_err(|_| BadCost)?;
        let plan_len = layout.plan_len();
        Ok(Self {
            problem: Problem {
                settings: settings.clone(),
                geometry: geometry.clone(),
                limits: *limits,
                arm,
                constraints: Constraints::new(n, rows),
                gradient: vec![0.0; n],
                layout,
                cost,
                rig,
                qp,
            },
            plant: Plant {
                s: [0.0; 6],
                v: [0.0; 6],
                last_good: [0.0; 6],
            },
            plan: Plan {
                accelerations: vec![0.0; plan_len],
                age: 0.0,
                since_solve: f64::INFINITY,
            },
            wanted: Wanted {
                mean: vec![[0.0; 6]; settings.mpc_horizon_steps as usize],
                at_end: vec![[0.0; 6]; settings.mpc_horizon_steps as usize],
                ahead: Vec::new(),
                ahead_age: 0.0,
                fade: 1.0,
                fading: [Fading::default(); 4],
                tilt_now: None,
            },
            remote: RemotePlanning {
                on: false,
                instant: 0,
                epoch: 0,
                request: None,
                reply: None,
            },
            counts: MpcCounts::default(),
            sensed: settings
                .vestibular
                .then(|| vestibular::Sensed::new(settings.mpc_solve_interval_s)),
        })
    }

    /// `motion` scaled by `s`: specific force (m/s²) and rates (rad/s).
    fn scaled(s: &CueingSettings, motion: &VehicleMotion) -> [f64; 6] {
        let [ax, ay, az] = motion.accel.map(|a| s.translation_scale * a);
        let [wx, wy, wz] = motion
            .rates_deg_s
            .map(|r| s.rotation_scale * r.to_radians());
        [ax, ay, az, wx, wy, wz]
    }

    /// Hold `motion` as the vehicle's from now on, over the whole horizon (what a live
    /// input knows).
    pub fn hold(&mut self, motion: &VehicleMotion) {
        self.wanted.ahead.clear();
        let w = Self::scaled(&self.problem.settings, motion);
        self.wanted.mean.iter_mut().for_each(|v| *v = w);
        self.wanted.at_end.iter_mut().for_each(|v| *v = w);
        for (f, &axis) in self.wanted.fading.iter_mut().zip(&FADING) {
            f.hold(w[axis]);
        }
        self.wanted.tilt_now = Some([w[3], w[4]]);
        self.predict_held();
    }

    /// A held motion's heave and rates over the horizon: what is new in them, fading
    /// ([`fading`]).
    fn predict_held(&mut self) {
        if !self.wanted.ahead.is_empty() {
            return;
        }
        let horizon = self.horizon_s();
        for k in 0..self.problem.layout.steps {
            for ((f, &axis), share) in self.wanted.fading.iter().zip(&FADING).zip(FADE_SHARES) {
                let (mean, end) = f.predicted(&self.problem.layout, k, share * horizon);
                self.wanted.mean[k][axis] = mean;
                self.wanted.at_end[k][axis] = end;
            }
        }
    }

    /// Let `dt` seconds pass for the fading axes.
    fn fade(&mut self, dt: f64) {
        let horizon = self.horizon_s();
        for (f, share) in self.wanted.fading.iter_mut().zip(FADE_SHARES) {
            f.advance(dt, share * horizon);
        }
    }

    /// The vehicle's motion from now on as `samples` (times from now, seconds, the first
    /// at 0, each held until the next): each step of the horizon asks for the sample held
    /// at its middle, and at its end (a recording, known ahead). Kept until the next
    /// sample, so that a solve between two samples looks from its own time.
    pub fn hold_ahead(&mut self, samples: &[(f64, VehicleMotion)]) {
        self.wanted.ahead.clear();
        self.wanted.tilt_now = None;
        self.wanted.ahead.extend_from_slice(samples);
        self.wanted.ahead_age = 0.0;
        self.look_ahead();
    }

    /// `wanted` from the samples ahead, as seen `ahead_age` after they were given: each
    /// step asks for the vehicle's motion averaged over it (so that the plan slides
    /// smoothly along the recording), and at its end for the sample held then.
    fn look_ahead(&mut self) {
        if self.wanted.ahead.is_empty() {
            return;
        }
        let (settings, samples, age) = (
            &self.problem.settings,
            &self.wanted.ahead,
            self.wanted.ahead_age,
        );
        // The sample held at `at` (one due at `at` to rounding counts as come).
        let index = |at: f64| {
            samples
                .partition_point(|(t, _)| *t <= age + at + 1e-9)
                .max(1)
                - 1
        };
        let scaled = |i: usize| Self::scaled(settings, &samples[i].1);
        // The mean of the held samples over [a, b].
        let mean = |a: f64, b: f64| {
            let mut sum = [0.0; 6];
            let mut i = index(a);
            let mut from = a;
            while from < b {
                let until = samples
                    .get(i + 1)
                    .map_or(b, |(t, _)| (t - age).min(b))
                    .max(from);
                let w = scaled(i);
                for (s, v) in sum.iter_mut().zip(w) {
                    *s += v * (until - from);
                }
                from = until;
                if i + 1 >= samples.len() {
                    break;
                }
                i += 1;
            }
            if from < b {
                let w = scaled(samples.len() - 1);
                for (s, v) in sum.iter_mut().zip(w) {
                    *s += v * (b - from);
                }
            }
            sum.map(|s| s / (b - a))
        };
        for k in 0..self.problem.layout.steps {
            let (start, length) = (self.problem.layout.start(k), self.problem.layout.length(k));
            self.wanted.mean[k] = mean(start, start + length);
            self.wanted.at_end[k] = scaled(index(start + length));
        }
    }

    /// Ask for only `fade` (0 to 1) of the vehicle's motion.
    pub fn set_fade(&mut self, fade: f64) {
        self.wanted.fade = fade;
    }

    /// Whether the platform is home and at rest (to 1e-4 m or rad, per second).
    pub fn settled(&self) -> bool {
        self.plant
            .s
            .iter()
            .chain(&self.plant.v)
            .all(|x| x.abs() < 1e-4)
    }

    /// How far ahead the plan reaches, seconds.
    pub fn horizon_s(&self) -> f64 {
        self.problem.layout.start(self.problem.layout.steps)
    }

    /// How the planner has fared so far.
    pub fn counts(&self) -> MpcCounts {
        self.counts
    }

    /// The acceleration of each axis the plan holds `age` seconds after it began.
    fn input_at(&self, age: f64) -> [f64; 6] {
        let mut u = [0.0; 6];
        let Some(j) = self.problem.layout.step_at(age) else {
            return u;
        };
        for (slot, &axis) in self.problem.layout.axes.iter().enumerate() {
            u[axis] = self.plan.accelerations[j * self.problem.layout.axes.len() + slot];
        }
        u
    }

    /// `(s, v, age)` moved on by `h` seconds along the plan.
    fn integrate(
        &self,
        mut s: [f64; 6],
        mut v: [f64; 6],
        mut age: f64,
        mut h: f64,
    ) -> ([f64; 6], [f64; 6], f64) {
        while h > 0.0 {
            // To the end of this plan step (or all of h once the plan is over).
            let left = match self.problem.layout.step_at(age) {
                Some(k) => {
                    (self.problem.layout.start(k) + self.problem.layout.length(k) - age).max(1e-12)
                }
                None => h,
            };
            let dt = h.min(left);
            let u = self.input_at(age);
            for i in 0..6 {
                s[i] += v[i] * dt + 0.5 * u[i] * dt * dt;
                v[i] += u[i] * dt;
            }
            age += dt;
            h -= dt;
        }
        (s, v, age)
    }

    /// Advance `h` seconds — planning again whenever the solve interval has passed — and
    /// return the pose then.
    pub fn advance(&mut self, mut h: f64) -> Pose {
        let every = self.problem.settings.mpc_solve_interval_s;
        // Times from a recording's differences are off by rounding: a remainder this
        // small is no interval of its own.
        const ROUNDING: f64 = 1e-9;
        // A gap longer than a plan (a clock that jumps): the plan is followed to its end,
        // at rest, in one go, and only the last stretch is planned — the work bounded
        // whatever the gap.
        let span = self.horizon_s() + 2.0 * every;
        if h > span {
            let skipped = h - span;
            (self.plant.s, self.plant.v, self.plan.age) =
                self.integrate(self.plant.s, self.plant.v, self.plan.age, skipped);
            self.wanted.ahead_age += skipped;
            self.fade(skipped);
            self.plan.since_solve = f64::INFINITY;
            self.remote.epoch += 1;
            h = span;
        }
        while h > 0.0 {
            if self.plan.since_solve >= every - ROUNDING {
                self.predict_held();
                if self.remote.on {
                    self.remote_instant();
                } else {
                    self.look_ahead();
                    self.solve();
                }
                self.plan.since_solve = 0.0;
            }
            let mut dt = h.min(every - self.plan.since_solve);
            if h - dt < ROUNDING {
                dt = h;
            }
            (self.plant.s, self.plant.v, self.plan.age) =
                self.integrate(self.plant.s, self.plant.v, self.plan.age, dt);
            self.plan.since_solve += dt;
            self.wanted.ahead_age += dt;
            self.fade(dt);
            h -= dt;
        }
        let pose = pose_of(&self.problem.geometry, self.problem.arm, &self.plant.s);
        if self
            .plant
            .s
            .iter()
            .chain(&self.plant.v)
            .all(|x| x.is_finite())
            && workspace::pose_within_limits_as_written(
                &self.problem.geometry,
                &self.problem.limits,
                &pose,
            )
        {
            self.plant.last_good = self.plant.s;
            return pose;
        }
        // Never a pose outside the limits: stop at the last one that passed (a plan on its
        // way for the state left behind is no longer adopted).
        self.counts.stops += 1;
        self.remote.epoch += 1;
        self.plant.s = self.plant.last_good;
        self.plant.v = [0.0; 6];
        self.plan.accelerations.iter_mut().for_each(|u| *u = 0.0);
        self.plan.since_solve = f64::INFINITY;
        pose_of(&self.problem.geometry, self.problem.arm, &self.plant.s)
    }

    /// The pose `h` seconds ahead along the plan, the state left as it is. No allocation.
    pub fn preview(&self, h: f64) -> Pose {
        let (s, _, _) = self.integrate(self.plant.s, self.plant.v, self.plan.age, h.max(0.0));
        let pose = pose_of(&self.problem.geometry, self.problem.arm, &s);
        if workspace::pose_within_limits_as_written(
            &self.problem.geometry,
            &self.problem.limits,
            &pose,
        ) {
            pose
        } else {
            pose_of(
                &self.problem.geometry,
                self.problem.arm,
                &self.plant.last_good,
            )
        }
    }

    /// The motion now, as a cue: translation, acceleration, angles (all of roll and pitch
    /// counted as tilt: the planner does not split them).
    pub fn cue(&self) -> Cue {
        let u = self.input_at(self.plan.age);
        Cue {
            position: [self.plant.s[0], self.plant.s[1], self.plant.s[2]],
            acceleration: [u[0], u[1], u[2]],
            angles: [self.plant.s[3], self.plant.s[4], self.plant.s[5]],
            tilt: [self.plant.s[3], self.plant.s[4]],
        }
    }

    /// Back to neutral and rest, the plan cleared.
    pub fn reset(&mut self) {
        self.plant.s = [0.0; 6];
        self.plant.v = [0.0; 6];
        self.plant.last_good = [0.0; 6];
        self.plan.accelerations.iter_mut().for_each(|u| *u = 0.0);
        self.plan.age = 0.0;
        self.plan.since_solve = f64::INFINITY;
        self.wanted.mean.iter_mut().for_each(|v| *v = [0.0; 6]);
        self.wanted.at_end.iter_mut().for_each(|v| *v = [0.0; 6]);
        self.wanted.ahead.clear();
        self.wanted.fading.iter_mut().for_each(Fading::reset);
        self.wanted.tilt_now = None;
        self.remote.request = None;
        self.remote.reply = None;
        self.remote.epoch += 1;
        if let Some(s) = &mut self.sensed {
            s.reset();
        }
    }

    /// Plan again from the state now; on failure keep the last plan.
    fn solve(&mut self) {
        let a0 = self.input_at(self.plan.age);
        self.sense(a0);
        if self.plan_from(a0) {
            self.plan.age = 0.0;
        }
    }

    /// The specific force felt now with the accelerations `a0` held.
    fn felt_force(&self, a0: [f64; 6]) -> [f64; 3] {
        Cue {
            acceleration: [a0[0], a0[1], a0[2]],
            angles: [self.plant.s[3], self.plant.s[4], self.plant.s[5]],
            ..Cue::default()
        }
        .specific_force()
    }

    /// At a solve instant, with the vestibular model: the organs stepped over the last
    /// interval, and the error felt now (with `a0` held) held over the next.
    fn sense(&mut self, a0: [f64; 6]) {
        let Some(sensed) = &self.sensed else {
            return;
        };
        let force = self.felt_force(a0);
        let rates = body_rates(&self.plant.s, &self.plant.v);
        let error: [f64; 6] = std::array::from_fn(|i| {
            let felt = if i < 3 { force[i] } else { rates[i - 3] };
            felt - self.wanted.fade * self.wanted.mean[0][i]
        });
        let mut sensed = sensed.clone();
        sensed.step(error);
        self.sensed = Some(sensed);
    }

    /// Plan from the state now, `a0` the accelerations held just before; on failure keep
    /// the last plan. Whether a plan was found.
    fn plan_from(&mut self, a0: [f64; 6]) -> bool {
        self.counts.solves += 1;
        let Some(lin) = self.problem.rig.linearise(&self.plant.s, &self.plant.v) else {
            self.counts.failed += 1;
            return false;
        };
        let now = Now {
            s: self.plant.s,
            v: self.plant.v,
            a: a0,
            force: self.felt_force(a0),
            rates: body_rates(&self.plant.s, &self.plant.v),
            wanted: &self.wanted.mean,
            wanted_end: &self.wanted.at_end,
            fade: self.wanted.fade,
            tilt_now: self.wanted.tilt_now,
            sensed: self.sensed.as_ref().map_or([[0.0; 3]; 6], |v| v.states),
        };
        self.problem
            .cost
            .gradient(&self.problem.layout, &now, &mut self.problem.gradient);
        let plan_len = self.problem.layout.plan_len();
        for e in 0..self.problem.layout.extra {
            self.problem.gradient[plan_len + e] += SLACK_LINEAR;
        }
        // Kept the margin inside, like the rig's limits: when the rig's limits leave the
        // tilt rate no way to be met exactly, its penalty lets it over by a hair.
        let tilt_limit = if self.problem.settings.tilt {
            self.problem.settings.tilt_rate_max_deg_s.to_radians()
                * (1.0 - self.problem.settings.mpc_margin)
        } else {
            0.0
        };
        build_constraints(
            &mut self.problem.constraints,
            &self.problem.layout,
            &self.problem.rig,
            tilt_limit,
            &lin,
            &now,
        );
        match self
            .problem
            .qp
            .solve(&self.problem.gradient, &self.problem.constraints)
        {
            Ok(x) if x.iter().all(|v| v.is_finite()) => {
                self.plan.accelerations.copy_from_slice(&x[..plan_len]);
                self.counts.active = self.problem.qp.active_count();
                true
            }
            // No plan, or one that is not a number (a wish beyond any float's range).
            _ => {
                self.counts.failed += 1;
                false
            }
        }
    }
}

/// The plan's constraints from the state `now`: at rest at the horizon's end, the rig's
/// limits linearised as `lin`, roll and pitch turning no faster than `tilt_limit` (rad/s)
/// beyond what the vehicle asks (each axis by its slack).
fn build_constraints(
    c: &mut Constraints,
    layout: &Horizon,
    rig: &Rig,
    tilt_limit: f64,
    lin: &rig::Linearised,
    now: &Now,
) {
    c.clear();
    let last = layout.steps - 1;
    // At rest at the horizon's end.
    for &axis in &layout.axes {
        let free = layout.free(StepValue::EndVelocity, last, now.s[axis], now.v[axis]);
        if let Some(row) = c.push_equality(-free) {
            layout.add_quantity(row, StepValue::EndVelocity, last, axis, 1.0);
        }
    }
    rig.push_rows(c, layout, lin, &now.s, &now.v);
    let limit = tilt_limit;
    let plan_len = layout.plan_len();
    let tilt_axes = layout.axes.iter().filter(|&&a| a == 3 || a == 4);
    for (e, &axis) in tilt_axes.enumerate() {
        // Not at the horizon's end, where the platform is at rest whatever the vehicle does.
        for k in 0..layout.steps - 1 {
            // Within the limit of the vehicle's rate over the step and of its rate from the
            // step's end on: so also over every interval between two samples.
            let [during, after] = now.tilt_reference(k, axis);
            // The body rate, linear in the angles' rates at the angles now.
            let slopes = body_rate_slopes(&now.s)[axis - 3];
            let free: f64 = (0..3)
                .map(|j| {
                    slopes[j] * layout.free(StepValue::EndVelocity, k, now.s[3 + j], now.v[3 + j])
                })
                .sum();
            for wanted in [during, after]
                .into_iter()
                .take(if during == after { 1 } else { 2 })
            {
                for side in [1.0, -1.0] {
                    // side (ω_k − wanted) − slack ≤ limit.
                    let row = c.push(f64::NEG_INFINITY, limit - side * (free - wanted));
                    for (j, m) in slopes.iter().enumerate() {
                        if *m != 0.0 {
                            layout.add_quantity(row, StepValue::EndVelocity, k, 3 + j, side * m);
                        }
                    }
                    row[plan_len + e] = -1.0;
                }
            }
        }
        c.push(0.0, f64::INFINITY)[plan_len + e] = 1.0;
    }
    c.normalise();
}

/// The body rates' slopes in the angles' rates: row `i` gives rate `i` about the
/// platform's own axes from the rates of roll, pitch and yaw at angles `s[3..6]`
/// (`R = R_z(yaw) R_y(pitch) R_x(roll)`).
pub fn body_rate_slopes(s: &[f64; 6]) -> [[f64; 3]; 3] {
    let (sr, cr) = s[3].sin_cos();
    let (sp, cp) = s[4].sin_cos();
    [[1.0, 0.0, -sp], [0.0, cr, sr * cp], [0.0, -sr, cr * cp]]
}

/// The body rates (about the platform's own axes, rad/s) of angles `s[3..6]` turning at
/// `v[3..6]`.
pub fn body_rates(s: &[f64; 6], v: &[f64; 6]) -> [f64; 3] {
    body_rate_slopes(s).map(|row| row[0] * v[3] + row[1] * v[4] + row[2] * v[5])
}

#[cfg(test)]
mod tests;
