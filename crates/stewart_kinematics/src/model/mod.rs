//! The platform and its motion as data: angles and poses, the geometry and its layouts,
//! the actuators (linear legs or rotary servos), pose limits, trajectories, the `[link]`
//! table, the `[appearance]` table (CAD parts), and the scene to draw.

pub mod actuator;
pub mod angle;
pub mod appearance;
pub mod cueing_settings;
pub mod dynamics_settings;
pub mod geometry;
pub mod layout;
pub mod leg_solution;
pub mod limits;
pub mod link_settings;
pub mod pose;
pub mod rotary;
pub mod scene;
pub mod switch;
pub mod trajectory;
