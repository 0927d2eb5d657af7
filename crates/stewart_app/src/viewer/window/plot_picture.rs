//! The window's side of the plot's curves picture (see
//! [`crate::viewer::panels::plot_picture`]): the curves the plot asks for are tessellated
//! as the frame's own shapes are, drawn off screen with the window's egui renderer into a
//! texture of the window's format at the window's density, and handed to the plot as an
//! egui texture.

use egui::epaint::ClippedShape;

use crate::viewer::state::plot_memory::{CurvesPicture, DrawnPicture, WantedPicture};

/// The picture's texture, its depth buffer (the window's egui pipeline has one) and its
/// egui id.
pub(crate) struct PictureTarget {
    texture: wgpu::Texture,
    depth: wgpu::Texture,
    id: egui::TextureId,
}

/// Draw the picture `picture` asks for, if it asks, into `target` (made or remade to
/// size); what it shows goes into `picture.drawn`.
pub(crate) fn draw_wanted(
    rs: &egui_wgpu::RenderState,
    ctx: &egui::Context,
    target: &mut Option<PictureTarget>,
    picture: &mut CurvesPicture,
) {
    let Some(wanted) = picture.wanted.take() else {
        return;
    };
    picture.drawn = draw(rs, ctx, target, &wanted).map(|(texture, parts)| DrawnPicture {
        texture,
        key: wanted.key,
        parts: std::sync::Arc::new(parts),
    });
}

/// A colour target of the window's format (render attachment, and `usage`) and the depth
/// buffer the window's egui pipeline draws with, both `size` pixels.
fn colour_and_depth(
    rs: &egui_wgpu::RenderState,
    size: [u32; 2],
    usage: wgpu::TextureUsages,
) -> (wgpu::Texture, wgpu::Texture) {
    let texture = |label, format, usage| {
        stewart_render::targets::texture(&rs.device, label, size, format, 1, usage)
    };
    (
        texture(
            "plot curves picture",
            rs.target_format,
            wgpu::TextureUsages::RENDER_ATTACHMENT | usage,
        ),
        texture(
            "plot curves picture depth",
            stewart_render::renderer::DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        ),
    )
}

/// The command buffers that draw `primitives` (tessellated at `ppp`) with the window's egui
/// renderer into `colour` over `clear`, with the depth buffer the window's pipeline has.
fn paint_into(
    rs: &egui_wgpu::RenderState,
    primitives: &[egui::ClippedPrimitive],
    (colour, depth): (&wgpu::Texture, &wgpu::Texture),
    ppp: f32,
    clear: wgpu::Color,
) -> Vec<wgpu::CommandBuffer> {
    let size = colour.size();
    let screen = egui_wgpu::ScreenDescriptor {
        size_in_pixels: [size.width, size.height],
        pixels_per_point: ppp,
    };
    let device = &rs.device;
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("plot curves picture"),
    });
    let mut commands =
        rs.renderer
            .write()
            .update_buffers(device, &rs.queue, &mut encoder, primitives, &screen);
    {
        let view = colour.create_view(&Default::default());
        let depth = depth.create_view(&Default::default());
        let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("plot curves picture"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(clear),
                    store: wgpu::StoreOp::Store,
                },
                depth_slice: None,
            })],
            depth_stencil_attachment: Some(stewart_render::targets::cleared_depth(&depth)),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        rs.renderer
            .read()
            .render(&mut pass.forget_lifetime(), primitives, &screen);
    }
    commands.push(encoder.finish());
    commands
}

/// The side of the squares, physical pixels, by which the picture's parts that hold
/// anything are found.
const PART: f32 = 16.0;

/// The rectangles of a picture of `size` pixels at `ppp` placed at `origin` (window
/// points) that `primitives` (tessellated in the picture's points) touch: squares of
/// [`PART`] pixels, those next to each other in a row joined.
fn parts_touched(
    primitives: &[egui::ClippedPrimitive],
    size: [u32; 2],
    ppp: f32,
    origin: egui::Vec2,
) -> Vec<egui::Rect> {
    let columns = (size[0] as f32 / PART).ceil() as usize;
    let rows = (size[1] as f32 / PART).ceil() as usize;
    let mut touched = vec![false; columns * rows];
    let cell = |v: f32, n: usize| ((v * ppp / PART).floor().max(0.0) as usize).min(n - 1);
    for primitive in primitives {
        let egui::epaint::Primitive::Mesh(mesh) = &primitive.primitive else {
            continue;
        };
        for triangle in mesh.indices.chunks_exact(3) {
            let corners = [0, 1, 2].map(|k| mesh.vertices[triangle[k] as usize].pos);
            let (lo, hi) = corners.iter().fold(
                (
                    egui::pos2(f32::INFINITY, f32::INFINITY),
                    egui::pos2(0.0, 0.0),
                ),
                |(lo, hi), p| (lo.min(*p), hi.max(*p)),
            );
            for row in cell(lo.y, rows)..=cell(hi.y, rows) {
                for column in cell(lo.x, columns)..=cell(hi.x, columns) {
                    touched[row * columns + column] = true;
                }
            }
        }
    }
    let (w, h) = (size[0] as f32 / ppp, size[1] as f32 / ppp);
    let side = PART / ppp;
    let mut parts = Vec::new();
    for row in 0..rows {
        let mut column = 0;
        while column < columns {
            if !touched[row * columns + column] {
                column += 1;
                continue;
            }
            let start = column;
            while column < columns && touched[row * columns + column] {
                column += 1;
            }
            let min = egui::pos2(start as f32 * side, row as f32 * side);
            let max = egui::pos2(
                (column as f32 * side).min(w),
                ((row + 1) as f32 * side).min(h),
            );
            parts.push(egui::Rect::from_min_max(min, max).translate(origin));
        }
    }
    parts
}

/// Draw `wanted` into `target`; the texture's id and the parts of it drawn on, or `None`
/// where it cannot be (a size the device refuses).
fn draw(
    rs: &egui_wgpu::RenderState,
    ctx: &egui::Context,
    target: &mut Option<PictureTarget>,
    wanted: &WantedPicture,
) -> Option<(egui::TextureId, Vec<egui::Rect>)> {
    let ppp = wanted.pixels_per_point;
    let size = [wanted.rect.width(), wanted.rect.height()].map(|v| (v * ppp).round() as u32);
    let max = rs.device.limits().max_texture_dimension_2d;
    if size.iter().any(|&v| v == 0 || v > max) {
        return None;
    }
    let device = &rs.device;
    let fits = target.as_ref().is_some_and(|t| {
        let s = t.texture.size();
        [s.width, s.height] == size
    });
    if !fits {
        let (texture, depth) = colour_and_depth(rs, size, wgpu::TextureUsages::TEXTURE_BINDING);
        let view = texture.create_view(&Default::default());
        let mut renderer = rs.renderer.write();
        let id = match target.take() {
            Some(old) => {
                renderer.update_egui_texture_from_wgpu_texture(
                    device,
                    &view,
                    wgpu::FilterMode::Nearest,
                    old.id,
                );
                old.id
            }
            None => renderer.register_native_texture(device, &view, wgpu::FilterMode::Nearest),
        };
        *target = Some(PictureTarget { texture, depth, id });
    }
    let target = target.as_ref()?;
    // The picture's top left corner is the window's pixel its rectangle starts on.
    let origin = wanted.rect.min.to_vec2();
    let clip = wanted.clip.translate(-origin);
    let shapes = (wanted.shapes.iter())
        .map(|shape| {
            let mut shape = shape.clone();
            shape.translate(-origin);
            ClippedShape::new(clip, shape)
        })
        .collect();
    let primitives = ctx.tessellate(shapes, ppp);
    let commands = paint_into(
        rs,
        &primitives,
        (&target.texture, &target.depth),
        ppp,
        wgpu::Color::TRANSPARENT,
    );
    rs.queue.submit(commands);
    Some((target.id, parts_touched(&primitives, size, ppp, origin)))
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use egui::{Color32, Pos2, Rect, Shape, Stroke, pos2, vec2};

    use super::*;
    use crate::viewer::panels::plot_picture::{on_pixels, picture_mesh};

    /// The window's egui renderer on the process's one device, as the window sets it up
    /// on a software rasteriser (one sample, a depth buffer), and a context whose font
    /// atlas it holds.
    fn window_like() -> (egui_wgpu::RenderState, egui::Context) {
        let gpu = stewart_render::Gpu::shared().unwrap_or_else(|e| panic!("{e}"));
        let format = wgpu::TextureFormat::Bgra8Unorm;
        let renderer = egui_wgpu::Renderer::new(
            &gpu.device,
            format,
            egui_wgpu::RendererOptions {
                msaa_samples: 1,
                depth_stencil_format: Some(stewart_render::renderer::DEPTH_FORMAT),
                ..Default::default()
            },
        );
        let rs = egui_wgpu::RenderState {
            adapter: gpu.adapter,
            available_adapters: Vec::new(),
            instance: gpu.instance,
            device: gpu.device,
            queue: gpu.queue,
            target_format: format,
            renderer: Arc::new(egui::mutex::RwLock::new(renderer)),
        };
        let ctx = egui::Context::default();
        let mut output = ctx.run_ui(egui::RawInput::default(), |_| {});
        let mut renderer = rs.renderer.write();
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                renderer.update_texture(&rs.device, &rs.queue, *id, delta);
            }
        }
        output.textures_delta.clear();
        drop(renderer);
        (rs, ctx)
    }

    /// `shapes` drawn over an opaque background into a `size`-pixel image at `ppp`.
    fn render(
        rs: &egui_wgpu::RenderState,
        ctx: &egui::Context,
        shapes: Vec<ClippedShape>,
        size: [u32; 2],
        ppp: f32,
    ) -> Vec<u8> {
        let primitives = ctx.tessellate(shapes, ppp);
        let device = &rs.device;
        let (colour, depth) = colour_and_depth(rs, size, wgpu::TextureUsages::COPY_SRC);
        let mut commands = paint_into(
            rs,
            &primitives,
            (&colour, &depth),
            ppp,
            wgpu::Color {
                r: 0.11,
                g: 0.12,
                b: 0.13,
                a: 1.0,
            },
        );
        let mut encoder = device.create_command_encoder(&Default::default());
        let readback =
            stewart_render::readback::Readback::new(device, "test readback", size[0], size[1]);
        readback.copy_from(&mut encoder, &colour);
        commands.push(encoder.finish());
        rs.queue.submit(commands);
        readback.read(device).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Curves like the plot's: six polylines of a thousand points with egui's
    /// anti-aliasing, in a band across a frame that starts between pixels.
    fn curves(frame: Rect) -> Vec<Shape> {
        (0..6)
            .map(|k| {
                let points: Vec<Pos2> = (0..1000)
                    .map(|i| {
                        let u = i as f32 / 999.0;
                        let y = 0.35 + 0.05 * k as f32 + 0.04 * (7.0 * u + k as f32).sin();
                        frame.min + vec2(u * frame.width(), y * frame.height())
                    })
                    .collect();
                let colour = Color32::from_rgb(200, 40 * k as u8, 255 - 40 * k as u8);
                Shape::line(points, Stroke::new(1.5, colour))
            })
            .collect()
    }

    #[test]
    fn the_curves_shown_from_their_picture_look_as_drawn_directly() {
        let (rs, ctx) = window_like();
        for ppp in [1.0, 1.5] {
            let size = [320, 200];
            let frame = Rect::from_min_max(pos2(5.3, 4.6), pos2(205.7, 130.2));
            let clip = frame;
            let shapes = curves(frame);
            let direct = render(
                &rs,
                &ctx,
                (shapes.iter().cloned())
                    .map(|s| ClippedShape::new(clip, s))
                    .collect(),
                size,
                ppp,
            );
            let rect = on_pixels(frame, ppp);
            let wanted = WantedPicture {
                key: Default::default(),
                rect,
                clip,
                pixels_per_point: ppp,
                shapes,
            };
            let mut target = None;
            let (texture, parts) =
                draw(&rs, &ctx, &mut target, &wanted).unwrap_or_else(|| panic!("not drawn"));
            // Only the parts the curves touch are drawn, and they are fewer than all.
            let whole = rect.area();
            let drawn_area: f32 = parts.iter().map(Rect::area).sum();
            assert!(drawn_area < 0.9 * whole, "{drawn_area} of {whole}");
            let drawn = DrawnPicture {
                texture,
                key: wanted.key,
                parts: Arc::new(parts),
            };
            let pictured = render(
                &rs,
                &ctx,
                vec![ClippedShape::new(
                    clip,
                    Shape::mesh(picture_mesh(&drawn, rect)),
                )],
                size,
                ppp,
            );
            // Dithering is applied once drawn directly and twice through the picture:
            // a level or two apart at most, nowhere more.
            let worst = (direct.iter().zip(&pictured))
                .map(|(a, b)| a.abs_diff(*b))
                .max()
                .unwrap_or(0);
            assert!(worst <= 3, "ppp {ppp}: a channel {worst} levels apart");
            // And the curves are there: the images are not both blank.
            let lit = direct.chunks_exact(4).filter(|p| p[2] > 100).count();
            assert!(lit > 1000, "{lit}");
        }
    }
}
