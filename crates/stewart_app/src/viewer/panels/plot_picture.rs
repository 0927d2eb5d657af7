//! The plot's curves shown from a picture while they stay the same.
//!
//! On a software rasteriser every triangle costs time, and the six curves are most of
//! them: a thousand points each, three triangles a segment with egui's anti-aliasing
//! (27 000 of the 1280×720 seed window's triangles, about 10 ms a frame). Playback moves
//! only the time marker, so while the curves, the plot's bounds and its place stay the
//! same, the window draws them once into a picture — with the same egui renderer, at the
//! same pixel density, on the same pixel grid — and the plot shows that picture as one
//! image under the marker and the limit lines. Where anything changed, the curves are
//! drawn directly; once they stayed the same for two frames, the window is asked for a
//! new picture. Used only where the window asks for it (a software rasteriser); on a GPU
//! the curves are always drawn directly.
//!
//! The hover and the plot's bounds still come from the curves themselves: each curve is
//! given to the plot wrapped ([`Pictured`]), drawing nothing while the picture is shown.

use std::cell::{Cell, RefCell};
use std::hash::{Hash, Hasher};

use egui::{Color32, Rect, Shape};
use egui_plot::{PlotGeometry, PlotItem, PlotItemBase, PlotTransform};

use crate::viewer::state::plot_memory::{CurvesPicture, DrawnPicture, PictureKey, WantedPicture};

/// One frame's plot and the picture: built before the plot, read by its items, closed
/// after it ([`PictureSession::finish`]).
pub(crate) struct PictureSession {
    data: u64,
    pixels_per_point: f32,
    drawn: Option<DrawnPicture>,
    /// The picture was shown this frame (the curves draw nothing).
    shown: Cell<bool>,
    /// This frame's key and picture rectangle (set when the plot drew its items).
    place: Cell<Option<(PictureKey, Rect)>>,
    /// The curves' shapes as drawn directly, and their clip.
    recorded: RefCell<(Vec<Shape>, Rect)>,
}

impl PictureSession {
    /// A session for curves whose data and style hash to `data`, at `pixels_per_point`,
    /// with the picture drawn so far.
    pub(crate) fn new(data: u64, pixels_per_point: f32, picture: &CurvesPicture) -> Self {
        Self {
            data,
            pixels_per_point,
            drawn: picture.drawn.clone(),
            shown: Cell::new(false),
            place: Cell::new(None),
            recorded: RefCell::new((Vec::new(), Rect::NOTHING)),
        }
    }

    /// The item that shows the picture (give it to the plot before the curves).
    pub(crate) fn picture(&self) -> PictureItem<'_> {
        PictureItem {
            session: self,
            base: PlotItemBase::new("curves picture".to_owned()),
        }
    }

    /// After the plot: ask for a picture of curves drawn directly that stayed the same
    /// since the last frame.
    pub(crate) fn finish(self, picture: &mut CurvesPicture) {
        let Some((key, rect)) = self.place.get() else {
            picture.last = None;
            return;
        };
        if self.shown.get() {
            picture.last = Some(key);
            return;
        }
        let (shapes, clip) = self.recorded.into_inner();
        if picture.last == Some(key) && !shapes.is_empty() {
            picture.wanted = Some(WantedPicture {
                key,
                rect,
                clip,
                pixels_per_point: self.pixels_per_point,
                shapes,
            });
        }
        picture.last = Some(key);
    }
}

/// A hash of curves' data and style, fed point by point.
#[derive(Default)]
pub(crate) struct DataHash(std::collections::hash_map::DefaultHasher);

impl DataHash {
    /// Feed one curve: its points, colour and width.
    pub(crate) fn curve(&mut self, points: &[[f64; 2]], colour: Color32, width: f32) {
        for p in points {
            p[0].to_bits().hash(&mut self.0);
            p[1].to_bits().hash(&mut self.0);
        }
        colour.hash(&mut self.0);
        width.to_bits().hash(&mut self.0);
    }

    /// The hash of everything fed.
    pub(crate) fn finish(&self) -> u64 {
        self.0.finish()
    }
}

/// The picture `drawn` placed on `rect`: the parts that hold anything, each mapped onto
/// its own texels.
pub(crate) fn picture_mesh(drawn: &DrawnPicture, rect: Rect) -> egui::Mesh {
    let mut mesh = egui::Mesh::with_texture(drawn.texture);
    let size = rect.size();
    for part in drawn.parts.iter() {
        let uv = Rect::from_min_max(
            ((part.min - rect.min) / size).to_pos2(),
            ((part.max - rect.min) / size).to_pos2(),
        );
        mesh.add_rect_with_uv(*part, uv, Color32::WHITE);
    }
    mesh
}

/// The rectangle on whole pixels at `pixels_per_point` that holds `frame`.
pub(crate) fn on_pixels(frame: Rect, pixels_per_point: f32) -> Rect {
    let ppp = pixels_per_point;
    Rect::from_min_max(
        (frame.min.to_vec2() * ppp).floor().to_pos2() / ppp,
        (frame.max.to_vec2() * ppp).ceil().to_pos2() / ppp,
    )
}

/// The plot item that shows the picture when it shows this frame's curves.
pub(crate) struct PictureItem<'s> {
    session: &'s PictureSession,
    base: PlotItemBase,
}

impl PlotItem for PictureItem<'_> {
    fn shapes(&self, _ui: &egui::Ui, transform: &PlotTransform, shapes: &mut Vec<Shape>) {
        let s = self.session;
        let rect = on_pixels(*transform.frame(), s.pixels_per_point);
        let mut place = std::collections::hash_map::DefaultHasher::new();
        let bounds = transform.bounds();
        for v in [bounds.min(), bounds.max()].into_iter().flatten() {
            v.to_bits().hash(&mut place);
        }
        for v in [
            rect.min.x,
            rect.min.y,
            rect.max.x,
            rect.max.y,
            s.pixels_per_point,
        ] {
            v.to_bits().hash(&mut place);
        }
        let key = PictureKey {
            data: s.data,
            place: place.finish(),
        };
        s.place.set(Some((key, rect)));
        if let Some(drawn) = &s.drawn
            && drawn.key == key
        {
            shapes.push(Shape::mesh(picture_mesh(drawn, rect)));
            s.shown.set(true);
        }
    }

    fn initialize(&mut self, _x_range: std::ops::RangeInclusive<f64>) {}

    fn color(&self) -> Color32 {
        Color32::TRANSPARENT
    }

    fn allow_hover(&self) -> bool {
        false
    }

    fn geometry(&self) -> PlotGeometry<'_> {
        PlotGeometry::None
    }

    fn bounds(&self) -> egui_plot::PlotBounds {
        egui_plot::PlotBounds::NOTHING
    }

    fn base(&self) -> &PlotItemBase {
        &self.base
    }

    fn base_mut(&mut self) -> &mut PlotItemBase {
        &mut self.base
    }
}

/// A curve given to the plot: drawn (and its shapes recorded for a picture) unless the
/// picture is shown; its bounds, hover and name are the curve's own.
pub(crate) struct Pictured<'s, I> {
    /// The curve.
    pub(crate) item: I,
    /// This frame's session.
    pub(crate) session: &'s PictureSession,
}

impl<I: PlotItem> PlotItem for Pictured<'_, I> {
    fn shapes(&self, ui: &egui::Ui, transform: &PlotTransform, shapes: &mut Vec<Shape>) {
        if self.session.shown.get() {
            return;
        }
        let start = shapes.len();
        self.item.shapes(ui, transform, shapes);
        let mut recorded = self.session.recorded.borrow_mut();
        recorded.0.extend_from_slice(&shapes[start..]);
        recorded.1 = ui.clip_rect();
    }

    fn initialize(&mut self, x_range: std::ops::RangeInclusive<f64>) {
        self.item.initialize(x_range);
    }

    fn name(&self) -> &str {
        self.item.name()
    }

    fn color(&self) -> Color32 {
        self.item.color()
    }

    fn highlight(&mut self) {
        self.item.highlight();
    }

    fn highlighted(&self) -> bool {
        self.item.highlighted()
    }

    fn allow_hover(&self) -> bool {
        self.item.allow_hover()
    }

    fn geometry(&self) -> PlotGeometry<'_> {
        self.item.geometry()
    }

    fn bounds(&self) -> egui_plot::PlotBounds {
        self.item.bounds()
    }

    fn base(&self) -> &PlotItemBase {
        self.item.base()
    }

    fn base_mut(&mut self) -> &mut PlotItemBase {
        self.item.base_mut()
    }

    fn find_closest(
        &self,
        point: egui::Pos2,
        transform: &PlotTransform,
    ) -> Option<egui_plot::ClosestElem> {
        self.item.find_closest(point, transform)
    }

    fn on_hover(
        &self,
        plot_area_response: &egui::Response,
        elem: egui_plot::ClosestElem,
        shapes: &mut Vec<Shape>,
        cursors: &mut Vec<egui_plot::Cursor>,
        plot: &egui_plot::PlotConfig<'_>,
        label_formatter: Option<&egui_plot::LabelFormatterFn<'_>>,
    ) {
        self.item.on_hover(
            plot_area_response,
            elem,
            shapes,
            cursors,
            plot,
            label_formatter,
        );
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use egui::epaint::Primitive;

    use super::*;
    use crate::viewer::panels::plot::{self, Shows};
    use crate::viewer::state::document::Document;
    use crate::viewer::state::look::Look;
    use crate::viewer::state::playback::Playback;

    /// One frame of the plot alone in a 900×300 window: the triangles drawn, and whether
    /// a mesh of the picture's texture was among them.
    fn frame(
        ctx: &egui::Context,
        doc: &Document,
        playback: &mut Playback,
        look: &mut Look,
    ) -> (usize, bool) {
        let input = egui::RawInput {
            screen_rect: Some(Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(900.0, 300.0),
            )),
            ..Default::default()
        };
        let shows = Shows {
            rolling: false,
            commanded: false,
            background: false,
            pictured: true,
        };
        let mut output = ctx.run_ui(input, |ui| {
            plot::show(ui, doc, playback, look, shows);
        });
        output.textures_delta.clear();
        let primitives = ctx.tessellate(output.shapes, output.pixels_per_point);
        let mut triangles = 0;
        let mut pictured = false;
        for p in &primitives {
            if let Primitive::Mesh(mesh) = &p.primitive {
                triangles += mesh.indices.len() / 3;
                pictured |= mesh.texture_id == PICTURE;
            }
        }
        (triangles, pictured)
    }

    /// The texture the test's "window" draws the picture into.
    const PICTURE: egui::TextureId = egui::TextureId::User(7);

    /// What the window does with a picture asked for: draws it (here: says it did).
    fn window_draws(look: &mut Look) -> bool {
        let Some(wanted) = look.curves_picture.wanted.take() else {
            return false;
        };
        let parts = vec![wanted.rect];
        look.curves_picture.drawn = Some(DrawnPicture {
            texture: PICTURE,
            key: wanted.key,
            parts: Arc::new(parts),
        });
        true
    }

    #[test]
    fn unchanged_curves_are_shown_from_their_picture_and_changed_ones_drawn_again() {
        let scenario = stewart_kinematics::Scenario::seed();
        let mut look = Look::new(crate::export::frames::default_camera(&scenario));
        let home = scenario.geometry.home_pose();
        let mut doc = Document::new(scenario, std::path::PathBuf::from("."));
        let mut playback = Playback::new(home);
        let ctx = egui::Context::default();
        // Drawn directly (the plot's bounds settle over its first frames); once the same
        // at two frames in a row, a picture is asked for.
        let (direct, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
        assert!(!pictured && !window_draws(&mut look));
        let asked = (0..5).position(|_| {
            let (again, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
            assert!(!pictured && again > 10_000);
            window_draws(&mut look)
        });
        assert!(asked.is_some(), "no picture asked for");
        // From then on, while the time marker moves, the curves come from the picture:
        // a few triangles instead of thousands.
        for step in 1..4 {
            playback.time = 0.5 * f64::from(step);
            let (triangles, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
            assert!(pictured, "step {step}");
            assert!(
                triangles + 10_000 < direct,
                "{triangles} triangles against {direct}"
            );
            assert!(look.curves_picture.wanted.is_none());
        }
        // The curves change (another trajectory): drawn directly at once, and a new
        // picture asked for once they stay.
        let mut other = doc.scenario().clone();
        other.geometry = stewart_kinematics::Scenario::preset("paired")
            .unwrap_or_else(|e| panic!("{e}"))
            .geometry;
        doc.replace(other, std::path::PathBuf::from("."));
        let (_, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
        assert!(!pictured);
        assert!(look.curves_picture.wanted.is_none());
        let asked = (0..5).position(|_| {
            let (_, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
            assert!(!pictured);
            window_draws(&mut look)
        });
        assert!(asked.is_some(), "no new picture asked for");
        let (_, pictured) = frame(&ctx, &doc, &mut playback, &mut look);
        assert!(pictured);
    }
}
