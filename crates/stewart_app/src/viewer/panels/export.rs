//! Export: video, frames, the plot and the CSV, written on a background thread with a
//! progress bar and a cancel button.

use std::path::PathBuf;

use stewart_render::{Overlays, Theme};

use super::widgets;
use crate::export::video::VideoRequest;
use crate::viewer::export_job::{ExportJob, ExportWork};
use crate::viewer::exports::ExportKind;
use crate::viewer::state::ViewerState;

/// Frame sizes offered.
const SIZES: [(u32, u32); 5] = [
    (640, 360),
    (1280, 720),
    (1920, 1080),
    (2560, 1440),
    (3840, 2160),
];

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    egui::CollapsingHeader::new(t.tr("export.heading"))
        .default_open(state.look.expand_panels)
        .show(ui, |ui| {
            if let Some(job) = &state.exports.job {
                ui.add(egui::ProgressBar::new(job.fraction()).show_percentage());
                ui.label(job.describe());
                let label = if job.cancelling() {
                    t.tr("export.cancelling")
                } else {
                    t.tr("export.cancel")
                };
                if ui
                    .add_enabled(!job.cancelling(), egui::Button::new(label))
                    .clicked()
                {
                    job.cancel();
                }
                return;
            }
            form(ui, state);
            let path = state.exports.form.path.trim().to_owned();
            if ui
                .add_enabled(!path.is_empty(), egui::Button::new(t.tr("export.export")))
                .clicked()
            {
                let work = work(state, PathBuf::from(path));
                state.exports.status = None;
                state.exports.job = Some(ExportJob::start(state.scenario(), work, t));
            }
            widgets::status(ui, &state.exports.status);
        });
}

fn form(ui: &mut egui::Ui, state: &mut ViewerState) {
    let name = state.scenario().name.clone();
    let t = state.look.lang;
    let form = &mut state.exports.form;
    let before = form.kind;
    egui::ComboBox::from_label(t.tr("export.what"))
        .selected_text(form.kind.label(t))
        .show_ui(ui, |ui| {
            for kind in ExportKind::ALL {
                ui.selectable_value(&mut form.kind, kind, kind.label(t));
            }
        });
    if form.kind != before || form.path.is_empty() {
        let suffix = if form.kind == ExportKind::Frames {
            "-frames"
        } else {
            ""
        };
        form.path = format!("{name}{suffix}{}", form.kind.extension());
    }
    ui.horizontal(|ui| {
        let label = ui.label(t.tr("export.output"));
        ui.text_edit_singleline(&mut form.path)
            .labelled_by(label.id);
    });
    if form.kind.is_video() {
        egui::ComboBox::from_label(t.tr("export.size"))
            .selected_text(format!("{}×{}", form.size.0, form.size.1))
            .show_ui(ui, |ui| {
                for size in SIZES {
                    ui.selectable_value(&mut form.size, size, format!("{}×{}", size.0, size.1));
                }
            });
        ui.add(egui::Slider::new(&mut form.fps, 0.0..=120.0).text(t.tr("export.fps")));
        ui.horizontal(|ui| {
            ui.checkbox(&mut form.light, t.tr("export.light"));
            ui.checkbox(&mut form.composite, t.tr("export.composite"));
        });
        let frames = request(state, PathBuf::new()).frame_count(state.scenario());
        if let Ok(n) = frames {
            ui.label(egui::RichText::new(t.fmt("export.frames", &[("count", &n)])).small());
        }
    }
}

fn request(state: &ViewerState, out: PathBuf) -> VideoRequest {
    let form = &state.exports.form;
    VideoRequest {
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
        readout: state.look.readouts.then(|| state.scenario().name.clone()),
        lang: state.look.lang,
    }
}

fn work(state: &ViewerState, path: PathBuf) -> ExportWork {
    match state.exports.form.kind {
        ExportKind::Gif | ExportKind::Mp4 | ExportKind::Frames => {
            ExportWork::Video(Box::new(request(state, path)))
        }
        ExportKind::PlotSvg | ExportKind::PlotPdf | ExportKind::PlotPng => ExportWork::Plot(path),
        ExportKind::Csv => ExportWork::Csv(path),
    }
}
