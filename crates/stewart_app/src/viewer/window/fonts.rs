//! The interface's fonts: egui's own, then the system's Chinese font as their fallback, so
//! Chinese labels (and Chinese scenario names in any language) show as characters, never
//! as boxes.

use egui::epaint::text::{FontInsert, FontPriority, InsertFontFamily};
use egui::{FontData, FontFamily};

use crate::i18n::fonts;

/// Set up a new context: the saved egui memory (open panels, scroll positions) first, then
/// the fonts. In that order: a font added is queued in the memory until the next pass, so a
/// memory restored after it would drop the Chinese font and show every Chinese glyph as a
/// box. Returns whether the Chinese font was installed.
pub(crate) fn start(ctx: &egui::Context, memory: Option<egui::Memory>) -> bool {
    if let Some(memory) = memory {
        ctx.memory_mut(|m| *m = memory);
    }
    install(ctx)
}

/// Add the system's Chinese font after egui's fonts in both families; `false` when the
/// system has none (Chinese then falls back to English, see [`fonts::usable`]).
pub(crate) fn install(ctx: &egui::Context) -> bool {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `ctx`'s fonts, after a pass, hold the system's Chinese font.
    fn has_cjk(ctx: &egui::Context) -> bool {
        let mut output = ctx.run_ui(egui::RawInput::default(), |_| {});
        output.textures_delta.clear();
        let family = fonts::cjk().map(|c| c.family.clone()).unwrap_or_default();
        ctx.fonts(|f| f.definitions().font_data.contains_key(&family))
    }

    #[test]
    fn a_restored_memory_keeps_the_chinese_font() {
        if fonts::cjk().is_none() {
            // No Chinese font on this system: nothing to lose (setup.sh installs one).
            return;
        }
        let saved = egui::Context::default();
        saved
            .run_ui(egui::RawInput::default(), |_| {})
            .textures_delta
            .clear();
        let text = saved.memory(|m| ron::to_string(m).unwrap_or_default());
        let memory = || ron::from_str::<egui::Memory>(&text).ok();
        let ctx = egui::Context::default();
        assert!(start(&ctx, memory()));
        assert!(has_cjk(&ctx));
        // The order that lost it: fonts first, then the memory over them.
        let lost = egui::Context::default();
        install(&lost);
        if let Some(m) = memory() {
            lost.memory_mut(|mem| *mem = m);
        }
        assert!(!has_cjk(&lost));
    }
}
