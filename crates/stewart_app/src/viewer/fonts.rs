//! The interface's fonts: egui's own, then the system's Chinese font as their fallback, so
//! Chinese labels (and Chinese scenario names in any language) show as characters, never
//! as boxes.

use egui::epaint::text::{FontInsert, FontPriority, InsertFontFamily};
use egui::{FontData, FontFamily};

use crate::i18n::fonts;

/// Add the system's Chinese font after egui's fonts in both families; `false` when the
/// system has none (Chinese then falls back to English, see [`fonts::usable`]).
pub fn install(ctx: &egui::Context) -> bool {
    let Some(cjk) = fonts::cjk() else {
        return false;
    };
    let data = FontData {
        index: cjk.index,
        ..FontData::from_static(&cjk.data)
    };
    ctx.add_font(FontInsert {
        name: cjk.family.clone(),
        data,
        families: [FontFamily::Proportional, FontFamily::Monospace]
            .into_iter()
            .map(|family| InsertFontFamily {
                family,
                priority: FontPriority::Lowest,
            })
            .collect(),
    });
    true
}
