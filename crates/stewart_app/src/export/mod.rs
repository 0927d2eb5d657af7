//! Exports: frame sequences, GIF and MP4 videos, the actuator plot, the workspace figure
//! and surface (PLY), and the geometry as a C header for firmware.

pub mod encode;
pub mod firmware;
pub mod frames;
pub mod gif_delta;
pub mod plot;
pub mod ply;
pub mod tables;
pub mod vector;
pub mod video;
pub mod workspace_plot;
