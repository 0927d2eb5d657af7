//! Rendering a trajectory's frames headlessly, optionally beside the leg-length plot.

use anyhow::{Result, anyhow};
use nalgebra::Vector3;
use stewart_kinematics::{Pose, Scenario};
use stewart_render::appearance::parts::PartSet;
use stewart_render::{DrawList, Image, Offscreen, OrbitCamera, Overlays, Theme};

use super::plot;
use super::vector;
use crate::i18n::Lang;

/// What to render.
pub struct FrameJob {
    /// Index of the first frame (frames `first_index..first_index + times.len()`).
    pub first_index: usize,
    /// Times of those frames, seconds.
    pub times: Vec<f64>,
    /// Output size, pixels.
    pub width: u32,
    /// Output size, pixels.
    pub height: u32,
    /// Colours.
    pub theme: Theme,
    /// The camera (for a view as wide as high; narrower views back off); `None`: the
    /// seed's angles, framing the whole motion over `times`.
    pub camera: Option<OrbitCamera>,
    /// The 3D view and the plot side by side.
    pub composite: bool,
    /// Grid, axes, path.
    pub overlays: Overlays,
    /// The readout's title, when the readout is burnt in.
    pub readout: Option<String>,
    /// The language of the readout and the plot.
    pub lang: Lang,
    /// The CAD parts drawn in place of the usual plates and legs.
    pub parts: PartSet,
}

/// The seed's view framing `scenario`'s platform.
pub fn default_camera(scenario: &Scenario) -> OrbitCamera {
    OrbitCamera::seed_view_of(&scenario.geometry)
}

/// Share of the view's half-width and half-height kept free around a framed motion.
pub(crate) const MOTION_MARGIN: f32 = 0.08;

/// Most poses sampled to frame a motion; longer exports take evenly spaced ones.
const FRAMING_POSES: usize = 1024;

/// What a framed view draws: the overlays' solids and the CAD parts.
pub(crate) type Drawn<'a> = (&'a Overlays, &'a PartSet);

/// The seed's angles, with the view (`aspect` = width / height) framing every solid the
/// motion sweeps at `times` (plates, legs, joints, servos, axes as `overlays` draw them,
/// CAD parts), centred below the `top` share of the height (kept for a readout).
pub(crate) fn motion_camera(
    scenario: &Scenario,
    times: &[f64],
    drawn: Drawn<'_>,
    aspect: f32,
    top: f32,
) -> OrbitCamera {
    let seed = default_camera(scenario);
    motion_camera_from(
        scenario,
        times,
        drawn,
        aspect,
        top,
        [seed.azimuth_deg, seed.elevation_deg],
    )
}

/// [`motion_camera`] looking from `[azimuth, elevation]` (degrees) instead of the seed's
/// angles.
pub(crate) fn motion_camera_from(
    scenario: &Scenario,
    times: &[f64],
    drawn: Drawn<'_>,
    aspect: f32,
    top: f32,
    angles: [f32; 2],
) -> OrbitCamera {
    let step = times.len().div_ceil(FRAMING_POSES).max(1);
    let poses = times
        .iter()
        .step_by(step)
        .chain(times.last())
        .map(|&t| scenario.motion.trajectory.pose_at(t));
    poses_camera(scenario, poses, drawn, aspect, top, angles)
}

/// The camera looking from `[azimuth, elevation]` whose view (`aspect` = width / height)
/// frames every solid of `scenario`'s platform at each of `poses`, centred below the `top`
/// share of the height.
pub(crate) fn poses_camera(
    scenario: &Scenario,
    poses: impl Iterator<Item = Pose>,
    (overlays, parts): Drawn<'_>,
    aspect: f32,
    top: f32,
    [azimuth_deg, elevation_deg]: [f32; 2],
) -> OrbitCamera {
    let seed = OrbitCamera {
        azimuth_deg,
        elevation_deg,
        ..default_camera(scenario)
    };
    let g = &scenario.geometry;
    // Only solids count: no grid lines, path or label text to build for each pose.
    let solids = Overlays {
        grid: false,
        path: false,
        labels: false,
        ..*overlays
    };
    let mut points = Vec::new();
    for pose in poses {
        let frame = g.scene_frame(&pose, Vec::new());
        DrawList::build_with_parts(&frame, &Theme::DARK, &solids, parts).solid_extent(&mut points);
    }
    OrbitCamera::fitting_points(
        seed.azimuth_deg,
        seed.elevation_deg,
        &points,
        aspect,
        MOTION_MARGIN,
        top.clamp(0.0, 0.5),
    )
    .unwrap_or_else(|| seed.fitted_to(aspect))
}

/// The plot half of a composite frame: the static plot once, then a marker per frame.
struct PlotPanel {
    width: u32,
    height: u32,
    rgba: Vec<u8>,
    /// Pixel x of t0 and t1 and the plot area's top and bottom rows.
    x_of_t: (f64, f64, f64, f64),
    rows: (u32, u32),
    /// The time marker's colour (dark on paper, light on the dark theme).
    marker: [u8; 4],
}

impl PlotPanel {
    /// The plot of `scenario` filling a `width × height` half in `theme`'s colours, its
    /// text sized for a frame (not a paper).
    fn new(
        scenario: &Scenario,
        lang: Lang,
        theme: &Theme,
        width: u32,
        height: u32,
    ) -> Result<Self> {
        let ink = if theme.background[0] < 0.5 {
            plot::DARK_INK
        } else {
            plot::PAPER_INK
        };
        let aspect = f64::from(width) / f64::from(height.max(1));
        // Text about 1/45 of the frame's height (16 px at 720), whatever the half's width.
        let text = (f64::from(height) / 45.0) / (11.0 * f64::from(width) / plot::WIDTH);
        let page = plot::Page::fitting(aspect, text.clamp(1.0, 3.0), ink);
        let (times, svg) = plot::scenario_svg_on(scenario, lang, &page);
        let (rgba, scale, (ox, oy)) = vector::rgba_fit(&svg, width, height)?;
        let (ml, mr, mt, mb) = page.margins();
        let (scale, ox, oy) = (f64::from(scale), f64::from(ox), f64::from(oy));
        let t0 = times.first().copied().unwrap_or(0.0);
        let t1 = times.last().copied().unwrap_or(1.0);
        Ok(Self {
            width,
            height,
            rgba,
            x_of_t: (ox + ml * scale, ox + (page.width - mr) * scale, t0, t1),
            rows: (
                (oy + mt * scale) as u32,
                (oy + (page.height - mb) * scale) as u32,
            ),
            marker: if ink == plot::DARK_INK {
                [235, 235, 235, 255]
            } else {
                [20, 20, 20, 255]
            },
        })
    }

    /// The panel with a 2-pixel marker at time `t`.
    fn at(&self, t: f64) -> Vec<u8> {
        let mut rgba = self.rgba.clone();
        let (x0, x1, t0, t1) = self.x_of_t;
        let x = (x0 + (t - t0) / (t1 - t0).max(1e-12) * (x1 - x0)).round() as i64;
        for y in self.rows.0..self.rows.1.min(self.height) {
            for dx in 0..2 {
                let xx = x + dx;
                if (0..self.width as i64).contains(&xx) {
                    let i = 4 * (y as usize * self.width as usize + xx as usize);
                    rgba[i..i + 4].copy_from_slice(&self.marker);
                }
            }
        }
        rgba
    }
}

/// Renders the frames of a job one by one.
pub struct FrameSource<'a> {
    scenario: &'a Scenario,
    job: &'a FrameJob,
    offscreen: Offscreen,
    panel: Option<PlotPanel>,
    path: Vec<Vector3<f64>>,
    view_width: u32,
    camera: OrbitCamera,
}

impl<'a> FrameSource<'a> {
    /// Open the GPU and prepare the plot panel.
    pub fn new(scenario: &'a Scenario, job: &'a FrameJob) -> Result<Self> {
        let offscreen = Offscreen::new()?;
        let (view_width, panel) = if job.composite {
            let view = (job.width as f64 * 0.55).round() as u32;
            (
                view,
                Some(PlotPanel::new(
                    scenario,
                    job.lang,
                    &job.theme,
                    job.width - view,
                    job.height,
                )?),
            )
        } else {
            (job.width, None)
        };
        if view_width == 0 {
            return Err(anyhow!("the frame is too narrow for the composite layout"));
        }
        let aspect = view_width as f32 / job.height as f32;
        // A burnt-in readout keeps its band at the top free of the platform.
        let top = match (&job.readout, job.times.first()) {
            (Some(title), Some(&t)) => {
                let pose = scenario.motion.trajectory.pose_at(t);
                let text = crate::readout::lines(
                    job.lang,
                    title,
                    &scenario.geometry,
                    Some(t),
                    &pose,
                    None,
                );
                crate::readout::height_share(&text, [view_width as f32, job.height as f32])
            }
            _ => 0.0,
        };
        let camera = match job.camera {
            Some(c) => c.fitted_to(aspect),
            None => motion_camera(
                scenario,
                &job.times,
                (&job.overlays, &job.parts),
                aspect,
                top,
            ),
        };
        Ok(Self {
            scenario,
            job,
            offscreen,
            panel,
            path: Vec::new(),
            view_width,
            camera,
        })
    }

    /// The adapter in words.
    pub(crate) fn adapter(&self) -> String {
        self.offscreen.adapter()
    }

    /// Width and height of the frames.
    pub(crate) fn frame_size(&self) -> (u32, u32) {
        (self.job.width, self.job.height)
    }

    /// Render frame `k` (frames must be asked for in order for the traced path).
    pub(crate) fn frame(&mut self, k: usize) -> Result<Image> {
        let t = k
            .checked_sub(self.job.first_index)
            .and_then(|i| self.job.times.get(i).copied())
            .ok_or_else(|| anyhow!("internal error: frame {k} is not part of this export"))?;
        let g = &self.scenario.geometry;
        let pose: Pose = self.scenario.motion.trajectory.pose_at(t);
        self.path.push(g.platform_centre(&pose));
        // The path moves into the scene and back: no copy per frame.
        let scene = g.scene_frame(&pose, std::mem::take(&mut self.path));
        let mut list = DrawList::build_with_parts(
            &scene,
            &self.job.theme,
            &self.job.overlays,
            &self.job.parts,
        );
        // The readout shows the values the picture was solved with: one inverse
        // kinematics per frame.
        let solved = scene.actuator_values();
        self.path = scene.path;
        if let Some(title) = &self.job.readout {
            let text = crate::readout::lines(self.job.lang, title, g, Some(t), &pose, solved);
            list.texts.push(crate::readout::item(text, &self.job.theme));
        }
        let view = self.offscreen.render(
            &list,
            &self.camera,
            &self.job.theme,
            self.view_width,
            self.job.height,
        )?;
        let Some(panel) = &self.panel else {
            return Ok(view);
        };
        let plot = panel.at(t);
        let (w, h) = (self.job.width as usize, self.job.height as usize);
        let mut rgba = Vec::with_capacity(w * h * 4);
        for y in 0..h {
            let left = y * self.view_width as usize * 4;
            rgba.extend_from_slice(&view.rgba[left..left + self.view_width as usize * 4]);
            let right = y * panel.width as usize * 4;
            rgba.extend_from_slice(&plot[right..right + panel.width as usize * 4]);
        }
        Ok(Image {
            width: self.job.width,
            height: self.job.height,
            rgba,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_motion_is_framed_below_a_kept_band() {
        let scenario = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let times: Vec<f64> = scenario.motion.sampling.times().step_by(10).collect();
        let overlays = Overlays::default();
        for (aspect, top) in [(16.0 / 9.0, 0.0), (16.0 / 9.0, 0.2), (0.98, 0.3)] {
            let camera = motion_camera(
                &scenario,
                &times,
                (&overlays, &PartSet::none()),
                aspect,
                top,
            );
            let vp = camera.view_proj(aspect);
            let (mut low, mut high) = (f32::INFINITY, f32::NEG_INFINITY);
            for &t in &times {
                let frame = scenario
                    .geometry
                    .scene_frame(&scenario.motion.trajectory.pose_at(t), Vec::new());
                let mut points = Vec::new();
                DrawList::build(&frame, &Theme::DARK, &overlays).solid_extent(&mut points);
                for p in points {
                    let y = vp.project_point3(p).y;
                    low = low.min(y);
                    high = high.max(y);
                }
            }
            // Normalised y runs from −1 (bottom) to 1 (top): the band is above 1 − 2·top.
            assert!(
                high <= 1.0 - 2.0 * top - 0.05,
                "{aspect} {top}: up to {high}"
            );
            assert!(low >= -0.99, "{aspect} {top}: down to {low}");
            let middle = 0.5 * (low + high);
            assert!(
                (middle + top).abs() < 0.02,
                "{aspect} {top}: centred at {middle}"
            );
        }
    }
}
