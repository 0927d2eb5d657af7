//! The window and its loop: winit 0.30, egui-winit for input, egui-wgpu's painter for the
//! surface; the 3D view shares its device. Redraws continuously only while playing.

pub(crate) mod fonts;
pub(crate) mod plot_picture;
pub(crate) mod window_shot;
pub(crate) mod window_size;

use std::io::Write as _;
use std::num::NonZeroU32;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use anyhow::{Result, anyhow};
use egui::ViewportId;
use egui_wgpu::winit::Painter;
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::window::{Window, WindowId};

use super::panels::viewer_ui;
use crate::viewer::error::ViewerError;
use crate::viewer::state::ViewerState;
use crate::viewer::view3d::shots::ShotScale;
use crate::viewer::view3d::{callback, quality};
use crate::viewer::window::window_shot::SAMPLES;

/// How the viewer runs.
#[derive(Clone, Debug)]
pub(crate) struct ViewOptions {
    /// After this many frames, save the window's image here and exit.
    pub(crate) screenshot: Option<PathBuf>,
    /// Frames to draw before the screenshot.
    pub(crate) frames: u32,
    /// The screenshot's size: as on screen, twice that, or 3840 pixels wide.
    pub(crate) screenshot_scale: ShotScale,
    /// Print frame-time statistics when the window closes.
    pub(crate) stats: bool,
    /// Where the window's size comes from.
    pub(crate) size: window_size::WindowSize,
}

/// A shot of the window at another scale: its path, the scale, and whether it ends a
/// `--screenshot` run.
type ScaledShot = (PathBuf, ShotScale, bool);

/// Per-frame timings, milliseconds.
#[derive(Default)]
struct FrameTimes {
    /// UI, kinematics, draw list and tessellation (CPU work before the GPU is involved).
    cpu: Vec<f64>,
    /// The whole frame, including recording, submission, uploads and presentation.
    total: Vec<f64>,
    /// Frames by how the 3D view was drawn (`full`, `direct`, `scaled`, `gpu`), in the
    /// order first seen.
    drawn: Vec<(&'static str, usize)>,
}

impl FrameTimes {
    fn summary(&self) -> String {
        let stat = |v: &[f64]| {
            let mut s = v.to_vec();
            s.sort_by(f64::total_cmp);
            let mean = s.iter().sum::<f64>() / s.len().max(1) as f64;
            let p95 = s
                .get((s.len() as f64 * 0.95) as usize)
                .copied()
                .unwrap_or(0.0);
            format!("mean {mean:.2} ms, 95th percentile {p95:.2} ms")
        };
        // The first frames compile shaders and upload fonts: leave them out.
        let skip = self.cpu.len().min(5);
        let drawn: Vec<String> = (self.drawn.iter())
            .map(|(how, n)| format!("{how} {n}"))
            .collect();
        format!(
            "{} frames: CPU (UI, kinematics, draw list, tessellation) {}; total {}; 3D view drawn: {}",
            self.cpu.len() - skip,
            stat(&self.cpu[skip..]),
            stat(&self.total[skip..]),
            drawn.join(", ")
        )
    }

    /// One more frame whose 3D view was drawn as the quality key `key` says.
    fn count_drawn(&mut self, key: &'static str) {
        let how = key.strip_prefix("quality.").unwrap_or(key);
        match self.drawn.iter_mut().find(|(h, _)| *h == how) {
            Some((_, n)) => *n += 1,
            None => self.drawn.push((how, 1)),
        }
    }
}

struct Open {
    window: Arc<Window>,
    painter: Painter,
    input: egui_winit::State,
    /// MSAA samples of the window's pass.
    samples: u32,
    /// The surface stores sRGB-encoded colours itself (the clear colour is then linear).
    srgb: bool,
}

struct App {
    state: ViewerState,
    ctx: egui::Context,
    options: ViewOptions,
    open: Option<Open>,
    frames: u32,
    last: Instant,
    screenshot: Arc<Mutex<Option<Result<()>>>>,
    screenshot_asked: bool,
    /// The outcome of a whole-window shot asked for from the Screenshot menu.
    window_shot: Arc<Mutex<Option<Result<String, ViewerError>>>>,
    error: Option<anyhow::Error>,
    times: FrameTimes,
    /// When egui asked to be drawn again (a tooltip delay, the text cursor's blink, an
    /// animation); `None`: only on input.
    repaint_at: Option<Instant>,
    /// The window's size, logical pixels, as last reported (kept so that saving the
    /// session at exit asks the window system nothing: it may be gone).
    logical_size: [u32; 2],
    /// Gamepads for teleoperation.
    gamepads: crate::viewer::state::gamepad::Gamepads,
    /// Whether the window was last put in full screen (F11).
    fullscreen: bool,
    /// Whether the last frame left something moving (playback, an export, the link).
    was_busy: bool,
    /// The plot's curves picture (a software rasteriser).
    plot_picture: Option<plot_picture::PictureTarget>,
}

/// Open the viewer on `state` and run until the window closes.
pub(crate) fn run(state: ViewerState, options: ViewOptions) -> Result<()> {
    check_scale_factor_setting()?;
    stewart_render::gpu::check_environment()?;
    if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
        return Err(anyhow!(
            "the viewer needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is set: run it on a desktop, or under `xvfb-run -a stewart view` (every other command works without a display)"
        ));
    }
    let event_loop = EventLoop::new().map_err(|e| anyhow!("cannot open the window system: {e}"))?;
    let mut state = state;
    // Signals are watched from the start (see `about_to_wait`).
    let _ = crate::interrupt::flag();
    let ctx = egui::Context::default();
    // The panels' open states from the saved session (a memory that does not read is
    // dropped: the panels start closed, as on a first run), then the fonts.
    let memory = state
        .session
        .panels
        .take()
        .and_then(|text| ron::from_str::<egui::Memory>(&text).ok());
    fonts::start(&ctx, memory);
    let mut app = App {
        state,
        ctx,
        options,
        open: None,
        frames: 0,
        last: Instant::now(),
        screenshot: Arc::new(Mutex::new(None)),
        screenshot_asked: false,
        window_shot: Arc::new(Mutex::new(None)),
        error: None,
        times: FrameTimes::default(),
        repaint_at: None,
        logical_size: [0, 0],
        gamepads: crate::viewer::state::gamepad::Gamepads::new(),
        fullscreen: false,
        was_busy: false,
        plot_picture: None,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| anyhow!("the window loop failed: {e}"))?;
    if app.options.stats {
        let _ = writeln!(std::io::stderr(), "{}", app.times.summary());
    }
    match app.error {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// The largest window side in physical pixels: egui-wgpu asks the GPU for textures of
/// up to 8192 pixels a side (the depth and MSAA buffers cover the whole window).
const MAX_SURFACE_SIDE: u32 = 8192;

/// Largest HiDPI scale factor accepted from `WINIT_X11_SCALE_FACTOR`.
const MAX_SCALE_FACTOR: f64 = 16.0;

/// winit panics on a `WINIT_X11_SCALE_FACTOR` it cannot read: check it first.
fn check_scale_factor_setting() -> Result<()> {
    let Some(value) = std::env::var_os("WINIT_X11_SCALE_FACTOR") else {
        return Ok(());
    };
    let text = value.to_string_lossy();
    if text == "randr" {
        return Ok(());
    }
    match text.parse::<f64>() {
        Ok(f) if f.is_normal() && f > 0.0 && f <= MAX_SCALE_FACTOR => Ok(()),
        _ => Err(anyhow!(
            "WINIT_X11_SCALE_FACTOR is `{text}`: it must be `randr` or a number above 0 and at most {MAX_SCALE_FACTOR}"
        )),
    }
}

/// The logical window size that fits the largest surface at `scale` (never larger
/// than asked).
fn fitting_size(asked: (u32, u32), scale: f64) -> (f64, f64) {
    let limit = f64::from(MAX_SURFACE_SIDE) / scale.max(1e-3);
    let (w, h) = (f64::from(asked.0), f64::from(asked.1));
    let shrink = (limit / w).min(limit / h).min(1.0);
    ((w * shrink).floor().max(1.0), (h * shrink).floor().max(1.0))
}

/// A physical size clamped to the largest surface, so that a window stretched across
/// several monitors cannot ask the GPU for a texture it refuses.
fn clamp_surface(w: NonZeroU32, h: NonZeroU32) -> (NonZeroU32, NonZeroU32) {
    let clamp = |v: NonZeroU32| v.min(NonZeroU32::MIN.saturating_add(MAX_SURFACE_SIDE - 1));
    (clamp(w), clamp(h))
}

impl App {
    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<()> {
        let attributes = self.attributes(event_loop);
        let window = Arc::new(
            event_loop
                .create_window(attributes)
                .map_err(|e| anyhow!("cannot create the window: {e}"))?,
        );
        let size = window.inner_size();
        if size.width > MAX_SURFACE_SIDE || size.height > MAX_SURFACE_SIDE {
            return Err(anyhow!(
                "the window is {}×{} pixels at scale {}; the GPU surface can be at most {MAX_SURFACE_SIDE} pixels a side: choose a smaller --size",
                size.width,
                size.height,
                window.scale_factor()
            ));
        }
        // A software rasteriser pays for every sample of every pixel: its window's pass has
        // one, and the 3D view chooses its own quality (see `quality`).
        let software = stewart_render::gpu::renders_in_software();
        let samples = if software { 1 } else { SAMPLES };
        let options = egui_wgpu::RendererOptions {
            msaa_samples: samples,
            depth_stencil_format: Some(stewart_render::renderer::DEPTH_FORMAT),
            ..Default::default()
        };
        let mut painter = pollster::block_on(Painter::new(
            self.ctx.clone(),
            egui_wgpu::WgpuConfiguration::default(),
            false,
            options,
        ));
        pollster::block_on(painter.set_window(ViewportId::ROOT, Some(window.clone())))
            .map_err(|e| anyhow!("cannot draw into the window: {e} (install a GPU driver or Mesa's `mesa-vulkan-drivers`)"))?;
        let render_state = painter
            .render_state()
            .ok_or_else(|| anyhow!("no GPU device for the window"))?;
        share_device(&render_state, samples);
        self.state.quality = quality::Quality::new(samples == 1, quality::Policy::from_env());
        self.state.quality.window_clears = true;
        let srgb = render_state.target_format.is_srgb();
        self.state.look.renderer_missing = None;
        let max_side = render_state.device.limits().max_texture_dimension_2d as usize;
        let input = egui_winit::State::new(
            self.ctx.clone(),
            ViewportId::ROOT,
            &window,
            Some(window.scale_factor() as f32),
            None,
            Some(max_side),
        );
        self.open = Some(Open {
            window,
            painter,
            input,
            samples,
            srgb,
        });
        Ok(())
    }

    /// The window's title and size: the size asked, on the primary monitor, within what
    /// the GPU can draw into (a HiDPI scale makes the window larger in pixels than asked in
    /// points).
    fn attributes(&mut self, event_loop: &ActiveEventLoop) -> winit::window::WindowAttributes {
        Window::default_attributes()
            .with_title(self.state.window_title())
            .with_inner_size({
                // A HiDPI scale makes the window larger in pixels than asked in points:
                // keep it within what the GPU can draw into.
                let monitor = event_loop.primary_monitor();
                let scale = monitor.as_ref().map_or(1.0, |m| m.scale_factor());
                let screen = monitor.map(|m| {
                    let s = m.size().to_logical::<f64>(scale);
                    (s.width, s.height)
                });
                let asked = self.options.size.on_screen(screen);
                self.logical_size = [asked.0, asked.1];
                let (w, h) = fitting_size(asked, scale);
                winit::dpi::LogicalSize::new(w, h)
            })
            .with_max_inner_size(winit::dpi::PhysicalSize::new(
                MAX_SURFACE_SIDE,
                MAX_SURFACE_SIDE,
            ))
    }

    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        if self.open.is_none() {
            return;
        }
        let now = Instant::now();
        let frame_start = now;
        let dt = self.time_step(now);
        self.state.advance(dt);
        self.poll_gamepad();
        let Some(open) = self.open.as_mut() else {
            return;
        };
        let raw = open.input.take_egui_input(&open.window);
        let state = &mut self.state;
        if self.options.screenshot.is_some() {
            // A screenshot shows the settled picture, report and workspace included.
            state.wait_for_report();
            state.settle_workspace();
        }
        let mut output = self.ctx.run_ui(raw, |ui| viewer_ui(ui, state));
        // The title follows the scenario (its name, the edit mark, the language).
        let title = state.window_title();
        if open.window.title() != title {
            open.window.set_title(&title);
        }
        if state.quit_asked {
            // Ctrl+Q: as the close button (the link stops first, the session is kept).
            self.state.link.disconnect_now();
            self.save_session();
            event_loop.exit();
            return;
        }
        let state = &mut self.state;
        self.was_busy = state.animating();
        follow_fullscreen(&open.window, state.look.fullscreen, &mut self.fullscreen);
        // Honour egui's own repaint requests (zero: at once; otherwise after the delay).
        self.repaint_at = output
            .viewport_output
            .get(&ViewportId::ROOT)
            .and_then(|v| now.checked_add(v.repaint_delay));
        open.input
            .handle_platform_output(&open.window, std::mem::take(&mut output.platform_output));
        // The plot's curves, drawn into their picture where the plot asks for one.
        if let Some(rs) = open.painter.render_state() {
            plot_picture::draw_wanted(
                &rs,
                &self.ctx,
                &mut self.plot_picture,
                &mut self.state.look.curves_picture,
            );
        }
        let primitives = self
            .ctx
            .tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point);
        let cpu_ms = frame_start.elapsed().as_secs_f64() * 1e3;
        self.frames += 1;
        let (capture, scaled) = self.screen_captures();
        let Some(open) = self.open.as_mut() else {
            return;
        };
        let clear = clear_colour(&self.ctx, open.srgb);
        open.painter.paint_and_update_textures(
            ViewportId::ROOT,
            output.pixels_per_point,
            clear,
            &primitives,
            &mut output.textures_delta,
            capture,
            &open.window,
        );
        let total_ms = frame_start.elapsed().as_secs_f64() * 1e3;
        self.times.cpu.push(cpu_ms);
        self.times.total.push(total_ms);
        self.times.count_drawn(self.state.quality.words_key());
        self.state.quality.record(total_ms);
        self.finish_shots(scaled, event_loop);
    }

    /// The time this frame moves the state by: the time since the last frame (see
    /// `frame_step`), or a fixed 1/60 s in a screenshot run so its image is reproducible.
    fn time_step(&mut self, now: Instant) -> f64 {
        let dt = if self.options.screenshot.is_some() {
            1.0 / 60.0
        } else {
            crate::viewer::state::playback::frame_step(
                (now - self.last).as_secs_f64(),
                self.was_busy,
            )
        };
        self.last = now;
        dt
    }

    /// Read the gamepad, and say in the Motion panel which one it is (or why there is none).
    fn poll_gamepad(&mut self) {
        let pad = self.gamepads.poll();
        let lang = self.state.look.lang;
        self.state.teleop.pad_words = match &pad {
            Some((_, name)) => Some(lang.fmt("motion.gamepad", &[("name", name)])),
            None => self
                .gamepads
                .note
                .as_ref()
                .map(|why| lang.fmt("motion.no_gamepad", &[("why", why)])),
        };
        self.state.teleop.pad = pad.map(|(state, _)| state);
    }

    /// The screenshots this frame asks for: egui's captures of the window at its own
    /// scale, and a scaled shot (its path, scale, and whether it ends a `--screenshot`
    /// run) to render after painting.
    fn screen_captures(&mut self) -> (Vec<egui::ScreenshotCallback>, Option<ScaledShot>) {
        let mut capture = Vec::new();
        let mut scaled = None;
        // A shot shows the full picture: when this frame's 3D view was drawn at a lower
        // quality (moving, on a software rasteriser), the shot waits for the next frame,
        // drawn at full quality.
        let run_shot = self.options.screenshot.is_some()
            && self.frames >= self.options.frames.max(1)
            && !self.screenshot_asked;
        if (run_shot || self.state.shots.window_request.is_some())
            && !self.state.quality.last_was_full()
        {
            self.state.quality.ask_full();
            if let Some(open) = &self.open {
                open.window.request_redraw();
            }
            return (capture, scaled);
        }
        if let Some(path) = &self.options.screenshot
            && self.frames >= self.options.frames.max(1)
            && !self.screenshot_asked
            && self.options.screenshot_scale != ShotScale::One
        {
            self.screenshot_asked = true;
            scaled = Some((path.clone(), self.options.screenshot_scale, true));
        }
        if let Some(path) = &self.options.screenshot
            && self.frames >= self.options.frames.max(1)
            && !self.screenshot_asked
        {
            self.screenshot_asked = true;
            let path = path.clone();
            let slot = Arc::clone(&self.screenshot);
            capture.push(egui::ScreenshotCallback::new(move |image| {
                let result = save_png(&path, &image);
                if let Ok(mut s) = slot.lock() {
                    *s = Some(result);
                }
            }));
        }
        if let Some((path, scale)) = self.state.shots.window_request.take() {
            if scale != ShotScale::One {
                scaled = Some((path, scale, false));
            } else {
                let slot = Arc::clone(&self.window_shot);
                let lang = self.state.look.lang;
                capture.push(egui::ScreenshotCallback::new(move |image| {
                    let [w, h] = image.size;
                    let status = save_png(&path, &image)
                        .map(|()| {
                            lang.fmt(
                                "shots.saved_window",
                                &[("w", &w), ("h", &h), ("path", &path.display())],
                            )
                        })
                        .map_err(|e| ViewerError::Export(Arc::new(e)));
                    if let Ok(mut s) = slot.lock() {
                        *s = Some(status);
                    }
                }));
            }
        }
        (capture, scaled)
    }

    /// After painting: write the scaled shot asked for, take the window shot's outcome to
    /// the View panel, and end a `--screenshot` run once its image is written (or failed).
    fn finish_shots(&mut self, scaled: Option<ScaledShot>, event_loop: &ActiveEventLoop) {
        if let Some((path, scale, exit)) = scaled {
            let outcome = self.scaled_window_shot(&path, scale);
            if exit {
                // A --screenshot run: done (or failed) once the image is written.
                let result = outcome.map(|_| ()).map_err(anyhow::Error::from);
                if let Ok(mut s) = self.screenshot.lock() {
                    *s = Some(result);
                }
            } else {
                self.state.shots.say(Some(outcome));
            }
        }
        if let Some(status) = self.window_shot.lock().ok().and_then(|mut s| s.take()) {
            self.state.shots.say(Some(status));
        }
        let done = self.screenshot.lock().ok().and_then(|mut s| s.take());
        if let Some(result) = done {
            if let Err(e) = result {
                self.error = Some(e);
            }
            event_loop.exit();
        }
    }

    /// Remember the scenario, look, panels and window size for the next run (unless this
    /// run keeps no session or *Reset to defaults* was pressed).
    fn save_session(&self) {
        let session = &self.state.session;
        let (Some(folder), false) = (&session.folder, session.forgotten) else {
            return;
        };
        let panels = self.ctx.memory(|m| ron::to_string(m).ok());
        let mut saved = crate::viewer::state::session::Session::capture(
            self.state.scenario(),
            &session.origin,
            &self.state.look,
            self.logical_size,
            panels,
        );
        saved.recent = (self.state.files.recent.iter())
            .map(|p| p.display().to_string())
            .collect();
        saved.export = Some(self.state.exports.form.clone());
        if let Err(e) = crate::viewer::state::session::save(folder, &saved) {
            let _ = writeln!(std::io::stderr(), "viewer: the session was not saved: {e}");
        }
    }

    /// The whole window at `scale` (2×, 4K): the UI laid out again in the same points at
    /// that pixel density and drawn off screen (see [`crate::viewer::window::window_shot`]).
    fn scaled_window_shot(
        &mut self,
        path: &std::path::Path,
        scale: ShotScale,
    ) -> Result<String, ViewerError> {
        let Some(open) = self.open.as_ref() else {
            return Err(ViewerError::WindowGone);
        };
        let Some(rs) = open.painter.render_state() else {
            return Err(ViewerError::NoGpuDevice);
        };
        let native = open.window.scale_factor() as f32;
        let k = window_shot::factor(scale, open.window.inner_size().width);
        let rect = self.ctx.content_rect();
        let mut raw = egui::RawInput {
            screen_rect: Some(rect),
            ..egui::RawInput::default()
        };
        raw.viewports.insert(
            ViewportId::ROOT,
            egui::ViewportInfo {
                native_pixels_per_point: Some(native * k),
                ..egui::ViewportInfo::default()
            },
        );
        let state = &mut self.state;
        state.quality.ask_full();
        let mut output = self.ctx.run_ui(raw, |ui| viewer_ui(ui, state));
        // The title follows the scenario (its name, the edit mark, the language).
        let title = state.window_title();
        if open.window.title() != title {
            open.window.set_title(&title);
        }
        let ppp = output.pixels_per_point;
        let primitives = self.ctx.tessellate(std::mem::take(&mut output.shapes), ppp);
        let size = [
            (rect.width() * ppp).round() as u32,
            (rect.height() * ppp).round() as u32,
        ];
        let clear = clear_colour(&self.ctx, open.srgb);
        let image = window_shot::render(
            &rs,
            open.samples,
            &primitives,
            &mut output.textures_delta,
            size,
            ppp,
            clear,
        );
        {
            let mut renderer = rs.renderer.write();
            for id in &output.textures_delta.free {
                renderer.free_texture(id);
            }
        }
        // Applied (or, when the image could not be drawn, superseded by the next frame's).
        output.textures_delta.clear();
        // The next frame is drawn at the window's own density again.
        if let Some(open) = &self.open {
            open.window.request_redraw();
        }
        let image = image?;
        let [w, h] = image.size;
        save_png(path, &image).map_err(|e| ViewerError::Export(Arc::new(e)))?;
        Ok(self.state.look.lang.fmt(
            "shots.saved_window",
            &[("w", &w), ("h", &h), ("path", &path.display())],
        ))
    }

    fn busy(&self) -> bool {
        self.state.animating()
            || self.state.quality.wants_full_frame()
            || (self.options.screenshot.is_some() && self.error.is_none())
    }
}

/// The colour the window is cleared to: the panels' own (they draw no fill of their
/// own: on a software rasteriser each large fill costs milliseconds), linear on a
/// surface that encodes sRGB itself.
fn clear_colour(ctx: &egui::Context, srgb: bool) -> [f32; 4] {
    let fill = ctx.global_style().visuals.panel_fill;
    let gamma = [fill.r(), fill.g(), fill.b()].map(|c| f32::from(c) / 255.0);
    let colour = [gamma[0], gamma[1], gamma[2], 1.0];
    if srgb {
        stewart_render::theme::linear(colour)
    } else {
        colour
    }
}

fn save_png(path: &std::path::Path, image: &egui::ColorImage) -> Result<()> {
    let [w, h] = image.size;
    let bytes: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
    let mut png = Vec::new();
    image::ImageEncoder::write_image(
        image::codecs::png::PngEncoder::new(&mut png),
        &bytes,
        w as u32,
        h as u32,
        image::ExtendedColorType::Rgba8,
    )
    .map_err(|e| anyhow!("cannot encode the screenshot: {e}"))?;
    crate::output::write_atomically(path, &png)
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.open.is_none()
            && let Err(e) = self.open(event_loop)
        {
            self.error = Some(e);
            event_loop.exit();
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(open) = self.open.as_mut() else {
            return;
        };
        let response = open.input.on_window_event(&open.window, &event);
        match event {
            WindowEvent::CloseRequested => {
                // The stream to hardware stops first: e-stop, home or hold, disarmed.
                self.state.link.disconnect_now();
                self.save_session();
                event_loop.exit();
            }
            WindowEvent::Resized(size) => {
                let logical = size.to_logical::<f64>(open.window.scale_factor());
                self.logical_size = [logical.width.round() as u32, logical.height.round() as u32];
                // Minimised windows have a zero size: keep the old surface until they return.
                if let (Some(w), Some(h)) =
                    (NonZeroU32::new(size.width), NonZeroU32::new(size.height))
                {
                    let (w, h) = clamp_surface(w, h);
                    open.painter.on_window_resized(ViewportId::ROOT, w, h);
                }
            }
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            _ => {}
        }
        if response.repaint
            && let Some(open) = &self.open
        {
            open.window.request_redraw();
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        // Ctrl-C, SIGTERM or SIGHUP close the window as its close button does: the link
        // stops first and the session is saved.
        if crate::interrupt::requested() {
            self.state.link.disconnect_now();
            self.save_session();
            event_loop.exit();
            return;
        }
        let Some(open) = &self.open else {
            event_loop.set_control_flow(ControlFlow::Wait);
            return;
        };
        let now = Instant::now();
        // Idle, the loop still looks at the stop flag four times a second.
        let watch = now + std::time::Duration::from_millis(250);
        let due = self.repaint_at.is_some_and(|at| at <= now);
        if self.busy() || due {
            self.repaint_at = None;
            open.window.request_redraw();
            event_loop.set_control_flow(ControlFlow::Wait);
        } else {
            event_loop.set_control_flow(ControlFlow::WaitUntil(
                self.repaint_at.map_or(watch, |at| at.min(watch)),
            ));
        }
    }
}

/// The window made full screen, or not, when the look `wanted` it otherwise than it is
/// (`shown`, updated).
fn follow_fullscreen(window: &Window, wanted: bool, shown: &mut bool) {
    if wanted != *shown {
        *shown = wanted;
        window.set_fullscreen(wanted.then_some(winit::window::Fullscreen::Borderless(None)));
    }
}

/// The window's device made the process's one (shots and exports render on it too), and
/// the 3D view's renderer on it for the window's format and `samples`.
fn share_device(render_state: &egui_wgpu::RenderState, samples: u32) {
    // Shots and exports render on this device too: one device per process.
    stewart_render::Gpu::adopt(stewart_render::Gpu {
        instance: render_state.instance.clone(),
        adapter: render_state.adapter.clone(),
        device: render_state.device.clone(),
        queue: render_state.queue.clone(),
    });
    let renderer =
        stewart_render::Renderer::new(&render_state.device, render_state.target_format, samples);
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(callback::SceneResources::new(
            &render_state.device,
            renderer,
        ));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_fit_the_largest_surface_at_any_scale() {
        assert_eq!(fitting_size((1280, 720), 1.0), (1280.0, 720.0));
        let (w, h) = fitting_size((3000, 720), 3.0);
        assert!(w * 3.0 <= 8192.0 && h * 3.0 <= 8192.0, "{w}×{h}");
        assert!(
            (w / h - 3000.0 / 720.0).abs() < 0.01,
            "aspect kept: {w}×{h}"
        );
        let n = |v| NonZeroU32::new(v).unwrap_or(NonZeroU32::MIN);
        assert_eq!(clamp_surface(n(9000), n(100)), (n(8192), n(100)));
    }
}
