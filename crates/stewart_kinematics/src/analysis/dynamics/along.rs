//! Dynamics along a sampled motion: the actuator efforts at every sample (velocities and
//! accelerations by central differences, as `forces` takes them) and the lowest natural
//! frequency over the motion.

use nalgebra::{Matrix3, Vector3, Vector6};

use super::{DynamicsError, DynamicsSettings, MotionState};
use crate::analysis::differences::{first_difference, second_difference};
use crate::analysis::dynamics;
use crate::analysis::forces;
use crate::analysis::forces::{ForceError, ForceSeries, Payload, skew_vector};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::trajectory::Samples;

/// The motion state at every sample: the pivot point's velocity and acceleration by
/// central differences of the positions, `ω` and `α` from those of the rotations
/// (`Ṙ = [ω]× R`, and `R̈ Rᵀ = [α]× + [ω]×²` whose skew part is `[α]×`).
pub fn motion_states(samples: &Samples) -> Vec<MotionState> {
    let times = &samples.times;
    let positions: Vec<Vector3<f64>> = samples.poses.iter().map(|p| p.position).collect();
    let rotations: Vec<Matrix3<f64>> = samples.poses.iter().map(|p| p.rotation()).collect();
    let (zero_v, zero_m) = (Vector3::zeros(), Matrix3::zeros());
    (0..samples.len())
        .map(|k| {
            let v = first_difference(times, &positions, k).unwrap_or(zero_v);
            let a = second_difference(times, &positions, k).unwrap_or(zero_v);
            let rt = rotations[k].transpose();
            let w = skew_vector(&(first_difference(times, &rotations, k).unwrap_or(zero_m) * rt));
            let alpha =
                skew_vector(&(second_difference(times, &rotations, k).unwrap_or(zero_m) * rt));
            MotionState {
                pose: samples.poses[k],
                twist: Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z),
                twist_rate: Vector6::new(a.x, a.y, a.z, alpha.x, alpha.y, alpha.z),
            }
        })
        .collect()
}

impl DynamicsSettings {
    /// Whether the legs add nothing: no part has mass or inertia and there is no friction.
    pub fn adds_nothing(&self) -> bool {
        self.cylinder().is_massless()
            && self.rod().is_massless()
            && self.horn().is_massless()
            && self.actuator_friction == 0.0
    }
}

/// Static efforts (gravity on platform, payload and legs) and dynamic ones (with
/// inertia and friction) at every sample of a motion. With massless legs and no
/// friction this is [`crate::analysis::forces::forces_along`] exactly.
pub fn efforts_along(
    geometry: &Geometry,
    samples: &Samples,
    payload: &Payload,
    dynamics: &DynamicsSettings,
) -> Result<ForceSeries, ForceError> {
    if dynamics.adds_nothing() {
        return forces::forces_along(geometry, samples, payload);
    }
    let states = motion_states(samples);
    let mut statics = Vec::with_capacity(states.len());
    let mut efforts = Vec::with_capacity(states.len());
    for (state, &time) in states.iter().zip(&samples.times) {
        let located = |e: DynamicsError| match e {
            DynamicsError::Unreachable { servo } => ForceError::Unreachable { time, servo },
            _ => ForceError::Singular { time },
        };
        let still = MotionState::still(state.pose);
        statics.push(
            dynamics::inverse_dynamics(geometry, &still, payload, dynamics).map_err(located)?,
        );
        efforts
            .push(dynamics::inverse_dynamics(geometry, state, payload, dynamics).map_err(located)?);
    }
    Ok(ForceSeries {
        times: samples.times.clone(),
        statics,
        dynamics: efforts,
    })
}

/// Where along a motion the lowest natural frequency occurs.
#[derive(Clone, Debug, PartialEq)]
pub struct LowestMode {
    /// Time of the sample, s.
    pub time: f64,
    /// The pose there.
    pub pose: Pose,
    /// The lowest natural frequency there, Hz.
    pub frequency_hz: f64,
    /// Its mode shape (unit vector).
    pub mode: Vector6<f64>,
}

/// The lowest natural frequency over every sample of a motion, and where it occurs; the
/// first sample whose modes cannot be computed stops with its time.
pub fn lowest_mode_along(
    geometry: &Geometry,
    samples: &Samples,
    payload: &Payload,
    dynamics: &DynamicsSettings,
) -> Result<Option<LowestMode>, (f64, DynamicsError)> {
    let mut lowest: Option<LowestMode> = None;
    for (pose, &time) in samples.poses.iter().zip(&samples.times) {
        let modes = dynamics::modes(geometry, pose, payload, dynamics).map_err(|e| (time, e))?;
        if lowest
            .as_ref()
            .is_none_or(|l| modes.frequencies_hz[0] < l.frequency_hz)
        {
            lowest = Some(LowestMode {
                time,
                pose: *pose,
                frequency_hz: modes.frequencies_hz[0],
                mode: modes.modes[0],
            });
        }
    }
    Ok(lowest)
}
