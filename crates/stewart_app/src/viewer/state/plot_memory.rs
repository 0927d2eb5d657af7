//! What the plot keeps between frames, in the look: where it drew its parts (what a plot
//! that fits its panel is judged by), and the picture of its curves handed between the
//! plot, which asks for one, and the window, which draws it (see
//! `panels/plot_picture.rs`).

use egui::{Rect, Shape};

/// Where the plot drew its parts, screen points (as last drawn): what a plot that fits its
/// panel is judged by.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PlotPlacement {
    /// The space the panel gave the plot and its legend.
    pub(crate) space: Rect,
    /// The plot's data area (inside its axes).
    pub(crate) frame: Rect,
    /// The times at its left and right edges, seconds.
    pub(crate) times: [f64; 2],
    /// Each limit line drawn: its screen height and its label's rectangle.
    pub(crate) limits: Vec<(f32, Rect)>,
    /// Each legend row.
    pub(crate) legend: Vec<Rect>,
    /// The values/forces toggle, when there is one.
    pub(crate) toggle: Option<Rect>,
    /// The length of the vertical axis's label (it is centred on the frame's height).
    pub(crate) y_label_length: f32,
}

/// What a picture of the curves shows: the curves' data and style, and where in the
/// window at which density (the plot's bounds and frame).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct PictureKey {
    pub(crate) data: u64,
    pub(crate) place: u64,
}

/// Curves the plot wants a picture of: their shapes in window points, the clip they are
/// drawn with, and the pixel-aligned rectangle the picture covers.
#[derive(Clone, Debug)]
pub(crate) struct WantedPicture {
    /// What it shows.
    pub(crate) key: PictureKey,
    /// The picture's rectangle, window points, on whole pixels.
    pub(crate) rect: Rect,
    /// The clip the curves are drawn with, window points.
    pub(crate) clip: Rect,
    /// The window's pixel density.
    pub(crate) pixels_per_point: f32,
    /// The curves' shapes, window points.
    pub(crate) shapes: Vec<Shape>,
}

/// A picture the window drew: its texture, what it shows, and the parts of it that hold
/// anything (window points; the rest is transparent and not drawn: on a software
/// rasteriser every pixel drawn costs time).
#[derive(Clone, Debug)]
pub(crate) struct DrawnPicture {
    /// The texture.
    pub(crate) texture: egui::TextureId,
    /// What it shows.
    pub(crate) key: PictureKey,
    /// The rectangles of it that hold anything.
    pub(crate) parts: std::sync::Arc<Vec<Rect>>,
}

/// The hand-over between the plot and the window (kept in the look).
#[derive(Clone, Debug, Default)]
pub struct CurvesPicture {
    /// The picture the window drew last.
    pub(crate) drawn: Option<DrawnPicture>,
    /// Curves drawn directly that stayed the same for two frames: the window draws their
    /// picture (and takes this).
    pub(crate) wanted: Option<WantedPicture>,
    /// What the curves drawn directly at the last frame were.
    pub(crate) last: Option<PictureKey>,
}
