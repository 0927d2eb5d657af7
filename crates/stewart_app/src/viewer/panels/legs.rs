//! Legs: the six lengths now, with stroke-usage bars, and the pose's conditioning.

use egui::{Color32, RichText};
use stewart_kinematics::scene::LegStatus;

use super::plot::leg_colour;
use super::widgets::ERROR;
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &ViewerState) {
    ui.heading("Legs");
    let pose = state.pose();
    let frame = state.scenario().geometry.scene_frame(&pose, Vec::new());
    for (i, leg) in frame.legs.iter().enumerate() {
        let (colour, note) = match leg.status {
            LegStatus::Normal => (Color32::from_rgb(70, 160, 90), ""),
            LegStatus::NearLimit => (Color32::from_rgb(230, 150, 20), " near limit"),
            LegStatus::OverLimit => (ERROR, " over stroke"),
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
                        .desired_width(ui.available_width().max(110.0))
                        .fill(colour)
                        .text(format!("{:.0}%{note}", 100.0 * u)),
                );
            }
        });
    }
    let c = state.scenario().geometry.conditioning(&pose);
    match c.condition_number {
        Some(k) => ui.label(format!("Condition number {k:.2}")),
        None => ui.label(
            RichText::new("Singular pose: the legs cannot control the platform in one direction")
                .color(ERROR),
        ),
    };
}
