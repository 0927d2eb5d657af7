//! glTF 2.0 (`.gltf` with its buffers beside it or inline, `.glb`), read by the `gltf`
//! crate: the triangle meshes under the default scene's nodes (each with its node's
//! transform from the file's root), coloured by their material's base colour.

use std::path::Path;
use std::sync::Arc;

use base64::Engine as _;
use glam::{Mat3, Mat4, Vec3};

use super::normals::FlatMesh;
use super::{Location, PartFileError, Piece, finite};
use crate::gpu_types::MeshVertex;
use crate::mesh::Mesh;

use stewart_kinematics::io::file::{FileKind, read_file};

fn malformed(path: &Path, at: Option<String>, reason: String) -> PartFileError {
    PartFileError::Malformed {
        path: path.to_owned(),
        at: at.map(Location::Item),
        reason,
    }
}

/// The pieces of a glTF file: one per primitive, in the default scene's node order.
/// Read a glTF or GLB file's triangles and colours; the buffer files it names are added
/// to `sidecars`.
pub(super) fn read(
    path: &Path,
    bytes: &[u8],
    sidecars: &mut Vec<std::path::PathBuf>,
) -> Result<Vec<Piece>, PartFileError> {
    let gltf = gltf::Gltf::from_slice(bytes)
        .map_err(|e| malformed(path, None, format!("not a valid glTF 2.0 file: {e}")))?;
    let buffers = buffers(path, &gltf, sidecars)?;
    let document = &gltf.document;
    let roots: Vec<gltf::Node> = match document
        .default_scene()
        .or_else(|| document.scenes().next())
    {
        Some(scene) => scene.nodes().collect(),
        None => document.nodes().collect(),
    };
    let mut pieces = Vec::new();
    let mut stack: Vec<(gltf::Node, Mat4)> =
        roots.into_iter().map(|n| (n, Mat4::IDENTITY)).collect();
    let mut visited = vec![false; document.nodes().len()];
    while let Some((node, parent)) = stack.pop() {
        // A tree: a node reached twice (two parents, or its own ancestor) is refused.
        if std::mem::replace(&mut visited[node.index()], true) {
            return Err(malformed(
                path,
                Some(format!("nodes[{}]", node.index())),
                "is reached twice in the scene: its nodes must form a tree".into(),
            ));
        }
        let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
        if let Some(mesh) = node.mesh() {
            for primitive in mesh.primitives() {
                if let Some(piece) = primitive_piece(path, &buffers, &mesh, &primitive, world)? {
                    pieces.push(piece);
                }
            }
        }
        // Children in file order: pushed last first.
        let children: Vec<gltf::Node> = node.children().collect();
        stack.extend(children.into_iter().rev().map(|c| (c, world)));
    }
    Ok(pieces)
}

/// Every buffer's bytes: the GLB's own chunk, a data URI, or a file beside this one.
fn buffers(
    path: &Path,
    gltf: &gltf::Gltf,
    sidecars: &mut Vec<std::path::PathBuf>,
) -> Result<Vec<Vec<u8>>, PartFileError> {
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut out = Vec::new();
    for buffer in gltf.document.buffers() {
        let at = || Some(format!("buffers[{}]", buffer.index()));
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => gltf.blob.clone().ok_or_else(|| {
                malformed(
                    path,
                    at(),
                    "refers to a GLB binary chunk the file lacks".into(),
                )
            })?,
            gltf::buffer::Source::Uri(uri) if uri.starts_with("data:") => {
                let (_, encoded) = uri
                    .split_once(";base64,")
                    .ok_or_else(|| malformed(path, at(), "its data URI is not base64".into()))?;
                base64::engine::general_purpose::STANDARD
                    .decode(encoded)
                    .map_err(|e| {
                        malformed(path, at(), format!("its data URI does not decode: {e}"))
                    })?
            }
            gltf::buffer::Source::Uri(uri) => {
                let file = folder.join(percent_decode(uri));
                sidecars.push(file.clone());
                read_file(&file, FileKind::MeshSidecar).map_err(|e| {
                    malformed(path, at(), format!("its data file cannot be read: {e}"))
                })?
            }
        };
        if data.len() < buffer.length() {
            return Err(malformed(
                path,
                at(),
                format!(
                    "holds {} bytes, the file declares {} (cut short?)",
                    data.len(),
                    buffer.length()
                ),
            ));
        }
        out.push(data);
    }
    Ok(out)
}

/// `%20` and friends in a relative URI, as glTF allows.
fn percent_decode(uri: &str) -> String {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        let hex = bytes
            .get(k + 1..k + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[k], hex) {
            (b'%', Some(b)) => {
                out.push(b);
                k += 3;
            }
            (c, _) => {
                out.push(c);
                k += 1;
            }
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// One primitive as a piece in the file's root frame (`None`: points or lines, which
/// draw no surface).
fn primitive_piece(
    path: &Path,
    buffers: &[Vec<u8>],
    mesh: &gltf::Mesh,
    primitive: &gltf::Primitive,
    world: Mat4,
) -> Result<Option<Piece>, PartFileError> {
    use gltf::mesh::Mode;
    let at = || {
        Some(format!(
            "meshes[{}].primitives[{}]",
            mesh.index(),
            primitive.index()
        ))
    };
    if !matches!(
        primitive.mode(),
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Ok(None);
    }
    use gltf::Semantic;
    use gltf::accessor::{DataType, Dimensions};
    let positions = primitive
        .get(&Semantic::Positions)
        .ok_or_else(|| malformed(path, at(), "has no vertex positions".into()))?;
    accessor_fits(
        path,
        buffers,
        &positions,
        &[DataType::F32],
        Dimensions::Vec3,
    )?;
    if let Some(normals) = primitive.get(&Semantic::Normals) {
        accessor_fits(path, buffers, &normals, &[DataType::F32], Dimensions::Vec3)?;
    }
    if let Some(indices) = primitive.indices() {
        accessor_fits(
            path,
            buffers,
            &indices,
            &[DataType::U8, DataType::U16, DataType::U32],
            Dimensions::Scalar,
        )?;
    }
    let reader = primitive.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
    let positions: Vec<Vec3> = reader
        .read_positions()
        .ok_or_else(|| {
            malformed(
                path,
                at(),
                "has no vertex positions (or their data lies outside its buffer)".into(),
            )
        })?
        .map(|p| -> Result<Vec3, PartFileError> {
            let placed = world.transform_point3(Vec3::from_array(p)).to_array();
            finite(path, placed, || at().map(Location::Item))?;
            Ok(Vec3::from_array(placed))
        })
        .collect::<Result<_, _>>()?;
    let list: Vec<u32> = match reader.read_indices() {
        Some(indices) => indices.into_u32().collect(),
        None => (0..positions.len() as u32).collect(),
    };
    if let Some(&bad) = list.iter().find(|&&i| i as usize >= positions.len()) {
        return Err(malformed(
            path,
            at(),
            format!(
                "an index ({bad}) lies beyond its {} vertices",
                positions.len()
            ),
        ));
    }
    let triangles = triangles(primitive.mode(), &list);
    let normals: Option<Vec<Vec3>> = reader.read_normals().map(|n| {
        let to_world = Mat3::from_mat4(world).inverse().transpose();
        n.map(|n| (to_world * Vec3::from_array(n)).normalize_or_zero())
            .collect()
    });
    // The file's normals when every one is a direction, else flat ones.
    let usable = |n: &Vec<Vec3>| {
        n.len() == positions.len() && n.iter().all(|v| (v.length() - 1.0).abs() < 1e-3)
    };
    let mesh = match normals.filter(usable) {
        Some(normals) => Mesh {
            vertices: positions
                .iter()
                .zip(&normals)
                .map(|(p, n)| MeshVertex {
                    position: p.to_array(),
                    normal: n.to_array(),
                })
                .collect(),
            indices: triangles,
        },
        None => {
            let mut flat = FlatMesh::with_capacity(triangles.len() / 3);
            for t in triangles.chunks_exact(3) {
                flat.push(
                    positions[t[0] as usize],
                    positions[t[1] as usize],
                    positions[t[2] as usize],
                );
            }
            flat.finish()
        }
    };
    // The base colour factor is linear; the studio's colours are sRGB.
    let [r, g, b, a] = primitive
        .material()
        .pbr_metallic_roughness()
        .base_color_factor();
    let colour = primitive
        .material()
        .index()
        .map(|_| [srgb(r), srgb(g), srgb(b), a.clamp(0.0, 1.0)]);
    Ok(Some(Piece {
        mesh: Arc::new(mesh),
        colour,
    }))
}

/// Refuse an accessor of another type than the attribute needs, of no elements, reaching
/// past its buffer view, or whose view has a stride that cannot hold its elements or
/// reaches past its buffer (the reader would otherwise fail, or panic, inside).
fn accessor_fits(
    path: &Path,
    buffers: &[Vec<u8>],
    accessor: &gltf::Accessor,
    types: &[gltf::accessor::DataType],
    dimensions: gltf::accessor::Dimensions,
) -> Result<(), PartFileError> {
    let at = || Some(format!("accessors[{}]", accessor.index()));
    if !types.contains(&accessor.data_type()) || accessor.dimensions() != dimensions {
        return Err(malformed(
            path,
            at(),
            format!(
                "is {:?} {:?}, where {:?} of {:?} is needed",
                accessor.dimensions(),
                accessor.data_type(),
                dimensions,
                types
            ),
        ));
    }
    if accessor.count() == 0 {
        return Err(malformed(path, at(), "holds no elements".into()));
    }
    if accessor.sparse().is_some() {
        return Err(malformed(
            path,
            at(),
            "is sparse, which parts do not take".into(),
        ));
    }
    let Some(view) = accessor.view() else {
        return Err(malformed(path, at(), "has no buffer view".into()));
    };
    let size = accessor.size();
    // A stride must hold an element, keep its components aligned and stay within the
    // 4 … 252 bytes glTF allows (the reader would otherwise slice out of bounds).
    let component = accessor.data_type().size();
    if let Some(stride) = view.stride()
        && (stride < size || stride % component != 0 || !(4..=252).contains(&stride))
    {
        return Err(malformed(
            path,
            Some(format!("bufferViews[{}]", view.index())),
            format!(
                "has a byteStride of {stride}, where an element of {size} bytes needs a multiple of {component} from {} to 252",
                size.max(4)
            ),
        ));
    }
    let stride = view.stride().unwrap_or(size);
    let in_buffer = buffers.get(view.buffer().index()).is_some_and(|b| {
        view.offset()
            .checked_add(view.length())
            .is_some_and(|end| end <= b.len())
    });
    if !in_buffer {
        return Err(malformed(
            path,
            Some(format!("bufferViews[{}]", view.index())),
            format!(
                "reaches past its buffer ({} bytes from byte {})",
                view.length(),
                view.offset()
            ),
        ));
    }
    let end = (accessor.count() - 1)
        .checked_mul(stride)
        .and_then(|n| n.checked_add(size))
        .and_then(|n| n.checked_add(accessor.offset()));
    match end {
        Some(end) if end <= view.length() => Ok(()),
        _ => Err(malformed(
            path,
            at(),
            format!(
                "reaches past its buffer view ({} elements of {stride} bytes from byte {}, in {} bytes)",
                accessor.count(),
                accessor.offset(),
                view.length()
            ),
        )),
    }
}

/// A linear channel value encoded as sRGB.
fn srgb(c: f32) -> f32 {
    let c = c.clamp(0.0, 1.0);
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// Strips and fans as plain triangle lists.
fn triangles(mode: gltf::mesh::Mode, list: &[u32]) -> Vec<u32> {
    use gltf::mesh::Mode;
    match mode {
        Mode::TriangleStrip => (2..list.len())
            .flat_map(|k| {
                if k % 2 == 0 {
                    [list[k - 2], list[k - 1], list[k]]
                } else {
                    [list[k - 1], list[k - 2], list[k]]
                }
            })
            .collect(),
        Mode::TriangleFan => (2..list.len())
            .flat_map(|k| [list[0], list[k - 1], list[k]])
            .collect(),
        _ => list[..list.len() - list.len() % 3].to_vec(),
    }
}
