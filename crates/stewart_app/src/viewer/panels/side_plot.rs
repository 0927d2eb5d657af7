//! Plots in the side panel: the wheel scrolls the panel, not the plot (Ctrl+wheel zooms,
//! a double-click restores the view); values on both axes at 1-2-5 steps; and a
//! legend below the data saying which line is which (dashed or solid).

use egui::Color32;
use egui_plot::Plot;

/// A side-panel plot over time (its axis named `time`) `height` points high with the live
/// plot's ticks, the wheel left to the panel and drags to the panel's scrolling.
pub(crate) fn plot(id: &str, height: f32, time: &str) -> Plot<'static> {
    Plot::new(id)
        .height(height)
        .allow_scroll(false)
        .allow_drag(false)
        .x_grid_spacer(super::plot_ticks::time_marks)
        .custom_x_axes(vec![super::plot_ticks::time_axis(time.to_owned())])
        .y_grid_spacer(super::plot_ticks::marks)
        .y_axis_formatter(|mark, _| super::plot_ticks::label(mark))
}

/// One entry of a legend: colour, words, dashed or solid, line width.
pub(crate) struct LegendEntry<'a> {
    /// The line's colour.
    pub(crate) colour: Color32,
    /// What it is.
    pub(crate) words: &'a str,
    /// Dashed (else solid).
    pub(crate) dashed: bool,
    /// The line's width, points.
    pub(crate) width: f32,
}

/// A legend below a plot, outside its data: a short line drawn as the curve is, and its
/// words, wrapping to the panel's width between entries, never inside one (a swatch stays
/// with its words).
pub(crate) fn legend(ui: &mut egui::Ui, entries: &[LegendEntry<'_>]) {
    ui.horizontal_wrapped(|ui| {
        for e in entries {
            entry(ui, e);
            ui.add_space(6.0);
        }
    });
}

/// One legend entry as a single widget: its swatch and its words, never parted.
fn entry(ui: &mut egui::Ui, e: &LegendEntry<'_>) {
    let galley = egui::WidgetText::from(e.words).into_galley(
        ui,
        Some(egui::TextWrapMode::Extend),
        f32::INFINITY,
        egui::TextStyle::Body,
    );
    let gap = ui.spacing().item_spacing.x;
    let size = egui::vec2(22.0 + gap + galley.size().x, galley.size().y.max(12.0));
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::hover());
    let line = egui::Rect::from_min_size(rect.left_top(), egui::vec2(22.0, rect.height()));
    paint_swatch(ui.painter(), line, e.colour, e.dashed, e.width);
    let at = egui::pos2(line.right() + gap, rect.center().y - galley.size().y / 2.0);
    ui.painter().galley(at, galley, ui.visuals().text_color());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, e.words));
}

/// A 22 × 12 point swatch of a line: dashed or solid.
pub(crate) fn swatch(ui: &mut egui::Ui, colour: Color32, dashed: bool, width: f32) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(22.0, 12.0), egui::Sense::hover());
    paint_swatch(ui.painter(), rect, colour, dashed, width);
}

/// A line across the middle of `rect`, dashed or solid.
fn paint_swatch(
    painter: &egui::Painter,
    rect: egui::Rect,
    colour: Color32,
    dashed: bool,
    width: f32,
) {
    let y = rect.center().y;
    let stroke = egui::Stroke::new(width, colour);
    if dashed {
        for k in 0..3 {
            let x = rect.left() + 8.0 * k as f32;
            painter.line_segment([egui::pos2(x, y), egui::pos2(x + 4.0, y)], stroke);
        }
    } else {
        painter.line_segment(
            [egui::pos2(rect.left(), y), egui::pos2(rect.right(), y)],
            stroke,
        );
    }
}
