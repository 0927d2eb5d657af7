//! One view's frame: its uniforms and the per-frame buffers its draw list fills. The
//! [`crate::Renderer`] prepares and paints any number of these with one set of pipelines
//! (as re_renderer's view builder does).

use std::sync::Arc;

use crate::analysis::AnalysisMesh;
use crate::gpu_mesh::GpuMesh;
use crate::gpu_types::Globals;
use crate::mesh::Mesh;

/// A vertex or instance buffer rewritten every frame, grown when needed.
pub(crate) struct DynamicBuffer {
    pub(crate) buffer: wgpu::Buffer,
    capacity: u64,
    usage: wgpu::BufferUsages,
    label: &'static str,
}

impl DynamicBuffer {
    fn new(device: &wgpu::Device, label: &'static str, usage: wgpu::BufferUsages) -> Self {
        let capacity = 4096;
        let usage = usage | wgpu::BufferUsages::COPY_DST;
        Self {
            buffer: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: capacity,
                usage,
                mapped_at_creation: false,
            }),
            capacity,
            usage,
            label,
        }
    }

    pub(crate) fn write(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, bytes: &[u8]) {
        let needed = bytes.len() as u64;
        if needed > self.capacity {
            self.capacity = needed.next_power_of_two();
            self.buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(self.label),
                size: self.capacity,
                usage: self.usage,
                mapped_at_creation: false,
            });
        }
        if !bytes.is_empty() {
            queue.write_buffer(&self.buffer, 0, bytes);
        }
    }
}

/// Ranges of the shared instance buffer, per mesh.
#[derive(Default, Clone)]
pub(crate) struct Batches {
    pub(crate) cylinders: std::ops::Range<u32>,
    pub(crate) spheres: std::ops::Range<u32>,
    pub(crate) cones: std::ops::Range<u32>,
    pub(crate) boxes: std::ops::Range<u32>,
    /// (first index, index count) of each plate in the plate buffer, back to front, and its instance.
    pub(crate) plates: Vec<(u32, u32, u32)>,
    pub(crate) lines: u32,
    /// Vertices of text quads.
    pub(crate) text: u32,
    /// CAD part pieces: (index into the view's part meshes, instance).
    pub(crate) parts: Vec<(usize, u32)>,
}

/// The GPU side of one view: made by [`crate::Renderer::new_view`], filled by
/// [`crate::Renderer::prepare`], drawn by [`crate::Renderer::paint`].
pub struct PreparedView {
    pub(crate) globals: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
    pub(crate) instances: DynamicBuffer,
    pub(crate) plate_vertices: DynamicBuffer,
    pub(crate) plate_indices: DynamicBuffer,
    pub(crate) line_vertices: DynamicBuffer,
    pub(crate) text_vertices: DynamicBuffer,
    pub(crate) batches: Batches,
    pub(crate) clear: wgpu::Color,
    /// The draw list's analysis meshes on the GPU, in drawing order, each kept while the
    /// same `Arc` comes back.
    pub(crate) analysis: Vec<(Arc<AnalysisMesh>, GpuMesh)>,
    /// The CAD parts' meshes on the GPU, each kept while the same `Arc` comes back.
    pub(crate) parts: Vec<(Arc<Mesh>, GpuMesh)>,
}

impl PreparedView {
    pub(crate) fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> Self {
        let globals = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("globals"),
            size: size_of::<Globals>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals.as_entire_binding(),
            }],
        });
        Self {
            globals,
            bind_group,
            instances: DynamicBuffer::new(device, "instances", wgpu::BufferUsages::VERTEX),
            plate_vertices: DynamicBuffer::new(
                device,
                "plate vertices",
                wgpu::BufferUsages::VERTEX,
            ),
            plate_indices: DynamicBuffer::new(device, "plate indices", wgpu::BufferUsages::INDEX),
            line_vertices: DynamicBuffer::new(device, "lines", wgpu::BufferUsages::VERTEX),
            text_vertices: DynamicBuffer::new(device, "text", wgpu::BufferUsages::VERTEX),
            batches: Batches::default(),
            clear: wgpu::Color::BLACK,
            analysis: Vec::new(),
            parts: Vec::new(),
        }
    }

    /// Keep `meshes` on the GPU: upload those not there yet, drop those no longer drawn.
    pub(crate) fn keep_analysis(&mut self, device: &wgpu::Device, meshes: &[Arc<AnalysisMesh>]) {
        keep(
            &mut self.analysis,
            meshes.iter().filter(|m| !m.is_empty()),
            |mesh| {
                GpuMesh::from_parts(
                    device,
                    bytemuck::cast_slice(&mesh.vertices),
                    &mesh.indices,
                    "analysis",
                )
            },
        );
    }

    /// Keep the CAD parts' `meshes` on the GPU (each once, however often it is drawn);
    /// the index of each in the view's list, in the order given.
    pub(crate) fn keep_parts<'a>(
        &mut self,
        device: &wgpu::Device,
        meshes: impl Iterator<Item = &'a Arc<Mesh>>,
    ) -> Vec<usize> {
        let mut unique: Vec<&Arc<Mesh>> = Vec::new();
        let slots: Vec<usize> = meshes
            .map(|m| match unique.iter().position(|u| Arc::ptr_eq(u, m)) {
                Some(k) => k,
                None => {
                    unique.push(m);
                    unique.len() - 1
                }
            })
            .collect();
        keep(&mut self.parts, unique.into_iter(), |mesh| {
            GpuMesh::new(device, mesh, "CAD part")
        });
        slots
    }
}

/// Keep on the GPU the meshes of `wanted`, in its order: those already in `cache` (the
/// same `Arc`) moved, the others uploaded by `upload`; the rest dropped.
fn keep<'a, T: 'a>(
    cache: &mut Vec<(Arc<T>, GpuMesh)>,
    wanted: impl Iterator<Item = &'a Arc<T>>,
    upload: impl Fn(&T) -> GpuMesh,
) {
    let mut kept = Vec::with_capacity(cache.len());
    for mesh in wanted {
        let gpu = match cache.iter().position(|(m, _)| Arc::ptr_eq(m, mesh)) {
            Some(k) => cache.swap_remove(k).1,
            None => upload(mesh),
        };
        kept.push((Arc::clone(mesh), gpu));
    }
    *cache = kept;
}
