//! Triangles without normals made drawable: each triangle its own flat normal (what glTF
//! prescribes for meshes without normals, and all an STL file describes).

use glam::Vec3;

use crate::gpu_types::MeshVertex;
use crate::mesh::Mesh;

/// A mesh growing triangle by triangle, flat-shaded.
#[derive(Default)]
pub(super) struct FlatMesh {
    mesh: Mesh,
}

impl FlatMesh {
    /// Room for `triangles` triangles.
    pub(super) fn with_capacity(triangles: usize) -> Self {
        Self {
            mesh: Mesh {
                vertices: Vec::with_capacity(3 * triangles),
                indices: Vec::with_capacity(3 * triangles),
            },
        }
    }

    /// Add the triangle `a`, `b`, `c` with its own normal; a triangle of no area is
    /// left out (it draws nothing and has no normal).
    pub(super) fn push(&mut self, a: Vec3, b: Vec3, c: Vec3) {
        let Some(n) = (b - a).cross(c - a).try_normalize() else {
            return;
        };
        let first = self.mesh.vertices.len() as u32;
        for p in [a, b, c] {
            self.mesh.vertices.push(MeshVertex {
                position: p.to_array(),
                normal: n.to_array(),
            });
        }
        self.mesh.indices.extend([first, first + 1, first + 2]);
    }

    /// The mesh built.
    pub(super) fn finish(self) -> Mesh {
        self.mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_triangle_gets_the_normal_its_winding_gives_and_slivers_of_no_area_are_dropped() {
        let mut m = FlatMesh::default();
        m.push(Vec3::ZERO, Vec3::X, Vec3::Y);
        m.push(Vec3::ZERO, Vec3::Y, Vec3::X);
        m.push(Vec3::ZERO, Vec3::X, 2.0 * Vec3::X);
        let mesh = m.finish();
        assert_eq!(mesh.indices, [0, 1, 2, 3, 4, 5]);
        assert_eq!(mesh.vertices[0].normal, [0.0, 0.0, 1.0]);
        assert_eq!(mesh.vertices[3].normal, [0.0, 0.0, -1.0]);
    }
}
