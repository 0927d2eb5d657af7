//! A view rendered off screen at a quality of its own (samples, size) and drawn into
//! another pass as one textured triangle: how a window whose UI pass has no MSAA still
//! shows the 3D view at full quality, and how a slow machine shows it at a lower scale
//! while it moves. Also the flat background a view draws when it shares a UI's pass.

use crate::pipelines::DEPTH_FORMAT;
use crate::renderer::Renderer;
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
