//! A lighter stand-in for a heavy part, for views drawn by a software rasteriser: vertex
//! clustering (Rossignac and Borrel, 1993) — the part's box cut into a grid, every vertex
//! moved to the mean of its cell's, triangles that collapse dropped — coarsened until the
//! part fits the budget. Exports and screenshots draw the part itself.

use std::collections::HashMap;
use std::sync::Arc;

use glam::Vec3;

use super::normals::FlatMesh;
use super::{PartMesh, Piece};

/// Triangles a part may have before a view on a software rasteriser draws a stand-in.
pub const PREVIEW_TRIANGLES: usize = 60_000;

/// Triangles of the lighter stand-in such a view draws while it moves (playback, a drag):
/// every triangle is CPU time there, and the picture at rest is the preview again.
pub const MOVING_TRIANGLES: usize = 20_000;

/// `part` with at most `budget` triangles (`None`: it has no more than that already).
pub fn simplified(part: &PartMesh, budget: usize) -> Option<PartMesh> {
    if part.triangles <= budget {
        return None;
    }
    let extent = (part.bounds[1] - part.bounds[0])
        .max_element()
        .max(f32::MIN_POSITIVE);
    let at = |cells: u32| {
        // A small piece can collapse into one cell: it is left out, never drawn empty.
        let pieces: Vec<Piece> = part
            .pieces
            .iter()
            .map(|p| Piece {
                mesh: Arc::new(clustered(&p.mesh, part.bounds[0], extent / cells as f32)),
                colour: p.colour,
            })
            .filter(|p| !p.mesh.indices.is_empty())
            .collect();
        let triangles: usize = pieces.iter().map(|p| p.mesh.indices.len() / 3).sum();
        PartMesh {
            pieces,
            triangles,
            bounds: part.bounds,
            sidecars: part.sidecars.clone(),
        }
    };
    // A surface's triangles grow with the square of the grid's: one trial grid, then the
    // grid that should just fit, halved while it does not.
    let trial = at(128);
    let mut cells = if trial.triangles <= budget {
        let grow = (budget as f64 / trial.triangles.max(1) as f64).sqrt() * 0.95;
        (128.0 * grow).clamp(128.0, 2048.0) as u32
    } else {
        let shrink = (budget as f64 / trial.triangles as f64).sqrt() * 0.95;
        (128.0 * shrink).clamp(2.0, 128.0) as u32
    };
    loop {
        let light = at(cells);
        if light.triangles <= budget || cells <= 2 {
            return Some(light);
        }
        cells /= 2;
    }
}

/// `mesh` with its vertices gathered into cubes of side `cell` from `origin`.
fn clustered(mesh: &crate::mesh::Mesh, origin: Vec3, cell: f32) -> crate::mesh::Mesh {
    let mut slot: HashMap<[i32; 3], u32> = HashMap::new();
    let mut sums: Vec<(Vec3, f32)> = Vec::new();
    let of: Vec<u32> = mesh
        .vertices
        .iter()
        .map(|v| {
            let p = Vec3::from(v.position);
            let key = ((p - origin) / cell).floor().as_ivec3().to_array();
            let k = *slot.entry(key).or_insert_with(|| {
                sums.push((Vec3::ZERO, 0.0));
                sums.len() as u32 - 1
            });
            let s = &mut sums[k as usize];
            *s = (s.0 + p, s.1 + 1.0);
            k
        })
        .collect();
    let centre: Vec<Vec3> = sums.iter().map(|(sum, n)| *sum / *n).collect();
    let mut kept: HashMap<[u32; 3], ()> = HashMap::new();
    let mut flat = FlatMesh::default();
    for t in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [of[t[0] as usize], of[t[1] as usize], of[t[2] as usize]];
        if a == b || b == c || a == c {
            continue;
        }
        // The same triangle from several: drawn once.
        let mut key = [a, b, c];
        key.sort_unstable();
        if kept.insert(key, ()).is_none() {
            flat.push(centre[a as usize], centre[b as usize], centre[c as usize]);
        }
    }
    flat.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;

    fn part(mesh: Mesh) -> PartMesh {
        let triangles = mesh.indices.len() / 3;
        let mut bounds = [Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)];
        for v in &mesh.vertices {
            bounds = [
                bounds[0].min(v.position.into()),
                bounds[1].max(v.position.into()),
            ];
        }
        PartMesh {
            pieces: vec![Piece {
                mesh: Arc::new(mesh),
                colour: Some([1.0, 0.0, 0.0, 1.0]),
            }],
            triangles,
            bounds,
            sidecars: Vec::new(),
        }
    }

    #[test]
    fn a_heavy_part_comes_within_the_budget_keeping_its_shape_and_colour() {
        // The unit sphere the renderer draws joints with: about a thousand triangles.
        let sphere = part(Mesh::sphere());
        assert!(
            simplified(&sphere, sphere.triangles).is_none(),
            "within the budget"
        );
        let light = simplified(&sphere, 300).unwrap_or_else(|| panic!("not simplified"));
        assert!(
            light.triangles <= 300 && light.triangles > 50,
            "{}",
            light.triangles
        );
        assert_eq!(light.pieces[0].colour, Some([1.0, 0.0, 0.0, 1.0]));
        // Still the unit sphere: every vertex within a cell of radius 1.
        for v in &light.pieces[0].mesh.vertices {
            let r = Vec3::from(v.position).length();
            assert!((r - 1.0).abs() < 0.25, "{r}");
        }
    }
}
