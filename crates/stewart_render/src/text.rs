//! Text drawn by the GPU path: leg labels beside the legs and head-up readouts, in the 3D
//! view and in exported frames alike. Glyphs are rasterised on the CPU (ab_glyph) from
//! fonts the system has (fontdb: a Latin sans first, then CJK fonts for Chinese) into one
//! coverage atlas; each string becomes screen-space quads. Pure CPU work up to the
//! vertices, tested without a GPU.

use std::collections::HashMap;
use std::sync::OnceLock;

use ab_glyph::{Font, FontArc, GlyphId, PxScale, ScaleFont};
use glam::{Mat4, Vec3};

use crate::gpu_types::TextVertex;
use crate::theme::{Srgba, linear};

/// Side of the square glyph atlas, pixels.
pub const ATLAS_SIZE: u32 = 1024;

/// Where a string stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Anchor {
    /// Pixels from the view's top-left corner.
    Screen([f32; 2]),
    /// Fractions of the view's width and height from its top-left corner.
    Fraction([f32; 2]),
    /// A world point (projected), moved by an offset in units of the text size (x right,
    /// y down).
    World(Vec3, [f32; 2]),
}

/// How large text is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TextSize {
    /// Line height in pixels.
    Px(f32),
    /// Line height as a fraction of the view's shorter side (the same look at 720p and 4K,
    /// and in a tall narrow view), at least 11 pixels.
    OfView(f32),
}

impl TextSize {
    /// The line height in pixels for a view of `viewport` pixels.
    pub fn px(self, viewport: [f32; 2]) -> f32 {
        match self {
            TextSize::Px(p) => p,
            TextSize::OfView(f) => (f * viewport[0].min(viewport[1])).max(11.0),
        }
        .clamp(4.0, 400.0)
    }
}

/// One string to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct TextItem {
    /// The text; `\n` starts a new line.
    pub text: String,
    /// Where it stands.
    pub anchor: Anchor,
    /// Which point of its box sits on the anchor: (0, 0) top-left, (0.5, 0.5) centre,
    /// (1, 1) bottom-right.
    pub align: [f32; 2],
    /// Font size (line height).
    pub size: TextSize,
    /// Text colour, sRGB.
    pub colour: Srgba,
    /// A box behind the text (with a margin of a quarter of the size), sRGB with alpha.
    pub background: Option<Srgba>,
}

/// The fonts text is drawn with: a Latin sans-serif first, then fonts for what it lacks
/// (Chinese). Found once per process.
pub struct Fonts {
    faces: Vec<FontArc>,
    /// The family names found, first to last.
    pub names: Vec<String>,
}

/// Sans-serif families tried first, in order (Linux, macOS, Windows).
const LATIN: [&str; 6] = [
    "DejaVu Sans",
    "Noto Sans",
    "Liberation Sans",
    "Helvetica",
    "Arial",
    "Segoe UI",
];
/// Families with Simplified Chinese, tried for characters the first font lacks (the
/// viewer's interface font searches the same list).
pub const CJK: [&str; 8] = [
    "WenQuanYi Micro Hei",
    "WenQuanYi Zen Hei",
    "Noto Sans CJK SC",
    "Source Han Sans SC",
    "Droid Sans Fallback",
    "Microsoft YaHei",
    "PingFang SC",
    "SimHei",
];

/// The system's fonts, read once per process and shared by everything that draws text
/// (the 3D labels here; the app's plots and Chinese interface font).
pub fn system_database() -> std::sync::Arc<fontdb::Database> {
    static DB: OnceLock<std::sync::Arc<fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = fontdb::Database::new();
        db.load_system_fonts();
        std::sync::Arc::new(db)
    })
    .clone()
}

impl Fonts {
    /// The system's fonts (searched once per process).
    pub fn system() -> &'static Fonts {
        static FONTS: OnceLock<Fonts> = OnceLock::new();
        FONTS.get_or_init(|| Fonts::from_database(&system_database()))
    }

    /// The first Latin and the first Chinese family of `db` (see [`LATIN`], [`CJK`]), or
    /// any sans-serif face when none of the Latin ones is there.
    pub fn from_database(db: &fontdb::Database) -> Fonts {
        let mut faces = Vec::new();
        let mut names = Vec::new();
        let mut load = |family: fontdb::Family<'_>| {
            // Bold reads better over a 3D scene and on projectors (the nearest weight is
            // taken where a family has no bold).
            let query = fontdb::Query {
                families: &[family],
                weight: fontdb::Weight::BOLD,
                ..fontdb::Query::default()
            };
            let id = db.query(&query)?;
            let name = db
                .face(id)
                .and_then(|f| f.families.first().map(|(n, _)| n.clone()))
                .unwrap_or_default();
            if names.contains(&name) {
                return Some(());
            }
            let font = db.with_face_data(id, |data, index| {
                ab_glyph::FontVec::try_from_vec_and_index(data.to_vec(), index).ok()
            })??;
            faces.push(FontArc::new(font));
            names.push(name);
            Some(())
        };
        let latin = LATIN
            .iter()
            .any(|name| load(fontdb::Family::Name(name)).is_some());
        if !latin {
            let _ = load(fontdb::Family::SansSerif);
        }
        for name in CJK {
            if load(fontdb::Family::Name(name)).is_some() {
                break;
            }
        }
        Fonts { faces, names }
    }

    /// Whether every character of `text` (but spaces and line breaks) has a glyph.
    pub fn covers(&self, text: &str) -> bool {
        text.chars()
            .filter(|c| !c.is_whitespace())
            .all(|c| self.face_of(c).is_some())
    }

    /// The first face that has `c`.
    fn face_of(&self, c: char) -> Option<(usize, GlyphId)> {
        self.faces.iter().enumerate().find_map(|(k, f)| {
            let id = f.glyph_id(c);
            (id.0 != 0).then_some((k, id))
        })
    }
}

/// Where a rasterised glyph sits in the atlas and how to place it.
#[derive(Clone, Copy, Debug)]
struct Placed {
    /// Atlas pixels x0, y0, x1, y1 (empty for blank glyphs).
    rect: [u32; 4],
    /// Offset of the bitmap's top-left from the pen on the baseline, pixels.
    offset: [f32; 2],
}

/// The CPU side of the glyph atlas: one channel of coverage, packed in shelves. A 2 × 2
/// opaque block at the origin draws background boxes.
pub(crate) struct GlyphAtlas {
    pub(crate) pixels: Vec<u8>,
    /// Set when pixels changed since the last upload.
    pub(crate) dirty: bool,
    placed: HashMap<(usize, GlyphId, u32), Placed>,
    shelf: [u32; 3],
}

impl GlyphAtlas {
    pub(crate) fn new() -> Self {
        let mut atlas = Self {
            pixels: vec![0; (ATLAS_SIZE * ATLAS_SIZE) as usize],
            dirty: true,
            placed: HashMap::new(),
            shelf: [0; 3],
        };
        atlas.clear();
        atlas
    }

    /// Empty it (it filled up): only the opaque block stays.
    fn clear(&mut self) {
        self.pixels.fill(0);
        for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            self.pixels[(y * ATLAS_SIZE + x) as usize] = 255;
        }
        self.placed.clear();
        // x, y, height of the current shelf; the block takes the first 4 pixels.
        self.shelf = [4, 0, 4];
        self.dirty = true;
    }

    /// A free `w × h` spot, or `None` when the atlas is full.
    fn reserve(&mut self, w: u32, h: u32) -> Option<[u32; 2]> {
        let [mut x, mut y, mut row] = self.shelf;
        if x + w + 1 > ATLAS_SIZE {
            y += row + 1;
            x = 0;
            row = 0;
        }
        if y + h + 1 > ATLAS_SIZE || w + 1 > ATLAS_SIZE {
            return None;
        }
        self.shelf = [x + w + 1, y, row.max(h)];
        Some([x, y])
    }

    /// The glyph `id` of face `face` at `px`, rasterised into the atlas on first use.
    fn glyph(&mut self, fonts: &Fonts, face: usize, id: GlyphId, px: f32) -> Option<Placed> {
        let key = (face, id, (px * 4.0).round() as u32);
        if let Some(p) = self.placed.get(&key) {
            return Some(*p);
        }
        let font = &fonts.faces[face];
        let glyph = id.with_scale_and_position(PxScale::from(px), ab_glyph::point(0.0, 0.0));
        let placed = match font.outline_glyph(glyph) {
            None => Placed {
                rect: [0; 4],
                offset: [0.0; 2],
            },
            Some(outline) => {
                let b = outline.px_bounds();
                let (w, h) = (b.width() as u32, b.height() as u32);
                let at = match self.reserve(w, h) {
                    Some(at) => at,
                    None => {
                        self.clear();
                        self.reserve(w, h)?
                    }
                };
                outline.draw(|gx, gy, c| {
                    let (x, y) = (at[0] + gx, at[1] + gy);
                    if x < ATLAS_SIZE && y < ATLAS_SIZE {
                        self.pixels[(y * ATLAS_SIZE + x) as usize] =
                            (c.clamp(0.0, 1.0) * 255.0).round() as u8;
                    }
                });
                self.dirty = true;
                Placed {
                    rect: [at[0], at[1], at[0] + w, at[1] + h],
                    offset: [b.min.x, b.min.y],
                }
            }
        };
        self.placed.insert(key, placed);
        Some(placed)
    }

    /// The quads of `items` for a `viewport` (pixels) seen through `view_proj`: two
    /// triangles per glyph and per background box, in normalised device coordinates.
    /// `scale`: the viewport is a picture at this scale of the view shown (text keeps the
    /// size it has in the view: its line heights are the view's times `scale`).
    pub(crate) fn layout(
        &mut self,
        fonts: &Fonts,
        items: &[TextItem],
        view_proj: Mat4,
        viewport: [f32; 2],
        scale: f32,
    ) -> Vec<TextVertex> {
        let mut out = Vec::new();
        let shown = viewport.map(|v| v / scale.max(1e-3));
        for item in items {
            let px = item.size.px(shown) * scale;
            let Some(origin) = anchor_px(item.anchor, view_proj, viewport, px) else {
                continue;
            };
            let lines: Vec<&str> = item.text.split('\n').collect();
            let widths: Vec<f32> = lines.iter().map(|l| line_width(fonts, l, px)).collect();
            let width = widths.iter().copied().fold(0.0, f32::max);
            let height = px * lines.len() as f32;
            let top_left = [
                (origin[0] - item.align[0] * width).round(),
                (origin[1] - item.align[1] * height).round(),
            ];
            if let Some(bg) = item.background {
                let m = 0.25 * px;
                quad(
                    &mut out,
                    [
                        top_left[0] - m,
                        top_left[1] - m,
                        top_left[0] + width + m,
                        top_left[1] + height + m,
                    ],
                    [0.5, 0.5, 1.5, 1.5],
                    linear(bg),
                    viewport,
                );
            }
            let colour = linear(item.colour);
            for (row, line) in lines.iter().enumerate() {
                let baseline = top_left[1] + px * row as f32 + 0.8 * px;
                let mut pen = top_left[0];
                for c in line.chars() {
                    let Some((face, id)) = fonts.face_of(c) else {
                        continue;
                    };
                    let advance = fonts.faces[face].as_scaled(PxScale::from(px)).h_advance(id);
                    if let Some(p) = self.glyph(fonts, face, id, px)
                        && p.rect[2] > p.rect[0]
                    {
                        let x0 = pen + p.offset[0];
                        let y0 = baseline + p.offset[1];
                        let w = (p.rect[2] - p.rect[0]) as f32;
                        let h = (p.rect[3] - p.rect[1]) as f32;
                        quad(
                            &mut out,
                            [x0, y0, x0 + w, y0 + h],
                            p.rect.map(|v| v as f32),
                            colour,
                            viewport,
                        );
                    }
                    pen += advance;
                }
            }
        }
        out
    }
}

/// The width of one line at `px`, pixels.
fn line_width(fonts: &Fonts, line: &str, px: f32) -> f32 {
    line.chars()
        .filter_map(|c| fonts.face_of(c))
        .map(|(face, id)| fonts.faces[face].as_scaled(PxScale::from(px)).h_advance(id))
        .sum()
}

/// The anchor in pixels (offsets in text sizes of `px`), or `None` for a world point
/// behind the camera.
fn anchor_px(anchor: Anchor, view_proj: Mat4, viewport: [f32; 2], px: f32) -> Option<[f32; 2]> {
    match anchor {
        Anchor::Screen(p) => Some(p),
        Anchor::Fraction([fx, fy]) => Some([fx * viewport[0], fy * viewport[1]]),
        Anchor::World(p, offset) => {
            let clip = view_proj * p.extend(1.0);
            if clip.w <= 1e-6 {
                return None;
            }
            let ndc = clip.truncate() / clip.w;
            Some([
                (ndc.x + 1.0) * 0.5 * viewport[0] + offset[0] * px,
                (1.0 - ndc.y) * 0.5 * viewport[1] + offset[1] * px,
            ])
        }
    }
}

/// Two triangles covering pixel rectangle `r` (x0, y0, x1, y1) with atlas pixels `uv`.
fn quad(
    out: &mut Vec<TextVertex>,
    r: [f32; 4],
    uv: [f32; 4],
    colour: [f32; 4],
    viewport: [f32; 2],
) {
    let ndc = |x: f32, y: f32| [2.0 * x / viewport[0] - 1.0, 1.0 - 2.0 * y / viewport[1]];
    let tex = |u: f32, v: f32| [u / ATLAS_SIZE as f32, v / ATLAS_SIZE as f32];
    let corner = |x: usize, y: usize| TextVertex {
        position: ndc(r[2 * x], r[1 + 2 * y]),
        uv: tex(uv[2 * x], uv[1 + 2 * y]),
        color: colour,
    };
    let (a, b, c, d) = (corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
    out.extend_from_slice(&[a, b, c, a, c, d]);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(text: &str, anchor: Anchor) -> TextItem {
        TextItem {
            text: text.to_owned(),
            anchor,
            align: [0.0, 0.0],
            size: TextSize::Px(20.0),
            colour: [1.0; 4],
            background: None,
        }
    }

    #[test]
    fn strings_become_glyph_quads_where_they_are_anchored() {
        let fonts = Fonts::system();
        assert!(
            !fonts.names.is_empty(),
            "no system font (scripts/setup.sh installs DejaVu)"
        );
        assert!(fonts.covers("L1 S6 x = 0.125 m, roll 3.5°"));
        // Chinese from the fallback font (scripts/setup.sh installs WenQuanYi Micro Hei).
        assert!(
            fonts.covers("腿长 位姿 行程 奇异位形 工作空间"),
            "fonts: {:?}",
            fonts.names
        );
        let mut atlas = GlyphAtlas::new();
        let viewport = [400.0, 200.0];
        let quads = atlas.layout(
            fonts,
            &[item("L1", Anchor::Screen([100.0, 50.0]))],
            Mat4::IDENTITY,
            viewport,
            1.0,
        );
        // Two glyphs, six vertices each, inside the box right of and below the anchor.
        assert_eq!(quads.len(), 12);
        for v in &quads {
            let x = (v.position[0] + 1.0) * 0.5 * viewport[0];
            let y = (1.0 - v.position[1]) * 0.5 * viewport[1];
            assert!(
                (99.0..140.0).contains(&x) && (50.0..72.0).contains(&y),
                "{x}, {y}"
            );
        }
        // A centred background box comes first and is centred on the anchor.
        let boxed = TextItem {
            align: [0.5, 0.5],
            background: Some([0.0, 0.0, 0.0, 0.5]),
            ..item("L1", Anchor::Screen([200.0, 100.0]))
        };
        let quads = atlas.layout(fonts, &[boxed], Mat4::IDENTITY, viewport, 1.0);
        assert_eq!(quads.len(), 18);
        let centre = (quads[0].position[0] + quads[2].position[0]) / 2.0;
        assert!(centre.abs() < 0.02, "{centre}");
        // Blanks advance but draw nothing; a second layout reuses the atlas.
        let spaced = atlas.layout(
            fonts,
            &[item("L 1", Anchor::Screen([0.0, 0.0]))],
            Mat4::IDENTITY,
            viewport,
            1.0,
        );
        assert_eq!(spaced.len(), 12);
        // In a picture at half the view's size, text keeps its size in the view: half the
        // pixels of the picture (even below the smallest size a view draws).
        let small = TextItem {
            size: TextSize::OfView(0.01),
            ..item("L", Anchor::Screen([0.0, 0.0]))
        };
        let height = |quads: &[TextVertex], viewport: [f32; 2]| {
            let ys = quads
                .iter()
                .map(|v| (1.0 - v.position[1]) * 0.5 * viewport[1]);
            let (lo, hi) = ys.fold((f32::MAX, f32::MIN), |(a, b), y| (a.min(y), b.max(y)));
            hi - lo
        };
        let full = atlas.layout(
            fonts,
            std::slice::from_ref(&small),
            Mat4::IDENTITY,
            viewport,
            1.0,
        );
        let half_viewport = viewport.map(|v| v / 2.0);
        let half = atlas.layout(fonts, &[small], Mat4::IDENTITY, half_viewport, 0.5);
        let (h_full, h_half) = (height(&full, viewport), height(&half, half_viewport));
        assert!((h_half - h_full / 2.0).abs() <= 1.0, "{h_full} {h_half}");
    }

    #[test]
    fn world_anchors_project_and_points_behind_the_camera_are_skipped() {
        let fonts = Fonts::system();
        let mut atlas = GlyphAtlas::new();
        // Looking along +y at the origin from 5 m.
        let camera = crate::OrbitCamera {
            azimuth_deg: -90.0,
            elevation_deg: 0.0,
            distance: 5.0,
            target: Vec3::ZERO,
        };
        let view_proj = camera.view_proj(2.0);
        let ahead = item("A", Anchor::World(Vec3::ZERO, [0.0, 0.0]));
        let quads = atlas.layout(fonts, &[ahead], view_proj, [400.0, 200.0], 1.0);
        // The origin projects to the middle of the view: the glyph starts there.
        let x = quads.iter().map(|v| v.position[0]).fold(f32::MAX, f32::min);
        assert!(x > -0.05 && x < 0.1, "{x}");
        let behind = item("A", Anchor::World(camera.eye() * 2.0, [0.0, 0.0]));
        assert!(
            atlas
                .layout(fonts, &[behind], view_proj, [400.0, 200.0], 1.0)
                .is_empty()
        );
    }
}
