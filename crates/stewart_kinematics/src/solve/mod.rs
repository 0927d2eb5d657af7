//! Kinematics solvers: inverse kinematics (one pose or millions on all cores), forward
//! kinematics (Newton, homotopy, every assembly mode), Jacobians and conditioning, and what
//! the actuators do at a pose whatever their kind (`actuation`).

pub mod actuation;
pub mod batch;
mod batch_lanes;
pub(crate) mod fast_trig;
pub mod forward;
pub mod inverse;
pub mod jacobian;
