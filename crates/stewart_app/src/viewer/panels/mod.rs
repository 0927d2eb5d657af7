//! The panels: each a function of only the parts of the viewer it edits, returning what it
//! asks of the rest; [`viewer_ui`] lays them out, hands out the parts and does what they
//! ask (this is the one file that names the whole `ViewerState`).

mod appearance;
mod byte_dump;
mod context;
mod cueing;
mod design;
mod diagnostics;
mod dynamics;
mod export;
mod file_dialogs;
mod geometry;
mod help;
mod legs;
mod link;
mod motion;
mod playback;
pub(crate) mod plot;
mod plot_legend;
pub(crate) mod plot_picture;
pub(crate) mod plot_ticks;
mod reach;
mod scenario;
pub(crate) mod side_panel;
mod side_plot;
mod view;
mod widgets;
mod workspace;

use context::PanelContext;

use crate::viewer::state::ViewerState;
use crate::viewer::state::editor::Editor;
use crate::viewer::state::files::Purpose;
use crate::viewer::state::live_link::CommandedFrom;
use crate::viewer::state::look::Look;
use crate::viewer::state::playback::MotionMode;
use crate::viewer::state::teleop;

/// The smallest text the viewer draws, points (body text is 12.5).
pub(crate) const SMALLEST_TEXT: f32 = 11.0;

/// The plot's lowest height, points.
const MIN_PLOT: f32 = 80.0;

/// The plot's height at first, points.
const PLOT_HEIGHT: f32 = 220.0;

/// The side panel's narrowest and widest, points.
const MIN_SIDE: f32 = 260.0;
const MAX_SIDE: f32 = 480.0;

/// The 3D view: its toolbar's requests done, the camera framed for the view's shape, then
/// the scene drawn.
fn view_panel(ui: &mut egui::Ui, state: &mut ViewerState) {
    let (area, action) = view::area(ui, &mut view_parts(state));
    match action {
        Some(view::ViewAction::LookFrom(azimuth, elevation)) => state.look_from(azimuth, elevation),
        Some(view::ViewAction::Fit) => state.fit_camera(state.look.view_aspect),
        Some(view::ViewAction::Screenshot) => state.take_screenshot(),
        None => {}
    }
    state.frame_for_presentation(area.aspect);
    state.follow_geometry(area.aspect);
    let list = state.draw_list(&state.theme());
    let animating = state.animating();
    view::paint(ui, &mut view_parts(state), &area, list, animating);
}

/// The parts the 3D view edits.
fn view_parts(state: &mut ViewerState) -> view::ViewParts<'_> {
    view::ViewParts {
        look: &mut state.look,
        playback: &mut state.playback,
        shots: &mut state.shots,
        exports: &mut state.exports,
        quality: &mut state.quality,
    }
}

/// The export window, and what it asks done.
fn export_window(ctx: &egui::Context, state: &mut ViewerState) {
    // Planned only while the form is shown (open, no export running, a video kind), for
    // the path as typed: its extension decides the format and so the default rate.
    let exports = &state.exports;
    let plan = if exports.open && exports.job.is_none() && exports.form.kind.is_video() {
        let request = state.video_request(std::path::PathBuf::from(exports.form.path.trim()));
        let scenario = state.scenario();
        request
            .plan(scenario)
            .ok()
            .zip(request.frame_count(scenario).ok())
    } else {
        None
    };
    let name = state.scenario().name.clone();
    let asked = export::window(
        ctx,
        export::ExportParts {
            exports: &mut state.exports,
            name: &name,
            duration: state.doc.scenario().motion.sampling.duration(),
            plan,
            lang: state.look.lang,
        },
    );
    match asked {
        Some(export::ExportAction::Browse) => state.choose_file(Purpose::ExportTo),
        Some(export::ExportAction::Export(path)) => state.export_asking(&path),
        None => {}
    }
}

/// What the Scenario panel asked, done.
fn scenario_action(ctx: &egui::Context, state: &mut ViewerState, action: scenario::ScenarioAction) {
    use scenario::ScenarioAction;
    match action {
        ScenarioAction::Undo => {
            state.undo_edit();
        }
        ScenarioAction::Redo => {
            state.redo_edit();
        }
        ScenarioAction::Preset(name) => match stewart_kinematics::Scenario::preset(&name) {
            Ok(s) => {
                state.load_scenario(s, std::path::PathBuf::from("."));
                state.session.origin = format!("preset {name}");
                state.files.status = None;
            }
            Err(e) => state.files.status = Some(Err(e.into())),
        },
        ScenarioAction::OpenPath(path) => state.open_path(&path),
        ScenarioAction::OpenFile(path) => state.open_file(&path),
        ScenarioAction::Save(path) => state.save_file_asking(&path),
        ScenarioAction::Choose(purpose) => state.choose_file(purpose),
        ScenarioAction::Language(lang) => state.set_language(lang),
        ScenarioAction::Reset => {
            state.reset_to_defaults();
            ctx.memory_mut(|m| *m = egui::Memory::default());
        }
    }
}

/// The side panel's sections, top to bottom, each given the parts it edits.
fn controls(ui: &mut egui::Ui, state: &mut ViewerState) {
    let asked = scenario::show(
        ui,
        scenario::ScenarioParts {
            doc: &state.doc,
            files: &mut state.files,
            look: &mut state.look,
            session: &state.session,
        },
    );
    if let Some(action) = asked {
        scenario_action(ui.ctx(), state, action);
    }
    ui.separator();
    geometry::show(ui, &mut state.editor());
    ui.separator();
    let cx = PanelContext::of(state);
    let next_mode = motion::show(
        ui,
        motion::MotionParts {
            doc: &mut state.doc,
            playback: &mut state.playback,
            teleop: &mut state.teleop,
            reach: &mut state.tools.reach,
            assembly_shown: state.tools.assembly.shown,
            assembly_error: state.tools.assembly_error.as_ref(),
            cx: &cx,
        },
    );
    if next_mode {
        state.next_assembly_mode();
    }
    ui.separator();
    playback::show(
        ui,
        &mut state.playback,
        &state.doc.scenario().motion.sampling,
        cx.lang,
    );
    view::drawing(ui, &mut state.look);
    ui.separator();
    if let Some(appearance::AppearanceAction::Browse(part)) =
        appearance::show(ui, &mut state.editor())
    {
        state.choose_file(Purpose::Mesh(part));
    }
    ui.separator();
    legs::show(ui, state.doc.scenario(), &state.pose(), &state.look);
    ui.separator();
    if let Some(time) = diagnostics::show(ui, &mut state.editor()) {
        let duration = state.duration();
        state.playback.pause_at(time, duration);
    }
    tool_sections(ui, state);
}

/// The side panel's analysis and hardware sections: design, workspace, reach, the link,
/// cueing, dynamics.
fn tool_sections(ui: &mut egui::Ui, state: &mut ViewerState) {
    let cx = PanelContext::of(state);
    design::show(ui, &mut state.tools.design, &mut state.doc, &cx);
    ui.separator();
    // The design may have changed the platform: the pose shown is read again.
    let cx = PanelContext::of(state);
    workspace::show(ui, &mut state.tools.workspace, state.doc.scenario(), &cx);
    reach::show(ui, &cx, || state.orientation_reach());
    ui.separator();
    let connect = link::show(
        ui,
        &mut state.link,
        &mut state.doc,
        &mut state.link_error,
        &cx,
    );
    if connect {
        state.connect_link();
    }
    ui.separator();
    let mut editor = Editor::new(&mut state.doc, &mut state.playback, cx.lang, cx.expand);
    if cueing::show(
        ui,
        &mut editor,
        cx.now,
        state.link.cue(),
        &mut state.tools.omct,
    ) {
        state.choose_file(Purpose::Open);
    }
    ui.separator();
    let pose = state.pose();
    let mut editor = Editor::new(&mut state.doc, &mut state.playback, cx.lang, cx.expand);
    dynamics::show(ui, &mut editor, &pose, &mut state.tools.modes);
}

/// The plot's panel at the bottom, sized for the window's `height` and the mode: at most
/// two fifths of the window, a third in presentation mode (the height from before kept to
/// give back when it ends).
fn plot_panel(height: f32, frame: egui::Frame, look: &mut Look) -> egui::Panel {
    let mut plot_panel = egui::Panel::bottom("plot")
        .frame(frame)
        .resizable(true)
        .default_size(if look.presentation {
            (height / 4.0).max(MIN_PLOT)
        } else {
            PLOT_HEIGHT
        });
    if look.presentation {
        // The height from before, taken before this frame's plot (a third at most) is
        // drawn (started in presentation mode: the default height).
        if look.plot_height_before_presentation.is_none() {
            let before = look.plot_height;
            look.plot_height_before_presentation = Some(if before >= MIN_PLOT {
                before
            } else {
                PLOT_HEIGHT
            });
        }
        plot_panel = plot_panel.size_range(MIN_PLOT..=(height / 3.0).max(MIN_PLOT));
    } else {
        // Never more than two fifths of the window: in a short window the 3D view keeps
        // the larger share.
        plot_panel = plot_panel.size_range(MIN_PLOT..=(0.4 * height).max(MIN_PLOT));
        if let Some(before) = look.plot_height_to_restore.take() {
            plot_panel =
                plot_panel.exact_size(before.clamp(MIN_PLOT, (0.4 * height).max(MIN_PLOT)));
        }
    }
    plot_panel
}

/// The file dialogs, and what they ask done.
fn file_dialogs(ctx: &egui::Context, state: &mut ViewerState) {
    let lang = state.look.lang;
    let kind = state.doc.scenario().geometry.actuator().kind();
    for action in file_dialogs::show(ctx, &mut state.files, kind, lang) {
        match action {
            file_dialogs::FileAction::Open(path) => state.open_path(&path),
            file_dialogs::FileAction::SaveAsking(path) => state.save_file_asking(&path),
            file_dialogs::FileAction::Save(path) => state.save_file(&path),
            file_dialogs::FileAction::ExportTo(path) => {
                state.exports.form.path = path.display().to_string();
            }
            file_dialogs::FileAction::Export(path) => state.start_export(path),
            file_dialogs::FileAction::Mesh(part, path) => state.attach_mesh(part, &path),
        }
    }
}

/// The whole window.
pub fn viewer_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    style(ui.ctx(), state);
    shortcuts(ui, state);
    if !ui.ctx().text_edit_focused() {
        teleoperate(ui, state);
    }
    state.poll();
    let unfilled = |frame: egui::Frame| {
        if state.quality.window_clears {
            frame.fill(egui::Color32::TRANSPARENT)
        } else {
            frame
        }
    };
    let (side_frame, central_frame) = (
        unfilled(egui::Frame::side_top_panel(ui.style())),
        unfilled(egui::Frame::central_panel(ui.style())),
    );
    if !state.look.presentation {
        // Capped: a long status line wraps instead of widening the panel (the width is
        // remembered between runs, so it only ever grew).
        let widest = (0.4 * ui.ctx().content_rect().width()).clamp(MIN_SIDE, MAX_SIDE);
        state.look.side_width = side_panel::show(ui, side_frame, MIN_SIDE..=widest, |ui| {
            egui::ScrollArea::vertical()
                .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
                .show(ui, |ui| controls(ui, state));
        });
    }
    // The plot's top edge is a splitter: drag it to give the plot more or less height (at
    // most two fifths of the window). In presentation mode it takes at most a third (G
    // hides it); leaving gives the height from before back.
    let plot_panel = plot_panel(
        ui.ctx().content_rect().height(),
        side_frame,
        &mut state.look,
    );
    let plot_hidden = state.look.presentation && state.look.plot_hidden;
    let plot_rect = if plot_hidden {
        state.look.plot_placement = None;
        egui::Rect::NOTHING
    } else {
        let shows = plot::Shows {
            rolling: state.plot_rolls(),
            commanded: state.link.commanded_pose().is_some(),
            background: !state.quality.software,
            pictured: state.quality.software,
        };
        let shown = plot_panel.show(ui, |ui| {
            plot::show(ui, &state.doc, &mut state.playback, &mut state.look, shows)
        });
        state.look.plot_placement = Some(shown.inner);
        shown.response.rect
    };
    state.look.plot_height = if plot_hidden { 0.0 } else { plot_rect.height() };
    egui::CentralPanel::default()
        .frame(central_frame)
        .show(ui, |ui| view_panel(ui, state));
    if !plot_hidden {
        splitter_grip(ui, plot_rect);
    }
    export_window(ui.ctx(), state);
    help::show(ui.ctx(), state.look.lang, &mut state.look.help);
    file_dialogs(ui.ctx(), state);
    if state.link.connected() {
        link_badge(ui.ctx(), state);
    }
}

/// A grip drawn on the plot's top edge, so that it is seen to drag.
fn splitter_grip(ui: &egui::Ui, plot: egui::Rect) {
    let stroke = ui.visuals().widgets.inactive.fg_stroke;
    let y = plot.top() - ui.spacing().item_spacing.y;
    let x = plot.center().x;
    for dy in [-2.0, 2.0] {
        ui.painter().hline(
            egui::Rangef::new(x - 14.0, x + 14.0),
            y + dy,
            egui::Stroke::new(1.5, stroke.color),
        );
    }
}

/// While a link streams, its state and an e-stop stay on screen whatever panels show
/// (presentation mode hides the controls), with what the 3D view shows. The badge is as
/// wide as its longest state in the language shown, and its words never wrap: a safety
/// display reads at a glance.
fn link_badge(ctx: &egui::Context, state: &mut ViewerState) {
    let Some(status) = state.link.sender_status() else {
        return;
    };
    let t = state.look.lang;
    let big = |text: &str| {
        egui::RichText::new(text)
            .size(20.0)
            .strong()
            .color(egui::Color32::WHITE)
    };
    egui::Area::new(egui::Id::unique("link-badge"))
        // The 3D view's bottom right, above the plot: at the top it hid the toolbar's end.
        .anchor(
            egui::Align2::RIGHT_BOTTOM,
            egui::vec2(-12.0, -(state.look.plot_height + 12.0)),
        )
        .show(ctx, |ui| {
            egui::Frame::new()
                .fill(link::state_colour(status.state))
                .inner_margin(8.0)
                .corner_radius(4.0)
                .show(ui, |ui| {
                    ui.set_min_width(link::longest_state_width(ui, t, 20.0));
                    ui.add(egui::Label::new(big(link::state_words(t, status.state))).extend());
                    let shown = if state.link.commanded_pose().is_some() {
                        let measured = state.link.measured_pose().is_some();
                        Some(t.tr(match state.link.commanded_from {
                            Some(CommandedFrom::Asked) => "link.view_cue_asked",
                            Some(CommandedFrom::LastGood) => "link.view_last_good",
                            _ if measured => "link.view_commanded_measured",
                            _ => "link.view_commanded",
                        }))
                    } else {
                        None
                    };
                    if let Some(words) = shown {
                        ui.add(
                            egui::Label::new(
                                egui::RichText::new(words).color(egui::Color32::WHITE),
                            )
                            .extend(),
                        );
                    }
                    let stop = egui::Button::new(
                        egui::RichText::new(t.tr("link.estop"))
                            .strong()
                            .color(egui::Color32::WHITE),
                    )
                    .fill(egui::Color32::from_rgb(200, 20, 20))
                    .wrap_mode(egui::TextWrapMode::Extend);
                    if ui.add(stop).on_hover_text(t.tr("link.estop_tip")).clicked() {
                        state.link.estop();
                    }
                });
        });
}

/// Manual mode: the keys held and the gamepad move the pose (see [`crate::viewer::state::teleop`]).
fn teleoperate(ui: &mut egui::Ui, state: &mut ViewerState) {
    if state.playback.mode != MotionMode::Manual {
        state.teleop.moving = false;
        return;
    }
    let (keys, dt) = ui.input(|i| {
        (
            teleop::from_keys(|k| i.key_down(k), i.modifiers.shift),
            f64::from(i.stable_dt).min(0.1),
        )
    });
    let pad = state
        .teleop
        .pad
        .as_ref()
        .map(teleop::from_pad)
        .unwrap_or_default();
    state.teleoperate(keys.plus(pad), dt);
    if state.teleop.moving {
        ui.ctx().request_repaint();
    }
}

/// Light or dark visuals, and large text in presentation mode.
fn style(ctx: &egui::Context, state: &ViewerState) {
    let visuals = if state.look.is_light() {
        egui::Visuals::light()
    } else {
        egui::Visuals::dark()
    };
    let mut style = egui::Style {
        visuals,
        ..egui::Style::default()
    };
    // A scroll bar that is always drawn, full width: the panels below the fold can be seen
    // to be there.
    style.spacing.scroll = egui::style::ScrollStyle::solid();
    // Notes and descriptions in small text stay readable (egui's 9 pt read as about 8 px).
    if let Some(small) = style.text_styles.get_mut(&egui::TextStyle::Small) {
        small.size = small.size.max(SMALLEST_TEXT);
    }
    if state.look.presentation {
        for font in style.text_styles.values_mut() {
            font.size *= crate::viewer::state::look::PRESENTATION_TEXT_SCALE;
        }
    }
    if *ctx.global_style() != style {
        ctx.set_global_style(style);
    }
}

/// Esc: while a link is connected, its e-stop and nothing else; otherwise it closes the
/// Help window when open, else leaves full screen and presentation mode. Space: play/pause; ←/→: step; Home: back to the start;
/// P or F5: presentation mode (G: the plot hidden or shown there); F11: full screen; F12:
/// screenshot; Ctrl+Z undo, Ctrl+Shift+Z or Ctrl+Y redo; Ctrl+O open, Ctrl+S save,
/// Ctrl+Shift+S save as; Ctrl+Q quit; F1 or ?: the keys (outside text fields, which keep
/// their own). [`help`] lists them for people.
fn shortcuts(ui: &mut egui::Ui, state: &mut ViewerState) {
    let pressed = |key| ui.input(|i| i.key_pressed(key));
    // The e-stop works whatever has the keyboard focus.
    if pressed(egui::Key::Escape) {
        if state.link.connected() {
            state.link.estop();
        } else if state.look.help {
            // The window on top goes first.
            state.look.help = false;
        } else {
            state.look.presentation = false;
            state.look.fullscreen = false;
        }
    }
    if pressed(egui::Key::F11) {
        state.look.fullscreen = !state.look.fullscreen;
    }
    if ui.ctx().text_edit_focused() {
        return;
    }
    // One gesture, one undo step: the step closes once no button is held.
    if !ui.input(|i| i.pointer.any_down()) {
        state.doc.undo.seal();
    }
    file_and_edit_keys(ui, state);
    let pressed = |key| ui.input(|i| i.key_pressed(key));
    if pressed(egui::Key::Space) {
        state.playback.toggle();
    }
    if pressed(egui::Key::ArrowLeft) {
        state.step(-1.0);
    }
    if pressed(egui::Key::ArrowRight) {
        state.step(1.0);
    }
    if pressed(egui::Key::Home) {
        state.playback.time = 0.0;
    }
    if pressed(egui::Key::F12) && !state.shots.busy() {
        state.take_screenshot();
    }
    if pressed(egui::Key::P) || pressed(egui::Key::F5) {
        // The audience sees the view, not the list of keys.
        state.look.help = false;
        state.look.presentation = !state.look.presentation;
    }
    if pressed(egui::Key::G) && state.look.presentation {
        state.look.plot_hidden = !state.look.plot_hidden;
    }
}

/// The keys with Ctrl (⌘): undo and redo, save, save as, open, quit; F1 for help.
fn file_and_edit_keys(ui: &mut egui::Ui, state: &mut ViewerState) {
    let pressed = |key| ui.input(|i| i.key_pressed(key));
    let shift = egui::Modifiers::COMMAND | egui::Modifiers::SHIFT;
    let (redo, undo) = ui.input_mut(|i| {
        let redo = i.consume_key(shift, egui::Key::Z)
            || i.consume_key(egui::Modifiers::COMMAND, egui::Key::Y);
        (redo, i.consume_key(egui::Modifiers::COMMAND, egui::Key::Z))
    });
    let (save_as, save, open, quit) = ui.input_mut(|i| {
        (
            i.consume_key(shift, egui::Key::S),
            i.consume_key(egui::Modifiers::COMMAND, egui::Key::S),
            i.consume_key(egui::Modifiers::COMMAND, egui::Key::O),
            i.consume_key(egui::Modifiers::COMMAND, egui::Key::Q),
        )
    });
    if quit {
        state.quit_asked = true;
    }
    if pressed(egui::Key::F1) || pressed(egui::Key::Questionmark) {
        state.look.help = !state.look.help;
    }
    if save_as {
        state.choose_file(Purpose::SaveScenario);
    } else if save {
        state.save();
    }
    if open {
        state.choose_file(Purpose::Open);
    }
    if redo {
        state.redo_edit();
    }
    if undo {
        state.undo_edit();
    }
}
