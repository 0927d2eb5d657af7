//! Whole-window screenshots larger than the screen (2×, 4K): the window's UI is laid out
//! again in the same points at a higher pixel density — text rasterised anew, not
//! upscaled — and drawn off screen with the window's own egui and 3D renderers (same
//! colour format, MSAA and depth as the window's pass), then read back.

use egui::epaint::ClippedPrimitive;
use egui::epaint::textures::TexturesDelta;
use stewart_render::readback::Readback;

use crate::viewer::error::ViewerError;

/// MSAA samples of the window and of its shots on a GPU (the 3D pipelines are built to
/// match); a software rasteriser's window has one (see [`crate::viewer::view3d::quality`]).
pub(crate) const SAMPLES: u32 = 4;

/// The pixel density factor that makes a window `width` physical pixels wide come out at
/// `scale`: 1 (as on screen), 2, or 3840 pixels wide for 4K.
pub(crate) fn factor(scale: crate::viewer::view3d::shots::ShotScale, width: u32) -> f32 {
    use crate::viewer::view3d::shots::ShotScale;
    match scale {
        ShotScale::One => 1.0,
        ShotScale::Two => 2.0,
        ShotScale::Uhd => 3840.0 / width.max(1) as f32,
    }
}

/// The render targets of one off-screen pass.
struct Targets {
    /// The multisampled colour (none with one sample: drawn into `resolve` itself).
    msaa: Option<wgpu::Texture>,
    depth: wgpu::Texture,
    resolve: wgpu::Texture,
}

impl Targets {
    fn new(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        [w, h]: [u32; 2],
        samples: u32,
    ) -> Self {
        let texture = |label, format, samples, usage| {
            stewart_render::targets::texture(device, label, [w, h], format, samples, usage)
        };
        Self {
            msaa: (samples > 1).then(|| {
                texture(
                    "window-shot msaa",
                    format,
                    samples,
                    wgpu::TextureUsages::RENDER_ATTACHMENT,
                )
            }),
            depth: texture(
                "window-shot depth",
                stewart_render::renderer::DEPTH_FORMAT,
                samples,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            ),
            resolve: texture(
                "window-shot resolve",
                format,
                1,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            ),
        }
    }
}

/// Draw `primitives` (tessellated at `pixels_per_point`) into a `size`-pixel image on
/// `clear` with the window's `samples`, applying `textures` (the font atlas at this
/// density) first.
pub(crate) fn render(
    rs: &egui_wgpu::RenderState,
    samples: u32,
    primitives: &[ClippedPrimitive],
    textures: &mut TexturesDelta,
    size: [u32; 2],
    pixels_per_point: f32,
    clear: [f32; 4],
) -> Result<egui::ColorImage, ViewerError> {
    let max = rs.device.limits().max_texture_dimension_2d;
    if size[0] == 0 || size[1] == 0 || size[0] > max || size[1] > max {
        return Err(ViewerError::TooLarge { size, max });
    }
    let (device, queue) = (&rs.device, &rs.queue);
    let targets = Targets::new(device, rs.target_format, size, samples);
    let screen = egui_wgpu::ScreenDescriptor {
        size_in_pixels: size,
        pixels_per_point,
    };
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("window-shot"),
    });
    let mut commands = {
        let mut renderer = rs.renderer.write();
        for (id, deltas) in &textures.set {
            for delta in deltas {
                renderer.update_texture(device, queue, *id, delta);
            }
        }
        renderer.update_buffers(device, queue, &mut encoder, primitives, &screen)
    };
    draw_pass(rs, &mut encoder, &targets, primitives, &screen, clear);
    let readback = Readback::new(device, "window-shot readback", size[0], size[1]);
    readback.copy_from(&mut encoder, &targets.resolve);
    commands.push(encoder.finish());
    queue.submit(commands);
    let data = readback.read(device).map_err(ViewerError::Readback)?;
    Ok(colour_image(&data, size, rs.target_format))
}

/// The pass that draws the window's `primitives` into `targets`, cleared to `clear`.
fn draw_pass(
    rs: &egui_wgpu::RenderState,
    encoder: &mut wgpu::CommandEncoder,
    targets: &Targets,
    primitives: &[ClippedPrimitive],
    screen: &egui_wgpu::ScreenDescriptor,
    clear: [f32; 4],
) {
    let msaa = targets
        .msaa
        .as_ref()
        .map(|t| t.create_view(&Default::default()));
    let resolve = targets.resolve.create_view(&Default::default());
    let (view, resolve_target) = match &msaa {
        Some(msaa) => (msaa, Some(&resolve)),
        None => (&resolve, None),
    };
    let depth = targets.depth.create_view(&Default::default());
    let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("window-shot"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            resolve_target,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color {
                    r: f64::from(clear[0]),
                    g: f64::from(clear[1]),
                    b: f64::from(clear[2]),
                    a: f64::from(clear[3]),
                }),
                store: wgpu::StoreOp::Store,
            },
            depth_slice: None,
        })],
        depth_stencil_attachment: Some(stewart_render::targets::cleared_depth(&depth)),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    });
    let renderer = rs.renderer.read();
    renderer.render(&mut pass.forget_lifetime(), primitives, screen);
}

/// Pixels read back in the target's `format` as an opaque egui image of `size`.
fn colour_image(data: &[u8], size: [u32; 2], format: wgpu::TextureFormat) -> egui::ColorImage {
    let bgra = matches!(
        format,
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
    );
    let pixels = data
        .chunks_exact(4)
        .map(|p| {
            let (r, b) = if bgra { (p[2], p[0]) } else { (p[0], p[2]) };
            egui::Color32::from_rgba_premultiplied(r, p[1], b, 255)
        })
        .collect();
    egui::ColorImage::new([size[0] as usize, size[1] as usize], pixels)
}
