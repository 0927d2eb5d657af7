//! Wavefront OBJ, read by `tobj` (faces triangulated, one index per corner), with the
//! diffuse colours (`Kd`) of its MTL file where it names one. `tobj` reports faults
//! without a line; [`locate`] finds the line by reading the text the way OBJ is written.

use std::path::Path;
use std::sync::Arc;

use glam::Vec3;
use stewart_kinematics::io::file::{FileKind, read_file};

use super::normals::FlatMesh;
use super::{Location, PartFileError, Piece, finite};
use crate::gpu_types::MeshVertex;
use crate::mesh::Mesh;

/// The pieces of an OBJ file: one per object and material, coloured by its MTL's `Kd`.
/// Read an OBJ file's triangles and colours; the material files it names, read or not,
/// are added to `sidecars`.
pub(super) fn read(
    path: &Path,
    bytes: &[u8],
    sidecars: &mut Vec<std::path::PathBuf>,
) -> Result<Vec<Piece>, PartFileError> {
    let folder = path.parent().unwrap_or(Path::new("")).to_owned();
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let text = String::from_utf8_lossy(bytes);
    let fault = |reason: String| {
        let (at, reason) = match locate(&text) {
            Some((line, why)) => (Some(Location::Line(line)), why),
            None => (None, reason),
        };
        PartFileError::Malformed {
            path: path.to_owned(),
            at,
            reason,
        }
    };
    // The loader's callback is `Fn`: the files it names are gathered through a cell.
    let named = std::cell::RefCell::new(Vec::new());
    let loaded = tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |mtl| {
        // Through the gate: a regular file within the cap (`mtllib /dev/zero` would
        // otherwise be read until memory runs out).
        named.borrow_mut().push(folder.join(mtl));
        let file = read_file(&folder.join(mtl), FileKind::MeshSidecar)
            .map_err(|_| tobj::LoadError::OpenFileFailed)?;
        tobj::load_mtl_buf(&mut std::io::Cursor::new(file))
    })
    .map_err(|e| fault(format!("not a readable OBJ file ({e})")))?;
    sidecars.extend(named.into_inner());
    let (models, materials) = loaded;
    // No MTL file, or one that cannot be read: the parts take the studio's colours.
    let materials = materials.unwrap_or_default();
    let mut pieces = Vec::with_capacity(models.len());
    for model in models {
        let m = &model.mesh;
        let position = |i: u32| -> Result<Vec3, PartFileError> {
            let k = 3 * i as usize;
            let p: [f32; 3] = m
                .positions
                .get(k..k + 3)
                .and_then(|s| s.try_into().ok())
                .ok_or_else(|| {
                    fault(format!(
                        "a face refers to vertex {} of {}",
                        i + 1,
                        m.positions.len() / 3
                    ))
                })?;
            finite(path, p, || {
                locate(&text).map(|(line, _)| Location::Line(line))
            })?;
            Ok(Vec3::from_array(p))
        };
        // The file's normals when every one is a direction, else flat ones.
        let usable = m.normals.len() == m.positions.len()
            && m.normals.chunks_exact(3).all(|n| {
                let n = Vec3::new(n[0], n[1], n[2]);
                n.is_finite() && n.length() > 1e-6
            });
        let mesh = if usable {
            // The file's normals, one per corner.
            let mut mesh = Mesh {
                vertices: Vec::with_capacity(m.positions.len() / 3),
                indices: m.indices.clone(),
            };
            for i in 0..(m.positions.len() / 3) as u32 {
                let k = 3 * i as usize;
                mesh.vertices.push(MeshVertex {
                    position: position(i)?.to_array(),
                    normal: Vec3::new(m.normals[k], m.normals[k + 1], m.normals[k + 2])
                        .normalize()
                        .to_array(),
                });
            }
            if let Some(&bad) = mesh
                .indices
                .iter()
                .find(|&&i| i as usize >= mesh.vertices.len())
            {
                return Err(fault(format!(
                    "a face refers to vertex {}, beyond the {} given",
                    bad + 1,
                    mesh.vertices.len()
                )));
            }
            mesh
        } else {
            let mut flat = FlatMesh::with_capacity(m.indices.len() / 3);
            for t in m.indices.chunks_exact(3) {
                flat.push(position(t[0])?, position(t[1])?, position(t[2])?);
            }
            flat.finish()
        };
        let colour = m
            .material_id
            .and_then(|id| materials.get(id))
            .and_then(|material| material.diffuse)
            .map(|[r, g, b]| [r, g, b, 1.0].map(|c: f32| c.clamp(0.0, 1.0)));
        pieces.push(Piece {
            mesh: Arc::new(mesh),
            colour,
        });
    }
    Ok(pieces)
}

/// The first line of an OBJ text that breaks the format, and why: a vertex (`v`) without
/// three numbers or with one not finite, a face (`f`) with fewer than three corners, a
/// corner that is not a number, or one referring to a vertex not given before it.
pub(super) fn locate(text: &str) -> Option<(usize, String)> {
    let mut counts = [0usize; 3]; // v, vt, vn
    for (n, line) in text.lines().enumerate() {
        let n = n + 1;
        let mut fields = line.split_whitespace();
        match fields.next() {
            Some("v") => {
                let numbers: Vec<Option<f32>> = fields.map(|f| f.parse().ok()).collect();
                if numbers.len() < 3 || numbers.iter().any(Option::is_none) {
                    return Some((
                        n,
                        format!("a vertex needs three numbers: `{}`", line.trim()),
                    ));
                }
                if numbers.iter().flatten().take(3).any(|v| !v.is_finite()) {
                    return Some((
                        n,
                        format!(
                            "a vertex coordinate is not a finite number: `{}`",
                            line.trim()
                        ),
                    ));
                }
                counts[0] += 1;
            }
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f") => {
                let corners: Vec<&str> = fields.collect();
                if corners.len() < 3 {
                    return Some((
                        n,
                        format!("a face needs at least three corners: `{}`", line.trim()),
                    ));
                }
                for corner in corners {
                    for (slot, index) in corner.split('/').enumerate().take(3) {
                        if index.is_empty() && slot > 0 {
                            continue;
                        }
                        let Ok(i) = index.parse::<i64>() else {
                            return Some((
                                n,
                                format!(
                                    "`{corner}` is not a face corner (v, v/vt, v//vn or v/vt/vn)"
                                ),
                            ));
                        };
                        let count = counts[slot] as i64;
                        let resolved = if i < 0 { count + i + 1 } else { i };
                        if !(1..=count).contains(&resolved) || i == 0 {
                            let what = ["vertex", "texture coordinate", "normal"][slot];
                            return Some((
                                n,
                                format!(
                                    "`{corner}` refers to {what} {i}, but {count} are given before this line"
                                ),
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    None
}
