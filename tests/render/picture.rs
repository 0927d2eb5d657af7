//! The window's ways of drawing the 3D view where its pass has one sample (a software
//! rasteriser): the full picture rendered off screen with 4× MSAA and drawn in is the very
//! image a 4× render gives, and the background triangle is the clear it stands for.

use stewart_kinematics::Geometry;
use stewart_render::readback::Readback;
use stewart_render::renderer::DEPTH_FORMAT;
use stewart_render::targets::{cleared_depth, texture};
use stewart_render::{DrawList, Gpu, Overlays, Picture, PreparedView, Renderer, Theme};

/// A window surface's format (not sRGB: the shaders encode).
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
const SIZE: [u32; 2] = [160, 120];

fn gpu() -> Gpu {
    Gpu::shared().unwrap_or_else(|e| panic!("{e}"))
}

/// The seed at home, prepared by `renderer` for the seed's view at [`SIZE`].
fn prepared(gpu: &Gpu, renderer: &Renderer, theme: &Theme) -> PreparedView {
    let g = Geometry::seed();
    let list = DrawList::build(
        &g.scene_frame(&g.home_pose(), Vec::new()),
        theme,
        &Overlays::default(),
    );
    let mut view = renderer.new_view(&gpu.device);
    let viewport = SIZE.map(|v| v as f32);
    let camera = stewart_render::OrbitCamera::seed_view_of(&g);
    let frame = stewart_render::ViewFrame::new(&list, &camera, theme, viewport);
    renderer.prepare(&gpu.device, &gpu.queue, &mut view, &frame);
    view
}

/// Record a one-sample pass into `target` cleared to `clear`, drawing with `draw`; then
/// read the target back.
fn one_sample_pass(
    gpu: &Gpu,
    encoder: wgpu::CommandEncoder,
    clear: wgpu::Color,
    draw: impl FnOnce(&mut wgpu::RenderPass<'_>),
) -> Vec<u8> {
    let mut encoder = encoder;
    let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC;
    let target = texture(&gpu.device, "window", SIZE, FORMAT, 1, usage);
    let depth = texture(&gpu.device, "depth", SIZE, DEPTH_FORMAT, 1, usage);
    {
        let view = target.create_view(&Default::default());
        let depth = depth.create_view(&Default::default());
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("window"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(clear),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(cleared_depth(&depth)),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        draw(&mut pass);
    }
    let readback = Readback::new(&gpu.device, "window", SIZE[0], SIZE[1]);
    readback.copy_from(&mut encoder, &target);
    gpu.queue.submit([encoder.finish()]);
    readback.read(&gpu.device).unwrap_or_else(|e| panic!("{e}"))
}

fn encoder(gpu: &Gpu) -> wgpu::CommandEncoder {
    gpu.device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor::default())
}

#[test]
fn the_full_picture_drawn_into_a_one_sample_pass_is_the_4x_render_itself() {
    let gpu = gpu();
    let theme = Theme::DARK;
    let window = Renderer::new(&gpu.device, FORMAT, 1);
    let full = Renderer::new(&gpu.device, FORMAT, 4);
    // The reference: the scene rendered with 4× MSAA, resolved, read back.
    let reference = {
        let view = prepared(&gpu, &full, &theme);
        let picture = Picture::new(&gpu.device, &window, SIZE, 4, false);
        let mut encoder = encoder(&gpu);
        picture.render(&full, &view, &mut encoder);
        // Drawn into a pass cleared to red: not one red pixel may be left.
        let red = wgpu::Color::RED;
        let window_view = prepared(&gpu, &window, &theme);
        one_sample_pass(&gpu, encoder, red, |pass| {
            window.paint_picture(&window_view, &picture, pass);
        })
    };
    // The same 4× render straight into a resolve target (as exports render).
    let direct = {
        let view = prepared(&gpu, &full, &theme);
        let mut encoder = encoder(&gpu);
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC;
        let msaa = texture(&gpu.device, "msaa", SIZE, FORMAT, 4, usage);
        let resolved = texture(&gpu.device, "resolved", SIZE, FORMAT, 1, usage);
        let depth = texture(&gpu.device, "depth", SIZE, DEPTH_FORMAT, 4, usage);
        full.render(
            &view,
            &mut encoder,
            &msaa.create_view(&Default::default()),
            Some(&resolved.create_view(&Default::default())),
            &depth.create_view(&Default::default()),
        );
        let readback = Readback::new(&gpu.device, "direct", SIZE[0], SIZE[1]);
        readback.copy_from(&mut encoder, &resolved);
        gpu.queue.submit([encoder.finish()]);
        readback.read(&gpu.device).unwrap_or_else(|e| panic!("{e}"))
    };
    assert_eq!(reference.len(), direct.len());
    let differing = reference
        .chunks_exact(4)
        .zip(direct.chunks_exact(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differing, 0, "pixels that differ from the 4× render");
    // And it shows the scene on the theme's background, encoded as the target wants.
    let corner = &reference[..4];
    let bg = theme.background.map(|c| (c * 255.0).round() as i32);
    for k in 0..3 {
        assert!(
            (i32::from(corner[k]) - bg[k]).abs() <= 1,
            "{corner:?} {bg:?}"
        );
    }
}

#[test]
fn the_background_triangle_is_the_clear_it_stands_for() {
    let gpu = gpu();
    for theme in [Theme::DARK, Theme::LIGHT] {
        let window = Renderer::new(&gpu.device, FORMAT, 1);
        let view = prepared(&gpu, &window, &theme);
        let bg = theme.background.map(f64::from);
        let cleared = one_sample_pass(
            &gpu,
            encoder(&gpu),
            wgpu::Color {
                r: bg[0],
                g: bg[1],
                b: bg[2],
                a: bg[3],
            },
            |pass| window.paint(&view, pass),
        );
        let drawn = one_sample_pass(&gpu, encoder(&gpu), wgpu::Color::RED, |pass| {
            window.paint_background(&view, pass);
            window.paint(&view, pass);
        });
        // The same picture, to the rounding of an 8-bit round trip through linear.
        let worst = cleared
            .iter()
            .zip(&drawn)
            .map(|(a, b)| (i32::from(*a) - i32::from(*b)).abs())
            .max()
            .unwrap_or(0);
        assert!(worst <= 1, "{worst}");
    }
}
