//! Dynamics: the moving mass (`[payload]`: mass, centre of mass, inertia tensor), what the
//! actuators add (`[dynamics]`: stiffness, friction, leg parts), and the natural modes at
//! the pose shown, one of which the 3D view can swing along.

use egui::RichText;
use nalgebra::{Matrix3, Vector3};
use stewart_kinematics::analysis::dynamics::{DynamicsError, dominant};
use stewart_kinematics::analysis::forces::Payload;
use stewart_kinematics::io::settings::{self, Group, Unit};
use stewart_kinematics::{Pose, Scenario};

use super::widgets::{WARNING, edit_error, fitted_slider, setting_slider};
use crate::viewer::state::editor::Editor;
use crate::viewer::tools::mode_view::{ModeView, NoModes, SHOWN_HZ};

/// A payload in proportion to the platform: a solid disc of the platform's size, 50 kg
/// on the seed's 0.6 m platform.
fn proportionate_payload(scenario: &Scenario) -> Option<Payload> {
    let size = scenario.geometry.characteristic_length();
    let mass = (50.0 * (size / 0.6).powi(3)).max(1e-3);
    let (side, axial) = (mass * size * size / 4.0, mass * size * size / 2.0);
    Payload::new(
        mass,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(side, side, axial)),
    )
    .ok()
}

/// The panel, at `pose` (the pose shown), with the mode viewer's settings.
pub(crate) fn show(ui: &mut egui::Ui, ed: &mut Editor, pose: &Pose, view: &mut ModeView) {
    let t = ed.lang;
    egui::CollapsingHeader::new(t.tr("dynamics.heading"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            payload(ui, ed);
            ui.label(RichText::new(t.tr("dynamics.actuators")).strong());
            let targets: Vec<_> = settings::all()
                .iter()
                .filter(|s| s.group == Group::Dynamics)
                .map(|s| s.target)
                .collect();
            for target in targets {
                setting_slider(ui, ed, target);
            }
            edit_error(ui, ed.doc, t, &[Group::Dynamics]);
            ui.separator();
            modes(ui, ed, pose, view);
        });
}

/// The payload's numbers, each edited through the file reader's own validation.
fn payload(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    ui.label(RichText::new(t.tr("dynamics.payload")).strong());
    let Some(p) = ed.scenario().payload else {
        ui.label(RichText::new(t.tr("dynamics.no_payload")).small());
        if ui.button(t.tr("dynamics.add_payload")).clicked() {
            let added = proportionate_payload(ed.scenario());
            ed.edit(Group::Dynamics, |s| {
                s.payload = added;
                Ok(())
            });
        }
        return;
    };
    let mut mass = p.mass;
    let mut com = [p.centre_of_mass.x, p.centre_of_mass.y, p.centre_of_mass.z];
    let i = p.inertia;
    let mut inertia = [
        i[(0, 0)],
        i[(1, 1)],
        i[(2, 2)],
        i[(0, 1)],
        i[(0, 2)],
        i[(1, 2)],
    ];
    let mut changed = false;
    // Each quantity's name above its values, so that the rows fit a narrow panel.
    ui.horizontal_wrapped(|ui| {
        ui.label(t.tr("dynamics.mass"));
        changed |= ui
            .add(
                egui::DragValue::new(&mut mass)
                    .speed(0.01 * p.mass.max(0.01))
                    .suffix(format!(" {}", Unit::Kilogram.symbol())),
            )
            .changed();
    });
    ui.label(t.tr("dynamics.com"));
    let size = ed.scenario().geometry.characteristic_length();
    ui.horizontal_wrapped(|ui| {
        for c in &mut com {
            changed |= ui
                .add(
                    egui::DragValue::new(c)
                        .speed(0.002 * size)
                        .suffix(format!(" {}", Unit::Metre.symbol())),
                )
                .changed();
        }
    });
    ui.label(t.tr("dynamics.inertia"));
    let moments = p.inertia.diagonal().max().max(1e-9);
    changed |= inertia_grid(ui, &mut inertia, moments, t);
    if changed {
        let [ixx, iyy, izz, ixy, ixz, iyz] = inertia;
        let tensor = Matrix3::new(ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz);
        ed.edit(Group::Dynamics, |s| {
            s.payload = Some(Payload::new(mass, Vector3::from(com), tensor)?);
            Ok(())
        });
    }
    if ui.small_button(t.tr("dynamics.remove_payload")).clicked() {
        ed.edit(Group::Dynamics, |s| {
            s.payload = None;
            Ok(())
        });
    }
}

/// The payload's inertia tensor's six entries, dragged at a pace of `moments` (its largest
/// principal moment); whether one changed.
fn inertia_grid(
    ui: &mut egui::Ui,
    inertia: &mut [f64; 6],
    moments: f64,
    t: crate::i18n::Lang,
) -> bool {
    let mut changed = false;
    egui::Grid::new("payload inertia")
        .num_columns(3)
        .show(ui, |ui| {
            for (row, names) in [(0, ["Ixx", "Iyy", "Izz"]), (3, ["Ixy", "Ixz", "Iyz"])] {
                for (k, name) in names.iter().enumerate() {
                    changed |= ui
                        .add(
                            egui::DragValue::new(&mut inertia[row + k])
                                .speed(0.005 * moments)
                                .prefix(format!("{name} ")),
                        )
                        .on_hover_text(t.tr("dynamics.inertia_tip"))
                        .changed();
                }
                ui.end_row();
            }
        });
    changed
}

/// The six modes at the pose shown, and the mode viewer's controls.
fn modes(ui: &mut egui::Ui, ed: &Editor, pose: &Pose, view: &mut ModeView) {
    let t = ed.lang;
    ui.label(RichText::new(t.tr("dynamics.modes")).strong());
    let modes = match ModeView::modes(ed.scenario(), pose) {
        Ok(m) => m,
        Err(why) => {
            let why = match why {
                NoModes::NoPayload => t.tr("dynamics.why_no_payload").to_owned(),
                NoModes::Dynamics(DynamicsError::NoStiffness) => {
                    t.tr("dynamics.why_no_stiffness").to_owned()
                }
                NoModes::Dynamics(DynamicsError::MassMatrixNotPositive) => {
                    t.tr("dynamics.why_not_positive").to_owned()
                }
                NoModes::Dynamics(DynamicsError::Unreachable { servo }) => {
                    t.fmt("dynamics.why_unreachable", &[("servo", &servo)])
                }
                NoModes::Dynamics(DynamicsError::Singular) => {
                    t.tr("dynamics.why_singular").to_owned()
                }
                NoModes::Dynamics(DynamicsError::LegWithoutDirection { leg }) => {
                    t.fmt("dynamics.why_zero_leg", &[("leg", &leg)])
                }
            };
            ui.label(RichText::new(t.fmt("dynamics.no_modes", &[("why", &why)])).color(WARNING));
            view.animate = false;
            return;
        }
    };
    // The chosen mode is one with stiffness (the stiffest always has some).
    if modes.without_stiffness(view.mode.min(5)) {
        view.mode = (0..6).find(|&k| !modes.without_stiffness(k)).unwrap_or(5);
    }
    egui::Grid::new("modes").num_columns(3).show(ui, |ui| {
        for k in 0..6 {
            // A direction without stiffness (a singular pose) has no swing to show.
            let stiff = !modes.without_stiffness(k);
            ui.add_enabled_ui(stiff, |ui| {
                ui.radio_value(&mut view.mode, k, format!("{}", k + 1))
                    .on_disabled_hover_text(t.tr("dynamics.no_stiffness_tip"));
            });
            if stiff {
                let hz = format!("{:.2}", modes.frequencies_hz[k]);
                ui.label(t.fmt("dynamics.frequency", &[("hz", &hz)]));
            } else {
                ui.label(RichText::new(t.tr("dynamics.no_stiffness")).color(WARNING))
                    .on_hover_text(t.tr("dynamics.no_stiffness_tip"));
            }
            let words: Vec<String> = dominant(&modes.modes[k])
                .iter()
                .map(|(axis, c)| format!("{axis} {c:+.2}"))
                .collect();
            ui.label(words.join(", "));
            ui.end_row();
        }
    });
    ui.checkbox(&mut view.animate, t.tr("dynamics.animate"))
        .on_hover_text(t.fmt("dynamics.animate_tip", &[("hz", &SHOWN_HZ)]));
    let mut percent = view.amplitude * 100.0;
    let value = percent;
    let slider = egui::Slider::new(&mut percent, 1.0..=20.0);
    if fitted_slider(ui, t.tr("dynamics.amplitude"), value, slider).changed() {
        view.amplitude = percent / 100.0;
    }
    if view.animate {
        ui.label(RichText::new(t.fmt(
            "dynamics.swinging",
            &[
                ("k", &(view.mode + 1)),
                (
                    "hz",
                    &format!("{:.2}", modes.frequencies_hz[view.mode.min(5)]),
                ),
                ("shown", &SHOWN_HZ),
            ],
        )));
    }
}
