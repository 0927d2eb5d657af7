//! What a stream follows: the target the sender asks for at each tick of stream time (a
//! [`Target`]), the [`Sample`] it gives — six actuator values in natural units (metres or
//! degrees), with their velocity and acceleration ([`ActuatorMotion`]) when the source knows them —
//! or why it has none ([`TargetError`]). Whoever builds a stream (the app's link plan)
//! speaks this vocabulary; the supervisor, the generator and the sender read it.

use thiserror::Error;

/// Position, velocity and acceleration of the six actuators, natural units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ActuatorMotion {
    /// Positions (metres or degrees).
    pub position: [f64; 6],
    /// Velocities, units per second.
    pub velocity: [f64; 6],
    /// Accelerations, units per second squared.
    pub acceleration: [f64; 6],
}

impl ActuatorMotion {
    /// At rest at `position`.
    pub fn at_rest(position: [f64; 6]) -> Self {
        Self {
            position,
            ..Self::default()
        }
    }
}

/// The target at one tick: its positions, with their velocity and acceleration when the
/// source knows them (a trajectory, differentiated), else estimated from the last targets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sample {
    /// Positions only (a teleoperated pose, a live signal).
    At([f64; 6]),
    /// Positions with velocity and acceleration.
    Moving(ActuatorMotion),
}

impl Sample {
    /// The positions.
    pub fn position(&self) -> &[f64; 6] {
        match self {
            Sample::At(p) => p,
            Sample::Moving(m) => &m.position,
        }
    }
}

/// Why a tick has no sound target: the supervisor holds (or, arming, comes to rest) on it.
#[derive(Clone, Debug, Error)]
pub enum TargetError {
    /// The motion has no values at this time (a servo cannot reach its joint, …): the
    /// source's own error, kept for callers to inspect.
    #[error(transparent)]
    Source(std::sync::Arc<dyn std::error::Error + Send + Sync>),
    /// A value that is NaN or infinite.
    #[error("actuator {actuator} has no value ({value})")]
    NotFinite {
        /// From 1.
        actuator: usize,
        /// The value.
        value: f64,
    },
    /// A value outside the actuator's range.
    #[error("actuator {actuator} would go to {value:.6}, outside its range {min} … {max}")]
    OutOfRange {
        /// From 1.
        actuator: usize,
        /// The value.
        value: f64,
        /// The range's lower end.
        min: f64,
        /// Its upper end.
        max: f64,
    },
}

impl TargetError {
    /// The source's error `e` (why the motion has no values now).
    pub fn source(e: impl std::error::Error + Send + Sync + 'static) -> Self {
        TargetError::Source(std::sync::Arc::new(e))
    }
}

impl From<&str> for TargetError {
    fn from(why: &str) -> Self {
        TargetError::Source(std::sync::Arc::from(Box::<
            dyn std::error::Error + Send + Sync,
        >::from(why)))
    }
}

impl From<String> for TargetError {
    fn from(why: String) -> Self {
        TargetError::Source(std::sync::Arc::from(Box::<
            dyn std::error::Error + Send + Sync,
        >::from(why)))
    }
}

/// The target at a stream time: six actuator values in natural units (with their velocity
/// and acceleration when the source knows them), or why there is none.
pub type Target = Box<dyn FnMut(f64) -> Result<Sample, TargetError> + Send>;
