//! Exports: frame sequences, GIF and MP4 videos, and the leg-length plot.

pub mod encode;
pub mod frames;
pub mod plot;
pub mod tables;
pub mod vector;
pub mod video;
