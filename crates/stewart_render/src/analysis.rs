//! Analysis drawn into the 3D view: the workspace surface (translucent, one colour) and a
//! slice through the workspace coloured by the condition number. Built on the CPU from
//! the kinematics' results (f64 → f32 here), uploaded once per result (the draw list
//! holds them behind an `Arc`, and a view keeps the GPU copy while the same `Arc` comes
//! back) and drawn translucent after the opaque scene.

use glam::Vec3;
use stewart_kinematics::analysis::workspace::{Plane, Slice, WorkspaceSurface};

use crate::colormap;
use crate::gpu_types::ColouredVertex;
use crate::theme::srgb_to_linear;

/// A triangle mesh in world coordinates with a colour per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnalysisMesh {
    /// Vertices.
    pub vertices: Vec<ColouredVertex>,
    /// Triangles, three indices each.
    pub indices: Vec<u32>,
}

impl AnalysisMesh {
    /// The workspace surface in linear `colour` (with its alpha), with smooth normals
    /// (each vertex the area-weighted mean of its triangles').
    pub fn surface(surface: &WorkspaceSurface, colour: [f32; 4]) -> Self {
        let positions: Vec<Vec3> = surface
            .positions
            .iter()
            .map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32))
            .collect();
        let mut normals = vec![Vec3::ZERO; positions.len()];
        for t in &surface.triangles {
            let [a, b, c] = t.map(|k| positions[k as usize]);
            let n = (b - a).cross(c - a);
            for k in t {
                normals[*k as usize] += n;
            }
        }
        Self {
            vertices: positions
                .iter()
                .zip(&normals)
                .map(|(p, n)| ColouredVertex {
                    position: p.to_array(),
                    normal: n.normalize_or(Vec3::Z).to_array(),
                    color: colour,
                })
                .collect(),
            indices: surface.triangles.iter().flatten().copied().collect(),
        }
    }

    /// The reachable cells of `slice` as flat squares in their plane, each in the colour
    /// of its condition number (threshold `condition_max`; past it the marked colour),
    /// with opacity `alpha`.
    pub fn slice(slice: &Slice, condition_max: f64, alpha: f32) -> Self {
        Self::slice_coloured(slice, alpha, |k| {
            colormap::condition_colour(k, condition_max)
        })
    }

    /// The reachable cells of a stiffness slice (see `stewart_kinematics::analysis::workspace::stiffness_slice`), each
    /// in viridis by its stiffness over the range `[low, high]` (soft dark, stiff
    /// yellow), with opacity `alpha`.
    pub fn stiffness_slice(slice: &Slice, [low, high]: [f64; 2], alpha: f32) -> Self {
        Self::slice_coloured(slice, alpha, |k| {
            let span = high - low;
            let s = if span > 0.0 { (k - low) / span } else { 1.0 };
            colormap::viridis(s.clamp(0.0, 1.0))
        })
    }

    /// The reachable cells of `slice` as flat squares in their plane, each in
    /// `colour(value)` with opacity `alpha`.
    fn slice_coloured(slice: &Slice, alpha: f32, colour: impl Fn(f64) -> [u8; 3]) -> Self {
        let mut mesh = Self::default();
        let [across, up] = slice.range;
        let size = [0, 1].map(|a| (slice.range[a][1] - slice.range[a][0]) / slice.cells[a] as f64);
        let point = |a: f64, b: f64| match slice.plane {
            Plane::Horizontal => [a as f32, b as f32, slice.at as f32],
            Plane::Vertical => [a as f32, slice.at as f32, b as f32],
        };
        let normal = match slice.plane {
            Plane::Horizontal => [0.0, 0.0, 1.0],
            Plane::Vertical => [0.0, 1.0, 0.0],
        };
        for j in 0..slice.cells[1] {
            for i in 0..slice.cells[0] {
                let Some(k) = slice.get(i, j) else {
                    continue;
                };
                let rgb = colour(k);
                let lin = rgb.map(|c| srgb_to_linear(f32::from(c) / 255.0));
                let color = [lin[0], lin[1], lin[2], alpha];
                let a0 = across[0] + i as f64 * size[0];
                let b0 = up[0] + j as f64 * size[1];
                let first = mesh.vertices.len() as u32;
                for (a, b) in [
                    (a0, b0),
                    (a0 + size[0], b0),
                    (a0 + size[0], b0 + size[1]),
                    (a0, b0 + size[1]),
                ] {
                    mesh.vertices.push(ColouredVertex {
                        position: point(a, b),
                        normal,
                        color,
                    });
                }
                mesh.indices.extend([0, 1, 2, 0, 2, 3].map(|k| first + k));
            }
        }
        mesh
    }

    /// Whether there is nothing to draw.
    pub fn is_empty(&self) -> bool {
        self.indices.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slice(values: Vec<Option<f64>>) -> Slice {
        Slice {
            plane: Plane::Horizontal,
            at: 0.8,
            range: [[-1.0, 1.0], [0.0, 1.0]],
            cells: [2, 2],
            values,
        }
    }

    #[test]
    fn a_slice_draws_one_square_per_reachable_cell_in_its_plane() {
        let m = AnalysisMesh::slice(
            &slice(vec![Some(1.0), None, Some(1e9), Some(10.0)]),
            100.0,
            0.5,
        );
        assert_eq!(m.vertices.len(), 12);
        assert_eq!(m.indices.len(), 18);
        assert!(
            m.vertices
                .iter()
                .all(|v| v.position[2] == 0.8 && v.color[3] == 0.5)
        );
        // Cell (0, 0) spans x −1..0, y 0..0.5, in viridis' first colour.
        let xs: Vec<f32> = m.vertices[..4].iter().map(|v| v.position[0]).collect();
        assert_eq!(xs, [-1.0, 0.0, 0.0, -1.0]);
        let first = [68u8, 1, 84].map(|c| srgb_to_linear(f32::from(c) / 255.0));
        assert_eq!(m.vertices[0].color[..3], first);
        // The cell past the threshold is magenta: more red than green.
        let past = m.vertices[4].color;
        assert!(past[0] > 0.5 && past[1] < 0.05, "{past:?}");
    }

    #[test]
    fn a_stiffness_slice_runs_from_viridis_dark_to_yellow() {
        let m = AnalysisMesh::stiffness_slice(
            &slice(vec![Some(2.0), Some(6.0), None, Some(4.0)]),
            [2.0, 6.0],
            0.85,
        );
        assert_eq!(m.vertices.len(), 12);
        let colour = |k: usize| m.vertices[4 * k].color;
        let lin = |c: [u8; 3]| c.map(|c| srgb_to_linear(f32::from(c) / 255.0));
        assert_eq!(colour(0)[..3], lin(colormap::viridis(0.0)));
        assert_eq!(colour(1)[..3], lin(colormap::viridis(1.0)));
        assert_eq!(colour(2)[..3], lin(colormap::viridis(0.5)));
        // The stiffest cell is the yellow end: more red and green than blue.
        assert!(colour(1)[0] > colour(1)[2] && colour(1)[1] > colour(1)[2]);
        assert_eq!(colour(0)[3], 0.85);
    }

    #[test]
    fn surface_normals_point_out_of_a_closed_box() {
        // Four columns as a 2 × 2 block: the surface is a box; its upper vertices' normals
        // point up, the lower ones' down.
        let ws = stewart_kinematics::analysis::workspace::ConstantOrientationWorkspace {
            orientation: [stewart_kinematics::Angle::ZERO; 3],
            resolution: 2,
            cell: 1.0,
            volume: 4.0,
            volume_error: 0.0,
            extent: Some([[0.0, 1.0], [0.0, 1.0], [1.0, 2.0]]),
            spans: vec![
                [0.0, 0.0, 1.0, 2.0],
                [0.0, 1.0, 1.0, 2.0],
                [1.0, 0.0, 1.0, 2.0],
                [1.0, 1.0, 1.0, 2.0],
            ],
        };
        let s = WorkspaceSurface::from_workspace(&ws);
        let m = AnalysisMesh::surface(&s, [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(m.vertices.len(), s.positions.len());
        assert_eq!(m.indices.len(), 3 * s.triangles.len());
        for v in &m.vertices {
            let up = v.position[2] == 2.0;
            assert_eq!(v.normal[2] > 0.0, up, "{v:?}");
            assert_eq!(v.color, [0.1, 0.2, 0.3, 0.4]);
        }
    }
}
