//! The live plot of leg lengths (or servo angles): the whole trajectory with a moving
//! time marker, or in manual mode (and while the link cues live vehicle motion) the
//! rolling history of the last seconds.

use egui::Color32;
use egui_plot::{HLine, Line, LineStyle, Plot, PlotPoint, PlotPoints, Text, VLine};

use super::plot_picture::{PictureSession, Pictured};
use stewart_kinematics::model::actuator::Quantity;

use crate::i18n::words;
use crate::viewer::state::document::Document;
use crate::viewer::state::history::History;
use crate::viewer::state::look::Look;
use crate::viewer::state::playback::Playback;
use crate::viewer::state::plot_memory::PlotPlacement;

/// Leg `i`'s colour, as in exported plots.
pub(crate) fn leg_colour(i: usize) -> Color32 {
    let [r, g, b] = stewart_render::theme::SERIES_RGB[i % 6];
    Color32::from_rgb(r, g, b)
}

/// The mark over the stretches of a curve beyond a limit.
pub(crate) const BEYOND: Color32 = Color32::from_rgb(215, 25, 28);

/// The stretches of `points` (time, value) beyond `[min, max]`, each with the crossing
/// points interpolated on the limit so that the mark starts where the curve crosses it.
pub(crate) fn beyond(limits: [Option<f64>; 2], points: &[[f64; 2]]) -> Vec<Vec<[f64; 2]>> {
    let [min, max] = limits;
    let outside = |v: f64| min.is_some_and(|m| v < m) || max.is_some_and(|m| v > m);
    // The limit crossed between two values (the one the outside value is past).
    let crossing = |a: [f64; 2], b: [f64; 2]| -> [f64; 2] {
        let out = if outside(b[1]) { b[1] } else { a[1] };
        let limit = match (min, max) {
            (Some(m), _) if out < m => m,
            (_, Some(m)) => m,
            (Some(m), None) => m,
            (None, None) => out,
        };
        let f = if b[1] == a[1] {
            0.0
        } else {
            ((limit - a[1]) / (b[1] - a[1])).clamp(0.0, 1.0)
        };
        [a[0] + f * (b[0] - a[0]), limit]
    };
    let mut out = Vec::new();
    let mut current: Vec<[f64; 2]> = Vec::new();
    for (k, &p) in points.iter().enumerate() {
        let prev = k.checked_sub(1).map(|j| points[j]);
        if outside(p[1]) {
            if current.is_empty()
                && let Some(a) = prev
            {
                current.push(crossing(a, p));
            }
            current.push(p);
        } else if !current.is_empty() {
            if let Some(a) = prev {
                current.push(crossing(a, p));
            }
            out.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out
}

/// What the plot shows besides the scenario.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shows {
    /// The rolling history of the values shown (manual mode, live vehicle motion through
    /// the link) instead of the trajectory's.
    pub(crate) rolling: bool,
    /// Those values are the link's commanded ones.
    pub(crate) commanded: bool,
    /// The plot's own darker background (left out on a software rasteriser, where a fill
    /// that large costs milliseconds a frame: the curves then lie on the panel's colour).
    pub(crate) background: bool,
    /// The curves are shown from a picture the window draws while they stay the same
    /// (a software rasteriser: see [`super::plot_picture`]).
    pub(crate) pictured: bool,
}

/// Curve width in points (presentation mode: the projector's, twice as wide).
fn line_width(look: &Look) -> f32 {
    if look.presentation { 3.5 } else { 1.5 }
}

/// The panel: the plot, and its legend beside it (outside the curves) in as many columns
/// as its rows need to fit the panel's height; the values/forces toggle sits in the plot's
/// top right corner. In trajectory mode, clicking or dragging on the plot scrubs the time
/// (the wheel still zooms, double-click resets the view). Returns where it all went.
pub(crate) fn show(
    ui: &mut egui::Ui,
    doc: &Document,
    playback: &mut Playback,
    look: &mut Look,
    shows: Shows,
) -> PlotPlacement {
    let Shows {
        rolling,
        commanded,
        background,
        pictured,
    } = shows;
    let size = ui.available_size();
    let space = ui.available_rect_before_wrap();
    let efforts = efforts_shown(doc, look, rolling).is_some();
    let entries = super::plot_legend::entries(doc, look, efforts, rolling);
    let columns = super::plot_legend::Columns::fitting(ui, &entries, size.y);
    ui.horizontal(|ui| {
        let mut placement = ui
            .allocate_ui(
                egui::vec2((size.x - columns.width()).max(100.0), size.y),
                |ui| {
                    let shows = [rolling, commanded, background, pictured];
                    plot(ui, doc, playback, look, shows)
                },
            )
            .inner;
        placement.legend = super::plot_legend::show(ui, &entries, columns, line_width(look));
        placement.space = space;
        placement
    })
    .inner
}

/// The actuator efforts to plot instead of the lengths: when asked for, along the
/// trajectory, with a payload.
fn efforts_shown<'a>(
    doc: &'a Document,
    look: &Look,
    rolling: bool,
) -> Option<(&'a [f64], &'a [[f64; 6]])> {
    (look.plot_efforts && !rolling)
        .then(|| doc.plot_efforts())
        .flatten()
}

/// The time marker's colour: black on light, white on dark.
fn marker_colour(look: &Look) -> Color32 {
    if look.is_light() {
        Color32::BLACK
    } else {
        Color32::WHITE
    }
}

/// The plot itself, with the values/forces toggle in its corner.
fn plot(
    ui: &mut egui::Ui,
    doc: &Document,
    playback: &mut Playback,
    look: &mut Look,
    [rolling, commanded, background, pictured]: [bool; 4],
) -> PlotPlacement {
    let width = line_width(look);
    let scenario = doc.scenario();
    let quantity = scenario.geometry.quantity();
    let [min, max] = scenario.geometry.quantity_limits();
    let t = look.lang;
    let efforts = efforts_shown(doc, look, rolling).is_some();
    let [min, max] = if efforts { [None, None] } else { [min, max] };
    let (name, symbol, unit) = if efforts {
        let (symbol, unit) = quantity.effort;
        (words::effort_name(t, &quantity), symbol, unit)
    } else {
        let name = words::quantity_name(t, &quantity);
        (name, quantity.symbol, quantity.unit)
    };
    let (y_label, y_label_length) = y_axis_label(ui, look, name, symbol, unit);
    let x_label = t.tr(match (rolling, commanded) {
        (true, true) => "plot.seconds_ago_commanded",
        (true, false) => "plot.seconds_ago",
        (false, _) => "plot.time",
    });
    let mut plot = Plot::new(match (rolling, efforts) {
        (true, _) => "leg history",
        (false, true) => "actuator efforts",
        (false, false) => "leg lengths",
    })
    .allow_drag(rolling)
    .show_background(background)
    .y_grid_spacer(super::plot_ticks::marks)
    .y_axis_formatter(|mark, _| super::plot_ticks::label(mark))
    .x_grid_spacer(super::plot_ticks::time_marks)
    .custom_x_axes(vec![super::plot_ticks::time_axis(x_label)])
    .y_axis_label(y_label);
    if rolling {
        plot = plot.include_x(-History::WINDOW).include_x(0.0);
    }
    // The limits always in view: how close the legs come to them is the point.
    for limit in [min, max].into_iter().flatten() {
        plot = plot.include_y(limit);
    }
    let left_end = if rolling {
        -History::WINDOW
    } else {
        scenario.motion.sampling.start()
    };
    let (lines, data) = curves(doc, playback, [min, max], look, rolling);
    // Shown from a picture where the window draws one (see `plot_picture`); never in
    // rolling mode, where the curves change every frame.
    let session = (pictured && !rolling)
        .then(|| PictureSession::new(data, ui.ctx().pixels_per_point(), &look.curves_picture));
    let shown = plot.show(ui, |plot| {
        match &session {
            Some(session) => {
                plot.add(session.picture());
                for item in lines {
                    plot.add(Pictured { item, session });
                }
            }
            None => lines.into_iter().for_each(|line| plot.line(line)),
        }
        limit_lines(plot, &quantity, [min, max], left_end, look);
        if !rolling {
            let now = scenario.motion.sampling.start() + playback.time;
            plot.vline(
                VLine::new(t.tr("plot.now"), now)
                    .color(marker_colour(look))
                    .width(width),
            );
        }
    });
    match session {
        Some(session) => session.finish(&mut look.curves_picture),
        None => look.curves_picture = Default::default(),
    }
    let response = &shown.response;
    if !rolling
        && (response.clicked() || response.dragged_by(egui::PointerButton::Primary))
        && let Some(pointer) = response.interact_pointer_pos()
    {
        let t = shown.transform.value_from_position(pointer).x;
        let start = scenario.motion.sampling.start();
        playback.time = (t - start).clamp(0.0, scenario.motion.sampling.duration());
        playback.playing = false;
    }
    let frame = *shown.transform.frame();
    let limits = limit_label_places(ui, &shown.transform, [min, max], left_end, &quantity, t);
    let toggle =
        (doc.plot_efforts().is_some() && !rolling).then(|| efforts_toggle(ui, frame, look));
    let bounds = shown.transform.bounds();
    PlotPlacement {
        space: egui::Rect::NOTHING,
        frame,
        times: [bounds.min()[0], bounds.max()[0]],
        limits,
        legend: Vec::new(),
        toggle,
        y_label_length,
    }
}

/// The vertical axis's label — the quantity's name along it, or its symbol where the plot
/// is too short for the name (a projector's large text): the label is centred on the axis
/// and cut at its ends — and its length, points.
fn y_axis_label(ui: &egui::Ui, look: &Look, name: &str, symbol: &str, unit: &str) -> (String, f32) {
    let body = egui::TextStyle::Body.resolve(ui.style());
    let length = |text: &str| {
        (ui.painter())
            .layout_no_wrap(text.to_owned(), body.clone(), Color32::WHITE)
            .size()
            .x
    };
    let room = (look.plot_placement.as_ref())
        .map_or(ui.available_height() - 3.0 * body.size, |p| {
            p.frame.height()
        });
    let y_label = [format!("{name} ({unit})"), format!("{symbol} ({unit})")]
        .into_iter()
        .find(|label| length(label) <= room)
        .unwrap_or_else(|| format!("{symbol} ({unit})"));
    let y_label_length = length(&y_label);
    (y_label, y_label_length)
}

/// Where each limit line's label sits: the line's screen height and the label's
/// rectangle.
fn limit_label_places(
    ui: &egui::Ui,
    transform: &egui_plot::PlotTransform,
    [min, max]: [Option<f64>; 2],
    left_end: f64,
    quantity: &Quantity,
    t: crate::i18n::Lang,
) -> Vec<(f32, egui::Rect)> {
    [min, max]
        .into_iter()
        .zip(["plot.min", "plot.max"])
        .filter_map(|(limit, name)| {
            let v = limit?;
            let at = transform.position_from_point(&PlotPoint::new(left_end, v));
            let size = ui
                .painter()
                .layout_no_wrap(
                    limit_label(quantity, t, name, v),
                    egui::TextStyle::Body.resolve(ui.style()),
                    Color32::WHITE,
                )
                .size();
            let anchor = limit_anchor(name);
            Some((at.y, anchor.anchor_size(at, size)))
        })
        .collect()
}

/// The values/forces toggle in the plot's top right corner, on a backing of the panel's
/// colour (over the curves); returns its rectangle.
fn efforts_toggle(ui: &mut egui::Ui, frame: egui::Rect, look: &mut Look) -> egui::Rect {
    let t = look.lang;
    let corner = egui::Rect::from_min_max(
        frame.left_top() + egui::vec2(4.0, 4.0),
        frame.right_bottom() - egui::vec2(4.0, 4.0),
    );
    let builder = egui::UiBuilder::new()
        .max_rect(corner)
        .layout(egui::Layout::right_to_left(egui::Align::Min));
    ui.scope_builder(builder, |ui| {
        egui::Frame::NONE
            .fill(ui.visuals().panel_fill)
            .corner_radius(4.0)
            .inner_margin(2.0)
            .show(ui, |ui| {
                // Right to left: forces last on the screen, as read.
                ui.selectable_value(&mut look.plot_efforts, true, t.tr("plot.efforts"))
                    .on_hover_text(t.tr("plot.efforts_tip"));
                ui.selectable_value(&mut look.plot_efforts, false, t.tr("plot.lengths"));
            })
            .response
            .rect
    })
    .inner
}

/// A limit line's label: `Lmax 1.3 m`.
fn limit_label(quantity: &Quantity, t: crate::i18n::Lang, name: &str, v: f64) -> String {
    format!(
        " {}{} {} {}",
        quantity.symbol,
        t.tr(name),
        stewart_kinematics::ground::bounds::short(v),
        quantity.unit
    )
}

/// Where a limit's label hangs from its point on the line: inside the band between the
/// limits (a label outside it would be cut by the plot's edge, where the bounds end at the
/// limit).
fn limit_anchor(name: &str) -> egui::Align2 {
    if name == "plot.max" {
        egui::Align2::LEFT_TOP
    } else {
        egui::Align2::LEFT_BOTTOM
    }
}

/// The six curves (the trajectory's, or in rolling mode the history's), each broken where a
/// servo cannot reach, with the stretches beyond `limits` marked over them; and the hash
/// of what they draw (see [`super::plot_picture`]).
fn curves(
    doc: &Document,
    playback: &Playback,
    [min, max]: [Option<f64>; 2],
    look: &Look,
    rolling: bool,
) -> (Vec<Line<'static>>, u64) {
    let (width, t) = (line_width(look), look.lang);
    let quantity = doc.scenario().geometry.quantity();
    let mut lines = Vec::new();
    let mut hash = super::plot_picture::DataHash::default();
    for leg in 0..6 {
        let points: Vec<[f64; 2]> = if rolling {
            playback
                .history
                .entries()
                .map(|(t, l)| [t - playback.clock, l[leg]])
                .collect()
        } else {
            let (times, lengths) =
                efforts_shown(doc, look, rolling).unwrap_or_else(|| doc.plot_samples());
            times
                .iter()
                .zip(lengths)
                .map(|(t, l)| [*t, l[leg]])
                .collect()
        };
        // A servo out of reach has no angle: its curve breaks there.
        let symbol = if efforts_shown(doc, look, rolling).is_some() {
            quantity.effort.0
        } else {
            quantity.symbol
        };
        let name = format!("{symbol}{}", leg + 1);
        for run in points.split(|p| p[1].is_nan()).filter(|r| !r.is_empty()) {
            let curve: PlotPoints = run.iter().copied().collect();
            hash.curve(run, leg_colour(leg), width);
            lines.push(
                Line::new(name.clone(), curve)
                    .color(leg_colour(leg))
                    .width(width),
            );
            // The stretches beyond a limit, marked over the curve.
            for stretch in beyond([min, max], run) {
                hash.curve(&stretch, BEYOND, width * 2.5);
                lines.push(
                    Line::new(t.tr("plot.beyond"), PlotPoints::from(stretch))
                        .color(BEYOND)
                        .width(width * 2.5),
                );
            }
        }
    }
    (lines, hash.finish())
}

/// The limits as dashed lines, labelled with their values at `left_end` (the start of
/// the time shown).
fn limit_lines(
    plot: &mut egui_plot::PlotUi,
    quantity: &Quantity,
    [min, max]: [Option<f64>; 2],
    left_end: f64,
    look: &Look,
) {
    let (width, t) = (line_width(look), look.lang);
    // The limits' labels as legible as the axes' (they were small and grey).
    let label_colour = if look.is_light() {
        Color32::from_gray(60)
    } else {
        Color32::from_gray(200)
    };
    for (name, limit) in [("plot.min", min), ("plot.max", max)] {
        if let Some(v) = limit {
            let words = format!("{}{}", quantity.symbol, t.tr(name));
            plot.hline(
                HLine::new(words.clone(), v)
                    .style(LineStyle::dashed_loose())
                    .color(Color32::GRAY)
                    .width(width * 0.7),
            );
            // Labelled at the line at the start of the time shown (a fixed place: the
            // plot's own bounds would grow to hold a label placed at their edge).
            plot.text(
                Text::new(
                    words.clone(),
                    PlotPoint::new(left_end, v),
                    egui::RichText::new(limit_label(quantity, t, name, v))
                        .text_style(egui::TextStyle::Body)
                        .color(label_colour),
                )
                .anchor(limit_anchor(name)),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stretches_beyond_a_limit_start_and_end_on_it() {
        let points = [
            [0.0, 0.5],
            [1.0, 1.5],
            [2.0, 1.5],
            [3.0, 0.5],
            [4.0, -0.5],
            [5.0, 0.5],
        ];
        let s = beyond([Some(0.0), Some(1.0)], &points);
        assert_eq!(s.len(), 2, "{s:?}");
        assert_eq!(s[0], vec![[0.5, 1.0], [1.0, 1.5], [2.0, 1.5], [2.5, 1.0]]);
        assert_eq!(s[1], vec![[3.5, 0.0], [4.0, -0.5], [4.5, 0.0]]);
        assert!(beyond([None, None], &points).is_empty());
        // Beyond from the first sample: it starts there.
        let s = beyond([None, Some(1.0)], &[[0.0, 2.0], [1.0, 0.0]]);
        assert_eq!(s, vec![vec![[0.0, 2.0], [0.5, 1.0]]]);
    }

    #[test]
    fn presentation_mode_draws_wider_curves() {
        let scenario = stewart_kinematics::Scenario::seed();
        let mut look = Look::new(crate::export::frames::default_camera(&scenario));
        let screen = line_width(&look);
        look.presentation = true;
        assert!(line_width(&look) >= 2.0 * screen);
    }
}
