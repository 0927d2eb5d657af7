//! Exports started from the viewer, run on a background job ([`crate::viewer::tools::job`]) so the window
//! stays live: progress is read from the exporter's progress bar (the one the command line
//! draws), cancel sets the job's flag, which the exporter checks.

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use anyhow::{Result, anyhow, bail};
use indicatif::{ProgressBar, ProgressDrawTarget};
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::analysis::workspace::{
    ConstantOrientationWorkspace, WorkspaceControl, WorkspaceSurface,
};
use stewart_kinematics::{Angle, Scenario};

use crate::export::plot::plot_file;
use crate::export::ply::{PlyHeader, ply};
use crate::export::tables::{solve_table, trajectory_place, trajectory_table, write_solved_csv};
use crate::export::video::{VideoRequest, bytes_in_words, export_video, rate_in_words};
use crate::export::workspace_plot::figure_file;
use crate::i18n::Lang;
use crate::output::{Destination, write_atomically};
use crate::viewer::error::JobFailed;
use crate::viewer::error::ViewerError;
use crate::viewer::tools::job::Job;

/// What to export.
#[derive(Clone, Debug)]
pub(crate) enum ExportWork {
    /// Frames, a GIF or an MP4.
    Video(Box<VideoRequest>),
    /// The leg-length plot (SVG, PDF or PNG by extension); with `true`, the actuator
    /// forces instead (as the viewer's plot shows them).
    Plot(PathBuf, bool),
    /// Poses and leg lengths along the trajectory, CSV.
    Csv(PathBuf),
    /// The trajectory as an animated glTF scene.
    Gltf(Box<crate::export::gltf::GltfRequest>),
    /// The workspace's slices through `position` at `orientation` (SVG, PDF or PNG by
    /// extension).
    WorkspaceFigure {
        /// Where.
        path: PathBuf,
        /// Roll, pitch, yaw.
        orientation: [Angle; 3],
        /// Where the slices cross, metres.
        position: [f64; 3],
    },
    /// The workspace surface at `orientation` as PLY.
    SurfacePly {
        /// Where.
        path: PathBuf,
        /// Roll, pitch, yaw.
        orientation: [Angle; 3],
    },
    /// The 3D view with the workspace, PNG.
    SurfacePng(Box<SurfaceView>),
}

/// The 3D view with the workspace surface (and slice) the export computes.
#[derive(Clone, Debug)]
pub(crate) struct SurfaceView {
    /// Where.
    pub(crate) path: PathBuf,
    /// The workspace to draw.
    pub(crate) request: crate::viewer::tools::workspace::Request,
    /// The scene without analysis.
    pub(crate) list: stewart_render::DrawList,
    /// The camera.
    pub(crate) camera: stewart_render::OrbitCamera,
    /// The colours.
    pub(crate) theme: stewart_render::Theme,
    /// Pixels.
    pub(crate) size: (u32, u32),
}

/// An export running (or finished) on a background job.
pub(crate) struct ExportJob {
    job: Job<Result<String>>,
    progress: ProgressBar,
    cancel_asked: bool,
    started: Instant,
    lang: Lang,
}

impl ExportJob {
    /// Start `work` on a copy of `scenario`; messages (and the plot's words) in `lang`.
    pub(crate) fn start(scenario: &Scenario, work: ExportWork, lang: Lang) -> Self {
        let scenario = scenario.clone();
        let progress = ProgressBar::with_draw_target(Some(1), ProgressDrawTarget::hidden());
        let bar = progress.clone();
        let mut job = Job::new("stewart-export");
        job.start(move |worker| {
            let stop = worker.cancel_flag();
            worker.send(run(&scenario, &work, lang, &bar, &stop));
        });
        Self {
            job,
            progress,
            cancel_asked: false,
            started: Instant::now(),
            lang,
        }
    }

    /// Done so far, 0 to 1.
    pub(crate) fn fraction(&self) -> f32 {
        let len = self.progress.length().unwrap_or(1).max(1);
        self.progress.position() as f32 / len as f32
    }

    /// Progress in words: frames done, rate and time left.
    pub(crate) fn describe(&self) -> String {
        let (done, len) = (
            self.progress.position(),
            self.progress.length().unwrap_or(1),
        );
        let seconds = self.started.elapsed().as_secs_f64();
        let rate = done as f64 / seconds.max(1e-3);
        if len <= 1 {
            return self
                .lang
                .fmt("export.working", &[("seconds", &format!("{seconds:.1}"))]);
        }
        let left = (len - done) as f64 / rate.max(1e-9);
        self.lang.fmt(
            "export.progress",
            &[
                ("done", &done),
                ("len", &len),
                ("rate", &format!("{rate:.1}")),
                ("left", &format!("{left:.0}")),
            ],
        )
    }

    /// Ask the export to stop; it then removes what it staged and reports the cancellation.
    pub(crate) fn cancel(&mut self) {
        self.cancel_asked = true;
        self.job.cancel();
    }

    /// Whether cancel was asked for.
    pub(crate) fn cancelling(&self) -> bool {
        self.cancel_asked
    }

    /// The outcome once the export has finished: a sentence saying what was written, or
    /// why nothing was.
    pub(crate) fn poll(&mut self) -> Option<Result<String, ViewerError>> {
        let outcome = self.job.poll()?;
        Some(self.words(outcome))
    }
    /// The job's outcome in words.
    fn words(
        &self,
        outcome: std::result::Result<Result<String>, JobFailed>,
    ) -> Result<String, ViewerError> {
        match outcome {
            Ok(Ok(message)) => Ok(message),
            // The user's own choice: said, not as an error.
            Ok(Err(_)) if self.cancel_asked => Ok(self.lang.tr("export.cancelled").to_owned()),
            Ok(Err(e)) => Err(ViewerError::Export(Arc::new(e))),
            Err(e) => Err(e.into()),
        }
    }
}

fn run(
    scenario: &Scenario,
    work: &ExportWork,
    lang: Lang,
    progress: &ProgressBar,
    stop: &AtomicBool,
) -> Result<String> {
    match work {
        ExportWork::Video(request) => video(scenario, request, lang, progress, stop),
        ExportWork::Plot(path, efforts) => {
            write_atomically(path, &plot_file(scenario, path, lang, *efforts)?)?;
            Ok(lang.fmt("export.wrote_plot", &[("path", &path.display())]))
        }
        ExportWork::Gltf(request) => {
            let report =
                crate::export::gltf::export_gltf(scenario, request, crate::output::NO_INPUTS)?;
            Ok(lang.fmt(
                "export.wrote_gltf",
                &[
                    ("keys", &report.samples),
                    ("path", &request.out.display()),
                    ("size", &bytes_in_words(report.bytes)),
                ],
            ))
        }
        ExportWork::Csv(path) => {
            let table = trajectory_table(scenario);
            let solved = solve_table(&scenario.geometry, &table, |k| trajectory_place(&table, k))?;
            Destination::new(path, crate::output::NO_INPUTS)?
                .write_with(|w| write_solved_csv(w, &table, &solved))?;
            Ok(lang.fmt(
                "export.wrote_csv",
                &[
                    ("count", &scenario.motion.sampling.len()),
                    ("path", &path.display()),
                ],
            ))
        }
        ExportWork::WorkspaceFigure {
            path,
            orientation,
            position,
        } => {
            let ws = workspace(scenario, *orientation, stop, lang)?;
            let bytes = figure_file(scenario, &ws, *orientation, *position, lang, path)?;
            write_atomically(path, &bytes)?;
            Ok(lang.fmt("export.wrote_workspace", &[("path", &path.display())]))
        }
        ExportWork::SurfacePly { path, orientation } => {
            surface_ply(scenario, path, *orientation, lang, stop)
        }
        ExportWork::SurfacePng(view) => surface_png(view, lang, stop),
    }
}

/// Write the video or frames of `request`, and say what was written.
fn video(
    scenario: &Scenario,
    request: &VideoRequest,
    lang: Lang,
    progress: &ProgressBar,
    stop: &AtomicBool,
) -> Result<String> {
    let report = export_video(scenario, request, progress, stop)?;
    Ok(lang.fmt(
        "export.wrote_frames",
        &[
            ("frames", &report.frames),
            ("path", &request.out.display()),
            ("fps", &rate_in_words(report.fps)),
            ("duration", &format!("{:.2}", report.duration)),
            ("size", &bytes_in_words(report.bytes)),
            ("seconds", &format!("{:.1}", report.seconds)),
            (
                "rate",
                &format!("{:.1}", report.frames as f64 / report.seconds.max(1e-9)),
            ),
        ],
    ))
}

/// Write the workspace surface at `orientation` as PLY, and say what was written.
fn surface_ply(
    scenario: &Scenario,
    path: &std::path::Path,
    orientation: [Angle; 3],
    lang: Lang,
    stop: &AtomicBool,
) -> Result<String> {
    let ws = workspace(scenario, orientation, stop, lang)?;
    let surface = WorkspaceSurface::from_workspace(&ws);
    let bytes = ply(
        &surface,
        &PlyHeader {
            name: &scenario.name,
            orientation_deg: orientation.map(Angle::degrees),
            volume: [ws.volume, ws.volume_error],
            resolution: ws.resolution,
        },
    );
    write_atomically(path, &bytes)?;
    Ok(lang.fmt(
        "export.wrote_surface",
        &[
            ("triangles", &surface.triangles.len()),
            ("volume", &format!("{:.6}", surface.enclosed_volume())),
            ("path", &path.display()),
        ],
    ))
}

/// Render the 3D view of `view` with the workspace surface (and slice) to PNG, the
/// computation stopped by `stop`, and say what was written.
fn surface_png(view: &SurfaceView, lang: Lang, stop: &AtomicBool) -> Result<String> {
    let control = WorkspaceControl::default();
    let outcome = std::thread::scope(|s| {
        // Ctrl-C or Cancel stops the computation.
        let watch = s.spawn(|| {
            while !stop.load(Ordering::Relaxed) && !control.cancel.load(Ordering::Relaxed) {
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            control.cancel.store(true, Ordering::Relaxed);
        });
        let outcome = crate::viewer::tools::workspace::compute(
            &view.request,
            crate::viewer::tools::workspace::FINE_COLUMNS,
            160,
            &control,
        );
        control.cancel.store(true, Ordering::Relaxed);
        let _ = watch.join();
        outcome
    })
    .map_err(|e| match e {
        Some(e) => anyhow::Error::from(e),
        None => anyhow!("{}", lang.tr("export.cancelled")),
    })?;
    if outcome.extent.is_none() {
        bail!("{}", lang.tr("export.no_workspace"));
    }
    let mut list = view.list.clone();
    list.analysis.push(outcome.surface);
    if let Some(slice) = outcome.slice {
        list.analysis.push(slice.mesh);
    }
    crate::viewer::view3d::shots::render_view(
        &list,
        view.camera,
        view.theme,
        false,
        view.size,
        &view.path,
        lang,
    )?;
    let (w, h) = view.size;
    Ok(lang.fmt(
        "export.wrote_view",
        &[("w", &w), ("h", &h), ("path", &view.path.display())],
    ))
}

/// The workspace of `scenario` at `orientation` on the viewer's refinement, stopped
/// when `stop` is set; nothing reachable is an error.
fn workspace(
    scenario: &Scenario,
    orientation: [Angle; 3],
    stop: &AtomicBool,
    lang: Lang,
) -> Result<ConstantOrientationWorkspace> {
    let control = WorkspaceControl::default();
    if stop.load(Ordering::Relaxed) {
        control.cancel.store(true, Ordering::Relaxed);
    }
    let ws = workspace::constant_orientation_workspace_with(
        &scenario.geometry,
        &scenario.limits,
        orientation,
        crate::viewer::tools::workspace::FINE_COLUMNS,
        &control,
    )?;
    if ws.extent.is_none() {
        bail!("{}", lang.tr("export.no_workspace"));
    }
    Ok(ws)
}
