//! A glTF 2.0 document being filled (`gltf-json`'s types) with its one binary buffer:
//! accessors over 4-byte-aligned views, meshes whose geometry is shared between nodes,
//! materials made once per colour.

use std::collections::HashMap;
use std::sync::Arc;

use glam::{Mat3, Mat4, Vec3};
use gltf_json as json;
use json::validation::Checked::Valid;
use json::validation::USize64;
use stewart_render::mesh::Mesh;

/// A primitive's geometry once written: its position, normal and index accessors.
#[derive(Clone, Copy)]
pub(super) struct Geometry {
    positions: json::Index<json::Accessor>,
    normals: json::Index<json::Accessor>,
    indices: json::Index<json::Accessor>,
}

/// The document and its binary data.
#[derive(Default)]
pub(super) struct Document {
    /// The glTF document (nodes, meshes, accessors, …).
    pub(super) root: json::Root,
    /// The one buffer's bytes.
    pub(super) bin: Vec<u8>,
    materials: HashMap<[u32; 4], json::Index<json::Material>>,
    /// Geometry written, by mesh and transform (a CAD part drawn six times is written
    /// once); each mesh held, so no other can take its address while the key stands.
    geometries: HashMap<(usize, [u32; 16]), (Geometry, Arc<Mesh>)>,
}

impl Document {
    /// A view of `bytes` in the buffer (aligned to 4 bytes).
    fn view(
        &mut self,
        bytes: &[u8],
        target: Option<json::buffer::Target>,
    ) -> json::Index<json::buffer::View> {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.root.push(json::buffer::View {
            buffer: json::Index::new(0),
            byte_length: USize64::from(bytes.len()),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            name: None,
            target: target.map(Valid),
            extensions: None,
            extras: Default::default(),
        })
    }

    /// An accessor over `values` (`width` floats an element: 1, 3 or 4), with the
    /// elementwise minimum and maximum when `bounds` (positions and animation times need
    /// them).
    pub(super) fn floats(
        &mut self,
        values: &[f32],
        width: usize,
        bounds: bool,
        target: Option<json::buffer::Target>,
    ) -> json::Index<json::Accessor> {
        let count = values.len() / width;
        let view = self.view(bytemuck::cast_slice(values), target);
        let (min, max) = if bounds {
            let mut lo = vec![f32::INFINITY; width];
            let mut hi = vec![f32::NEG_INFINITY; width];
            for chunk in values.chunks_exact(width) {
                for (k, v) in chunk.iter().enumerate() {
                    lo[k] = lo[k].min(*v);
                    hi[k] = hi[k].max(*v);
                }
            }
            (Some(json::Value::from(lo)), Some(json::Value::from(hi)))
        } else {
            (None, None)
        };
        self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(
                json::accessor::ComponentType::F32,
            )),
            extensions: None,
            extras: Default::default(),
            type_: Valid(match width {
                1 => json::accessor::Type::Scalar,
                3 => json::accessor::Type::Vec3,
                _ => json::accessor::Type::Vec4,
            }),
            min,
            max,
            name: None,
            normalized: false,
            sparse: None,
        })
    }

    /// `mesh` placed by `transform` (any affine map: normals go through its inverse
    /// transpose), written once (the same mesh and transform asked again give the same
    /// accessors).
    pub(super) fn geometry(&mut self, mesh: &Arc<Mesh>, transform: Mat4) -> Geometry {
        let key = (
            Arc::as_ptr(mesh) as usize,
            transform.to_cols_array().map(f32::to_bits),
        );
        if let Some((g, _)) = self.geometries.get(&key) {
            return *g;
        }
        let g = self.write_geometry(mesh, transform);
        self.geometries.insert(key, (g, Arc::clone(mesh)));
        g
    }

    /// `mesh` placed by `transform`, written now (for a mesh made for one use).
    pub(super) fn write_geometry(&mut self, mesh: &Mesh, transform: Mat4) -> Geometry {
        let turn = Mat3::from_mat4(transform).inverse().transpose();
        let mut positions = Vec::with_capacity(3 * mesh.vertices.len());
        let mut normals = Vec::with_capacity(3 * mesh.vertices.len());
        for v in &mesh.vertices {
            positions.extend(
                transform
                    .transform_point3(Vec3::from(v.position))
                    .to_array(),
            );
            normals.extend(
                (turn * Vec3::from(v.normal))
                    .normalize_or(Vec3::Z)
                    .to_array(),
            );
        }
        let target = Some(json::buffer::Target::ArrayBuffer);
        let positions = self.floats(&positions, 3, true, target);
        let normals = self.floats(&normals, 3, false, target);
        let view = self.view(
            bytemuck::cast_slice(&mesh.indices),
            Some(json::buffer::Target::ElementArrayBuffer),
        );
        let indices = self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64::from(mesh.indices.len()),
            component_type: Valid(json::accessor::GenericComponentType(
                json::accessor::ComponentType::U32,
            )),
            extensions: None,
            extras: Default::default(),
            type_: Valid(json::accessor::Type::Scalar),
            min: None,
            max: None,
            name: None,
            normalized: false,
            sparse: None,
        });
        Geometry {
            positions,
            normals,
            indices,
        }
    }

    /// The material of linear colour `rgba` (opaque, metallic-roughness), made once.
    pub(super) fn material(&mut self, rgba: [f32; 4]) -> json::Index<json::Material> {
        let key = rgba.map(f32::to_bits);
        if let Some(&m) = self.materials.get(&key) {
            return m;
        }
        let m = self.root.push(json::Material {
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor([
                    rgba[0], rgba[1], rgba[2], 1.0,
                ]),
                metallic_factor: json::material::StrengthFactor(0.1),
                roughness_factor: json::material::StrengthFactor(0.55),
                ..Default::default()
            },
            double_sided: true,
            ..Default::default()
        });
        self.materials.insert(key, m);
        m
    }

    /// A mesh of `pieces` (geometry and material), named `name`.
    pub(super) fn mesh(
        &mut self,
        name: &str,
        pieces: &[(Geometry, json::Index<json::Material>)],
    ) -> json::Index<json::Mesh> {
        let primitives = pieces
            .iter()
            .map(|(g, material)| json::mesh::Primitive {
                attributes: [
                    (Valid(json::mesh::Semantic::Positions), g.positions),
                    (Valid(json::mesh::Semantic::Normals), g.normals),
                ]
                .into_iter()
                .collect(),
                extensions: None,
                extras: Default::default(),
                indices: Some(g.indices),
                material: Some(*material),
                mode: Valid(json::mesh::Mode::Triangles),
                targets: None,
            })
            .collect();
        self.root.push(json::Mesh {
            extensions: None,
            extras: Default::default(),
            name: Some(name.to_owned()),
            primitives,
            weights: None,
        })
    }

    /// The file: a GLB (JSON and binary chunks), or the JSON naming `bin_uri` for the
    /// buffer written beside it.
    pub(super) fn finish(mut self, bin_uri: Option<&str>) -> (Vec<u8>, Vec<u8>) {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.root.push(json::Buffer {
            byte_length: USize64::from(self.bin.len()),
            name: None,
            uri: bin_uri.map(str::to_owned),
            extensions: None,
            extras: Default::default(),
        });
        // Serialising the document's plain structs cannot fail.
        let mut text = json::serialize::to_vec(&self.root)
            .unwrap_or_else(|e| unreachable!("glTF serialisation: {e}"));
        if bin_uri.is_some() {
            return (text, self.bin);
        }
        while !text.len().is_multiple_of(4) {
            text.push(b' ');
        }
        let total = 12 + 8 + text.len() + 8 + self.bin.len();
        let mut glb = Vec::with_capacity(total);
        glb.extend(b"glTF");
        glb.extend(2u32.to_le_bytes());
        glb.extend((total as u32).to_le_bytes());
        glb.extend((text.len() as u32).to_le_bytes());
        glb.extend(b"JSON");
        glb.extend(&text);
        glb.extend((self.bin.len() as u32).to_le_bytes());
        glb.extend(b"BIN\0");
        glb.extend(&self.bin);
        (glb, Vec::new())
    }
}
