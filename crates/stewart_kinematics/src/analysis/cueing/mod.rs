//! Motion cueing: vehicle motion (a recording, or live telemetry) made into platform poses
//! by classical washout ([`washout`]; kept within the stroke and limits, when asked, by
//! the workspace limiter, [`limiter`]) or by model-predictive cueing ([`mpc`]), cued at
//! the occupant's head (the `[cueing]` reference point: the platform turns about it).

pub mod compare;
pub mod guard;
mod limiter;
mod lti;
pub mod mpc;
pub mod omct;
mod washout;

use nalgebra::Vector3;
use thiserror::Error;

use crate::analysis::workspace;
use crate::io::table::TableError;
use crate::model::angle::Angle;
use crate::model::cueing_settings::{CueingAlgorithm, CueingProblem, CueingSettings};
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::{Pose, rotation_zyx};
use crate::model::trajectory::{Motion, PoseTable};

pub use limiter::Limiter;
pub use lti::Lti;
pub use mpc::{Mpc, MpcCounts};
pub use washout::{Cue, VehicleMotion, Washout};

/// Where two times written a microsecond apart differ by less once read (far from 0, a
/// number carries fewer decimals), the reason, said: the message would otherwise quote
/// two times that look exactly far enough apart.
fn rounding_hint(t: f64, previous: f64) -> &'static str {
    if t - previous > 0.99e-6 {
        "; this far from 0 a gap of 1e-6 s reads as a little less: start the times nearer 0"
    } else {
        ""
    }
}

/// Why vehicle motion could not be cued.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CueError {
    /// A `[cueing]` value that cannot work.
    #[error(transparent)]
    Settings(#[from] CueingProblem),
    /// Sample `index` (from 0) does not come after the one before it by at least a
    /// microsecond (the least gap between a pose table's rows).
    #[error(
        "t = {t} s does not come at least 1e-6 s after the previous sample's {previous} s (a pose table's rows must be that far apart){}",
        rounding_hint(*t, *previous)
    )]
    Time {
        /// The sample, from 0.
        index: usize,
        /// Its time, seconds.
        t: f64,
        /// The previous sample's time.
        previous: f64,
    },
    /// The cue of sample `index` (from 0) leaves the accepted range of poses
    /// ([`crate::ground::bounds::POSE_ROW`]): a pose table that no command would read back.
    #[error(
        "the cued pose at t = {t} s leaves the accepted range of poses: its {column} {why} (lower the [cueing] scales or strengthen the washout, or turn the workspace limiter on)"
    )]
    PoseOutside {
        /// The sample, from 0.
        index: usize,
        /// Its time, seconds.
        t: f64,
        /// The pose value's name: `x`, `y`, `z`, `roll_deg`, `pitch_deg` or `yaw_deg`.
        column: &'static str,
        /// Why the value is refused.
        why: crate::ground::bounds::OutOfBounds,
    },
    /// The limiter keeps poses within the limits by scaling toward home, which must be
    /// within them.
    #[error(
        "the workspace limiter needs the home pose within the stroke and limits, and it is not"
    )]
    HomeOutside,
    /// The actuator guard keeps the check's condition-number limit, which the home pose
    /// (where a cue starts and returns) already breaks.
    #[error(
        "the model-predictive cue keeps the condition number under `checks.condition_max` = {max}, and the home pose is already at {condition:.2}: raise the limit or change the layout"
    )]
    HomeIllConditioned {
        /// The home pose's condition number (infinite when singular).
        condition: f64,
        /// The limit.
        max: f64,
    },
    /// A cue is a pose table, which needs two moments.
    #[error(
        "a cue needs at least 2 samples (a pose table holds two moments at least), the input has {samples}"
    )]
    OneSample {
        /// The samples the input has.
        samples: usize,
    },
    /// The samples' times too close for their distance from zero: the table written
    /// would not read back (see [`crate::model::trajectory::SamplingError::TooFine`]).
    #[error(
        "the samples are {step:.3e} s apart on average, too fine to tell apart at {at} s (fewer than 1e10 steps per unit of time from zero): the pose table written would not read back; space the samples more, or start the times nearer 0"
    )]
    TimesTooFine {
        /// The average step, seconds.
        step: f64,
        /// The time farthest from zero, seconds.
        at: f64,
    },
    /// What a motion makes felt needs an acceleration: three samples at least.
    #[error("comparing needs at least 3 samples (an acceleration), the input has {samples}")]
    TooShort {
        /// The samples the input has.
        samples: usize,
    },
}

/// What turns vehicle motion into the cue.
#[derive(Clone, Debug)]
enum Engine {
    Washout(Box<Washout>),
    Mpc(Box<Mpc>),
}

/// The cueing of one platform: washout (the pose at the reference point, the limiter) or
/// the model-predictive planner.
#[derive(Clone, Debug)]
pub struct Cueing {
    engine: Engine,
    limiter: Option<Limiter>,
    geometry: Geometry,
    limits: Limits,
    /// The reference point relative to the rotation centre, platform frame.
    arm: Vector3<f64>,
    /// The share of the cue given (1: all; a stalled live input fades it to 0).
    fade: f64,
    /// Whether the planner looks ahead through a recording.
    preview: bool,
}

impl Cueing {
    /// Cueing by `settings` for `geometry` within `limits`, at rest at neutral (home).
    pub fn new(
        geometry: &Geometry,
        limits: &Limits,
        settings: &CueingSettings,
    ) -> Result<Self, CueError> {
        if let Some(p) = settings.problem() {
            return Err(p.into());
        }
        let limiter = settings
            .workspace_limiter
            .then(|| Limiter::new(settings.limiter_recovery_s));
        let mpc = settings.algorithm == CueingAlgorithm::Mpc;
        if (limiter.is_some() || mpc)
            && !workspace::pose_within_limits(geometry, limits, &geometry.home_pose())
        {
            return Err(CueError::HomeOutside);
        }
        let engine = if mpc {
            let planner = Mpc::new(geometry, limits, settings).map_err(|_| CueingProblem {
                key: "cueing.mpc_input_weight".to_owned(),
                reason: "leaves the planner's cost without a unique minimum: raise it".to_owned(),
            })?;
            Engine::Mpc(Box::new(planner))
        } else {
            Engine::Washout(Box::new(Washout::new(settings)))
        };
        Ok(Self {
            engine,
            limiter,
            geometry: geometry.clone(),
            limits: *limits,
            arm: Vector3::from(settings.reference_m) - geometry.pivot(),
            fade: 1.0,
            preview: settings.mpc_preview,
        })
    }

    /// Hold `motion` as the input from now until the next sample.
    pub fn hold(&mut self, motion: &VehicleMotion) {
        match &mut self.engine {
            Engine::Washout(w) => w.hold(motion),
            Engine::Mpc(m) => m.hold(motion),
        }
    }

    /// Hold the vehicle's motion from now on as `samples` (times from now, the first at
    /// 0): the planner with its look-ahead on plans with it; otherwise the first is held.
    pub fn hold_ahead(&mut self, samples: &[(f64, VehicleMotion)]) {
        let Some((_, first)) = samples.first() else {
            return;
        };
        match &mut self.engine {
            Engine::Mpc(m) if self.preview => m.hold_ahead(samples),
            Engine::Mpc(m) => m.hold(first),
            Engine::Washout(w) => w.hold(first),
        }
    }

    /// Advance `h` seconds and return the pose then (scaled back by the limiter when it
    /// runs and the full cue would leave the limits; the planner keeps within them
    /// itself).
    pub fn advance(&mut self, h: f64) -> Pose {
        let washout = match &mut self.engine {
            Engine::Washout(w) => w,
            Engine::Mpc(m) => {
                m.set_fade(self.fade);
                return m.advance(h);
            }
        };
        washout.advance(h);
        let cue = washout.cue();
        let fade = self.fade;
        let Some(limiter) = &mut self.limiter else {
            return pose_at(&self.geometry, self.arm, &cue, fade);
        };
        let fits = |s: f64| {
            let pose = pose_at(&self.geometry, self.arm, &cue, s * fade);
            workspace::pose_within_limits_as_written(&self.geometry, &self.limits, &pose)
        };
        let s = limiter.scale_for(h, fits);
        pose_at(&self.geometry, self.arm, &cue, s * fade)
    }

    /// The pose `h` seconds ahead with `motion` held from now, the state left as it is: a
    /// live input's look between two samples (its limiter judged as [`Cueing::advance`]
    /// would, on a copy). No allocation.
    pub fn preview(&self, h: f64, motion: &VehicleMotion) -> Pose {
        let washout = match &self.engine {
            Engine::Washout(w) => w,
            // The plan, followed: the next solve takes the new motion in.
            Engine::Mpc(m) => return m.preview(h),
        };
        let mut ahead = washout.clone();
        ahead.hold(motion);
        ahead.advance(h);
        let cue = ahead.cue();
        let fade = self.fade;
        let Some(limiter) = &self.limiter else {
            return pose_at(&self.geometry, self.arm, &cue, fade);
        };
        let mut limiter = limiter.clone();
        let fits = |s: f64| {
            let pose = pose_at(&self.geometry, self.arm, &cue, s * fade);
            workspace::pose_within_limits_as_written(&self.geometry, &self.limits, &pose)
        };
        let s = limiter.scale_for(h, fits);
        pose_at(&self.geometry, self.arm, &cue, s * fade)
    }

    /// Give only `fade` (0 to 1) of the cue from the next step on: a live input that
    /// stalls is faded to neutral by lowering it.
    pub fn set_fade(&mut self, fade: f64) {
        self.fade = fade.clamp(0.0, 1.0);
    }

    /// The share of the cue given.
    pub fn fade(&self) -> f64 {
        self.fade
    }

    /// The cue now (the washout's before the limiter; the planner's motion).
    pub fn cue(&self) -> Cue {
        match &self.engine {
            Engine::Washout(w) => w.cue(),
            Engine::Mpc(m) => m.cue(),
        }
    }

    /// Whether a reset would not move the platform: always for the washout (its fade
    /// scales the pose), for the planner once it is home and at rest (to 0.1 mm, 0.1 mm/s).
    pub fn settled(&self) -> bool {
        match &self.engine {
            Engine::Washout(_) => true,
            Engine::Mpc(m) => m.settled(),
        }
    }

    /// How far ahead the planner looks, seconds (0 for the washout).
    pub fn horizon_s(&self) -> f64 {
        match &self.engine {
            Engine::Washout(_) => 0.0,
            Engine::Mpc(m) => m.horizon_s(),
        }
    }

    /// The planner, when it is one (to plan elsewhere: [`mpc::remote`]).
    pub fn mpc_mut(&mut self) -> Option<&mut Mpc> {
        match &mut self.engine {
            Engine::Washout(_) => None,
            Engine::Mpc(m) => Some(m),
        }
    }

    /// How the planner has fared (`None` for the washout).
    pub fn mpc_counts(&self) -> Option<MpcCounts> {
        match &self.engine {
            Engine::Washout(_) => None,
            Engine::Mpc(m) => Some(m.counts()),
        }
    }

    /// The limiter's scale now (1 without a limiter).
    pub fn scale(&self) -> f64 {
        self.limiter.as_ref().map_or(1.0, Limiter::scale)
    }

    /// Back to neutral and rest.
    pub fn reset(&mut self) {
        match &mut self.engine {
            Engine::Washout(w) => w.reset(),
            Engine::Mpc(m) => m.reset(),
        }
        if let Some(l) = &mut self.limiter {
            l.reset();
        }
    }
}

/// The pose of `geometry` whose reference point (at `arm` from the rotation centre, in
/// the platform frame) is at its home place plus `s` times the cue's translation, the
/// platform turned by `s` times the cue's angles about it.
pub(crate) fn pose_at(geometry: &Geometry, arm: Vector3<f64>, cue: &Cue, s: f64) -> Pose {
    // The angles as a pose table writes and reads them, so that the limiter judges the
    // very pose `stewart check` reads back from `stewart cue`'s output.
    let [roll, pitch, yaw] = cue.angles.map(|a| Angle::from_radians(s * a).as_written());
    let rotation = rotation_zyx(roll, pitch, yaw);
    // A platform point a goes to p + R (a − c) + c; the reference point stays where the
    // cue puts it when p = home + x + arm − R arm.
    let position =
        geometry.home_pose().position + s * Vector3::from(cue.position) + arm - rotation * arm;
    Pose::new(position, roll, pitch, yaw)
}

/// A recording made into platform motion.
#[derive(Clone, Debug, PartialEq)]
pub struct CuedRecording {
    /// One pose per sample.
    pub poses: Vec<Pose>,
    /// The limiter's scale at each sample (all 1 without the limiter).
    pub scales: Vec<f64>,
    /// The washout's cue at each sample (before the limiter): its translation,
    /// acceleration, angles, tilt and the specific force it makes felt.
    pub cues: Vec<Cue>,
    /// How the planner fared (`None` for the washout).
    pub planner: Option<MpcCounts>,
}

impl CuedRecording {
    /// The poses as a motion through the samples' `times` (joined by straight lines,
    /// sampled once per sample), as a pose table written by `stewart cue` plays.
    pub fn to_motion(&self, times: &[f64], name: &str) -> Result<Motion, TableError> {
        let values = self.poses.iter().map(Pose::to_row).collect();
        let table = PoseTable {
            times: Some(times.to_vec()),
            poses: self.poses.clone(),
            values,
            lines: (2..).take(self.poses.len()).collect(),
        };
        table.to_motion(name)
    }
}

/// A model-predictive cue keeps the check's condition-number limit, so it starts from a
/// home pose within it (offline, where the guard keeps it; live, where the cue returns to
/// it): refused otherwise. Nothing to refuse for the washout, or on a geometry singular at
/// every pose (the check judges no condition number there).
pub fn home_conditioning(
    geometry: &Geometry,
    checks: &crate::analysis::checks::CheckSettings,
    settings: &CueingSettings,
) -> Result<(), CueError> {
    if settings.algorithm != CueingAlgorithm::Mpc
        || crate::analysis::architecture::architecture(geometry).singular
    {
        return Ok(());
    }
    let condition = (geometry.actuated_conditioning(&geometry.home_pose()))
        .and_then(|c| c.condition_number)
        .unwrap_or(f64::INFINITY);
    if condition > checks.condition_max {
        return Err(CueError::HomeIllConditioned {
            condition,
            max: checks.condition_max,
        });
    }
    Ok(())
}

/// The poses of a recording of vehicle motion, one per sample at its time (the first at
/// neutral: the filters start at rest), each sample's motion held until the next. A
/// model-predictive cue keeps the actuators' range, speed and acceleration, the joint
/// cones, the clearances and the condition number as `check` judges them with `checks`,
/// and avoids what it would call jumps (see [`guard`]; jerk limits are not kept).
pub fn cue_recording(
    geometry: &Geometry,
    limits: &Limits,
    checks: &crate::analysis::checks::CheckSettings,
    settings: &CueingSettings,
    samples: &[(f64, VehicleMotion)],
) -> Result<CuedRecording, CueError> {
    let mut cueing = Cueing::new(geometry, limits, settings)?;
    // The times as a pose table's rows must be (the table written reads back).
    if let [(first, _), .., (last, _)] = samples {
        if let Err(crate::model::trajectory::SamplingError::TooFine { step, at }) =
            crate::model::trajectory::Sampling::with_start(
                *first,
                last - first,
                samples.len() as u64,
            )
        {
            return Err(CueError::TimesTooFine { step, at });
        }
    } else {
        return Err(CueError::OneSample {
            samples: samples.len(),
        });
    }
    home_conditioning(geometry, checks, settings)?;
    let mut poses = Vec::with_capacity(samples.len());
    let mut scales = Vec::with_capacity(samples.len());
    let mut cues = Vec::with_capacity(samples.len());
    let mut previous: Option<f64> = None;
    let mut ahead = Vec::new();
    for (index, (t, motion)) in samples.iter().enumerate() {
        // Samples as far apart as a pose table's rows must be (its keys): the table
        // written reads back.
        let h = match previous {
            Some(p) if crate::model::trajectory::keyframes::far_enough_apart(*t - p) => t - p,
            Some(p) => {
                return Err(CueError::Time {
                    index,
                    t: *t,
                    previous: p,
                });
            }
            None => 0.0,
        };
        poses.push(cueing.advance(h));
        scales.push(cueing.scale());
        cues.push(cueing.cue());
        if cueing.preview {
            ahead.clear();
            // The horizon from every solve until the next sample (a second more than it).
            let end = t + cueing.horizon_s() + 1.0;
            ahead.extend(
                samples[index..]
                    .iter()
                    .take_while(|(ts, _)| *ts <= end)
                    .map(|(ts, m)| (ts - t, *m)),
            );
            cueing.hold_ahead(&ahead);
        } else {
            cueing.hold(motion);
        }
        previous = Some(*t);
    }
    let mut planner = cueing.mpc_counts();
    // The planner promises every limit as `check` measures it: kept after it.
    if let Some(counts) = &mut planner {
        let times: Vec<f64> = samples.iter().map(|(t, _)| *t).collect();
        let guard = guard::ActuatorGuard::new(geometry, limits, checks, settings.mpc_margin);
        let guarded = guard.guard_all(&times, &poses);
        counts.guarded = guarded.held as u64;
        counts.guard_rewinds = guarded.rewound as u64;
        counts.guard_stops = guarded.stopped as u64;
        counts.guard_jumps_left = guarded.jumps_left as u64;
        poses = guarded.poses;
    }
    for (index, (pose, (t, _))) in poses.iter().zip(samples).enumerate() {
        if let Err((column, why)) = crate::ground::bounds::check_pose_row(&pose.to_row()) {
            return Err(CueError::PoseOutside {
                index,
                t: *t,
                column: crate::model::trajectory::POSE_COLUMNS[column],
                why,
            });
        }
    }
    Ok(CuedRecording {
        poses,
        scales,
        cues,
        planner,
    })
}

#[cfg(test)]
mod tests;
