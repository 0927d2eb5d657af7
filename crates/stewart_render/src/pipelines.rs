//! The render pipelines every view shares, built once per device and colour format by
//! [`crate::Renderer::new`]: lit triangles (meshes, CAD parts, plates, analysis meshes),
//! lines, text, the flat background and the picture blit; and the bind group layouts
//! they read.

use crate::gpu_types::{ColouredVertex, LineVertex, MeshInstance, MeshVertex, TextVertex};
use crate::shaders;
use crate::text::ATLAS_SIZE;

/// Depth buffer format.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// The pipelines of one colour format and sample count, and the layouts of their bind
/// groups.
pub(crate) struct Pipelines {
    /// Opaque meshes (legs, joints, axes), back faces culled.
    pub(crate) opaque: wgpu::RenderPipeline,
    /// CAD parts: opaque, both faces drawn.
    pub(crate) parts: wgpu::RenderPipeline,
    /// Translucent plates, depth-tested but not written.
    pub(crate) translucent: wgpu::RenderPipeline,
    /// Analysis meshes, a colour per vertex.
    pub(crate) analysis: wgpu::RenderPipeline,
    /// Lines (grid, path).
    pub(crate) lines: wgpu::RenderPipeline,
    /// Text from the glyph atlas.
    pub(crate) text: wgpu::RenderPipeline,
    /// The theme's colour over the viewport.
    pub(crate) background: wgpu::RenderPipeline,
    /// A picture drawn over the viewport.
    pub(crate) picture: wgpu::RenderPipeline,
    /// Group 0 of every pipeline: the frame's globals.
    pub(crate) globals_layout: wgpu::BindGroupLayout,
    /// Group 1 of the picture pipeline.
    pub(crate) picture_layout: wgpu::BindGroupLayout,
}

impl Pipelines {
    /// Every pipeline for colour `format` with `samples` MSAA samples, and the glyph
    /// atlas's texture and bind group the text pipeline reads.
    pub(crate) fn new(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        samples: u32,
    ) -> (Self, wgpu::Texture, wgpu::BindGroup) {
        let layout = globals_layout(device);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("stewart"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
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
        let [opaque, parts, translucent] =
            mesh_pipelines(device, &pipeline_layout, multisample, &blend_target);
        let analysis = analysis_pipeline(device, &pipeline_layout, multisample, &blend_target);
        let lines = line_pipeline(device, &pipeline_layout, multisample, &blend_target);
        let (text, atlas_texture, atlas_bind_group) =
            text_pipeline(device, &layout, multisample, format);
        let background = background_pipeline(device, &pipeline_layout, multisample, format);
        let picture_layout = picture_layout(device);
        let picture = picture_pipeline(device, &layout, &picture_layout, multisample, format);
        let pipelines = Self {
            opaque,
            parts,
            translucent,
            analysis,
            lines,
            text,
            background,
            picture,
            globals_layout: layout,
            picture_layout,
        };
        (pipelines, atlas_texture, atlas_bind_group)
    }
}

/// The lit mesh pipelines (mesh.wgsl, a mesh and its instances): opaque meshes with
/// back faces culled, CAD parts (opaque, both faces), translucent plates (depth tested,
/// not written, both faces).
fn mesh_pipelines(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    multisample: wgpu::MultisampleState,
    blend_target: &[Option<wgpu::ColorTargetState>],
) -> [wgpu::RenderPipeline; 3] {
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
    let mesh_pipeline = |label: &str, depth_write: bool, cull: Option<wgpu::Face>| {
        triangle_pipeline(
            device,
            TriangleStages {
                label,
                layout,
                module: &mesh_module,
                buffers: &mesh_buffers,
            },
            depth_write,
            cull,
            multisample,
            blend_target,
        )
    };
    let opaque = mesh_pipeline("opaque meshes", true, Some(wgpu::Face::Back));
    // CAD parts: opaque, but both faces drawn (files do not always wind their
    // triangles the same way; the shading is two-sided).
    let parts = mesh_pipeline("CAD parts", true, None);
    // Translucent plates: depth-tested against the opaque scene, not written, both
    // faces drawn, back to front.
    let translucent = mesh_pipeline("translucent plates", false, None);
    [opaque, parts, translucent]
}

/// The analysis meshes' pipeline (analysis.wgsl): translucent, world coordinates, a colour
/// per vertex.
fn analysis_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    multisample: wgpu::MultisampleState,
    blend_target: &[Option<wgpu::ColorTargetState>],
) -> wgpu::RenderPipeline {
    let analysis_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("analysis.wgsl"),
        source: wgpu::ShaderSource::Wgsl(shaders::ANALYSIS.into()),
    });
    // Analysis meshes: translucent, world coordinates, a colour per vertex.
    triangle_pipeline(
        device,
        TriangleStages {
            label: "analysis meshes",
            layout,
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
        blend_target,
    )
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
    let layout = sampled_texture_layout(device, "glyph atlas");
    let (texture, bind_group) = glyph_atlas(device, &layout);
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

/// The glyph atlas: a one-channel texture, sampled nearest (glyphs are placed on whole
/// pixels at their own size, and so stay crisp), and its bind group of `layout`.
fn glyph_atlas(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
) -> (wgpu::Texture, wgpu::BindGroup) {
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
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("glyph atlas"),
        ..wgpu::SamplerDescriptor::default()
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("glyph atlas"),
        layout,
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
    (texture, bind_group)
}

/// The layout of a picture's bind group (group 1): the texture and its sampler.
pub(crate) fn picture_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    sampled_texture_layout(device, "picture")
}

/// A bind group layout of one filterable 2-D texture (binding 0) and its sampler
/// (binding 1), read by the fragment stage: a picture's, the glyph atlas's.
pub(crate) fn sampled_texture_layout(device: &wgpu::Device, label: &str) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: true },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                count: None,
            },
        ],
    })
}

/// A full-viewport pipeline without vertex buffers, replacing what is there (no
/// blending), over everything drawn before (depth neither tested nor written).
fn overwrite_pipeline(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    multisample: wgpu::MultisampleState,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[],
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
            module,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: None,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// The background pipeline (background.wgsl): the theme's colour over the viewport.
pub(crate) fn background_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    multisample: wgpu::MultisampleState,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("background.wgsl"),
        source: wgpu::ShaderSource::Wgsl(shaders::BACKGROUND.into()),
    });
    overwrite_pipeline(device, "background", layout, &module, multisample, format)
}

/// The picture pipeline (blit.wgsl): globals in group 0, the picture in group 1.
pub(crate) fn picture_pipeline(
    device: &wgpu::Device,
    globals: &wgpu::BindGroupLayout,
    picture: &wgpu::BindGroupLayout,
    multisample: wgpu::MultisampleState,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("picture"),
        bind_group_layouts: &[Some(globals), Some(picture)],
        immediate_size: 0,
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("blit.wgsl"),
        source: wgpu::ShaderSource::Wgsl(shaders::BLIT.into()),
    });
    overwrite_pipeline(device, "picture", &layout, &module, multisample, format)
}
