//! Export: video, frames, the plot and the CSV, written on a background thread with a
//! progress bar and a cancel button.

use std::path::{Path, PathBuf};

use stewart_render::{Overlays, Theme};

use super::widgets;
use crate::export::video::{FramePlan, RateNote, VideoRequest, rate_in_words};
use crate::i18n::Lang;
use crate::viewer::state::ViewerState;
use crate::viewer::state::export_job::{ExportJob, ExportWork, SurfaceView};
use crate::viewer::state::exports::{ExportKind, Exports};
use crate::viewer::state::files::{Overwrite, Purpose, WriteAction, absolute};

/// Frame sizes offered.
const SIZES: [(u32, u32); 7] = [
    (640, 360),
    (1280, 720),
    (1920, 1080),
    (2560, 1440),
    (3840, 2160),
    (1024, 768),
    (1600, 1200),
];

/// The largest side a frame may have, pixels (as `stewart render --size`).
const MAX_SIDE: u32 = 4096;

/// The toolbar's *Export…* button: opens (or closes) the export window.
pub(super) fn open_button(ui: &mut egui::Ui, exports: &mut Exports, t: Lang) {
    let busy = exports.job.is_some();
    let words = if busy {
        t.fmt(
            "export.open_busy",
            &[(
                "percent",
                &format!(
                    "{:.0}",
                    100.0 * exports.job.as_ref().map_or(0.0, |j| j.fraction())
                ),
            )],
        )
    } else {
        t.tr("export.open").to_owned()
    };
    // As wide as its widest words ("Exporting 100 %"): the toolbar's buttons after it stay
    // where they are while an export runs.
    let widest = [
        t.tr("export.open").to_owned(),
        t.fmt("export.open_busy", &[("percent", &"100")]),
    ]
    .iter()
    .map(|w| {
        egui::WidgetText::from(w.as_str())
            .into_galley(
                ui,
                Some(egui::TextWrapMode::Extend),
                f32::INFINITY,
                egui::TextStyle::Button,
            )
            .size()
            .x
    })
    .fold(0.0, f32::max);
    let width = widest + 2.0 * ui.spacing().button_padding.x;
    let button = egui::Button::selectable(exports.open, words).min_size(egui::vec2(width, 0.0));
    if ui
        .add(button)
        .on_hover_text(t.tr("export.open_tip"))
        .clicked()
    {
        exports.open = !exports.open;
    }
}

/// The export window, while it is open.
pub fn window(ctx: &egui::Context, state: &mut ViewerState) {
    if !state.exports.open {
        return;
    }
    let t = state.look.lang;
    let mut open = true;
    egui::Window::new(t.tr("export.heading"))
        .open(&mut open)
        .resizable(false)
        .collapsible(false)
        .default_pos(ctx.content_rect().right_top() + egui::vec2(-420.0, 60.0))
        .show(ctx, |ui| body(ui, state));
    state.exports.open &= open;
}

/// What the export window holds: the form and *Export*, or the running export's progress.
fn body(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    if let Some(job) = &mut state.exports.job {
        ui.add(egui::ProgressBar::new(job.fraction()).show_percentage());
        ui.label(job.describe());
        let label = if job.cancelling() {
            t.tr("export.cancelling")
        } else {
            t.tr("export.cancel")
        };
        if ui
            .add_enabled(!job.cancelling(), egui::Button::new(label))
            .on_hover_text(t.tr("export.cancel_tip"))
            .clicked()
        {
            job.cancel();
        }
        return;
    }
    form(ui, state);
    let path = state.exports.form.path.trim().to_owned();
    let sound = title_error(&state.exports.form.title).is_none();
    if ui
        .add_enabled(
            !path.is_empty() && sound,
            egui::Button::new(t.tr("export.export")),
        )
        .on_hover_text(t.tr("export.export_tip"))
        .clicked()
    {
        let full = absolute(Path::new(&path));
        if full.exists() {
            state.files.confirm = Some(Overwrite {
                path: full,
                action: WriteAction::Export,
            });
        } else {
            start(state, full);
        }
    }
    widgets::status(ui, &state.exports.status);
    if let Some(written) = state.exports.written.clone()
        && ui
            .button(t.tr("export.show_folder"))
            .on_hover_text(t.tr("export.show_folder_tip"))
            .clicked()
    {
        state.exports.status = crate::viewer::window::reveal::show_in_folder(&written)
            .err()
            .map(Err)
            .or(state.exports.status.take());
    }
}

/// Start the export to `path` (absolute; the user has agreed to replace it if it exists).
pub(super) fn start(state: &mut ViewerState, path: PathBuf) {
    let t = state.look.lang;
    let work = work(state, path.clone());
    state.exports.status = None;
    state.exports.written = None;
    state.exports.writing = Some(path);
    // Titled as shown: "seed (edited)" once the preset was changed.
    let mut scenario = state.scenario().clone();
    scenario.name = state.title();
    state.exports.job = Some(ExportJob::start(&scenario, work, t));
}

fn form(ui: &mut egui::Ui, state: &mut ViewerState) {
    let name = state.scenario().name.clone();
    let duration = state.duration();
    let t = state.look.lang;
    let form = &mut state.exports.form;
    let before = form.kind;
    egui::ComboBox::from_label(t.tr("export.what"))
        .selected_text(form.kind.label(t))
        // Every kind in view at once.
        .height(400.0)
        .show_ui(ui, |ui| {
            for kind in ExportKind::ALL {
                ui.selectable_value(&mut form.kind, kind, kind.label(t));
            }
        });
    if form.kind != before || form.path.is_empty() {
        form.path = format!("{name}{}{}", form.kind.suffix(), form.kind.extension());
    }
    let mut browse = false;
    ui.horizontal(|ui| {
        let label = ui.label(t.tr("export.output"));
        ui.add(egui::TextEdit::singleline(&mut form.path).desired_width(220.0))
            .labelled_by(label.id)
            .on_hover_text(absolute(Path::new(form.path.trim())).display().to_string());
        browse = ui
            .button(t.tr("export.browse"))
            .on_hover_text(t.tr("export.browse_tip"))
            .clicked();
    });
    if browse {
        state.choose_file(Purpose::ExportTo);
    }
    let form = &mut state.exports.form;
    let workspace = matches!(
        form.kind,
        ExportKind::WorkspaceSvg
            | ExportKind::WorkspacePdf
            | ExportKind::WorkspacePng
            | ExportKind::SurfacePly
            | ExportKind::SurfacePng
    );
    if workspace {
        ui.label(egui::RichText::new(t.tr("export.workspace_note")).small());
    }
    if form.kind.is_video() || form.kind == ExportKind::SurfacePng {
        ui.horizontal(|ui| {
            egui::ComboBox::from_label(t.tr("export.size"))
                .selected_text(format!("{}×{}", form.size.0, form.size.1))
                .show_ui(ui, |ui| {
                    for size in SIZES {
                        let words = format!("{}×{}", size.0, size.1);
                        ui.selectable_value(&mut form.size, size, words);
                    }
                });
            // Any other size, typed or dragged.
            ui.add(egui::DragValue::new(&mut form.size.0).range(16..=MAX_SIDE))
                .on_hover_text(t.tr("export.width"));
            ui.label("×");
            ui.add(egui::DragValue::new(&mut form.size.1).range(16..=MAX_SIDE))
                .on_hover_text(t.tr("export.height"));
        });
    }
    if form.kind.is_video() {
        ui.add(egui::Slider::new(&mut form.fps, 0.0..=120.0).text(t.tr("export.fps")));
        ui.add(
            egui::Slider::new(&mut form.speed, 0.05..=2.0)
                .logarithmic(true)
                .text(t.tr("export.speed")),
        )
        .on_hover_text(t.tr("export.speed_tip"));
        ui.horizontal(|ui| {
            ui.checkbox(&mut form.light, t.tr("export.light"));
            ui.checkbox(&mut form.composite, t.tr("export.composite"));
        });
        span(ui, form, duration, t);
        ui.horizontal(|ui| {
            let label = ui.label(t.tr("export.title"));
            ui.add(
                egui::TextEdit::singleline(&mut form.title)
                    .hint_text(name.as_str())
                    .desired_width(200.0),
            )
            .labelled_by(label.id)
            .on_hover_text(t.tr("export.title_tip"));
        });
        if let Some(e) = title_error(&form.title) {
            ui.label(egui::RichText::new(e).color(widgets::ERROR));
        }
        // What the export will write, planned for the path as typed (its extension
        // decides the format and so the default rate).
        let request = request(state, PathBuf::from(state.exports.form.path.trim()));
        let scenario = state.scenario();
        if let (Ok(plan), Ok(n)) = (request.plan(scenario), request.frame_count(scenario)) {
            let words = t.fmt(
                "export.frames",
                &[
                    ("count", &n),
                    ("fps", &rate_in_words(plan.fps)),
                    ("seconds", &format!("{:.2}", n as f64 / plan.fps)),
                ],
            );
            ui.label(egui::RichText::new(words).small());
            if let Some(RateNote::GifRounded {
                asked,
                fps,
                delay_cs,
            }) = plan.note
            {
                let words = t.fmt(
                    "export.gif_rounded",
                    &[
                        ("asked", &rate_in_words(asked)),
                        ("fps", &rate_in_words(fps)),
                        ("delay", &delay_cs),
                    ],
                );
                ui.label(egui::RichText::new(words).small());
            }
        }
    }
}

/// Why the readout's title cannot be burnt in (`None`: empty, or one line that fits).
fn title_error(title: &str) -> Option<String> {
    if title.is_empty() {
        None
    } else {
        crate::cli::parse_title(title).err()
    }
}

/// *Only part of the motion*: from and to, seconds from its start, within `duration`.
fn span(
    ui: &mut egui::Ui,
    form: &mut crate::viewer::state::exports::ExportForm,
    duration: f64,
    t: Lang,
) {
    let mut part = form.span_s.is_some();
    ui.horizontal(|ui| {
        if ui
            .checkbox(&mut part, t.tr("export.span"))
            .on_hover_text(t.tr("export.span_tip"))
            .changed()
        {
            form.span_s = part.then_some([0.0, duration]);
        }
        if let Some([from, to]) = &mut form.span_s {
            let step = duration / 1000.0;
            ui.add(
                egui::DragValue::new(from)
                    .range(0.0..=duration)
                    .speed(step)
                    .suffix(" s"),
            )
            .on_hover_text(t.tr("export.span_from"));
            ui.label("–");
            ui.add(
                egui::DragValue::new(to)
                    .range(0.0..=duration)
                    .speed(step)
                    .suffix(" s"),
            )
            .on_hover_text(t.tr("export.span_to"));
            *to = to.max(*from);
        }
    });
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
    let w = &state.workspace;
    let z = if w.show_slice && !w.slice_follows {
        // The panel's height is the platform centre's; a pose places the reference point.
        p.z + w.slice_height - state.centre().z
    } else {
        p.z
    };
    [p.x, p.y, z]
}

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
                    let mut list = state.draw_list(&theme);
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
