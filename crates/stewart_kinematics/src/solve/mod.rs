//! Kinematics solvers: inverse kinematics (one pose or millions on all cores), forward
//! kinematics (Newton, homotopy, every assembly mode), Jacobians and conditioning, what
//! the actuators do at a pose whatever their kind (`actuation`), a servo platform's angles
//! and level height (`servo_angles`), the scene to draw for a pose (`scene_frame`), and each
//! leg as an open chain for robot descriptions (`chains`).

pub mod actuation;
pub mod batch;
pub mod chains;
pub(crate) mod fast_trig;
pub mod forward;
pub mod inverse;
pub mod jacobian;
mod queries;
mod scene_frame;
mod servo_angles;
pub mod servo_closure;
pub(crate) mod wide;
