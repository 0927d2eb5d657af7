//! Trajectories: poses as a function of time, and their sampling.
//!
//! Time is always an argument; nothing here reads a clock.

pub mod keyframes;
pub mod pose_table;
pub mod shapes;
pub mod sinusoid;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::pose::Pose;
pub use keyframes::{Interpolation, Keyframe, KeyframeError, Keyframes};
pub use pose_table::{POSE_COLUMNS, PoseTable, check_pose_ranges};
pub use shapes::{Circle, FigureEight, Helix, Sway};
pub use sinusoid::{CHANNEL_NAMES, Channel, Sinusoid, Wave};

/// A motion of the platform over time.
#[derive(Clone, Debug, PartialEq)]
pub enum Trajectory {
    /// Six independent sinusoids (the seed's motion).
    Sinusoid(Sinusoid),
    /// A level circle.
    Circle(Circle),
    /// A level figure-eight.
    FigureEight(FigureEight),
    /// A rising helix.
    Helix(Helix),
    /// A circle banking into the turn.
    Sway(Sway),
    /// Interpolated keyframes (also what an imported pose table becomes).
    Keyframes(Keyframes),
}

impl Trajectory {
    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        match self {
            Trajectory::Sinusoid(s) => s.pose_at(t),
            Trajectory::Circle(s) => s.pose_at(t),
            Trajectory::FigureEight(s) => s.pose_at(t),
            Trajectory::Helix(s) => s.pose_at(t),
            Trajectory::Sway(s) => s.pose_at(t),
            Trajectory::Keyframes(s) => s.pose_at(t),
        }
    }

    /// The name of the kind, as written in scenario files.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Trajectory::Sinusoid(_) => "sinusoid",
            Trajectory::Circle(_) => "circle",
            Trajectory::FigureEight(_) => "figure8",
            Trajectory::Helix(_) => "helix",
            Trajectory::Sway(_) => "sway",
            Trajectory::Keyframes(_) => "keyframes",
        }
    }
}

/// Why a sampling was refused.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SamplingError {
    /// Duration not a positive finite number.
    #[error("`duration_s` must be a positive finite number of seconds, got {0}")]
    Duration(f64),
    /// Fewer than two samples or more than [`MAX_SAMPLES`].
    #[error("`samples` must be a whole number from 2 to {MAX_SAMPLES}, got {0}")]
    TooFewSamples(u64),
    /// Samples so close that their times cannot be told apart at that distance from zero.
    #[error(
        "the time step {step:e} s is too fine to be told apart from the times around {at:e} s (fewer than 1e10 steps per unit of time from zero): use fewer `samples` or a `start_s` nearer 0"
    )]
    TooFine {
        /// The step, seconds.
        step: f64,
        /// The time farthest from zero, seconds.
        at: f64,
    },
    /// Start time not finite.
    #[error("`start_s` must be a finite number of seconds, got {0}")]
    Start(f64),
}

/// Evenly spaced sample times over `[start, start + duration]`, both ends included
/// (MATLAB's `linspace(start, start + duration, samples)`), or, for a keyframed motion
/// such as a pose table, its keys' own times ([`Sampling::at_keys`]: what `check` judges
/// is then exactly what every command plays, row for row).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sampling {
    start: f64,
    duration: f64,
    samples: usize,
    /// Sampled at the keys' own times (`start`, `duration` and `samples` are then the
    /// keys' span and count).
    #[serde(default)]
    at_keys: bool,
}

/// Most samples a sampling may ask for (about 80 MB of poses); protects against typos.
pub const MAX_SAMPLES: usize = 10_000_000;

impl Sampling {
    /// The seed's sampling: 1001 samples over [0, 10] s.
    pub const SEED: Sampling = Sampling {
        start: 0.0,
        duration: 10.0,
        samples: 1001,
        at_keys: false,
    };

    /// `samples` times from 0 to `duration` seconds.
    pub fn new(duration: f64, samples: u64) -> Result<Self, SamplingError> {
        Self::with_start(0.0, duration, samples)
    }

    /// `samples` times from `start` to `start + duration` seconds.
    pub fn with_start(start: f64, duration: f64, samples: u64) -> Result<Self, SamplingError> {
        if !start.is_finite() {
            return Err(SamplingError::Start(start));
        }
        if !(duration.is_finite() && duration > 0.0) {
            return Err(SamplingError::Duration(duration));
        }
        if !(2..=MAX_SAMPLES as u64).contains(&samples) {
            return Err(SamplingError::TooFewSamples(samples));
        }
        let step = duration / (samples - 1) as f64;
        let at = start.abs().max((start + duration).abs());
        if step < 1e-10 * at || !(start + duration).is_finite() {
            return Err(SamplingError::TooFine { step, at });
        }
        Ok(Self {
            start,
            duration,
            samples: samples as usize,
            at_keys: false,
        })
    }

    /// Sampled at the times of `keys` themselves (a pose table's rows): the first is the
    /// start, the last the end.
    pub fn at_keys(keys: &Keyframes) -> Result<Self, SamplingError> {
        let (first, last) = keys.time_span();
        let n = keys.keys().len().max(2) as u64;
        Ok(Self {
            at_keys: true,
            ..Self::with_start(first, last - first, n)?
        })
    }

    /// Whether the samples are the keys' own times.
    pub const fn is_at_keys(&self) -> bool {
        self.at_keys
    }

    /// Number of samples.
    pub const fn len(&self) -> usize {
        self.samples
    }

    /// Always false: a sampling has at least two samples.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Duration, seconds.
    pub const fn duration(&self) -> f64 {
        self.duration
    }

    /// First time, seconds.
    pub fn start(&self) -> f64 {
        self.start
    }

    /// Time between samples, seconds.
    pub fn step(&self) -> f64 {
        self.duration / (self.samples - 1) as f64
    }

    /// Time of sample `k` (0-based): `start + k·duration/(n − 1)`, computed so that
    /// `k·duration` is divided last (sample 1 of the seed is exactly the double 0.01).
    pub fn time(&self, k: usize) -> f64 {
        self.start + (k as f64 * self.duration) / (self.samples - 1) as f64
    }

    /// All sample times.
    pub fn times(&self) -> impl ExactSizeIterator<Item = f64> + '_ {
        (0..self.samples).map(|k| self.time(k))
    }
}

/// A trajectory together with how it is sampled.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The trajectory.
    pub trajectory: Trajectory,
    /// Its sample times.
    pub sampling: Sampling,
}

impl Motion {
    /// The seed's motion for home height `h0`.
    pub fn seed(h0: f64) -> Self {
        Self {
            trajectory: Trajectory::Sinusoid(Sinusoid::seed(h0)),
            sampling: Sampling::SEED,
        }
    }

    /// Time of sample `k` (0-based): the `k`-th key's when the motion is sampled at its
    /// keys, else the sampling's even time.
    pub fn time(&self, k: usize) -> f64 {
        match &self.trajectory {
            Trajectory::Keyframes(keys) if self.sampling.is_at_keys() => {
                let keys = keys.keys();
                keys.get(k)
                    .or(keys.last())
                    .map_or(self.sampling.start(), |key| key.t)
            }
            _ => self.sampling.time(k),
        }
    }

    /// All sample times.
    pub fn times(&self) -> impl ExactSizeIterator<Item = f64> + '_ {
        (0..self.sampling.len()).map(|k| self.time(k))
    }

    /// What `check` judges: the samples, and for keys sampled at their own times but
    /// joined by curves (cubic, smoothstep: a spline overshoots between rows) also every
    /// instant the link plays at `link_rate_hz` from the first key, so that what is judged
    /// is what plays (more finely spread where that would be over [`MAX_SAMPLES`]). An instant within a quarter period of a key is left to the key (the
    /// differences that judge speed, acceleration and jerk need steps of that order).
    pub fn samples_judged(&self, link_rate_hz: f64) -> Samples {
        let curved = match &self.trajectory {
            Trajectory::Keyframes(keys) if self.sampling.is_at_keys() => {
                (keys.interpolation() != Interpolation::Linear).then_some(keys)
            }
            _ => None,
        };
        let Some(keys) = curved else {
            return self.sample();
        };
        let (first, last) = keys.time_span();
        if !(link_rate_hz.is_finite() && link_rate_hz > 0.0) {
            return self.sample();
        }
        // A motion longer than the most samples judged at that rate is judged as finely as
        // they allow (still between the rows, never at the rows alone).
        let rate = link_rate_hz.min((MAX_SAMPLES - keys.keys().len()) as f64 / (last - first));
        let period = 1.0 / rate;
        let ticks = ((last - first) / period).floor();
        if !(ticks.is_finite() && ticks >= 0.0) {
            return self.sample();
        }
        let mut times: Vec<f64> = Vec::with_capacity(keys.keys().len() + ticks as usize + 1);
        let mut key_times = keys.keys().iter().map(|k| k.t).peekable();
        let mut previous_key = f64::NEG_INFINITY;
        for k in 0..=ticks as u64 {
            let tick = first + k as f64 * period;
            while let Some(&t) = key_times.peek().filter(|&&t| t <= tick) {
                times.push(t);
                previous_key = t;
                key_times.next();
            }
            let next_key = key_times.peek().copied().unwrap_or(f64::INFINITY);
            if tick - previous_key > 0.25 * period && next_key - tick > 0.25 * period {
                times.push(tick);
            }
        }
        times.extend(key_times);
        let poses = times.iter().map(|&t| self.trajectory.pose_at(t)).collect();
        Samples { times, poses }
    }

    /// Sample times and poses.
    pub fn sample(&self) -> Samples {
        let times: Vec<f64> = self.times().collect();
        let poses = times.iter().map(|&t| self.trajectory.pose_at(t)).collect();
        Samples { times, poses }
    }
}

/// Poses at times: a sampled motion or an imported table.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Samples {
    /// Times, seconds.
    pub times: Vec<f64>,
    /// Pose at each time.
    pub poses: Vec<Pose>,
}

impl Samples {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.poses.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.poses.is_empty()
    }
}

#[cfg(test)]
mod tests;
