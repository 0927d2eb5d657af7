//! The link's plan: everything a stream needs, read once from the scenario — the wire
//! format and rate, the channel map, the supervisor (limits, home, ramp, stop), where the
//! frames go, and the motion as a target with its velocity and acceleration. The command
//! line (`stewart link`) and the viewer's Link panel both start their senders from a plan,
//! so the same scenario sends the same thing from either.

use std::sync::{Arc, Mutex, PoisonError};

use anyhow::Result;
use stewart_kinematics::model::link_settings::LinkSettings;
use stewart_kinematics::{Geometry, Pose, Scenario, Trajectory};
use stewart_link::channels::ChannelMap;
use stewart_link::safety::Supervisor;
use stewart_link::sender::{Clock, SenderConfig, WireFormat};
use stewart_link::target::{ActuatorMotion, Sample, Target, TargetError};
use stewart_link::transport::Transport;

use crate::vehicle_in::live_cue::LiveCue;

mod follow;
mod hardware;

pub(crate) use follow::{Drive, Followed};

/// The pose a live cue asked for last, shared with whoever shows it.
pub(crate) type AskedPose = Arc<Mutex<Option<Pose>>>;
pub(crate) use hardware::{actuator_range, template_problem};

/// The step of the central differences that give the target's velocity and acceleration,
/// seconds (their error is ~h⁴ of the motion's fifth and sixth derivatives, their rounding
/// ~1e-16/h² of its size: both far below a micrometre per second squared).
const DIFFERENCE_STEP_S: f64 = 1e-3;

/// A stream's plan, built once from a scenario.
#[derive(Clone, Debug)]
pub struct LinkPlan {
    /// The scenario's `[link]` table (with any command-line overrides).
    pub(crate) settings: LinkSettings,
    /// The actuator values at the home pose: where arming starts and the way home ends.
    pub(crate) home: [f64; 6],
    /// Values to wire.
    pub(crate) map: ChannelMap,
    /// What goes on the wire: frames, lines, or a template's bytes.
    pub(crate) format: WireFormat,
    /// The safety state machine for the scenario's limits (disarmed, at home).
    pub(crate) supervisor: Supervisor,
    /// The platform, for the target's actuator values.
    pub(crate) geometry: Geometry,
    /// The motion streamed.
    pub(crate) trajectory: Trajectory,
    /// The motion's first sample time and length, seconds.
    pub(crate) span: (f64, f64),
}

impl LinkPlan {
    /// The plan for `scenario` (its `[link]` as it stands). Fails, naming the setting,
    /// when the channel map, the template or a board format is refused or the home pose has
    /// no actuator values.
    pub fn new(scenario: &Scenario) -> Result<Self> {
        let home = hardware::home_values(scenario)?;
        hardware::check_board_format(scenario)?;
        Ok(Self {
            settings: scenario.link.clone(),
            home,
            map: hardware::channel_map(scenario)?,
            format: hardware::format(&scenario.link)?,
            supervisor: hardware::supervisor(scenario, home),
            geometry: scenario.geometry.clone(),
            trajectory: scenario.motion.trajectory.clone(),
            span: (
                scenario.motion.sampling.start(),
                scenario.motion.sampling.duration(),
            ),
        })
    }

    /// The sender's settings: arm at the first tick or wait for an arm command; stop after
    /// so many seconds, or run until stopped.
    pub fn sender_config(&self, arm_at_start: bool, stop_after: Option<f64>) -> SenderConfig {
        SenderConfig {
            rate_hz: self.settings.rate_hz,
            format: self.format.clone(),
            map: self.map,
            supervisor: self.supervisor.clone(),
            arm_at_start,
            stop_after,
            record: None,
            clock: Clock::Wall,
        }
    }

    /// Where a platform whose actuators stand at `values` is, in words: its pose (forward
    /// kinematics from home, or why there is none) and the values themselves.
    pub(crate) fn left_at(&self, values: &[f64; 6]) -> (String, String) {
        let q = self.geometry.quantity();
        let (letter, digits) = (q.letter, q.decimals);
        let unit = if q.unit == "m" { " m" } else { q.unit };
        let actuators: Vec<String> = values
            .iter()
            .enumerate()
            .map(|(k, v)| format!("{letter}{} = {v:.digits$}{unit}", k + 1))
            .collect();
        let pose = match self
            .geometry
            .pose_from_actuator_values(values, &self.geometry.home_pose())
        {
            Ok(p) => {
                let [x, y, z] = [p.position.x, p.position.y, p.position.z];
                let [roll, pitch, yaw] = p.rpy_degrees();
                format!(
                    "x = {x:.6} m, y = {y:.6} m, z = {z:.6} m, roll = {roll:.4}°, pitch = {pitch:.4}°, yaw = {yaw:.4}°"
                )
            }
            Err(why) => format!("pose unknown ({why})"),
        };
        (pose, actuators.join(", "))
    }

    /// Open the serial port or UDP peer the settings name.
    pub(crate) fn open_device(&self) -> Result<Box<dyn Transport>> {
        hardware::open_device(&self.settings)
    }

    /// The motion as a target of stream time (from the motion's first sample; wrapping
    /// with `repeat`, else at rest at its last pose), with the actuators' velocity and
    /// acceleration.
    pub(crate) fn trajectory_target(&self, repeat: bool) -> Target {
        let geometry = self.geometry.clone();
        let trajectory = self.trajectory.clone();
        let (start, duration) = self.span;
        Box::new(move |t| match motion_time(t, duration, repeat) {
            None => {
                let values = geometry
                    .actuator_values_at(&trajectory.pose_at(start + duration))
                    .map_err(TargetError::source)?;
                Ok(Sample::Moving(ActuatorMotion::at_rest(values)))
            }
            Some(local) => moving_sample(&geometry, |s| trajectory.pose_at(start + s), local, 1.0),
        })
    }

    /// A live cue as a target: the actuator values of the cued pose at each tick (the cue
    /// reads its datagrams and steps the washout on the sender's thread).
    pub fn cue_target(&self, live: LiveCue) -> Target {
        self.cue_target_telling(live, None)
    }

    /// A live cue as a target, each tick's cued pose also left in `asked` (for the viewer:
    /// the values sent may give no pose by forward kinematics, on a singular layout). The
    /// tick never waits for it: a pose the viewer is reading is left for the next tick.
    pub(crate) fn cue_target_telling(&self, mut live: LiveCue, asked: Option<AskedPose>) -> Target {
        let geometry = self.geometry.clone();
        Box::new(move |t| {
            let pose = live.tick(t);
            if let Some(cell) = &asked
                && let Ok(mut slot) = cell.try_lock()
            {
                *slot = Some(pose);
            }
            geometry
                .actuator_values_at(&pose)
                .map(Sample::At)
                .map_err(TargetError::source)
        })
    }

    /// What a stream that follows the viewer samples, starting with `drive` (the viewer
    /// changes it as playback goes on).
    pub(crate) fn followed(&self, looping: bool, drive: Drive) -> Arc<Mutex<Followed>> {
        Arc::new(Mutex::new(Followed::new(
            self.geometry.clone(),
            self.trajectory.clone(),
            self.span,
            looping,
            drive,
        )))
    }

    /// The target of a stream that follows the viewer: whatever `followed` holds at each
    /// tick.
    pub(crate) fn followed_target(followed: Arc<Mutex<Followed>>) -> Target {
        Box::new(move |_t| {
            followed
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .sample()
        })
    }

    /// The actuator values the trajectory target asks for at stream time `t` (`None`
    /// where the motion is out of reach), without their derivatives.
    pub(crate) fn values_at(&self, t: f64, repeat: bool) -> Option<[f64; 6]> {
        let (start, duration) = self.span;
        let local = motion_time(t, duration, repeat).unwrap_or(duration);
        self.geometry
            .actuator_values_at(&self.trajectory.pose_at(start + local))
            .ok()
    }

    /// The first arming's ramp, planned against the motion's start (its speed there
    /// included): the ramp asked when the limits allow it, else the shortest that they
    /// do (`None` when the motion's start is out of reach). See
    /// [`stewart_link::safety::planned_ramp`].
    pub(crate) fn planned_first_ramp(&self, repeat: bool) -> Option<f64> {
        stewart_link::safety::planned_ramp(
            self.supervisor.limits(),
            &self.home,
            self.settings.ramp_s,
            |t| self.values_at(t, repeat),
            1e-3,
        )
    }
}

/// The motion's own time at stream time `t` (from its start), wrapping with `repeat`;
/// `None` once a motion played once has ended.
fn motion_time(t: f64, duration: f64, repeat: bool) -> Option<f64> {
    if !repeat && t >= duration {
        return None;
    }
    Some(if repeat && duration > 0.0 {
        t.rem_euclid(duration)
    } else {
        t
    })
}

/// The actuator values at `pose_at(time)` with their velocity and acceleration per second of
/// stream when `pose_at`'s clock runs `speed` times as fast: five-point central
/// differences. Where a neighbouring pose has no values (the motion leaves the workspace
/// there), the values alone.
pub(crate) fn moving_sample(
    geometry: &Geometry,
    pose_at: impl Fn(f64) -> Pose,
    time: f64,
    speed: f64,
) -> Result<Sample, TargetError> {
    let centre = geometry
        .actuator_values_at(&pose_at(time))
        .map_err(TargetError::source)?;
    if speed == 0.0 {
        return Ok(Sample::Moving(ActuatorMotion::at_rest(centre)));
    }
    let h = DIFFERENCE_STEP_S;
    let mut around = [[0.0; 6]; 4];
    for (slot, k) in around.iter_mut().zip([-2.0, -1.0, 1.0, 2.0]) {
        match geometry.actuator_values_at(&pose_at(time + k * h)) {
            Ok(v) => *slot = v,
            Err(_) => return Ok(Sample::At(centre)),
        }
    }
    let [m2, m1, p1, p2] = around;
    let velocity =
        std::array::from_fn(|j| speed * (m2[j] - 8.0 * m1[j] + 8.0 * p1[j] - p2[j]) / (12.0 * h));
    let acceleration = std::array::from_fn(|j| {
        speed * speed * (-m2[j] + 16.0 * m1[j] - 30.0 * centre[j] + 16.0 * p1[j] - p2[j])
            / (12.0 * h * h)
    });
    Ok(Sample::Moving(ActuatorMotion {
        position: centre,
        velocity,
        acceleration,
    }))
}

#[cfg(test)]
mod tests;
