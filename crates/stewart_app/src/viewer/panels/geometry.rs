//! Geometry: radii, home height, stroke, layout with its separation angles, every joint
//! angle and the pivot.

use stewart_kinematics::Layout;
use stewart_kinematics::settings::{GeometryKey, Group, Target};

use super::widgets::{edit_error, setting_slider};
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    egui::CollapsingHeader::new("Geometry")
        .default_open(state.look.expand_panels)
        .show(ui, |ui| {
            for key in [
                GeometryKey::BaseRadius,
                GeometryKey::PlatformRadius,
                GeometryKey::HomeHeight,
                GeometryKey::LegMin,
                GeometryKey::LegMax,
            ] {
                setting_slider(ui, state, Target::Geometry(key));
            }
            layout(ui, state);
            egui::CollapsingHeader::new("Joint angles")
                .default_open(state.look.expand_panels)
                .show(ui, |ui| {
                    for i in 0..6 {
                        setting_slider(ui, state, Target::Geometry(GeometryKey::BaseAngle(i)));
                    }
                    for i in 0..6 {
                        setting_slider(ui, state, Target::Geometry(GeometryKey::PlatformAngle(i)));
                    }
                });
            egui::CollapsingHeader::new("Pivot (rotation centre, platform frame)")
                .default_open(state.look.expand_panels)
                .show(ui, |ui| {
                    for i in 0..3 {
                        setting_slider(ui, state, Target::Geometry(GeometryKey::Pivot(i)));
                    }
                });
            edit_error(ui, state, &[Group::Geometry]);
        });
}

/// Named layouts: choosing one, or moving its angle, rewrites all twelve joint angles.
/// Angles edited one by one into no named layout show as "Custom".
fn layout(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.label("Layout (rewrites the joint angles):");
    let current = state.layout();
    let mut chosen = current;
    ui.horizontal(|ui| {
        let staggered = matches!(current, Some(Layout::Staggered { .. }));
        let paired = matches!(current, Some(Layout::Paired { .. }));
        if ui.selectable_label(staggered, "Staggered (seed)").clicked() {
            chosen = Some(Layout::seed());
        }
        if ui.selectable_label(paired, "Paired").clicked() {
            chosen = Some(Layout::paired(20.0));
        }
        if current.is_none() {
            let _ = ui.selectable_label(true, "Custom");
        }
    });
    match &mut chosen {
        Some(Layout::Staggered { offset_deg }) => {
            ui.add(egui::Slider::new(offset_deg, 1.0..=59.0).text("platform offset (°)"));
        }
        Some(Layout::Paired {
            base_separation_deg,
            platform_separation_deg,
        }) => {
            ui.add(egui::Slider::new(base_separation_deg, 1.0..=110.0).text("base separation (°)"));
            ui.add(
                egui::Slider::new(platform_separation_deg, 1.0..=110.0)
                    .text("platform separation (°)"),
            );
        }
        None => {
            ui.label(egui::RichText::new("The joint angles follow no named layout.").small());
        }
    }
    if chosen != current
        && let Some(layout) = chosen
    {
        // Validated like any edit: a refused layout leaves geometry and controls as they were.
        state.set_layout(layout);
    }
}
