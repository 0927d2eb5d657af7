//! Design: the stroke (or servo range) a box of poses needs, searched as by `stewart
//! design`, with a button that writes it into the limits.

use egui::RichText;
use stewart_kinematics::io::settings;

use super::context::PanelContext;
use super::widgets::{self, ERROR, OK, WARNING};
use crate::i18n::Lang;
use crate::viewer::state::document::Document;
use crate::viewer::tools::design::DesignTool;

/// The panel: the tool and the document it writes limits into, nothing else of the
/// viewer's state.
pub(crate) fn show(
    ui: &mut egui::Ui,
    tool: &mut DesignTool,
    doc: &mut Document,
    cx: &PanelContext,
) {
    let (t, open) = (cx.lang, cx.expand);
    egui::CollapsingHeader::new(t.tr("design.heading"))
        .default_open(open)
        .show(ui, |ui| {
            envelope(ui, tool, doc, t);
            let busy = tool.busy();
            if ui
                .add_enabled(!busy, egui::Button::new(t.tr("design.compute")))
                .on_hover_text(t.tr("design.compute_tip"))
                .clicked()
            {
                let geometry = doc.scenario().geometry.clone();
                tool.start(&geometry);
            }
            if busy {
                ui.label(t.tr("design.searching"));
                ui.ctx()
                    .request_repaint_after(std::time::Duration::from_millis(50));
            }
            result(ui, tool, doc, t);
        });
}

/// The envelope: for each coordinate how far below and above home it reaches, in its
/// unit; the command line that asks the same in the tooltip.
fn envelope(ui: &mut egui::Ui, tool: &mut DesignTool, doc: &Document, t: Lang) {
    let home = doc.scenario().geometry.home_pose();
    let scale = doc.scenario().geometry.characteristic_length();
    ui.label(t.tr("design.envelope")).on_hover_text(t.fmt(
        "design.envelope_tip",
        &[("line", &tool.command_line(&home))],
    ));
    egui::Grid::new("design-envelope")
        .num_columns(3)
        .spacing([8.0, 2.0])
        .show(ui, |ui| {
            ui.label("");
            ui.label(t.tr("design.below"));
            ui.label(t.tr("design.above"));
            ui.end_row();
            for (k, span) in tool.spans.iter_mut().enumerate() {
                let linear = k < 3;
                let (unit, speed, decimals) = if linear {
                    ("m", 0.002 * scale, 3)
                } else {
                    ("°", 0.1, 1)
                };
                let name = t.fmt(
                    "design.coordinate",
                    &[("name", &t.tr(POSE_WORDS[k])), ("unit", &unit)],
                );
                let label = ui.label(&name);
                let [lo, hi] = span;
                ui.add(
                    egui::DragValue::new(lo)
                        .speed(speed)
                        .max_decimals(decimals)
                        .range(f64::NEG_INFINITY..=0.0),
                )
                .labelled_by(label.id)
                .on_hover_text(t.tr("design.below_tip"));
                ui.add(
                    egui::DragValue::new(hi)
                        .speed(speed)
                        .max_decimals(decimals)
                        .range(0.0..=f64::INFINITY),
                )
                .labelled_by(label.id)
                .on_hover_text(t.tr("design.above_tip"));
                ui.end_row();
            }
        });
}

/// The words for x, y, z, roll, pitch, yaw.
const POSE_WORDS: [&str; 6] = [
    "pose.x",
    "pose.y",
    "pose.z",
    "pose.roll",
    "pose.pitch",
    "pose.yaw",
];

/// The outcome: each actuator's range, the range needed, whether it fits, the worst
/// conditioning, and the button that writes the range into the limits.
fn result(ui: &mut egui::Ui, tool: &DesignTool, doc: &mut Document, t: Lang) {
    let report = match &tool.result {
        None => return,
        Some(Err(e)) => {
            widgets::not_applied(ui, e, t);
            return;
        }
        Some(Ok(report)) => report.clone(),
    };
    let g = &doc.scenario().geometry;
    let q = g.quantity();
    let (decimals, unit) = if q.unit == "m" { (4, " m") } else { (2, "°") };
    let range = |lo: f64, hi: f64| format!("{lo:.decimals$} .. {hi:.decimals$}{unit}");
    for (i, [lo, hi]) in report.actuators.iter().enumerate() {
        ui.label(
            RichText::new(format!(
                "{}{}  {}",
                q.letter,
                i + 1,
                range(lo.value, hi.value)
            ))
            .color(super::plot::leg_colour(i)),
        );
    }
    let Some([lo, hi]) = report.overall() else {
        ui.label(RichText::new(t.tr("design.none_reachable")).color(ERROR));
        return;
    };
    ui.label(t.fmt("design.needed", &[("range", &range(lo.value, hi.value))]));
    if let Some(fits) = report.fits(g.quantity_limits()) {
        let (key, colour) = if fits {
            ("design.fits", OK)
        } else {
            ("design.does_not_fit", ERROR)
        };
        ui.label(RichText::new(t.tr(key)).color(colour));
    }
    if report.unreachable.is_some() {
        ui.label(RichText::new(t.tr("design.some_unreachable")).color(WARNING));
    }
    if let Some(w) = &report.worst_condition {
        let value = if w.value.is_finite() {
            format!("{:.2}", w.value)
        } else {
            t.tr("finding.singular_value").to_owned()
        };
        ui.label(t.fmt("design.worst_condition", &[("value", &value)]));
    }
    if ui
        .button(t.tr("design.use_as_limits"))
        .on_hover_text(t.tr("design.use_as_limits_tip"))
        .clicked()
    {
        let [low, high] = settings::quantity_limit_targets(g.actuator().kind());
        // Widen first, so that no intermediate stroke is inverted.
        doc.apply(settings::of(high), Some(hi.value.max(lo.value)));
        doc.apply(settings::of(low), Some(lo.value));
        doc.apply(settings::of(high), Some(hi.value));
    }
}
