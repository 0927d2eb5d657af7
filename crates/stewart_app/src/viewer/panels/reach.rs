//! Orientation reach: at the platform's position, how far roll, pitch and yaw can each go
//! alone, and a map of the roll–pitch pairs reachable at its yaw; updated as the pose
//! moves.

use egui::{RichText, Stroke};

use super::context::PanelContext;
use super::widgets::{ERROR, OK, UNREACHABLE, range_bar};
use crate::i18n::Lang;
use crate::i18n::words;
use crate::viewer::tools::reach::{ANGLE_SPAN_DEG, MAP_SPAN_DEG, OrientationReach};

/// The panel in language `t`, at `pose`, open at first when `open`; `reach` is asked only
/// while the panel is open.
pub(crate) fn show(ui: &mut egui::Ui, cx: &PanelContext, reach: impl FnOnce() -> OrientationReach) {
    let (t, open) = (cx.lang, cx.expand);
    let pose = &cx.pose;
    egui::CollapsingHeader::new(t.tr("reach.heading"))
        .default_open(open)
        .show(ui, |ui| {
            let reach = reach();
            let now = pose.rpy_degrees();
            if reach.angles.iter().all(Option::is_none) {
                ui.label(RichText::new(t.tr("reach.out_of_reach")).color(ERROR));
                return;
            }
            ui.label(t.tr("reach.alone"));
            for (a, name) in ["roll", "pitch", "yaw"].iter().enumerate() {
                let Some([lo, hi]) = reach.angles[a] else {
                    continue;
                };
                let (lo, hi) = (lo.to_degrees(), hi.to_degrees());
                ui.label(
                    RichText::new(t.fmt(
                        "reach.range",
                        &[
                            ("axis", &words::coordinate(t, name)),
                            ("min", &format!("{lo:.1}")),
                            ("max", &format!("{hi:.1}")),
                        ],
                    ))
                    .monospace(),
                );
                let span = ANGLE_SPAN_DEG + now[a].abs();
                range_bar(ui, [-span, span], Some([lo, hi]), None, now[a], 220.0);
            }
            let reachable = reach.map.reachable.iter().filter(|&&r| r).count();
            ui.label(t.fmt(
                "reach.map",
                &[
                    ("yaw", &format!("{:.1}", now[2])),
                    ("span", &format!("{MAP_SPAN_DEG:.0}")),
                    ("count", &reachable),
                    ("cells", &reach.map.reachable.len()),
                ],
            ));
            map(ui, t, &reach.map, [now[0], now[1]]);
        });
}

/// The roll–pitch map: reachable cells green, the others dark, the pose's own angles as a
/// cross, ticks at −span, 0, +span.
fn map(
    ui: &mut egui::Ui,
    t: Lang,
    map: &stewart_kinematics::analysis::workspace::ReachMap,
    now: [f64; 2],
) {
    let side = 170.0;
    // Room for the pitch ticks on the left, the roll ticks and label below, half a tick
    // label above and to the right.
    let (left, top, right, bottom) = (34.0, 8.0, 12.0, 30.0);
    let (rect, _) = ui.allocate_exact_size(
        egui::vec2(left + side + right, top + side + bottom),
        egui::Sense::hover(),
    );
    let painter = ui.painter_at(rect);
    let plot = egui::Rect::from_min_size(rect.min + egui::vec2(left, top), egui::vec2(side, side));
    let cell = side / map.cells as f32;
    for j in 0..map.cells {
        for i in 0..map.cells {
            let colour = if map.get(i, j) { OK } else { UNREACHABLE };
            let min = egui::pos2(
                plot.left() + i as f32 * cell,
                plot.bottom() - (j + 1) as f32 * cell,
            );
            painter.rect_filled(
                egui::Rect::from_min_size(min, egui::vec2(cell + 0.5, cell + 0.5)),
                0.0,
                colour,
            );
        }
    }
    let span = map.span.degrees();
    let at = |v: [f64; 2]| {
        egui::pos2(
            plot.left() + ((v[0] + span) / (2.0 * span)) as f32 * side,
            plot.bottom() - ((v[1] + span) / (2.0 * span)) as f32 * side,
        )
    };
    let text = ui.visuals().text_color();
    let stroke = Stroke::new(2.0, ui.visuals().strong_text_color());
    let c = at(now);
    if plot.contains(c) {
        painter.line_segment([c - egui::vec2(6.0, 0.0), c + egui::vec2(6.0, 0.0)], stroke);
        painter.line_segment([c - egui::vec2(0.0, 6.0), c + egui::vec2(0.0, 6.0)], stroke);
    }
    let font = egui::FontId::proportional(super::SMALLEST_TEXT);
    let (roll, pitch) = (words::coordinate(t, "roll"), words::coordinate(t, "pitch"));
    for v in [-span, 0.0, span] {
        let p = at([v, -span]);
        painter.text(
            p + egui::vec2(0.0, 2.0),
            egui::Align2::CENTER_TOP,
            format!("{v:.0}"),
            font.clone(),
            text,
        );
        let q = at([-span, v]);
        painter.text(
            q - egui::vec2(3.0, 0.0),
            egui::Align2::RIGHT_CENTER,
            format!("{v:.0}"),
            font.clone(),
            text,
        );
    }
    painter.text(
        egui::pos2(plot.center().x, plot.bottom() + 14.0),
        egui::Align2::CENTER_TOP,
        format!("{roll} (°)"),
        font.clone(),
        text,
    );
    painter.text(
        egui::pos2(rect.left(), plot.center().y - 18.0),
        egui::Align2::LEFT_CENTER,
        pitch,
        font,
        text,
    );
}
