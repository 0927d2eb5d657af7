//! What is computed from a model: the architecture verdict, the pre-flight checks, the
//! workspace, the actuator range an envelope needs, forces, calibration of a built
//! platform, motion cueing from vehicle motion, the nearest sound layout, finite
//! differences.

pub mod architecture;
pub mod calibration;
pub mod certified;
pub mod checks;
pub mod cueing;
pub mod design;
pub mod differences;
pub mod dynamics;
pub mod forces;
pub mod sound_layout;
pub mod workspace;
