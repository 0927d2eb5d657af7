//! Legs: the six lengths now (or a rotary platform's six servo angles), with bars of the
//! stroke or servo range used, and the pose's conditioning.

use egui::{Color32, RichText};
use stewart_kinematics::model::scene::LegStatus;

use super::plot::leg_colour;
use super::widgets::ERROR;
use crate::i18n::Lang;
use stewart_kinematics::{Pose, Scenario};

use crate::viewer::state::look::Look;

/// The panel: the actuators of `scenario` at `pose`.
pub(crate) fn show(ui: &mut egui::Ui, scenario: &Scenario, pose: &Pose, look: &Look) {
    let geometry = &scenario.geometry;
    let kind = geometry.actuator().kind();
    let t = look.lang;
    ui.heading(t.tr_kind("legs.heading", kind));
    let frame = geometry.scene_frame(pose, Vec::new());
    let letter = geometry.quantity().letter;
    let theme = look.theme();
    for (i, leg) in frame.legs.iter().enumerate() {
        let angle = frame.servos.map(|s| s[i].angle_deg);
        // The bar takes the leg's own colour (its curve's in the plot, its body's in the 3D
        // view), or the warning colours near and past a limit.
        let colour = match leg.status {
            LegStatus::Normal if look.coloured_legs => leg_colour(i),
            status => {
                let [r, g, b, _] = theme
                    .leg_colours(status)
                    .0
                    .map(|c| (c * 255.0).round() as u8);
                Color32::from_rgb(r, g, b)
            }
        };
        let note = match leg.status {
            LegStatus::Normal => "",
            LegStatus::NearLimit => t.tr("legs.near_limit"),
            LegStatus::OverLimit => t.tr_kind("legs.over_limit", kind),
        };
        ui.horizontal(|ui| {
            ui.label(
                RichText::new(format!("{letter}{}", i + 1))
                    .color(leg_colour(i))
                    .strong(),
            );
            match angle {
                None => ui.label(format!("{:.4} m", leg.length)),
                Some(Some(a)) => ui.label(format!("{a:+.2}°")),
                Some(None) => ui.label(RichText::new(t.tr("legs.out_of_reach")).color(ERROR)),
            };
            if let Some(u) = leg.stroke_usage {
                let usage = t.fmt_kind(
                    "legs.usage",
                    kind,
                    &[("percent", &format!("{:.0}", 100.0 * u))],
                );
                let text = if note.is_empty() {
                    usage
                } else {
                    format!("{usage} — {note}")
                };
                usage_bar(ui, u, colour, text);
            }
        });
    }
    match geometry
        .actuated_conditioning(pose)
        .map(|c| c.condition_number)
    {
        Some(Some(k)) => {
            singularity_gauge(ui, t, scenario.checks.condition_max, k);
            ui.label(t.fmt("legs.condition", &[("k", &format!("{k:.2}"))]))
        }
        Some(None) => ui.label(
            RichText::new(t.tr_kind("legs.singular", kind)).color(ui.visuals().warn_fg_color),
        ),
        None => ui.label(RichText::new(t.tr("legs.servo_unreachable")).color(ERROR)),
    };
}

/// A bar of the share `u` of the stroke or range used, in `colour`, with `text` on it.
fn usage_bar(ui: &mut egui::Ui, u: f64, colour: Color32, text: String) {
    // Dark text on light fills (the warning colours), white on dark ones (the legs' blue),
    // in either theme.
    let [r, g, b, _] = colour.to_array();
    let luminance = 0.2126 * f32::from(r) + 0.7152 * f32::from(g) + 0.0722 * f32::from(b);
    let ink = if luminance > 140.0 {
        Color32::BLACK
    } else {
        Color32::WHITE
    };
    ui.add(
        egui::ProgressBar::new(u.clamp(0.0, 1.0) as f32)
            .desired_width(ui.available_width().max(110.0))
            .fill(colour)
            .text(RichText::new(text).color(ink)),
    );
}

/// How far the pose is from a singularity: the inverse condition number 1/κ as a bar (1 at
/// a perfectly conditioned pose, 0 at a singular one), red past the near-singular threshold
/// `checks.condition_max`, amber within twice it.
fn singularity_gauge(ui: &mut egui::Ui, t: Lang, max: f64, k: f64) {
    let distance = (1.0 / k).clamp(0.0, 1.0);
    let fill = if k > max {
        ERROR
    } else if k > 0.5 * max {
        super::widgets::WARNING
    } else {
        super::widgets::OK
    };
    ui.horizontal(|ui| {
        ui.label(t.tr("legs.distance"))
            .on_hover_text(t.fmt("legs.distance_tip", &[("max", &max)]));
        ui.add(
            egui::ProgressBar::new(distance as f32)
                .fill(fill)
                .desired_width(ui.available_width().max(80.0))
                .text(RichText::new(format!("1/κ = {distance:.3}")).color(Color32::WHITE)),
        );
    });
}
