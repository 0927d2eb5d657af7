//! How the viewer looks: the camera, colours, presentation mode, what the 3D view
//! draws beyond the platform, and whether the 3D renderer is there at all.

use stewart_render::{OrbitCamera, Theme};

use crate::i18n::Lang;

/// Text sizes are multiplied by this in presentation mode.
pub(crate) const PRESENTATION_TEXT_SCALE: f32 = 1.5;

/// The view's settings.
#[derive(Clone, Debug)]
pub struct Look {
    /// The camera.
    pub(crate) camera: OrbitCamera,
    /// The interface's language.
    pub(crate) lang: Lang,
    /// Light (presentation) or dark colours.
    pub(crate) light_theme: bool,
    /// Presentation mode: light colours, large text, control panels hidden.
    pub(crate) presentation: bool,
    /// The camera before presentation mode re-framed the scene for its larger view, put
    /// back when presentation mode ends (`None` outside it).
    pub(crate) camera_before_presentation: Option<OrbitCamera>,
    /// The camera presentation mode framed and the view's aspect it framed it for: while
    /// the camera is left as framed, a new aspect (the layout settling, a resized window)
    /// frames it again.
    pub(crate) presentation_framed: Option<(OrbitCamera, f32)>,
    /// The plot's height before presentation mode, given back when it ends.
    pub(crate) plot_height_before_presentation: Option<f32>,
    /// The plot's height to set at the next frame (leaving presentation mode).
    pub(crate) plot_height_to_restore: Option<f32>,
    /// Presentation mode shows the view alone (G shows the plot again).
    pub(crate) plot_hidden: bool,
    /// The platform the camera was last checked against (a geometry edit that takes the
    /// scene out of the view fits the camera to it again).
    pub(crate) geometry_seen: Option<stewart_kinematics::GeometryParams>,
    /// The *Help / keys* window is open (F1 or ?).
    pub(crate) help: bool,
    /// Full screen (F11); the window follows it.
    pub(crate) fullscreen: bool,
    /// Open every collapsible section at start (for screenshots of everything).
    pub expand_panels: bool,
    /// Draw the path the platform centre has traced.
    pub(crate) show_path: bool,
    /// Draw the platform's own axes.
    pub(crate) platform_axes: bool,
    /// Each leg in its plot colour (off: the single-colour look).
    pub(crate) coloured_legs: bool,
    /// Numbered labels beside the legs.
    pub(crate) labels: bool,
    /// The head-up readout (time, pose, values) over the view and in exported frames.
    pub(crate) readouts: bool,
    /// The frame-time readout in the 3D view's status line (Advanced).
    pub(crate) frame_times: bool,
    /// The plot shows the actuator forces (or torques) instead of lengths (or angles).
    pub(crate) plot_efforts: bool,
    /// The controls' panel's width as last drawn, logical pixels (its edge drags).
    pub(crate) side_width: f32,
    /// The plot panel's height as last drawn, logical pixels (its top edge drags).
    pub(crate) plot_height: f32,
    /// Where the plot drew its frame, limits, legend and toggle last (`None` while hidden
    /// or before the first frame).
    pub(crate) plot_placement: Option<crate::viewer::state::plot_memory::PlotPlacement>,
    /// The plot's curves as a picture the window draws (a software rasteriser).
    pub(crate) curves_picture: crate::viewer::state::plot_memory::CurvesPicture,
    /// The 3D view's size on screen, physical pixels (for screenshots at 1× and 2×).
    pub(crate) view_px: [u32; 2],
    /// The 3D view's width over its height, as laid out last frame.
    pub(crate) view_aspect: f32,
    /// Why the 3D view cannot be drawn, empty for "no renderer yet" (`None` once the window
    /// registered its renderer).
    pub(crate) renderer_missing: Option<String>,
}

impl Look {
    /// Dark colours, path shown, looking through `camera`; no renderer yet.
    pub(crate) fn new(camera: OrbitCamera) -> Self {
        Self {
            camera,
            lang: Lang::En,
            light_theme: false,
            presentation: false,
            camera_before_presentation: None,
            presentation_framed: None,
            plot_height_before_presentation: None,
            plot_height_to_restore: None,
            plot_hidden: false,
            geometry_seen: None,
            help: false,
            fullscreen: false,
            expand_panels: false,
            show_path: true,
            platform_axes: false,
            coloured_legs: true,
            labels: true,
            readouts: false,
            frame_times: false,
            plot_efforts: false,
            side_width: 0.0,
            plot_height: 0.0,
            plot_placement: None,
            curves_picture: Default::default(),
            view_px: [1280, 720],
            view_aspect: 16.0 / 9.0,
            renderer_missing: Some(String::new()),
        }
    }

    /// Whether colours are light (the light theme, or presentation mode).
    pub(crate) fn is_light(&self) -> bool {
        self.light_theme || self.presentation
    }

    /// The colour theme (presentation mode is always light).
    pub(crate) fn theme(&self) -> Theme {
        Theme::from_light(self.is_light())
    }
}
