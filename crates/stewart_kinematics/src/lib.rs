//! Kinematics of the six-degree-of-freedom Gough–Stewart platform.
//!
//! Pure math on `nalgebra` (f64): no GPU, window or UI. The model follows the seed
//! article (docs/guide/file-format.md, "The model"): base joints `b_i` on a circle of radius `r_b` in
//! the base plane, platform joints `a_i` on a circle of radius `r_p` in the platform
//! plane, pose `(p, R)` with `R = Rz(yaw)·Ry(pitch)·Rx(roll)`, and leg `i` the segment
//! from `b_i` to `q_i = p + c + R (a_i − c)` (`c` the pivot, zero in the seed).
//!
//! The tree shows the layers, each a wall the one below cannot see through (see
//! ARCHITECTURE.md; `scripts/layer-check.py` keeps them):
//!
//! - [`model`] — the platform and its motion as data: [`model::angle`], [`model::pose`],
//!   [`model::geometry`] and its [`model::layout`]s, the [`model::actuator`]s (linear legs or
//!   [`model::rotary`] servos), pose [`model::limits`], [`model::trajectory`], the tables of
//!   settings each feature reads (`[link]`, `[cueing]`, `[dynamics]`), and the
//!   [`model::scene`] a renderer draws;
//! - [`solve`] — what a pose makes of the model: [`solve::inverse`] kinematics one pose at a
//!   time or millions in a [`solve::batch`], [`solve::forward`] kinematics with every
//!   assembly mode, [`solve::jacobian`]s and conditioning, and [`solve::actuation`] (what the
//!   actuators do, whatever their kind);
//! - [`analysis`] — what is computed from a model over many poses: the pre-flight
//!   [`analysis::checks`], the [`analysis::workspace`], [`analysis::design`] ranges,
//!   [`analysis::forces`] and [`analysis::dynamics`], [`analysis::calibration`],
//!   [`analysis::cueing`] from vehicle motion, singular [`analysis::architecture`]s;
//! - [`io`] — beside them: [`io::scenario`] files and presets, the [`io::settings`] every
//!   number is declared in, numeric CSV [`io::table`]s;
//! - [`ground`] — under all of them: the accepted range of every kind of number
//!   ([`ground::bounds`]) and the rules input [`ground::text`] is read by.
//!
//! The root names what most users start from; everything else is reached through its
//! layer (`stewart_kinematics::analysis::workspace`):
//!
//! - [`Scenario`], [`ScenarioError`]: a scenario file or preset, read and checked;
//! - [`Geometry`], [`GeometryParams`], [`GeometryError`]: the platform, its parameters, and
//!   why a set of parameters is not a platform;
//! - [`Pose`], [`Angle`]: where the platform is, and angles whose unit is in the type;
//! - [`Trajectory`], [`Sampling`]: motions over time and how they are sampled;
//! - [`BatchSolver`]: inverse kinematics for millions of poses on all cores;
//! - [`CheckReport`]: what the pre-flight checks found over a motion.

pub mod analysis;
pub mod ground;
pub mod io;
pub mod model;
pub mod solve;

pub use analysis::checks::CheckReport;
pub use io::scenario::{Scenario, ScenarioError};
pub use model::angle::Angle;
pub use model::geometry::{Geometry, GeometryError, GeometryParams};
pub use model::pose::Pose;
pub use model::trajectory::{Sampling, Trajectory};
pub use solve::batch::BatchSolver;

#[cfg(test)]
mod test_support;
