//! The renderer: pipelines and buffers, and one entry point that draws a scene into a
//! colour view (a window's surface, an egui viewport or an offscreen texture).

use crate::camera::OrbitCamera;
use crate::draw_list::DrawList;
use crate::gpu_mesh::GpuMesh;
use crate::gpu_types::{ColouredVertex, Globals, LineVertex, MeshInstance, MeshVertex, TextVertex};
use crate::mesh::Mesh;
use crate::shaders;
use crate::text::{ATLAS_SIZE, Fonts, GlyphAtlas};
use crate::theme::{Theme, linear};
use crate::view::{Batches, PreparedView};

/// Depth buffer format.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Pipelines and meshes for drawing a Stewart platform: built once per device and
/// colour format, shared by every view. What one view draws in one frame lives in a
/// [`PreparedView`], so a window can draw several views (the 3D view, thumbnails, a
/// workspace view) with one renderer.
pub struct Renderer {
    opaque: wgpu::RenderPipeline,
    parts: wgpu::RenderPipeline,
    translucent: wgpu::RenderPipeline,
    analysis: wgpu::RenderPipeline,
    lines: wgpu::RenderPipeline,
    globals_layout: wgpu::BindGroupLayout,
    cylinder: GpuMesh,
    sphere: GpuMesh,
    cone: GpuMesh,
    cuboid: GpuMesh,
    text: wgpu::RenderPipeline,
    atlas_texture: wgpu::Texture,
    atlas_bind_group: wgpu::BindGroup,
    atlas: std::sync::Mutex<GlyphAtlas>,
    fonts: &'static Fonts,
    background: wgpu::RenderPipeline,
    picture: wgpu::RenderPipeline,
    picture_layout: wgpu::BindGroupLayout,
    /// MSAA sample count the pipelines were built for.
    pub samples: u32,
    /// Colour format the pipelines were built for.
    pub format: wgpu::TextureFormat,
}

impl Renderer {
    /// Build the pipelines for colour `format` with `samples` (1 or 4) MSAA samples.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat, samples: u32) -> Self {
        let layout = globals_layout(device);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("stewart"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let mesh_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("mesh.wgsl"),
            source: wgpu::ShaderSource::Wgsl(shaders::MESH.into()),
        });
        let mesh_buffers = [
            Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<MeshVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<MeshInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &wgpu::vertex_attr_array![2 => Float32x4, 3 => Float32x4, 4 => Float32x4, 5 => Float32x4, 6 => Float32x4],
            }),
        ];
        let multisample = wgpu::MultisampleState {
            count: samples,
            mask: !0,
            alpha_to_coverage_enabled: false,
        };
        let blend_target = [Some(wgpu::ColorTargetState {
            format,
            blend: Some(wgpu::BlendState::ALPHA_BLENDING),
            write_mask: wgpu::ColorWrites::ALL,
        })];
        let mesh_pipeline = |label: &str, depth_write: bool, cull: Option<wgpu::Face>| {
            triangle_pipeline(
                device,
                TriangleStages {
                    label,
                    layout: &pipeline_layout,
                    module: &mesh_module,
                    buffers: &mesh_buffers,
                },
                depth_write,
                cull,
                multisample,
                &blend_target,
            )
        };
        let opaque = mesh_pipeline("opaque meshes", true, Some(wgpu::Face::Back));
        // CAD parts: opaque, but both faces drawn (files do not always wind their
        // triangles the same way; the shading is two-sided).
        let parts = mesh_pipeline("CAD parts", true, None);
        // Translucent plates: depth-tested against the opaque scene, not written, both
        // faces drawn, back to front.
        let translucent = mesh_pipeline("translucent plates", false, None);
        let analysis_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("analysis.wgsl"),
            source: wgpu::ShaderSource::Wgsl(shaders::ANALYSIS.into()),
        });
        // Analysis meshes: translucent, world coordinates, a colour per vertex.
        let analysis = triangle_pipeline(
            device,
            TriangleStages {
                label: "analysis meshes",
                layout: &pipeline_layout,
                module: &analysis_module,
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: size_of::<ColouredVertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4],
                })],
            },
            false,
            None,
            multisample,
            &blend_target,
        );
        let lines = line_pipeline(device, &pipeline_layout, multisample, &blend_target);
        let (text, atlas_texture, atlas_bind_group) =
            text_pipeline(device, &layout, multisample, format);
        let background =
            crate::picture::background_pipeline(device, &pipeline_layout, multisample, format);
        let picture_layout = crate::picture::bind_group_layout(device);
        let picture =
            crate::picture::pipeline(device, &layout, &picture_layout, multisample, format);
        Self {
            background,
            picture,
            picture_layout,
            opaque,
            parts,
            translucent,
            analysis,
            lines,
            text,
            atlas_texture,
            atlas_bind_group,
            atlas: std::sync::Mutex::new(GlyphAtlas::new()),
            fonts: Fonts::system(),
            globals_layout: layout,
            cylinder: GpuMesh::new(device, &Mesh::cylinder(), "cylinder"),
            sphere: GpuMesh::new(device, &Mesh::sphere(), "sphere"),
            cone: GpuMesh::new(device, &Mesh::cone(), "cone"),
            cuboid: GpuMesh::new(device, &Mesh::cuboid(), "box"),
            samples,
            format,
        }
    }

    /// A new view's per-frame buffers (grown as its scenes need).
    pub fn new_view(&self, device: &wgpu::Device) -> PreparedView {
        PreparedView::new(device, &self.globals_layout)
    }

    /// The fonts text is drawn with (found on the system once).
    pub fn fonts(&self) -> &'static Fonts {
        self.fonts
    }

    /// Upload one frame of `view`: the camera for a `viewport` of width × height pixels,
    /// the theme and the draw list (text laid out in those pixels).
    #[allow(clippy::too_many_arguments)]
    pub fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        view: &mut PreparedView,
        list: &DrawList,
        camera: &OrbitCamera,
        theme: &Theme,
        viewport: [f32; 2],
    ) {
        self.prepare_scaled(device, queue, view, list, camera, theme, viewport, 1.0);
    }

    /// [`Renderer::prepare`] for a picture at `scale` of the view it is shown in (a view
    /// rendered smaller and filtered up): text keeps its size in the view.
    #[allow(clippy::too_many_arguments)]
    pub fn prepare_scaled(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        view: &mut PreparedView,
        list: &DrawList,
        camera: &OrbitCamera,
        theme: &Theme,
        viewport: [f32; 2],
        scale: f32,
    ) {
        let viewport = [viewport[0].max(1.0), viewport[1].max(1.0)];
        let aspect = viewport[0] / viewport[1];
        let eye = camera.eye();
        // Key light over the viewer's right shoulder and above; fill from the other side.
        let forward = -camera.direction();
        let right = forward.cross(glam::Vec3::Z).normalize_or(glam::Vec3::X);
        let key = (-forward + right * 0.6 + glam::Vec3::Z * 0.9).normalize();
        let fill = (-forward - right * 0.8 + glam::Vec3::Z * 0.2).normalize();
        let globals = Globals {
            view_proj: camera.view_proj(aspect).to_cols_array_2d(),
            eye: [eye.x, eye.y, eye.z, 1.0],
            key_light: [key.x, key.y, key.z, 0.75],
            fill_light: [fill.x, fill.y, fill.z, 0.25],
            shading: [
                0.22,
                0.25,
                48.0,
                if self.format.is_srgb() { 0.0 } else { 1.0 },
            ],
            background: {
                let bg = linear(theme.background);
                [bg[0], bg[1], bg[2], theme.background[3]]
            },
        };
        queue.write_buffer(&view.globals, 0, bytemuck::bytes_of(&globals));
        // A clear writes its colour as it is: linear into an sRGB target, encoded into
        // one that is not (a window's surface, a picture drawn into it).
        let bg = if self.format.is_srgb() {
            linear(theme.background)
        } else {
            theme.background
        };
        view.clear = wgpu::Color {
            r: bg[0] as f64,
            g: bg[1] as f64,
            b: bg[2] as f64,
            a: f64::from(theme.background[3]),
        };

        // Instances: cylinders, spheres, cones, boxes, then one identity instance per plate.
        let mut instances: Vec<MeshInstance> = Vec::with_capacity(
            list.cylinders.len()
                + list.spheres.len()
                + list.cones.len()
                + list.boxes.len()
                + list.plates.len()
                + list.parts.len(),
        );
        let range = |items: &[MeshInstance], all: &mut Vec<MeshInstance>| {
            let start = all.len() as u32;
            all.extend_from_slice(items);
            start..all.len() as u32
        };
        let cylinders = range(&list.cylinders, &mut instances);
        let spheres = range(&list.spheres, &mut instances);
        let cones = range(&list.cones, &mut instances);
        let boxes = range(&list.boxes, &mut instances);
        let slots = view.keep_parts(device, list.parts.iter().map(|p| &p.mesh));
        let parts = slots
            .into_iter()
            .zip(&list.parts)
            .map(|(slot, part)| {
                instances.push(part.instance);
                (slot, instances.len() as u32 - 1)
            })
            .collect();
        // Plates back to front from the eye.
        let mut order: Vec<usize> = (0..list.plates.len()).collect();
        order.sort_by(|&a, &b| {
            let da = (list.plates[a].2 - eye).length_squared();
            let db = (list.plates[b].2 - eye).length_squared();
            db.total_cmp(&da)
        });
        let mut plate_vertices: Vec<MeshVertex> = Vec::new();
        let mut plate_indices: Vec<u32> = Vec::new();
        let mut plates = Vec::new();
        for k in order {
            let (mesh, color, _) = &list.plates[k];
            let base = plate_vertices.len() as u32;
            let first = plate_indices.len() as u32;
            plate_vertices.extend_from_slice(&mesh.vertices);
            plate_indices.extend(mesh.indices.iter().map(|i| i + base));
            let instance = instances.len() as u32;
            instances.push(MeshInstance {
                model: glam::Mat4::IDENTITY.to_cols_array_2d(),
                color: *color,
            });
            plates.push((first, mesh.indices.len() as u32, instance));
        }
        view.instances
            .write(device, queue, bytemuck::cast_slice(&instances));
        view.plate_vertices
            .write(device, queue, bytemuck::cast_slice(&plate_vertices));
        view.plate_indices
            .write(device, queue, bytemuck::cast_slice(&plate_indices));
        view.line_vertices
            .write(device, queue, bytemuck::cast_slice(&list.lines));
        view.keep_analysis(device, &list.analysis);
        let text = self.prepare_text(queue, list, camera.view_proj(aspect), viewport, scale);
        view.text_vertices
            .write(device, queue, bytemuck::cast_slice(&text));
        view.batches = Batches {
            cylinders,
            spheres,
            cones,
            boxes,
            plates,
            lines: list.lines.len() as u32,
            text: text.len() as u32,
            parts,
        };
    }

    /// Lay out the draw list's text and upload the glyphs it added to the atlas.
    fn prepare_text(
        &self,
        queue: &wgpu::Queue,
        list: &DrawList,
        view_proj: glam::Mat4,
        viewport: [f32; 2],
        scale: f32,
    ) -> Vec<TextVertex> {
        if list.texts.is_empty() {
            return Vec::new();
        }
        let mut atlas = self
            .atlas
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let vertices = atlas.layout(self.fonts, &list.texts, view_proj, viewport, scale);
        if atlas.dirty {
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &self.atlas_texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                &atlas.pixels,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(ATLAS_SIZE),
                    rows_per_image: Some(ATLAS_SIZE),
                },
                wgpu::Extent3d {
                    width: ATLAS_SIZE,
                    height: ATLAS_SIZE,
                    depth_or_array_layers: 1,
                },
            );
            atlas.dirty = false;
        }
        vertices
    }

    /// Draw `view`'s prepared frame into an open render pass.
    pub fn paint(&self, view: &PreparedView, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        if view.batches.lines > 0 {
            pass.set_pipeline(&self.lines);
            pass.set_vertex_buffer(0, view.line_vertices.buffer.slice(..));
            pass.draw(0..view.batches.lines, 0..1);
        }
        pass.set_pipeline(&self.opaque);
        pass.set_vertex_buffer(1, view.instances.buffer.slice(..));
        for (mesh, range) in [
            (&self.cylinder, &view.batches.cylinders),
            (&self.sphere, &view.batches.spheres),
            (&self.cone, &view.batches.cones),
            (&self.cuboid, &view.batches.boxes),
        ] {
            if range.is_empty() {
                continue;
            }
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.count, 0, range.clone());
        }
        if !view.batches.parts.is_empty() {
            pass.set_pipeline(&self.parts);
            for &(slot, instance) in &view.batches.parts {
                let mesh = &view.parts[slot].1;
                if mesh.count == 0 {
                    continue;
                }
                pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.count, 0, instance..instance + 1);
            }
        }
        if !view.batches.plates.is_empty() {
            pass.set_pipeline(&self.translucent);
            pass.set_vertex_buffer(0, view.plate_vertices.buffer.slice(..));
            pass.set_index_buffer(
                view.plate_indices.buffer.slice(..),
                wgpu::IndexFormat::Uint32,
            );
            for &(first, count, instance) in &view.batches.plates {
                pass.draw_indexed(first..first + count, 0, instance..instance + 1);
            }
        }
        if !view.analysis.is_empty() {
            pass.set_pipeline(&self.analysis);
            for (_, mesh) in &view.analysis {
                pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.count, 0, 0..1);
            }
        }
        if view.batches.text > 0 {
            pass.set_pipeline(&self.text);
            pass.set_bind_group(1, &self.atlas_bind_group, &[]);
            pass.set_vertex_buffer(0, view.text_vertices.buffer.slice(..));
            pass.draw(0..view.batches.text, 0..1);
        }
    }

    /// Draw `view`'s background (the theme's colour) over the whole viewport of an open
    /// pass: what a clear would do, where the view shares its pass with a UI.
    pub fn paint_background(&self, view: &PreparedView, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        pass.set_pipeline(&self.background);
        pass.draw(0..3, 0..1);
    }

    /// Draw a picture rendered off screen ([`crate::Picture`]) over the whole viewport of
    /// an open pass; `view` is any view prepared by this renderer (its globals are bound).
    pub fn paint_picture(
        &self,
        view: &PreparedView,
        picture: &crate::Picture,
        pass: &mut wgpu::RenderPass<'_>,
    ) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        pass.set_bind_group(1, picture.bind_group(), &[]);
        pass.set_pipeline(&self.picture);
        pass.draw(0..3, 0..1);
    }

    /// The layout of a picture's bind group (its texture and sampler), for
    /// [`crate::Picture::new`].
    pub(crate) fn picture_layout(&self) -> &wgpu::BindGroupLayout {
        &self.picture_layout
    }

    /// Record a whole pass: clear `target` (and `depth`), draw, resolve into `resolve` when MSAA is on.
    pub fn render(
        &self,
        view: &PreparedView,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        resolve: Option<&wgpu::TextureView>,
        depth: &wgpu::TextureView,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("stewart scene"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: resolve,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(view.clear),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(crate::targets::cleared_depth(depth)),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        self.paint(view, &mut pass);
    }
}

/// What a triangle pipeline is made of: its name, layout, shader module (`vs_main`,
/// `fs_main`) and vertex buffers.
struct TriangleStages<'a> {
    label: &'a str,
    layout: &'a wgpu::PipelineLayout,
    module: &'a wgpu::ShaderModule,
    buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
}

/// A lit triangle pipeline, depth-tested (`Less`) and writing depth or not, culling `cull`.
fn triangle_pipeline(
    device: &wgpu::Device,
    stages: TriangleStages<'_>,
    depth_write: bool,
    cull: Option<wgpu::Face>,
    multisample: wgpu::MultisampleState,
    targets: &[Option<wgpu::ColorTargetState>],
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(stages.label),
        layout: Some(stages.layout),
        vertex: wgpu::VertexState {
            module: stages.module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: stages.buffers,
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            cull_mode: cull,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(depth_write),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample,
        fragment: Some(wgpu::FragmentState {
            module: stages.module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// The text pipeline (screen-space quads over everything, alpha-blended), the glyph atlas
/// texture and its bind group.
/// The layout of the per-view globals (camera, light): one uniform buffer for both stages.
fn globals_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("globals"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    })
}

/// The pipeline of coloured line lists (grid, axes, path), depth-tested and written.
fn line_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    multisample: wgpu::MultisampleState,
    targets: &[Option<wgpu::ColorTargetState>],
) -> wgpu::RenderPipeline {
    let line_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("lines.wgsl"),
        source: wgpu::ShaderSource::Wgsl(shaders::LINES.into()),
    });
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("lines"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: &line_module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<LineVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x4],
            })],
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::LineList,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::LessEqual),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample,
        fragment: Some(wgpu::FragmentState {
            module: &line_module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets,
        }),
        multiview_mask: None,
        cache: None,
    })
}

fn text_pipeline(
    device: &wgpu::Device,
    globals: &wgpu::BindGroupLayout,
    multisample: wgpu::MultisampleState,
    format: wgpu::TextureFormat,
) -> (wgpu::RenderPipeline, wgpu::Texture, wgpu::BindGroup) {
    let layout = crate::picture::sampled_texture_layout(device, "glyph atlas");
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("glyph atlas"),
        size: wgpu::Extent3d {
            width: ATLAS_SIZE,
            height: ATLAS_SIZE,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R8Unorm,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    // Glyphs are placed on whole pixels at their own size: nearest sampling keeps them crisp.
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("glyph atlas"),
        ..wgpu::SamplerDescriptor::default()
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("glyph atlas"),
        layout: &layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(
                    &texture.create_view(&wgpu::TextureViewDescriptor::default()),
                ),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::Sampler(&sampler),
            },
        ],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("text"),
        bind_group_layouts: &[Some(globals), Some(&layout)],
        immediate_size: 0,
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("text.wgsl"),
        source: wgpu::ShaderSource::Wgsl(shaders::TEXT.into()),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("text"),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<TextVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x2, 1 => Float32x2, 2 => Float32x4],
            })],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample,
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    });
    (pipeline, texture, bind_group)
}
