//! The Stewart platform studio's renderer, on wgpu.
//!
//! It draws a [`stewart_kinematics::model::scene::SceneFrame`] — base and platform plates,
//! legs as actuator body and rod, joints, ground grid, axes, the traced path — into any
//! colour view: a window's surface, a texture inside the UI, or an offscreen texture
//! read back for export and tests. It knows nothing of egui or winit.
//!
//! - [`camera`]: the orbit camera (glam), and the camera that frames a cloud of points;
//! - [`draw_list`]: scene frame → instances, plates, lines and placed CAD parts (CPU);
//! - [`analysis`]: the workspace surface and the conditioning slice as coloured meshes;
//! - [`renderer`]: the one draw entry point ([`ViewFrame`] → a prepared view → a pass), on the
//!   shared pipelines of `pipelines.rs`;
//! - [`appearance`]: the CAD parts `[appearance]` names: STL, OBJ and glTF files read into meshes;
//! - [`offscreen`]: headless targets and read-back;
//! - [`Picture`]: a view rendered off screen at its own quality, drawn into another pass;
//! - [`gpu`]: adapter choice (a GPU, else lavapipe), honouring `WGPU_BACKEND` / `WGPU_ADAPTER_NAME`.

pub mod analysis;
pub mod appearance;
pub mod camera;
mod camera_fit;
pub mod colormap;
pub mod draw_list;
mod extent;
pub mod gpu;
mod gpu_mesh;
pub mod gpu_types;
pub mod mesh;
pub mod offscreen;
mod picture;
mod pipelines;
pub mod plate_shape;
pub mod readback;
pub mod renderer;
pub mod shaders;
pub mod targets;
pub mod text;
pub mod theme;
pub mod ticks;
pub mod view;

pub use camera::OrbitCamera;
pub use draw_list::{DrawList, Overlays};
pub use gpu::{Gpu, GpuError};
pub use offscreen::{Image, Offscreen, OffscreenError};
pub use picture::Picture;
pub use renderer::{Renderer, ViewFrame};
pub use text::{Anchor, Fonts, TextItem, TextSize};
pub use theme::Theme;
pub use view::PreparedView;
