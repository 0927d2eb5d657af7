//! The WGSL sources, from the top-level `shaders/` folder.

/// Lit instanced meshes.
pub const MESH: &str = include_str!("../../../shaders/mesh.wgsl");
/// Unlit lines.
pub const LINES: &str = include_str!("../../../shaders/lines.wgsl");

/// Every shader with its file name, for validation.
pub const ALL: [(&str, &str); 2] = [("mesh.wgsl", MESH), ("lines.wgsl", LINES)];
