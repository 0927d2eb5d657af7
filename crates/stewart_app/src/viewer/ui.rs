//! The panels: each a function of the viewer state.

use egui::{Color32, RichText};
use egui_plot::{HLine, Legend, Line, LineStyle, Plot, PlotPoints, VLine};
use stewart_kinematics::scene::LegStatus;
use stewart_kinematics::{Angle, Layout, Scenario};
use stewart_render::{DrawList, Overlays};

use super::state::{MotionMode, ViewerState};
use super::view3d::SceneCallback;
use crate::export::plot::LEG_COLOURS;

/// Colours of the plot's legs, as egui colours.
fn leg_colour(i: usize) -> Color32 {
    Color32::from_hex(LEG_COLOURS[i]).unwrap_or(Color32::GRAY)
}

/// The whole window.
pub fn viewer_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    let visuals = if state.light_theme {
        egui::Visuals::light()
    } else {
        egui::Visuals::dark()
    };
    if ui.ctx().global_style().visuals != visuals {
        ui.ctx().set_visuals(visuals);
    }
    shortcuts(ui, state);
    egui::Panel::left("controls")
        .resizable(true)
        .default_size(290.0)
        .show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| {
                scenario_ui(ui, state);
                ui.separator();
                geometry_ui(ui, state);
                ui.separator();
                motion_ui(ui, state);
                ui.separator();
                playback_ui(ui, state);
                ui.separator();
                legs_ui(ui, state);
                ui.separator();
                diagnostics_ui(ui, state);
            });
        });
    egui::Panel::bottom("plot")
        .resizable(true)
        .default_size(220.0)
        .show(ui, |ui| plot_ui(ui, state));
    egui::CentralPanel::default().show(ui, |ui| view_ui(ui, state));
}

/// Space: play/pause; ←/→: step; Home: back to the start.
fn shortcuts(ui: &mut egui::Ui, state: &mut ViewerState) {
    if ui.ctx().text_edit_focused() {
        return;
    }
    let (space, left, right, home) = ui.input(|i| {
        (
            i.key_pressed(egui::Key::Space),
            i.key_pressed(egui::Key::ArrowLeft),
            i.key_pressed(egui::Key::ArrowRight),
            i.key_pressed(egui::Key::Home),
        )
    });
    if space {
        state.playing = !state.playing;
        state.mode = MotionMode::Trajectory;
    }
    if left {
        state.step(-1.0);
    }
    if right {
        state.step(1.0);
    }
    if home {
        state.time = 0.0;
    }
}

fn diagnostics_ui(ui: &mut egui::Ui, state: &ViewerState) {
    ui.heading("Diagnostics");
    let Some(report) = &state.report else { return };
    if report.architecture.singular {
        ui.label(
            RichText::new(report.architecture.explanation()).color(Color32::from_rgb(220, 40, 40)),
        );
    }
    if report.findings.is_empty() {
        ui.label("No problem found along the trajectory.");
    } else {
        ui.label(format!(
            "{} problem(s) along the trajectory:",
            report.findings.len()
        ));
        for f in report.findings.iter().take(12) {
            ui.label(RichText::new(format!("• {f}")).small());
        }
    }
}

fn scenario_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Scenario");
    let current = state.scenario.name.clone();
    egui::ComboBox::from_label("Preset")
        .selected_text(&current)
        .show_ui(ui, |ui| {
            for name in stewart_kinematics::scenario::presets::names() {
                if ui.selectable_label(current == name, name).clicked()
                    && let Ok(s) = Scenario::preset(name)
                {
                    *state = ViewerState {
                        light_theme: state.light_theme,
                        ..ViewerState::new(s)
                    };
                }
            }
        });
    ui.checkbox(&mut state.light_theme, "Presentation theme (light)");
}

fn geometry_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    egui::CollapsingHeader::new("Geometry")
        .default_open(false)
        .show(ui, |ui| {
            let mut p = state.scenario.geometry.params().clone();
            let mut changed = false;
            changed |= ui
                .add(egui::Slider::new(&mut p.base_radius, 0.2..=3.0).text("base radius (m)"))
                .changed();
            changed |= ui
                .add(
                    egui::Slider::new(&mut p.platform_radius, 0.1..=3.0)
                        .text("platform radius (m)"),
                )
                .changed();
            changed |= ui
                .add(egui::Slider::new(&mut p.home_height, 0.1..=3.0).text("home height (m)"))
                .changed();
            if let Some(min) = p.stroke.min.as_mut() {
                changed |= ui
                    .add(egui::Slider::new(min, 0.05..=3.0).text("leg min (m)"))
                    .changed();
            }
            if let Some(max) = p.stroke.max.as_mut() {
                changed |= ui
                    .add(egui::Slider::new(max, 0.05..=4.0).text("leg max (m)"))
                    .changed();
            }
            ui.label("Layout (rewrites the joint angles):");
            ui.horizontal(|ui| {
                if ui.button("Staggered 30°").clicked() {
                    (p.base_angles, p.platform_angles) = Layout::seed().angles();
                    changed = true;
                }
                for separation in [10.0, 20.0, 40.0] {
                    if ui.button(format!("Paired {separation}°")).clicked() {
                        (p.base_angles, p.platform_angles) = Layout::paired(separation).angles();
                        changed = true;
                    }
                }
            });
            if changed {
                state.set_geometry(p);
            }
            if let Some(e) = &state.geometry_error {
                ui.label(
                    RichText::new(format!("Not applied: {e}"))
                        .color(Color32::from_rgb(220, 40, 40)),
                );
            }
        });
}

fn motion_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Motion");
    ui.horizontal(|ui| {
        ui.selectable_value(&mut state.mode, MotionMode::Trajectory, "Trajectory");
        ui.selectable_value(&mut state.mode, MotionMode::Manual, "Manual pose");
    });
    if state.mode == MotionMode::Manual {
        let h = state.scenario.geometry.home_height();
        let p = &mut state.manual;
        ui.add(egui::Slider::new(&mut p.position.x, -0.3..=0.3).text("x (m)"));
        ui.add(egui::Slider::new(&mut p.position.y, -0.3..=0.3).text("y (m)"));
        ui.add(egui::Slider::new(&mut p.position.z, 0.5 * h..=1.5 * h).text("z (m)"));
        for (angle, label, range) in [
            (&mut p.roll, "roll (°)", 30.0),
            (&mut p.pitch, "pitch (°)", 30.0),
            (&mut p.yaw, "yaw (°)", 45.0),
        ] {
            let mut deg = angle.degrees();
            if ui
                .add(egui::Slider::new(&mut deg, -range..=range).text(label))
                .changed()
            {
                *angle = Angle::from_degrees(deg);
            }
        }
        if ui.button("Home").clicked() {
            state.manual = state.scenario.geometry.home_pose();
        }
    }
}

fn playback_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Playback");
    ui.horizontal(|ui| {
        let label = if state.playing { "Pause" } else { "Play" };
        if ui.button(label).clicked() {
            state.playing = !state.playing;
            state.mode = MotionMode::Trajectory;
        }
        if ui.button("Step back").clicked() {
            state.step(-1.0);
        }
        if ui.button("Step").clicked() {
            state.step(1.0);
        }
        ui.checkbox(&mut state.looping, "Loop");
    });
    let duration = state.duration();
    ui.add(egui::Slider::new(&mut state.time, 0.0..=duration).text("time (s)"));
    ui.add(
        egui::Slider::new(&mut state.speed, 0.1..=4.0)
            .logarithmic(true)
            .text("speed (×)"),
    );
}

fn legs_ui(ui: &mut egui::Ui, state: &ViewerState) {
    ui.heading("Legs");
    let frame = state
        .scenario
        .geometry
        .scene_frame(&state.pose(), Vec::new());
    for (i, leg) in frame.legs.iter().enumerate() {
        let (colour, note) = match leg.status {
            LegStatus::Normal => (Color32::from_rgb(70, 160, 90), ""),
            LegStatus::NearLimit => (Color32::from_rgb(230, 150, 20), " near limit"),
            LegStatus::OverLimit => (Color32::from_rgb(220, 40, 40), " OVER STROKE"),
        };
        ui.horizontal(|ui| {
            ui.label(
                RichText::new(format!("L{}", i + 1))
                    .color(leg_colour(i))
                    .strong(),
            );
            ui.label(format!("{:.4} m", leg.length));
            if let Some(u) = leg.stroke_usage {
                ui.add(
                    egui::ProgressBar::new(u.clamp(0.0, 1.0) as f32)
                        .desired_width(90.0)
                        .fill(colour)
                        .text(format!("{:.0}%{note}", 100.0 * u)),
                );
            }
        });
    }
    let c = state.scenario.geometry.conditioning(&state.pose());
    match c.condition_number {
        Some(k) => ui.label(format!("Condition number {k:.2}")),
        None => ui.label(
            RichText::new("Singular pose: the legs cannot control the platform in one direction")
                .color(Color32::from_rgb(220, 40, 40)),
        ),
    };
}

fn plot_ui(ui: &mut egui::Ui, state: &ViewerState) {
    let (times, lengths) = &state.samples;
    let stroke = state.scenario.geometry.stroke();
    Plot::new("leg lengths")
        .legend(Legend::default())
        .x_axis_label("time (s)")
        .y_axis_label("leg length (m)")
        .show(ui, |plot| {
            for leg in 0..6 {
                let points: PlotPoints = times
                    .iter()
                    .zip(lengths)
                    .map(|(t, l)| [*t, l[leg]])
                    .collect();
                plot.line(Line::new(format!("L{}", leg + 1), points).color(leg_colour(leg)));
            }
            for (name, limit) in [("min", stroke.min), ("max", stroke.max)] {
                if let Some(v) = limit {
                    plot.hline(
                        HLine::new(format!("L{name}"), v)
                            .style(LineStyle::dashed_loose())
                            .color(Color32::GRAY),
                    );
                }
            }
            if state.mode == MotionMode::Trajectory {
                let marker = if state.light_theme {
                    Color32::BLACK
                } else {
                    Color32::WHITE
                };
                plot.vline(VLine::new("now", state.time).color(marker));
            }
        });
}

fn view_ui(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.horizontal(|ui| {
        for (label, az, el) in [
            ("Iso", 135.0, 20.0),
            ("Front", 0.0, 0.0),
            ("Side", 90.0, 0.0),
            ("Top", 0.0, 89.5),
        ] {
            if ui.button(label).clicked() {
                state.look_from(az, el);
            }
        }
        if ui.button("Reset view").clicked() {
            state.look_from(135.0, 20.0);
        }
    });
    let rect = ui.available_rect_before_wrap();
    let response = ui.allocate_rect(rect, egui::Sense::click_and_drag());
    if response.dragged_by(egui::PointerButton::Primary) {
        let d = response.drag_delta();
        state.camera.orbit(-0.4 * d.x, 0.4 * d.y);
    }
    if response.dragged_by(egui::PointerButton::Secondary)
        || response.dragged_by(egui::PointerButton::Middle)
    {
        let d = response.drag_delta();
        let scale = state.camera.distance * 0.0015;
        state.camera.pan(-d.x * scale, d.y * scale);
    }
    if response.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            state.camera.zoom((-scroll * 0.002).exp());
        }
    }
    let theme = state.theme();
    let bg = theme.background.map(|c| (c * 255.0) as u8);
    ui.painter()
        .rect_filled(rect, 0.0, Color32::from_rgb(bg[0], bg[1], bg[2]));
    let path = Vec::new();
    let frame = state.scenario.geometry.scene_frame(&state.pose(), path);
    let list = DrawList::build(&frame, &theme, &Overlays::default());
    let aspect = rect.width() / rect.height().max(1.0);
    ui.painter().add(egui_wgpu::Callback::new_paint_callback(
        rect,
        SceneCallback {
            list,
            camera: state.camera,
            theme,
            aspect,
        },
    ));
}
