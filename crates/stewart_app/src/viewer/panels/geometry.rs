//! Geometry: radii, home height, the actuator kind (linear legs with their stroke, or
//! rotary servos with horns, rods, range and trims), layout with its separation angles,
//! every joint angle and the pivot.

use stewart_kinematics::io::settings::{
    self, ActuatorKey, ActuatorKind, GeometryKey, Group, SettingTarget, switch_actuator,
};
use stewart_kinematics::{model::geometry::Plate, model::layout::Layout};

use super::widgets::{edit_error, fitted_slider, setting_slider};
use crate::viewer::state::editor::Editor;

/// The panel.
pub(crate) fn show(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    egui::CollapsingHeader::new(t.tr("geometry.heading"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            for key in [
                GeometryKey::BaseRadius,
                GeometryKey::PlatformRadius,
                GeometryKey::HomeHeight,
            ] {
                setting_slider(ui, ed, SettingTarget::Geometry(key));
            }
            actuators(ui, ed);
            layout(ui, ed);
            egui::CollapsingHeader::new(t.tr("geometry.joint_angles"))
                .default_open(ed.expand)
                .show(ui, |ui| {
                    for (plate, key) in [
                        (
                            Plate::Base,
                            GeometryKey::BaseAngle as fn(usize) -> GeometryKey,
                        ),
                        (Plate::Platform, GeometryKey::PlatformAngle),
                    ] {
                        if ed
                            .scenario()
                            .geometry
                            .params()
                            .plate(plate)
                            .circle()
                            .is_none()
                        {
                            ui.label(egui::RichText::new(t.tr(points_note(plate))).small());
                        }
                        for i in 0..6 {
                            setting_slider(ui, ed, SettingTarget::Geometry(key(i)));
                        }
                    }
                });
            egui::CollapsingHeader::new(t.tr("geometry.coordinates"))
                .default_open(ed.expand)
                .show(ui, |ui| joint_table(ui, ed))
                .header_response
                .on_hover_text(t.tr("geometry.coordinates_tip"));
            egui::CollapsingHeader::new(t.tr("geometry.pivot"))
                .default_open(ed.expand)
                .show(ui, |ui| {
                    for i in 0..3 {
                        setting_slider(ui, ed, SettingTarget::Geometry(GeometryKey::Pivot(i)));
                    }
                });
            edit_error(ui, ed.doc, ed.lang, &[Group::Geometry]);
        });
}

/// The note under the joint angles for a plate whose joints are coordinates.
fn points_note(plate: Plate) -> &'static str {
    match plate {
        Plate::Base => "geometry.base_points",
        Plate::Platform => "geometry.platform_points",
    }
}

/// The twelve joints as an editable table: one row per joint, x, y and z in metres.
/// An edit goes through the setting `geometry.{plate}_joints_m[i][k]`, validated like a
/// typed `--set`.
fn joint_table(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    let mut edit = None;
    egui::Grid::new("joint_table")
        .num_columns(4)
        .striped(true)
        .show(ui, |ui| {
            ui.label(t.tr("geometry.joint"));
            let columns = ["x", "y", "z"].map(|axis| ui.label(axis).id);
            ui.end_row();
            for plate in [Plate::Base, Plate::Platform] {
                let joints = *ed.scenario().geometry.joints(plate);
                let letter = match plate {
                    Plate::Base => "B",
                    Plate::Platform => "P",
                };
                for (i, joint) in joints.iter().enumerate() {
                    let row = ui.label(format!("{letter}{}", i + 1)).id;
                    for (k, column) in columns.iter().enumerate() {
                        let mut v = joint[k];
                        let response = ui
                            .add(
                                egui::DragValue::new(&mut v)
                                    .speed(0.001)
                                    .max_decimals(6)
                                    .min_decimals(3),
                            )
                            .labelled_by(row)
                            .labelled_by(*column);
                        if response.changed() {
                            edit = Some((plate, i, k, v));
                        }
                    }
                    ui.end_row();
                }
            }
        });
    if let Some((plate, i, k, v)) = edit {
        ed.apply(
            settings::of(SettingTarget::Geometry(GeometryKey::Joint(plate, i, k))),
            Some(v),
        );
    }
}

/// The actuator kind and its numbers: the stroke of linear legs (sliders that apply to
/// legs only), or the servos' horns, rods, range, directions and trims, and the level
/// home height.
fn actuators(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    let current = ed.scenario().geometry.actuator().kind();
    let mut chosen = None;
    ui.horizontal(|ui| {
        ui.label(t.tr("geometry.actuators"));
        for kind in ActuatorKind::ALL {
            if ui
                .selectable_label(current == kind, t.tr_kind("geometry.kind", kind))
                .on_hover_text(t.tr_kind("geometry.kind_tip", kind))
                .clicked()
                && current != kind
            {
                chosen = Some(kind);
            }
        }
    });
    if let Some(kind) = chosen {
        ed.edit(Group::Geometry, |s| Ok(switch_actuator(s, kind)?));
    }
    // Each slider shows only for the kind it belongs to.
    for key in [GeometryKey::LegMin, GeometryKey::LegMax] {
        setting_slider(ui, ed, SettingTarget::Geometry(key));
    }
    for key in [
        ActuatorKey::HornLength,
        ActuatorKey::RodLength,
        ActuatorKey::ServoMin,
        ActuatorKey::ServoMax,
    ] {
        setting_slider(ui, ed, SettingTarget::Actuator(key));
    }
    let Some(level) = ed.scenario().geometry.servo_home_height() else {
        return;
    };
    let home = settings::of(SettingTarget::Geometry(GeometryKey::HomeHeight));
    if ui
        .button(t.fmt("geometry.level_home", &[("value", &format!("{level:.4}"))]))
        .on_hover_text(t.tr("geometry.level_home_tip"))
        .clicked()
    {
        ed.apply(home, Some(level));
    }
    egui::CollapsingHeader::new(t.tr("geometry.horns"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            for i in 0..6 {
                setting_slider(ui, ed, SettingTarget::Actuator(ActuatorKey::HornAngle(i)));
            }
            for i in 0..6 {
                setting_slider(ui, ed, SettingTarget::Actuator(ActuatorKey::Trim(i)));
            }
        });
}

/// Named layouts: choosing one, or moving its angle, rewrites all twelve joint angles.
/// Angles edited one by one into no named layout show as "Custom".
fn layout(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    ui.label(t.tr("geometry.layout"));
    let current = ed.doc.layout();
    let mut chosen = current;
    ui.horizontal(|ui| {
        let staggered = matches!(current, Some(Layout::Staggered { .. }));
        let paired = matches!(current, Some(Layout::Paired { .. }));
        if ui
            .selectable_label(staggered, t.tr("geometry.staggered"))
            .on_hover_text(t.tr("geometry.staggered_tip"))
            .clicked()
        {
            chosen = Some(Layout::seed());
        }
        if ui
            .selectable_label(paired, t.tr("geometry.paired"))
            .on_hover_text(t.tr("geometry.paired_tip"))
            .clicked()
        {
            chosen = Some(Layout::paired(20.0));
        }
        if current.is_none() {
            let _ = ui
                .selectable_label(true, t.tr("geometry.custom"))
                .on_hover_text(t.tr("geometry.custom_tip"));
        }
    });
    match &mut chosen {
        Some(Layout::Staggered { offset_deg }) => {
            let value = *offset_deg;
            let slider = egui::Slider::new(offset_deg, 1.0..=59.0);
            fitted_slider(ui, t.tr("geometry.platform_offset"), value, slider);
        }
        Some(Layout::Paired {
            base_separation_deg,
            platform_separation_deg,
        }) => {
            for (words, separation) in [
                ("geometry.base_separation", base_separation_deg),
                ("geometry.platform_separation", platform_separation_deg),
            ] {
                let value = *separation;
                let slider = egui::Slider::new(separation, 1.0..=110.0);
                fitted_slider(ui, t.tr(words), value, slider);
            }
        }
        None => {
            ui.label(egui::RichText::new(t.tr("geometry.no_layout")).small());
        }
    }
    if chosen != current
        && let Some(layout) = chosen
    {
        // Validated like any edit: a refused layout leaves geometry and controls as they were.
        ed.set_layout(layout);
    }
}
