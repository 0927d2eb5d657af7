//! The 3D view: standard view buttons, overlays, mouse orbit / pan / zoom toward the
//! cursor, and the scene drawn by the renderer through a paint callback.

use egui::Color32;

use stewart_render::OrbitCamera;

use crate::i18n::Lang;
use crate::viewer::state::exports::Exports;
use crate::viewer::state::look::Look;
use crate::viewer::state::playback::Playback;
use crate::viewer::view3d::callback::SceneCallback;
use crate::viewer::view3d::quality::Quality;
use crate::viewer::view3d::shots::Shots;

/// Standard views: the label's key, azimuth and elevation (MATLAB's `view(az, el)`).
const VIEWS: [(&str, f32, f32); 4] = [
    ("view.iso", 135.0, 20.0),
    ("view.front", 0.0, 0.0),
    ("view.side", 90.0, 0.0),
    ("view.top", 0.0, 89.5),
];

/// The Screenshot menu: what, how large, background; Save (or F12 with these choices).
/// Returns whether *Save* was pressed.
fn screenshot_menu(ui: &mut egui::Ui, shots: &mut Shots, t: Lang) -> bool {
    use crate::viewer::view3d::shots::{ShotKind, ShotScale};
    ui.radio_value(&mut shots.kind, ShotKind::View, t.tr("view.shot_view"));
    ui.radio_value(&mut shots.kind, ShotKind::Window, t.tr("view.shot_window"));
    ui.horizontal(|ui| {
        for (scale, words) in ShotScale::ALL {
            ui.radio_value(&mut shots.scale, scale, words);
        }
    });
    ui.add_enabled_ui(shots.kind == ShotKind::View, |ui| {
        ui.checkbox(&mut shots.transparent, t.tr("view.transparent"));
    });
    let save = ui
        .add_enabled(!shots.busy(), egui::Button::new(t.tr("view.save_png")))
        .on_hover_text(t.tr("view.save_png_tip"))
        .clicked();
    if save {
        ui.close();
    }
    save
}

/// What the 3D view asks of the viewer: each needs more of it than the view holds, so the
/// caller does it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ViewAction {
    /// Look from this azimuth and elevation, degrees.
    LookFrom(f32, f32),
    /// Frame the platform and its motion.
    Fit,
    /// Take a screenshot with the menu's choices.
    Screenshot,
}

/// The parts the 3D view and its toolbar edit.
pub(crate) struct ViewParts<'a> {
    /// Camera, theme, overlays, presentation.
    pub(crate) look: &'a mut Look,
    /// Play and pause; the frames-skipped note.
    pub(crate) playback: &'a mut Playback,
    /// The screenshot menu's choices and status.
    pub(crate) shots: &'a mut Shots,
    /// Whether the export window is open, and its job's progress.
    pub(crate) exports: &'a mut Exports,
    /// How the view is drawn and its frame times.
    pub(crate) quality: &'a mut Quality,
}

/// The toolbar over the view, always in sight: play/pause and export first; the standard
/// views and overlays, or in presentation mode full screen and the way out.
fn toolbar(ui: &mut egui::Ui, parts: &mut ViewParts) -> Option<ViewAction> {
    let t = parts.look.lang;
    let mut action = None;
    // Wrapped: a narrow window keeps every switch reachable.
    ui.horizontal_wrapped(|ui| {
        super::playback::play_button(ui, parts.playback, t);
        if parts.look.presentation {
            presentation_buttons(ui, parts.look);
            return;
        }
        super::export::open_button(ui, parts.exports, t);
        ui.separator();
        for (label, az, el) in VIEWS {
            if ui
                .button(t.tr(label))
                .on_hover_text(t.tr("view.standard_tip"))
                .clicked()
            {
                action = Some(ViewAction::LookFrom(az, el));
            }
        }
        if ui
            .button(t.tr("view.reset"))
            .on_hover_text(t.tr("view.reset_tip"))
            .clicked()
        {
            action = Some(ViewAction::LookFrom(VIEWS[0].1, VIEWS[0].2));
        }
        if ui
            .button(t.tr("view.fit"))
            .on_hover_text(t.tr("view.fit_tip"))
            .clicked()
        {
            action = Some(ViewAction::Fit);
        }
        ui.checkbox(&mut parts.look.show_path, t.tr("view.path"));
        ui.checkbox(&mut parts.look.platform_axes, t.tr("view.platform_axes"));
        ui.checkbox(&mut parts.look.coloured_legs, t.tr("view.leg_colours"))
            .on_hover_text(t.tr("view.leg_colours_tip"));
        ui.checkbox(&mut parts.look.labels, t.tr("view.labels"))
            .on_hover_text(t.tr("view.labels_tip"));
        ui.checkbox(&mut parts.look.readouts, t.tr("view.readouts"))
            .on_hover_text(t.tr("view.readouts_tip"));
        let shots = &mut *parts.shots;
        ui.menu_button(t.tr("view.screenshot"), |ui| {
            if screenshot_menu(ui, shots, t) {
                action = Some(ViewAction::Screenshot);
            }
        })
        .response
        .on_hover_text(t.tr("view.screenshot_tip"));
    });
    if !parts.look.presentation && parts.shots.status.is_some() {
        shot_status(ui, parts.shots, t);
    }
    action
}

/// In presentation mode the toolbar holds only full screen and the way out.
fn presentation_buttons(ui: &mut egui::Ui, look: &mut Look) {
    let t = look.lang;
    let words = if look.fullscreen {
        t.tr("view.leave_fullscreen")
    } else {
        t.tr("view.fullscreen")
    };
    if ui.button(words).on_hover_text("F11").clicked() {
        look.fullscreen = !look.fullscreen;
    }
    if ui
        .button(t.tr("view.leave_presentation"))
        .on_hover_text(t.tr("view.leave_presentation_tip"))
        .clicked()
    {
        look.presentation = false;
    }
}

/// The last screenshot's outcome, over the view below the toolbar (not a line that pushes
/// the view down); a success goes after a few seconds.
fn shot_status(ui: &mut egui::Ui, shots: &Shots, t: Lang) {
    let below = ui.min_rect().left_bottom() + egui::vec2(0.0, 4.0);
    egui::Area::new(ui.scope_id().with("shot said"))
        .fixed_pos(below)
        .order(egui::Order::Foreground)
        .show(ui.ctx(), |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                super::widgets::status(ui, &shots.status, t);
            });
        });
    ui.ctx()
        .request_repaint_after(crate::viewer::view3d::shots::SAID_FOR);
}

/// Where the view is drawn this frame and how wide it is.
pub(crate) struct ViewArea {
    /// The view's rectangle, points.
    pub(crate) rect: egui::Rect,
    /// Width over height.
    pub(crate) aspect: f32,
    /// Whether the camera is being dragged.
    dragged: bool,
}

/// The toolbar and the camera's input: where the view is this frame, and what the toolbar
/// asks (the caller does it, frames the camera for the new aspect, then [`paint`]s).
pub(crate) fn area(ui: &mut egui::Ui, parts: &mut ViewParts) -> (ViewArea, Option<ViewAction>) {
    let action = toolbar(ui, parts);
    let rect = ui.available_rect_before_wrap();
    // The camera's drags start a little inside the view: the splitters of the controls
    // (left) and of the plot (below) take the pointer near their edges.
    let keep_clear =
        ui.style().interaction.resize_grab_radius_side + ui.style().interaction.interact_radius;
    let camera_rect = egui::Rect::from_min_max(
        rect.min + egui::vec2(keep_clear, 0.0),
        rect.max - egui::vec2(0.0, keep_clear),
    );
    let response = ui.allocate_rect(camera_rect, egui::Sense::click_and_drag());
    camera_input(ui, &mut parts.look.camera, &response, rect);
    let aspect = rect.width() / rect.height().max(1.0);
    parts.look.view_aspect = aspect;
    let dragged = response.dragged();
    (
        ViewArea {
            rect,
            aspect,
            dragged,
        },
        action,
    )
}

/// The scene `list` drawn in `area` (or why it cannot be), and the status line.
/// `animating`: whether the viewer moves on its own this frame (playback, a stream).
pub(crate) fn paint(
    ui: &mut egui::Ui,
    parts: &mut ViewParts,
    area: &ViewArea,
    list: stewart_render::DrawList,
    animating: bool,
) {
    let rect = area.rect;
    let t = parts.look.lang;
    let theme = parts.look.theme();
    if let Some(missing) = &parts.look.renderer_missing {
        let bg = theme.background.map(|c| (c * 255.0) as u8);
        ui.painter()
            .rect_filled(rect, 0.0, Color32::from_rgb(bg[0], bg[1], bg[2]));
        // Say why rather than show an empty view.
        ui.painter().text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            t.fmt(
                "view.cannot_draw",
                &[(
                    "why",
                    &if missing.is_empty() {
                        t.tr("view.no_renderer")
                    } else {
                        missing.as_str()
                    },
                )],
            ),
            egui::FontId::proportional(14.0),
            ui.visuals().warn_fg_color,
        );
        status_line(ui, rect, parts);
        return;
    }
    // The view changes from frame to frame: playback, a stream, a drag or the wheel.
    let moving =
        animating || area.dragged || ui.input(|i| i.smooth_scroll_delta != egui::Vec2::ZERO);
    let drawn = parts.quality.choose(moving);
    parts.look.view_px = [
        (rect.width() * ui.ctx().pixels_per_point()).round() as u32,
        (rect.height() * ui.ctx().pixels_per_point()).round() as u32,
    ];
    ui.painter().add(egui_wgpu::Callback::new_paint_callback(
        rect,
        SceneCallback {
            view: ui.scope_id().with("scene"),
            list,
            camera: parts.look.camera.fitted_to(area.aspect),
            theme,
            viewport: (rect.size() * ui.ctx().pixels_per_point()).into(),
            drawn,
        },
    ));
    status_line(ui, rect, parts);
}

/// The view's status line, bottom left, in a place of its own (it never moves the
/// toolbar): the frame times when asked for (Advanced), else the note that frames are
/// skipped. Never in presentation mode.
fn status_line(ui: &mut egui::Ui, rect: egui::Rect, parts: &ViewParts) {
    if parts.look.presentation {
        return;
    }
    let t = parts.look.lang;
    let (text, tip) = if parts.look.frame_times {
        (frame_words(t, parts.quality), "quality.show_tip")
    } else if let Some(rate) = parts.playback.skipping_frames() {
        let words = t.fmt("playback.skipping", &[("fps", &format!("{rate:.0}"))]);
        (words, "playback.skipping_tip")
    } else {
        return;
    };
    let colour = if parts.look.is_light() {
        Color32::from_rgb(150, 60, 0)
    } else {
        ui.visuals().warn_fg_color
    };
    let line = egui::Rect::from_min_max(
        rect.left_bottom() + egui::vec2(10.0, -28.0),
        rect.right_bottom() - egui::vec2(10.0, 6.0),
    );
    // Not selectable: a drag over it still turns the camera.
    let label = egui::Label::new(egui::RichText::new(text).color(colour))
        .selectable(false)
        .truncate();
    let layout = egui::Layout::left_to_right(egui::Align::Center);
    ui.scope_builder(egui::UiBuilder::new().max_rect(line).layout(layout), |ui| {
        ui.add(label).on_hover_text(t.tr(tip));
    });
}

/// The frame-time readout: mean and 95th percentile of the last frames, and how the 3D
/// view is drawn.
fn frame_words(t: Lang, quality: &Quality) -> String {
    let how = t.tr(quality.words_key());
    match quality.frame_times() {
        Some((mean, p95)) => t.fmt(
            "quality.frame_times",
            &[
                ("mean", &format!("{mean:.1}")),
                ("p95", &format!("{p95:.1}")),
                ("how", &how),
            ],
        ),
        None => how.to_owned(),
    }
}

/// The drawing settings (Advanced): the frame-time readout and what it says.
pub(crate) fn drawing(ui: &mut egui::Ui, look: &mut Look) {
    let t = look.lang;
    egui::CollapsingHeader::new(t.tr("quality.advanced"))
        .default_open(look.expand_panels)
        .show(ui, |ui| {
            ui.checkbox(&mut look.frame_times, t.tr("quality.show"))
                .on_hover_text(t.tr("quality.show_tip"));
        });
}

/// Left drag orbits, right or middle drag pans, the wheel zooms toward the cursor.
fn camera_input(
    ui: &egui::Ui,
    camera: &mut OrbitCamera,
    response: &egui::Response,
    rect: egui::Rect,
) {
    if response.dragged_by(egui::PointerButton::Primary) {
        let d = response.drag_delta();
        camera.orbit(-0.4 * d.x, 0.4 * d.y);
    }
    if response.dragged_by(egui::PointerButton::Secondary)
        || response.dragged_by(egui::PointerButton::Middle)
    {
        let d = response.drag_delta();
        let scale = camera.distance * 0.0015;
        camera.pan(-d.x * scale, d.y * scale);
    }
    if let Some(pointer) = response.hover_pos() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            let ndc = glam::Vec2::new(
                2.0 * (pointer.x - rect.left()) / rect.width().max(1.0) - 1.0,
                1.0 - 2.0 * (pointer.y - rect.top()) / rect.height().max(1.0),
            );
            let aspect = rect.width() / rect.height().max(1.0);
            // The view is drawn from the fitted camera, farther away in narrow views: the
            // cursor's offset in the target plane grows by the same ratio.
            let fit = camera.fitted_to(aspect).distance / camera.distance;
            camera.zoom_toward((-scroll * 0.002).exp(), ndc * fit, aspect);
        }
    }
}
