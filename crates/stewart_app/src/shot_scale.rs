//! How large a screenshot is: the view's size, twice it, or 4K. Shared by the command line
//! (`view --screenshot-scale`) and the viewer's Screenshot menu, so neither reaches into
//! the other.

/// How large a 3D-view shot is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ShotScale {
    /// The view's size on screen.
    One,
    /// Twice that.
    Two,
    /// 3840 × 2160.
    Uhd,
}

impl ShotScale {
    /// Every scale, with its words.
    pub(crate) const ALL: [(ShotScale, &'static str); 3] = [
        (ShotScale::One, "1×"),
        (ShotScale::Two, "2×"),
        (ShotScale::Uhd, "4K"),
    ];

    /// The image size for a view of `view_px` pixels.
    pub(crate) fn size(self, view_px: [u32; 2]) -> (u32, u32) {
        let [w, h] = view_px.map(|v| v.max(16));
        match self {
            ShotScale::One => (w, h),
            ShotScale::Two => ((2 * w).min(8192), (2 * h).min(8192)),
            ShotScale::Uhd => (3840, 2160),
        }
    }
}
