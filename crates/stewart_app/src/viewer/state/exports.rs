//! The Export panel's side of the viewer: what to write and how, the export running on
//! its own thread, and the outcome of the last one.

use crate::i18n::Lang;
use crate::viewer::error::ActionStatus;
use crate::viewer::state::export_job::ExportJob;

/// What the export panel will write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub(crate) enum ExportKind {
    /// Animated GIF.
    Gif,
    /// H.264 MP4 (needs ffmpeg).
    Mp4,
    /// A folder of numbered PNG frames.
    Frames,
    /// The whole trajectory as an animated glTF 2.0 scene (GLB).
    Gltf,
    /// The leg-length plot as SVG.
    PlotSvg,
    /// The leg-length plot as PDF.
    PlotPdf,
    /// The leg-length plot as a 300 dpi PNG.
    PlotPng,
    /// Poses and leg lengths, CSV.
    Csv,
    /// The workspace's two conditioning slices as SVG.
    WorkspaceSvg,
    /// The same as PDF.
    WorkspacePdf,
    /// The same as a 300 dpi PNG.
    WorkspacePng,
    /// The workspace surface as a PLY mesh.
    SurfacePly,
    /// The 3D view with the workspace surface and slice, PNG.
    SurfacePng,
}

impl ExportKind {
    /// Every kind, in menu order.
    pub(crate) const ALL: [ExportKind; 13] = [
        ExportKind::Gif,
        ExportKind::Mp4,
        ExportKind::Frames,
        ExportKind::Gltf,
        ExportKind::PlotSvg,
        ExportKind::PlotPdf,
        ExportKind::PlotPng,
        ExportKind::Csv,
        ExportKind::WorkspaceSvg,
        ExportKind::WorkspacePdf,
        ExportKind::WorkspacePng,
        ExportKind::SurfacePly,
        ExportKind::SurfacePng,
    ];

    /// Words for the menu.
    pub(crate) fn label(self, lang: Lang) -> &'static str {
        lang.tr(match self {
            ExportKind::Gif => "export.kind_gif",
            ExportKind::Mp4 => "export.kind_mp4",
            ExportKind::Frames => "export.kind_frames",
            ExportKind::Gltf => "export.kind_gltf",
            ExportKind::PlotSvg => "export.kind_svg",
            ExportKind::PlotPdf => "export.kind_pdf",
            ExportKind::PlotPng => "export.kind_png",
            ExportKind::Csv => "export.kind_csv",
            ExportKind::WorkspaceSvg => "export.kind_workspace_svg",
            ExportKind::WorkspacePdf => "export.kind_workspace_pdf",
            ExportKind::WorkspacePng => "export.kind_workspace_png",
            ExportKind::SurfacePly => "export.kind_surface_ply",
            ExportKind::SurfacePng => "export.kind_surface_png",
        })
    }

    /// What the output's name ends in (`""` for a folder).
    pub(crate) fn extension(self) -> &'static str {
        match self {
            ExportKind::Gif => ".gif",
            ExportKind::Mp4 => ".mp4",
            ExportKind::Frames => "",
            ExportKind::Gltf => ".glb",
            ExportKind::PlotSvg | ExportKind::WorkspaceSvg => ".svg",
            ExportKind::PlotPdf | ExportKind::WorkspacePdf => ".pdf",
            ExportKind::PlotPng | ExportKind::WorkspacePng | ExportKind::SurfacePng => ".png",
            ExportKind::Csv => ".csv",
            ExportKind::SurfacePly => ".ply",
        }
    }

    /// What the default file name adds to the scenario's name.
    pub(crate) fn suffix(self) -> &'static str {
        match self {
            ExportKind::Frames => "-frames",
            ExportKind::WorkspaceSvg
            | ExportKind::WorkspacePdf
            | ExportKind::WorkspacePng
            | ExportKind::SurfacePly
            | ExportKind::SurfacePng => "-workspace",
            _ => "",
        }
    }

    /// Whether it renders frames (and so has size, rate and theme).
    pub(crate) fn is_video(self) -> bool {
        matches!(self, ExportKind::Gif | ExportKind::Mp4 | ExportKind::Frames)
    }
}

/// The export panel's choices (kept in the session).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub(crate) struct ExportForm {
    /// What to write.
    pub(crate) kind: ExportKind,
    /// Where.
    pub(crate) path: String,
    /// Frame size, pixels.
    pub(crate) size: (u32, u32),
    /// Frames per second; 0: the format's default (25 for GIF, 50 for MP4, one frame
    /// per trajectory sample for PNG frames).
    pub(crate) fps: f64,
    /// Light colours.
    pub(crate) light: bool,
    /// The plot beside the 3D view.
    pub(crate) composite: bool,
    /// Only this part of the motion, seconds from its start (`None`: all of it).
    #[serde(default)]
    pub(crate) span_s: Option<[f64; 2]>,
    /// The readout's title burnt into the frames (empty: the readout as the view shows
    /// it, under the scenario's name).
    #[serde(default)]
    pub(crate) title: String,
    /// How fast the motion plays against real time (below 1: slow motion).
    #[serde(default = "real_time")]
    pub(crate) speed: f64,
}

/// Real time: the speed of a form saved before there was one.
fn real_time() -> f64 {
    1.0
}

impl Default for ExportForm {
    fn default() -> Self {
        Self {
            kind: ExportKind::Gif,
            path: String::new(),
            size: (1280, 720),
            fps: 0.0,
            light: false,
            composite: false,
            span_s: None,
            title: String::new(),
            speed: 1.0,
        }
    }
}

/// The Export panel's state.
#[derive(Default)]
pub(crate) struct Exports {
    /// Whether the export window is open.
    pub(crate) open: bool,
    /// The choices.
    pub(crate) form: ExportForm,
    /// The export running or last run.
    pub(crate) job: Option<ExportJob>,
    /// What the last export did.
    pub(crate) status: ActionStatus,
    /// Where the running export writes (absolute).
    pub(crate) writing: Option<std::path::PathBuf>,
    /// What the last export that succeeded wrote (absolute): *Show in folder* opens its
    /// folder.
    pub(crate) written: Option<std::path::PathBuf>,
}

impl Exports {
    /// Collect the outcome of a finished export.
    pub(crate) fn poll(&mut self) {
        if let Some(job) = &mut self.job
            && let Some(outcome) = job.poll()
        {
            // A cancelled export says so without an error, and wrote nothing.
            self.written = if outcome.is_ok() && !job.cancelling() {
                self.writing.take()
            } else {
                None
            };
            self.writing = None;
            self.status = Some(outcome);
            self.job = None;
        }
    }
}
