//! The interactive viewer: a window with the 3D view, panels and the live plot.
//!
//! - [`state`]: what the viewer shows, and its one edit path for the scenario;
//! - [`derived`]: the plotted samples, path, layout and the background report;
//! - [`playback`], [`look`], [`files`], [`exports`]: the parts of the state the panels edit;
//! - [`panels`]: one egui function per panel;
//! - [`view3d`]: the renderer inside egui (a paint callback);
//! - [`history`], [`export_job`]: the manual-mode history and background exports;
//! - [`live_link`]: the stream to hardware, following what the viewer shows;
//! - [`teleop`], [`gamepad`]: keyboard and gamepad moves of the manual pose, stopped at
//!   the edge of the reachable set;
//! - [`session`]: what the viewer remembers between runs; [`undo`]: undo and redo of edits;
//! - [`shots`]: screenshots of the 3D view (any size, transparent) or the window;
//! - [`window`]: winit, egui-winit and egui-wgpu around all that; [`window_size`]: the
//!   size it opens at.

pub mod assembly;
pub mod derived;
pub mod design;
pub mod document;
pub mod editor;
pub mod export_job;
pub mod exports;
mod file_actions;
pub mod files;
pub mod fonts;
pub mod gamepad;
pub mod history;
pub mod job;
pub mod live_link;
pub mod look;
pub mod mode_view;
pub mod panels;
pub mod playback;
pub mod quality;
pub mod reach;
pub mod reveal;
pub mod session;
pub mod shots;
pub mod state;
pub mod teleop;
pub mod undo;
pub mod vehicle;
pub mod view3d;
pub mod window;
pub mod window_shot;
pub mod window_size;
pub mod workspace;

pub use state::ViewerState;
pub use window::{ViewOptions, run};
