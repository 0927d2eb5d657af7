//! The interactive viewer: a window with the 3D view, panels and the live plot.
//!
//! - [`state`]: what the viewer shows (plain core types; the panels edit it);
//! - [`panels`]: one egui function per panel;
//! - [`view3d`]: the renderer inside egui (a paint callback);
//! - [`history`], [`export_job`]: the manual-mode history and background exports;
//! - [`window`]: winit, egui-winit and egui-wgpu around all that.

pub mod export_job;
pub mod history;
pub mod panels;
pub mod state;
pub mod view3d;
pub mod window;

pub use state::ViewerState;
pub use window::{ViewOptions, run};
