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
    let theme = state.theme();
    for (i, leg) in frame.legs.iter().enumerate() {
        // The bar takes the colour the leg has in the 3D view.
        let [r, g, b, _] = theme
            .leg_colours(leg.status)
            .0
            .map(|c| (c * 255.0).round() as u8);
        let colour = Color32::from_rgb(r, g, b);
        let note = match leg.status {
            LegStatus::Normal => "",
            LegStatus::NearLimit => " near limit",
            LegStatus::OverLimit => " over stroke",
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
                        .text({
                            // Dark text on light fills (the warning colours), white on
                            // dark ones (the legs' blue), in either theme.
                            let luminance = 0.2126 * f32::from(r)
                                + 0.7152 * f32::from(g)
                                + 0.0722 * f32::from(b);
                            let ink = if luminance > 140.0 {
                                Color32::BLACK
                            } else {
                                Color32::WHITE
                            };
                            RichText::new(format!("{:.0}%{note}", 100.0 * u)).color(ink)
                        }),
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
