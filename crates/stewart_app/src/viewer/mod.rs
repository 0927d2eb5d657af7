//! The interactive viewer: a window with the 3D view, panels and the live plot.

pub mod state;
pub mod ui;
pub mod view3d;
pub mod window;

pub use state::ViewerState;
pub use window::{ViewOptions, run};
