//! Chinese needs a font the system has (egui's own fonts have no CJK glyphs): the first of
//! the renderer's Chinese families that fontdb finds (WenQuanYi Micro Hei on Debian,
//! Microsoft YaHei on Windows, PingFang SC on macOS, …). Without one, Chinese falls back
//! to English with a note, never to boxes.

use std::sync::{Arc, OnceLock};

use super::Lang;

/// A font with Simplified Chinese.
pub(crate) struct CjkFont {
    /// Its family name, as SVG and PDF name it.
    pub(crate) family: String,
    /// The font file's bytes.
    pub(crate) data: Vec<u8>,
    /// The face's index in a collection (`.ttc`).
    pub(crate) index: u32,
}

/// The system's fonts, read once per process and shared by the plots (resvg, svg2pdf)
/// and the Chinese font search (`FONTCONFIG_FILE` narrows them as it does for every
/// fontconfig program; DejaVu Sans on Debian: `fonts-dejavu-core`).
pub(crate) fn system() -> Arc<fontdb::Database> {
    stewart_render::text::system_database()
}

/// The system's Chinese font (searched once per process).
pub(crate) fn cjk() -> Option<&'static CjkFont> {
    static FONT: OnceLock<Option<CjkFont>> = OnceLock::new();
    FONT.get_or_init(|| find(&system())).as_ref()
}

/// The first family of [`stewart_render::text::CJK`] that `db` has, regular weight.
pub(crate) fn find(db: &fontdb::Database) -> Option<CjkFont> {
    stewart_render::text::CJK.iter().find_map(|name| {
        let id = db.query(&fontdb::Query {
            families: &[fontdb::Family::Name(name)],
            ..fontdb::Query::default()
        })?;
        let family = db.face(id)?.families.first()?.0.clone();
        db.with_face_data(id, |data, index| CjkFont {
            family,
            data: data.to_vec(),
            index,
        })
    })
}

/// The language to use when `wanted` was asked for and a Chinese font is (or is not)
/// there: Chinese without a font falls back to English, with the note to show once.
pub(crate) fn usable(wanted: Lang, font_found: bool) -> (Lang, Option<String>) {
    if wanted == Lang::Zh && !font_found {
        (
            Lang::En,
            Some(
                "no font with Chinese characters was found (on Debian: apt-get install fonts-wqy-microhei); \
                 showing English instead"
                    .to_owned(),
            ),
        )
    } else {
        (wanted, None)
    }
}

/// [`usable`] with this system's fonts.
pub(crate) fn usable_here(wanted: Lang) -> (Lang, Option<String>) {
    usable(wanted, wanted == Lang::En || cjk().is_some())
}
