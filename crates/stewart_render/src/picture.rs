//! A view rendered off screen at a quality of its own (samples, size) and drawn into
//! another pass as one textured triangle: how a window whose UI pass has no MSAA still
//! shows the 3D view at full quality, and how a slow machine shows it at a lower scale
//! while it moves. Also the flat background a view draws when it shares a UI's pass.

use crate::renderer::{DEPTH_FORMAT, Renderer};
use crate::view::PreparedView;

/// A view's off-screen picture: its colour (multisampled, then resolved), depth, and the
/// bind group that draws the resolved colour.
pub struct Picture {
    size: [u32; 2],
    samples: u32,
    filtered: bool,
    msaa: Option<wgpu::TextureView>,
    resolved: wgpu::TextureView,
    depth: wgpu::TextureView,
    bind_group: wgpu::BindGroup,
}

impl Picture {
    /// A `size` picture rendered with `samples` MSAA samples by a renderer built for them,
    /// in `shown_by`'s colour format, to be drawn by `shown_by`; `filtered`: sampled
    /// linearly (a picture smaller than the viewport), else nearest (pixel for pixel).
    pub fn new(
        device: &wgpu::Device,
        shown_by: &Renderer,
        size: [u32; 2],
        samples: u32,
        filtered: bool,
    ) -> Self {
        let size = [size[0].max(1), size[1].max(1)];
        let format = shown_by.format;
        let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let view = |t: wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
        let msaa = (samples > 1).then(|| {
            view(crate::targets::texture(
                device,
                "picture msaa",
                size,
                format,
                samples,
                attachment,
            ))
        });
        let resolved = view(crate::targets::texture(
            device,
            "picture",
            size,
            format,
            1,
            attachment | wgpu::TextureUsages::TEXTURE_BINDING,
        ));
        let depth = view(crate::targets::texture(
            device,
            "picture depth",
            size,
            DEPTH_FORMAT,
            samples,
            attachment,
        ));
        let filter = if filtered {
            wgpu::FilterMode::Linear
        } else {
            wgpu::FilterMode::Nearest
        };
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("picture"),
            mag_filter: filter,
            min_filter: filter,
            ..wgpu::SamplerDescriptor::default()
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("picture"),
            layout: shown_by.picture_layout(),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&resolved),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&sampler),
                },
            ],
        });
        Self {
            size,
            samples,
            filtered,
            msaa,
            resolved,
            depth,
            bind_group,
        }
    }

    /// Whether this picture is `size` pixels with `samples` samples and that filtering
    /// (else a new one is needed).
    pub fn fits(&self, size: [u32; 2], samples: u32, filtered: bool) -> bool {
        self.size == [size[0].max(1), size[1].max(1)]
            && self.samples == samples
            && self.filtered == filtered
    }

    /// Its size, pixels.
    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    /// Record the pass that renders `view` (prepared by `renderer`, built for this
    /// picture's samples) into the picture: cleared to the view's background.
    pub fn render(
        &self,
        renderer: &Renderer,
        view: &PreparedView,
        encoder: &mut wgpu::CommandEncoder,
    ) {
        match &self.msaa {
            Some(msaa) => renderer.render(view, encoder, msaa, Some(&self.resolved), &self.depth),
            None => renderer.render(view, encoder, &self.resolved, None, &self.depth),
        }
    }

    /// The bind group that samples the picture.
    pub(crate) fn bind_group(&self) -> &wgpu::BindGroup {
        &self.bind_group
    }
}

/// The layout of a picture's bind group (group 1): the texture and its sampler.
pub(crate) fn bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
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
        source: wgpu::ShaderSource::Wgsl(crate::shaders::BACKGROUND.into()),
    });
    overwrite_pipeline(device, "background", layout, &module, multisample, format)
}

/// The picture pipeline (blit.wgsl): globals in group 0, the picture in group 1.
pub(crate) fn pipeline(
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
        source: wgpu::ShaderSource::Wgsl(crate::shaders::BLIT.into()),
    });
    overwrite_pipeline(device, "picture", &layout, &module, multisample, format)
}
