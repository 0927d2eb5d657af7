//! An export started from the viewer: what the Export panel's form and the view make of
//! it — the video request (size, rate, span, camera, overlays, readout), the work for the
//! background job — and starting it, or asking first when it would replace a file.

use std::path::{Path, PathBuf};

use stewart_render::{Overlays, Theme};

use super::ViewerState;
use crate::export::video::{FramePlan, VideoRequest};
use crate::viewer::state::export_job::{ExportJob, ExportWork, SurfaceView};
use crate::viewer::state::exports::ExportKind;
use crate::viewer::state::files::{Overwrite, WriteAction, absolute};

impl ViewerState {
    /// Export to `path` as the form says: at once, or after asking when it would replace
    /// a file.
    pub(crate) fn export_asking(&mut self, path: &Path) {
        let full = absolute(path);
        if full.exists() {
            self.files.confirm = Some(Overwrite {
                path: full,
                action: WriteAction::Export,
            });
        } else {
            self.start_export(full);
        }
    }

    /// Start the export to `path` (absolute; the user has agreed to replace it if it
    /// exists).
    pub(crate) fn start_export(&mut self, path: PathBuf) {
        let t = self.look.lang;
        let work = work(self, path.clone());
        self.exports.status = None;
        self.exports.written = None;
        self.exports.writing = Some(path);
        // Titled for the audience: the name, without the window's edit mark.
        let mut scenario = self.scenario().clone();
        scenario.name = self.title();
        self.exports.job = Some(ExportJob::start(&scenario, work, t));
    }

    /// The video the form asks for, written to `out`.
    pub(crate) fn video_request(&self, out: PathBuf) -> VideoRequest {
        request(self, out)
    }
}

/// The frame indices `[first, end)` of `plan` whose times lie within `[from, to]` seconds
/// of the motion's start (`None` when none does).
fn frames_within(plan: &FramePlan, [from, to]: [f64; 2]) -> Option<(usize, usize)> {
    // Times grow with the index: the first at or after `from`, the last at or before `to`.
    let start = plan.time(0);
    let tolerance = 1e-9 * (1.0 + to.abs());
    let first = partition_point(plan.count, |k| plan.time(k) - start < from - tolerance);
    let end = partition_point(plan.count, |k| plan.time(k) - start <= to + tolerance);
    (first < end).then_some((first, end))
}

/// The first index in `0..count` where `before` turns false (it is true, then false).
fn partition_point(count: usize, before: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, count);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The video the form asks for (see [`ViewerState::video_request`]).
fn request(state: &ViewerState, out: PathBuf) -> VideoRequest {
    let form = &state.exports.form;
    let mut request = VideoRequest {
        out,
        size: form.size,
        fps: (form.fps > 0.0).then_some(form.fps),
        frames: (None, None),
        theme: Theme::from_light(form.light),
        camera: Some(state.look.camera),
        composite: form.composite,
        overlays: Overlays {
            platform_axes: state.look.platform_axes,
            path: state.look.show_path,
            coloured_legs: state.look.coloured_legs,
            labels: state.look.labels,
            ..Overlays::default()
        },
        readout: if form.title.is_empty() {
            state.look.readouts.then(|| state.title())
        } else {
            Some(form.title.clone())
        },
        lang: state.look.lang,
        speed: form.speed,
        parts: state.doc.parts().clone(),
    };
    if let Some(span) = form.span_s
        && let Ok(plan) = request.plan(state.scenario())
        && let Some((first, end)) = frames_within(&plan, span)
    {
        request.frames = (Some(first), Some(end));
    }
    request
}

/// Where the workspace figure's slices cross: the platform's position, at the slice's
/// height when the Workspace panel sets one.
fn workspace_position(state: &ViewerState) -> [f64; 3] {
    let p = state.pose().position;
    let w = &state.tools.workspace;
    let z = if w.show_slice && !w.slice_follows {
        // The panel's height is the platform centre's; a pose places the reference point.
        p.z + w.slice_height - state.centre().z
    } else {
        p.z
    };
    [p.x, p.y, z]
}

/// The background job's work for the form's kind, written to `path`.
fn work(state: &ViewerState, path: PathBuf) -> ExportWork {
    match state.exports.form.kind {
        ExportKind::Gif | ExportKind::Mp4 | ExportKind::Frames => {
            ExportWork::Video(Box::new(request(state, path)))
        }
        ExportKind::PlotSvg | ExportKind::PlotPdf | ExportKind::PlotPng => {
            let efforts = state.look.plot_efforts && state.doc.plot_efforts().is_some();
            ExportWork::Plot(path, efforts)
        }
        ExportKind::Csv => ExportWork::Csv(path),
        ExportKind::Gltf => ExportWork::Gltf(Box::new(crate::export::gltf::GltfRequest {
            out: path,
            theme: Theme::from_light(state.exports.form.light),
            coloured_legs: state.look.coloured_legs,
            parts: state.doc.parts().clone(),
        })),
        ExportKind::WorkspaceSvg | ExportKind::WorkspacePdf | ExportKind::WorkspacePng => {
            ExportWork::WorkspaceFigure {
                path,
                orientation: state.workspace_orientation(),
                position: workspace_position(state),
            }
        }
        ExportKind::SurfacePly => ExportWork::SurfacePly {
            path,
            orientation: state.workspace_orientation(),
        },
        ExportKind::SurfacePng => {
            let theme = state.theme();
            ExportWork::SurfacePng(Box::new(SurfaceView {
                path,
                request: state.workspace_request(),
                list: {
                    // The job draws the surface it computes, not the one on screen.
                    let mut list = state.scene_list(&theme, Default::default());
                    list.analysis.clear();
                    list
                },
                camera: state.look.camera,
                theme,
                size: state.exports.form.size,
            }))
        }
    }
}
