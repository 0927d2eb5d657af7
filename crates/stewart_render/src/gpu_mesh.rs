//! A static mesh uploaded to the GPU: vertex and index buffers. The renderer keeps its
//! unit shapes in them; a prepared view keeps its plates and surfaces.

use wgpu::util::DeviceExt;

use crate::mesh::Mesh;

/// A static mesh on the GPU.
pub(crate) struct GpuMesh {
    /// Vertex buffer.
    pub(crate) vertices: wgpu::Buffer,
    /// Triangle indices.
    pub(crate) indices: wgpu::Buffer,
    /// How many indices.
    pub(crate) count: u32,
}

impl GpuMesh {
    /// Upload `mesh`.
    pub(crate) fn new(device: &wgpu::Device, mesh: &Mesh, label: &str) -> Self {
        Self::from_parts(
            device,
            bytemuck::cast_slice(&mesh.vertices),
            &mesh.indices,
            label,
        )
    }

    /// Upload vertex bytes and triangle indices.
    pub(crate) fn from_parts(
        device: &wgpu::Device,
        vertices: &[u8],
        indices: &[u32],
        label: &str,
    ) -> Self {
        Self {
            vertices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: vertices,
                usage: wgpu::BufferUsages::VERTEX,
            }),
            indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(indices),
                usage: wgpu::BufferUsages::INDEX,
            }),
            count: indices.len() as u32,
        }
    }
}
