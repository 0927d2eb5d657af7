//! The Export panel's side of the viewer: what to write and how, the export running on
//! its own thread, and the outcome of the last one.

use super::export_job::ExportJob;
use super::files::Status;
use crate::i18n::Lang;

/// What the export panel will write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExportKind {
    /// Animated GIF.
    Gif,
    /// H.264 MP4 (needs ffmpeg).
    Mp4,
    /// A folder of numbered PNG frames.
    Frames,
    /// The leg-length plot as SVG.
    PlotSvg,
    /// The leg-length plot as PDF.
    PlotPdf,
    /// The leg-length plot as a 300 dpi PNG.
    PlotPng,
    /// Poses and leg lengths, CSV.
    Csv,
}

impl ExportKind {
    /// Every kind, in menu order.
    pub const ALL: [ExportKind; 7] = [
        ExportKind::Gif,
        ExportKind::Mp4,
        ExportKind::Frames,
        ExportKind::PlotSvg,
        ExportKind::PlotPdf,
        ExportKind::PlotPng,
        ExportKind::Csv,
    ];

    /// Words for the menu.
    pub fn label(self, lang: Lang) -> &'static str {
        lang.tr(match self {
            ExportKind::Gif => "export.kind_gif",
            ExportKind::Mp4 => "export.kind_mp4",
            ExportKind::Frames => "export.kind_frames",
            ExportKind::PlotSvg => "export.kind_svg",
            ExportKind::PlotPdf => "export.kind_pdf",
            ExportKind::PlotPng => "export.kind_png",
            ExportKind::Csv => "export.kind_csv",
        })
    }

    /// What the output's name ends in (`""` for a folder).
    pub fn extension(self) -> &'static str {
        match self {
            ExportKind::Gif => ".gif",
            ExportKind::Mp4 => ".mp4",
            ExportKind::Frames => "",
            ExportKind::PlotSvg => ".svg",
            ExportKind::PlotPdf => ".pdf",
            ExportKind::PlotPng => ".png",
            ExportKind::Csv => ".csv",
        }
    }

    /// Whether it renders frames (and so has size, rate and theme).
    pub fn is_video(self) -> bool {
        matches!(self, ExportKind::Gif | ExportKind::Mp4 | ExportKind::Frames)
    }
}

/// The export panel's choices.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportForm {
    /// What to write.
    pub kind: ExportKind,
    /// Where.
    pub path: String,
    /// Frame size, pixels.
    pub size: (u32, u32),
    /// Frames per second; 0: one frame per trajectory sample.
    pub fps: f64,
    /// Light colours.
    pub light: bool,
    /// The plot beside the 3D view.
    pub composite: bool,
}

impl Default for ExportForm {
    fn default() -> Self {
        Self {
            kind: ExportKind::Gif,
            path: String::new(),
            size: (1280, 720),
            fps: 30.0,
            light: false,
            composite: false,
        }
    }
}

/// The Export panel's state.
#[derive(Default)]
pub struct Exports {
    /// The choices.
    pub form: ExportForm,
    /// The export running or last run.
    pub job: Option<ExportJob>,
    /// What the last export did.
    pub status: Status,
}

impl Exports {
    /// Collect the outcome of a finished export.
    pub fn poll(&mut self) {
        if let Some(job) = &mut self.job
            && let Some(outcome) = job.poll()
        {
            self.status = Some(outcome);
            self.job = None;
        }
    }
}
