//! GPU-side structs, `#[repr(C)]` and Pod, mirroring the WGSL structs in `shaders/`.

use bytemuck::{Pod, Zeroable};

/// `Globals` in `mesh.wgsl` and `lines.wgsl` (std140-compatible: vec4 and mat4 only).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct Globals {
    /// Projection × view.
    pub view_proj: [[f32; 4]; 4],
    /// Eye position (xyz).
    pub eye: [f32; 4],
    /// Direction towards the key light (xyz) and its strength (w).
    pub key_light: [f32; 4],
    /// Direction towards the fill light (xyz) and its strength (w).
    pub fill_light: [f32; 4],
    /// Ambient, specular strength, shininess, and 1 when the shader must encode sRGB itself.
    pub shading: [f32; 4],
}

/// A mesh vertex: position and normal.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct MeshVertex {
    /// Position, model space.
    pub position: [f32; 3],
    /// Normal, model space.
    pub normal: [f32; 3],
}

/// `InstanceIn` in `mesh.wgsl`: a model matrix (columns) and a linear colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct MeshInstance {
    /// Model matrix, column by column.
    pub model: [[f32; 4]; 4],
    /// Linear RGB and alpha.
    pub color: [f32; 4],
}

/// `VertexIn` in `lines.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct LineVertex {
    /// Position, world.
    pub position: [f32; 3],
    /// Linear RGB and alpha.
    pub color: [f32; 4],
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_match_the_wgsl_layouts() {
        assert_eq!(size_of::<Globals>(), 64 + 4 * 16);
        assert_eq!(size_of::<MeshVertex>(), 24);
        assert_eq!(size_of::<MeshInstance>(), 80);
        assert_eq!(size_of::<LineVertex>(), 28);
    }
}
