//! Kinematics of the six-degree-of-freedom Gough–Stewart platform.
//!
//! Pure math on `nalgebra` (f64): no GPU, window or UI. The model follows the seed
//! article (README.md, "The model"): base joints `b_i` on a circle of radius `r_b` in
//! the base plane, platform joints `a_i` on a circle of radius `r_p` in the platform
//! plane, pose `(p, R)` with `R = Rz(yaw)·Ry(pitch)·Rx(roll)`, and leg `i` the segment
//! from `b_i` to `q_i = p + c + R (a_i − c)` (`c` the pivot, zero in the seed).
//!
//! The tree shows the layers (see ARCHITECTURE.md): [`model`] — the platform and its
//! motion as data; [`solve`] — inverse and forward kinematics, batches, Jacobians and what
//! the actuators do at a pose; [`analysis`] — what is computed from a model (checks,
//! workspace, design, forces, calibration); [`io`] — files and user input (scenarios,
//! settings, tables, text, accepted ranges). Each module is also reachable at the crate's
//! root (`stewart_kinematics::workspace`), as before the layers.
//!
//! - [`angle`]: angles whose unit is carried by the type;
//! - [`geometry`], [`layout`]: the platform and its named joint layouts;
//! - [`pose`], [`inverse`], [`batch`]: poses and inverse kinematics, one or millions;
//! - [`trajectory`]: motions over time and their sampling;
//! - [`checks`]: the pre-flight checks over a motion (stroke, rates, cones, clearance,
//!   singularity, jumps, rigid body); [`differences`]: the finite differences they use;
//! - [`jacobian`], [`architecture`], [`forward`], [`workspace`], [`forces`], [`limits`]:
//!   conditioning, singular geometries, forward kinematics, reach, loads, pose limits;
//! - [`scene`]: plain data describing what to draw (the renderer's input);
//! - [`rotary`]: rotary-servo (6-RSS) actuators and their closed-form inverse kinematics;
//! - [`link_settings`]: the `[link]` table (transport, rate, channel map) for real hardware;
//! - [`settings`], [`bounds`]: every adjustable number and the accepted range of each;
//! - [`calibration`]: joints and actuator offsets of a built platform from measured poses;
//! - [`scenario`]: scenario files (TOML) and the shipped presets;
//! - [`table`]: numeric CSV tables with located errors;
//! - [`text`]: input text with a size cap and plain words for foreign encodings.

pub mod analysis;
pub mod io;
pub mod model;
pub mod solve;

pub use analysis::{
    architecture, calibration, checks, cueing, design, differences, dynamics, forces, sound_layout,
    workspace,
};
pub use io::{bounds, scenario, settings, table, text};
pub use model::{
    actuator, angle, cueing_settings, dynamics_settings, geometry, layout, limits, link_settings,
    pose, rotary, scene, trajectory,
};
pub(crate) use solve::fast_trig;
pub use solve::{actuation, batch, forward, inverse, jacobian};

#[cfg(test)]
mod test_support;

pub use angle::Angle;
pub use batch::{BatchSolver, ServoBatch};
pub use checks::{CheckReport, CheckSettings, Finding, FindingKind, check_motion};
pub use forward::{ForwardError, ForwardOptions, ForwardSolution};
pub use geometry::{Geometry, GeometryError, GeometryParams, Plate, PlateJoints, StrokeLimits};
pub use inverse::LegSolution;
pub use jacobian::Conditioning;
pub use layout::Layout;
pub use limits::Limits;
pub use pose::Pose;
pub use scenario::{Scenario, ScenarioError};
pub use trajectory::{Motion, Samples, Sampling, Trajectory};
