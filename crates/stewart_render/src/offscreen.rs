//! Rendering into a texture with no window, and reading the pixels back.

use crate::camera::OrbitCamera;
use crate::draw_list::DrawList;
use crate::gpu::{Gpu, GpuError};
use crate::pipelines::DEPTH_FORMAT;
use crate::readback::Readback;
use crate::renderer::{Renderer, ViewFrame};
use crate::theme::Theme;
use crate::view::PreparedView;

/// Colour format of offscreen frames (sRGB, so images match the screen).
pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// Largest frame side, pixels (4K is 3840 × 2160).
pub const MAX_SIDE: u32 = 4096;

/// An RGBA image read back from the GPU, rows top to bottom, no padding.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
    /// `width × height × 4` bytes, sRGB.
    pub rgba: Vec<u8>,
}

impl Image {
    /// The pixel at `(x, y)`.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = 4 * (y as usize * self.width as usize + x as usize);
        [
            self.rgba[i],
            self.rgba[i + 1],
            self.rgba[i + 2],
            self.rgba[i + 3],
        ]
    }
}

/// Textures of one size.
struct Targets {
    width: u32,
    height: u32,
    msaa: Option<wgpu::TextureView>,
    resolve: wgpu::Texture,
    resolve_view: wgpu::TextureView,
    depth: wgpu::TextureView,
    readback: Readback,
}

impl Targets {
    fn new(device: &wgpu::Device, width: u32, height: u32, samples: u32) -> Self {
        let texture = |label: &str, format, samples, usage| {
            crate::targets::texture(device, label, [width, height], format, samples, usage)
        };
        let msaa = (samples > 1).then(|| {
            texture(
                "msaa colour",
                FORMAT,
                samples,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            )
            .create_view(&Default::default())
        });
        let resolve = texture(
            "colour",
            FORMAT,
            1,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let resolve_view = resolve.create_view(&Default::default());
        let depth = texture(
            "depth",
            DEPTH_FORMAT,
            samples,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
        .create_view(&Default::default());
        let readback = Readback::new(device, "readback", width, height);
        Self {
            width,
            height,
            msaa,
            resolve,
            resolve_view,
            depth,
            readback,
        }
    }
}

/// Why an offscreen frame could not be made.
#[derive(Debug, thiserror::Error)]
pub enum OffscreenError {
    /// No device.
    #[error(transparent)]
    Gpu(#[from] GpuError),
    /// A size of zero or beyond the limit.
    #[error("the frame size {width}×{height} is not between 1×1 and {max}×{max}")]
    Size {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
        /// Largest side.
        max: u32,
    },
    /// Reading the pixels back failed.
    #[error("reading the frame back from the GPU failed: {0}")]
    Readback(String),
}

/// A headless renderer: the scene renderer plus offscreen targets.
pub struct Offscreen {
    gpu: Gpu,
    renderer: Renderer,
    view: Option<PreparedView>,
    targets: Option<Targets>,
}

impl Offscreen {
    /// Build the renderer on the process's shared headless device (see [`Gpu::shared`]),
    /// with 4× MSAA when the adapter supports it.
    pub fn new() -> Result<Self, OffscreenError> {
        Ok(Self::on(Gpu::shared()?))
    }

    /// Build the renderer on `gpu` (a window's device, say, so that a program opens one
    /// device only), with 4× MSAA when the adapter supports it.
    pub fn on(gpu: Gpu) -> Self {
        let features = gpu.adapter.get_texture_format_features(FORMAT);
        let samples = if features.flags.sample_count_supported(4) {
            4
        } else {
            1
        };
        let renderer = Renderer::new(&gpu.device, FORMAT, samples);
        let view = Some(renderer.new_view(&gpu.device));
        Self {
            gpu,
            renderer,
            view,
            targets: None,
        }
    }

    /// The adapter in words.
    pub fn adapter(&self) -> String {
        self.gpu.describe()
    }

    /// MSAA samples in use.
    pub fn samples(&self) -> u32 {
        self.renderer.samples
    }

    /// Draw `list` seen by `camera` in `theme` at `width × height` and read it back.
    pub fn render(
        &mut self,
        list: &DrawList,
        camera: &OrbitCamera,
        theme: &Theme,
        width: u32,
        height: u32,
    ) -> Result<Image, OffscreenError> {
        self.submit(list, camera, theme, width, height)?;
        self.read()
    }

    /// Draw and start copying to the readback buffer, without waiting.
    pub fn submit(
        &mut self,
        list: &DrawList,
        camera: &OrbitCamera,
        theme: &Theme,
        width: u32,
        height: u32,
    ) -> Result<(), OffscreenError> {
        // The own view is taken out while drawing and put back: no buffers made per frame.
        let mut view = match self.view.take() {
            Some(v) => v,
            None => self.new_view(),
        };
        self.prepare(&mut view, list, camera, theme, width, height);
        let submitted = self.submit_prepared(&view, width, height);
        self.view = Some(view);
        submitted
    }

    /// A view of its own (several may be prepared, then drawn in any order).
    pub fn new_view(&self) -> PreparedView {
        self.renderer.new_view(&self.gpu.device)
    }

    /// Upload `list` seen by `camera` into `view`, for a `width × height` image.
    pub fn prepare(
        &self,
        view: &mut PreparedView,
        list: &DrawList,
        camera: &OrbitCamera,
        theme: &Theme,
        width: u32,
        height: u32,
    ) {
        let frame = ViewFrame::new(list, camera, theme, [width as f32, height as f32]);
        self.renderer
            .prepare(&self.gpu.device, &self.gpu.queue, view, &frame);
    }

    /// Draw a prepared `view` and start copying it to the readback buffer.
    pub fn submit_prepared(
        &mut self,
        view: &PreparedView,
        width: u32,
        height: u32,
    ) -> Result<(), OffscreenError> {
        if !(1..=MAX_SIDE).contains(&width) || !(1..=MAX_SIDE).contains(&height) {
            return Err(OffscreenError::Size {
                width,
                height,
                max: MAX_SIDE,
            });
        }
        let device = &self.gpu.device;
        if self
            .targets
            .as_ref()
            .is_none_or(|t| t.width != width || t.height != height)
        {
            self.targets = Some(Targets::new(device, width, height, self.renderer.samples));
        }
        let Some(t) = &self.targets else {
            unreachable!("targets were just made")
        };
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("offscreen"),
        });
        match &t.msaa {
            Some(msaa) => {
                self.renderer
                    .render(view, &mut encoder, msaa, Some(&t.resolve_view), &t.depth)
            }
            None => self
                .renderer
                .render(view, &mut encoder, &t.resolve_view, None, &t.depth),
        }
        t.readback.copy_from(&mut encoder, &t.resolve);
        self.gpu.queue.submit([encoder.finish()]);
        Ok(())
    }

    /// Wait for the last submitted frame and return its pixels.
    pub fn read(&mut self) -> Result<Image, OffscreenError> {
        let Some(t) = &self.targets else {
            return Err(OffscreenError::Readback(
                "no frame was submitted".to_owned(),
            ));
        };
        let rgba = t
            .readback
            .read(&self.gpu.device)
            .map_err(OffscreenError::Readback)?;
        Ok(Image {
            width: t.width,
            height: t.height,
            rgba,
        })
    }
}
