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
    /// The view's background, linear RGB and alpha.
    pub background: [f32; 4],
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

/// `VertexIn` in `analysis.wgsl`: a world position, a normal and a linear colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct ColouredVertex {
    /// Position, world space.
    pub position: [f32; 3],
    /// Normal, world space (not necessarily unit length).
    pub normal: [f32; 3],
    /// Linear RGB and alpha.
    pub color: [f32; 4],
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

/// A model-space normal in world space, as `mesh.wgsl`'s `vs_main` computes it: the
/// inverse transpose of the model's linear part applied to `n`, for instance matrices
/// whose columns are orthogonal (a rotation times a scale along the mesh's own axes):
/// each column divided by its squared length. Not normalised (the fragment shader does).
pub fn normal_to_world(model: &[[f32; 4]; 4], n: glam::Vec3) -> glam::Vec3 {
    let column = |k: usize| glam::Vec3::new(model[k][0], model[k][1], model[k][2]);
    let (c0, c1, c2) = (column(0), column(1), column(2));
    c0 * (n.x / c0.dot(c0)) + c1 * (n.y / c1.dot(c1)) + c2 * (n.z / c2.dot(c2))
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

/// `VertexIn` in `text.wgsl`: a corner of a glyph or box quad.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct TextVertex {
    /// Normalised device coordinates.
    pub position: [f32; 2],
    /// Atlas coordinates, 0..1.
    pub uv: [f32; 2],
    /// Linear RGB and alpha.
    pub color: [f32; 4],
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stretched_cone_keeps_its_side_normals_perpendicular_to_its_sides() {
        use glam::{Mat4, Quat, Vec3};
        // An axis arrow's tip: radius 0.026 m, length 0.06 m, tilted.
        let model = Mat4::from_scale_rotation_translation(
            Vec3::new(0.026, 0.026, 0.06),
            Quat::from_rotation_arc(Vec3::Z, Vec3::new(1.0, 0.5, 0.3).normalize()),
            Vec3::new(0.2, -0.1, 0.8),
        );
        let cols = model.to_cols_array_2d();
        let cone = crate::mesh::Mesh::cone();
        let apex = model.transform_point3(Vec3::Z);
        let mut checked = 0;
        for v in &cone.vertices {
            let p = Vec3::from_array(v.position);
            let n = Vec3::from_array(v.normal);
            if p.z != 0.0 || n.z <= 0.0 {
                continue; // the apex, or the base disc
            }
            let slant = (apex - model.transform_point3(p)).normalize();
            let good = normal_to_world(&cols, n).normalize();
            assert!(good.dot(slant).abs() < 1e-5, "{}", good.dot(slant));
            // The model matrix alone (the old way) tilts them off the surface.
            let naive = model.transform_vector3(n).normalize();
            assert!(naive.dot(slant).abs() > 0.1, "{}", naive.dot(slant));
            checked += 1;
        }
        assert_eq!(checked, 64);
    }

    #[test]
    fn sizes_match_the_wgsl_layouts() {
        assert_eq!(size_of::<Globals>(), 64 + 5 * 16); // checked against naga in tests/render
        assert_eq!(size_of::<MeshVertex>(), 24);
        assert_eq!(size_of::<MeshInstance>(), 80);
        assert_eq!(size_of::<LineVertex>(), 28);
    }
}
