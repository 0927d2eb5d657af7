//! The live plot's legend beside its curves: a swatch and the name of each curve, the
//! limits, the stretches beyond them and the time marker, in as many columns as it takes
//! to fit the plot's height (presentation text is half as large again, and a projector's
//! plot is short).

use egui::Color32;

use super::plot::{BEYOND, leg_colour};
use crate::viewer::state::document::Document;
use crate::viewer::state::look::Look;

/// One row of the legend.
pub(crate) struct Entry {
    /// The line's colour.
    colour: Color32,
    /// What it is.
    words: String,
    /// Dashed (the limits) or solid.
    dashed: bool,
}

/// The rows: the six curves (values or efforts), the limits when values are shown, the
/// stretches beyond them when there are any, and the time marker along a trajectory.
pub(crate) fn entries(doc: &Document, look: &Look, efforts: bool, rolling: bool) -> Vec<Entry> {
    let quantity = doc.scenario().geometry.quantity();
    let t = look.lang;
    let symbol = if efforts {
        quantity.effort.0
    } else {
        quantity.symbol
    };
    let solid = |colour, words| Entry {
        colour,
        words,
        dashed: false,
    };
    let mut out: Vec<Entry> = (0..6)
        .map(|leg| solid(leg_colour(leg), format!("{symbol}{}", leg + 1)))
        .collect();
    let [min, max] = doc.scenario().geometry.quantity_limits();
    for (name, limit) in [("plot.max", max), ("plot.min", min)] {
        if limit.is_some() && !efforts {
            out.push(Entry {
                colour: Color32::GRAY,
                words: format!("{}{}", quantity.symbol, t.tr(name)),
                dashed: true,
            });
        }
    }
    if !rolling && doc.beyond_limits() && !efforts {
        out.push(solid(BEYOND, t.tr("plot.beyond").to_owned()));
    }
    if !rolling {
        let marker = if look.is_light() {
            Color32::BLACK
        } else {
            Color32::WHITE
        };
        out.push(solid(marker, t.tr("plot.now").to_owned()));
    }
    out
}

/// How the rows are laid out: so many to a column, in columns this wide.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Columns {
    /// Rows in each column (the last may hold fewer).
    per_column: usize,
    /// Columns.
    count: usize,
    /// Each column's width, points.
    column_width: f32,
    /// The space before each column, points.
    gap: f32,
}

/// The swatch's width and the space after it, points.
const SWATCH: f32 = 22.0;

impl Columns {
    /// The columns that fit `rows` rows into `height` points: as many rows to a column as
    /// fit, each column as wide as its widest words (`words`).
    pub(crate) fn fitting(ui: &egui::Ui, entries: &[Entry], height: f32) -> Self {
        let row = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
        let per_column = ((height / row).floor() as usize).max(1);
        let font = egui::TextStyle::Body.resolve(ui.style());
        let widest = entries
            .iter()
            .map(|e| {
                ui.painter()
                    .layout_no_wrap(e.words.clone(), font.clone(), Color32::WHITE)
                    .size()
                    .x
            })
            .fold(0.0_f32, f32::max);
        // Balanced: as few columns as fit, the rows shared evenly between them.
        let count = entries.len().div_ceil(per_column).max(1);
        Self {
            per_column: entries.len().div_ceil(count).max(1),
            count,
            column_width: SWATCH + ui.spacing().item_spacing.x + widest.ceil(),
            gap: ui.spacing().item_spacing.x,
        }
    }

    /// The legend's whole width with the space before each column, points.
    pub(crate) fn width(&self) -> f32 {
        self.count as f32 * (self.gap + self.column_width)
    }
}

/// The legend in its columns, lines drawn `width` points wide; the rectangle of each row.
pub(crate) fn show(
    ui: &mut egui::Ui,
    entries: &[Entry],
    columns: Columns,
    width: f32,
) -> Vec<egui::Rect> {
    let mut rows = Vec::with_capacity(entries.len());
    for column in entries.chunks(columns.per_column) {
        ui.vertical(|ui| {
            ui.set_width(columns.column_width);
            for e in column {
                let row = ui.horizontal(|ui| {
                    super::side_plot::swatch(ui, e.colour, e.dashed, width);
                    ui.label(&e.words);
                });
                rows.push(row.response.rect);
            }
        });
    }
    rows
}
