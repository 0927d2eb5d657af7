//! The interactive viewer: a window with the 3D view, panels and the live plot. Its
//! folders say who owns what:
//!
//! - [`state`]: what the viewer shows and edits — [`ViewerState`] and its parts: the
//!   document (the scenario, its one edit path, undo, what is derived from it), playback,
//!   the look, files, exports, the live link to hardware, teleoperation, the session;
//! - [`tools`]: the background computations the panels ask for — the job runner, the
//!   workspace, the design search, reach, the mode viewer, assembly modes;
//! - [`view3d`]: the 3D view's services — its quality, the paint callback that draws it
//!   inside egui's pass, screenshots — below the state and panels that use them;
//! - [`window`]: the shell around it all — winit and egui-wgpu, the window's size, fonts,
//!   whole-window shots; nothing in the state, the panels or the tools reaches into it;
//! - [`panels`]: one egui function per panel, each given the parts it edits;
//! - [`error`]: the one error everything above returns, worded only where it is shown,
//!   and the status line of a file action; [`reveal`]: *Show in folder*.

pub(crate) mod error;
pub mod panels;
pub(crate) mod reveal;
pub(crate) mod state;
pub(crate) mod tools;
pub(crate) mod view3d;
pub(crate) mod window;

#[cfg(test)]
mod ui_tests;

pub use state::ViewerState;
pub(crate) use window::{ViewOptions, run};
