//! Exports: frame sequences, GIF and MP4 videos, the actuator plot, the workspace figure
//! and surface (PLY), and the geometry as a C header for firmware.

pub mod encode;
pub(crate) mod firmware;
pub mod frames;
pub(crate) mod gif_delta;
pub(crate) mod gltf;
pub(crate) mod omct_plot;
pub(crate) mod plot;
pub(crate) mod ply;
pub(crate) mod robot;
pub mod tables;
pub(crate) mod vector;
pub(crate) mod video;
pub(crate) mod workspace_plot;
