//! Export: video, frames, the plot and the CSV, written on a background thread with a
//! progress bar and a cancel button.

use std::path::{Path, PathBuf};

use super::widgets;
use crate::export::video::{FramePlan, RateNote, rate_in_words};
use crate::i18n::Lang;
use crate::viewer::state::exports::{ExportKind, Exports};
use crate::viewer::state::files::absolute;

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

/// A fraction done as whole percent, rounded down (the window and the button agree; 100 %
/// only once done).
fn percent_done(fraction: f32) -> u32 {
    (100.0 * fraction.clamp(0.0, 1.0)).floor() as u32
}

/// The toolbar's *Export…* button: opens (or closes) the export window.
pub(super) fn open_button(ui: &mut egui::Ui, exports: &mut Exports, t: Lang) {
    let busy = exports.job.is_some();
    let words = if busy {
        t.fmt(
            "export.open_busy",
            &[(
                "percent",
                &exports
                    .job
                    .as_ref()
                    .map_or(0, |j| percent_done(j.fraction())),
            )],
        )
    } else {
        t.tr("export.open").to_owned()
    };
    // As wide as its widest words ("Exporting 100 %"): the toolbar's buttons after it stay
    // where they are while an export runs.
    let width = widgets::button_width_for(
        ui,
        &[
            t.tr("export.open").to_owned(),
            t.fmt("export.open_busy", &[("percent", &"100")]),
        ],
    );
    let button = egui::Button::selectable(exports.open, words).min_size(egui::vec2(width, 0.0));
    if ui
        .add(button)
        .on_hover_text(t.tr("export.open_tip"))
        .clicked()
    {
        exports.open = !exports.open;
    }
}

/// What the export window edits and shows: the form, job and status, with the scenario's
/// name and length, and what a video export would write (planned for the path typed).
pub(crate) struct ExportParts<'a> {
    /// The form, the running job, the status, the file last written.
    pub(crate) exports: &'a mut Exports,
    /// The scenario's name (the default file name and title).
    pub(crate) name: &'a str,
    /// The motion's length, seconds.
    pub(crate) duration: f64,
    /// A video export's plan and frame count for the form as it stands.
    pub(crate) plan: Option<(FramePlan, usize)>,
    /// The interface's language.
    pub(crate) lang: Lang,
}

/// What the export window asks of the viewer.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ExportAction {
    /// Choose the output in the file dialog.
    Browse,
    /// Export to this path (asking first when it would replace a file).
    Export(PathBuf),
}

/// The export window, while it is open. Returns what it asks of the viewer.
pub(crate) fn window(ctx: &egui::Context, mut parts: ExportParts) -> Option<ExportAction> {
    if !parts.exports.open {
        return None;
    }
    let t = parts.lang;
    let mut open = true;
    let mut action = None;
    egui::Window::new(t.tr("export.heading"))
        .open(&mut open)
        .resizable(false)
        .collapsible(false)
        .default_pos(ctx.content_rect().right_top() + egui::vec2(-420.0, 60.0))
        .show(ctx, |ui| action = body(ui, &mut parts));
    parts.exports.open &= open;
    action
}

/// What the export window holds: the form and *Export*, or the running export's progress.
fn body(ui: &mut egui::Ui, parts: &mut ExportParts) -> Option<ExportAction> {
    let t = parts.lang;
    let exports = &mut *parts.exports;
    if let Some(job) = &mut exports.job {
        // The percentage the toolbar's button shows, to the unit.
        let done = percent_done(job.fraction());
        ui.add(egui::ProgressBar::new(job.fraction()).text(format!("{done} %")));
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
        return None;
    }
    let mut action = form(ui, parts);
    let exports = &mut *parts.exports;
    let path = exports.form.path.trim().to_owned();
    let sound = title_error(&exports.form.title, t).is_none();
    if ui
        .add_enabled(
            !path.is_empty() && sound,
            egui::Button::new(t.tr("export.export")),
        )
        .on_hover_text(t.tr("export.export_tip"))
        .clicked()
    {
        action = Some(ExportAction::Export(PathBuf::from(path)));
    }
    widgets::status(ui, &exports.status, t);
    if let Some(written) = exports.written.clone()
        && ui
            .button(t.tr("export.show_folder"))
            .on_hover_text(t.tr("export.show_folder_tip"))
            .clicked()
    {
        exports.status = crate::viewer::reveal::show_in_folder(&written)
            .err()
            .map(Err)
            .or(exports.status.take());
    }
    action
}

/// A scenario's name as the start of a file name: runs of spaces and of characters a
/// shell or another system would stumble on (`/ \ : * ? " < > | ( ) [ ]`) become one `-`,
/// none at either end ("My rig (v2)" → "My-rig-v2"; an empty name → "scenario").
pub(crate) fn file_stem(name: &str) -> String {
    let awkward = |c: char| c.is_whitespace() || "/\\:*?\"<>|()[]".contains(c);
    let parts: Vec<&str> = name.split(awkward).filter(|p| !p.is_empty()).collect();
    if parts.is_empty() {
        "scenario".to_owned()
    } else {
        parts.join("-")
    }
}

/// The form; returns [`ExportAction::Browse`] when *Browse…* was pressed.
fn form(ui: &mut egui::Ui, parts: &mut ExportParts) -> Option<ExportAction> {
    let (t, name, duration) = (parts.lang, parts.name, parts.duration);
    let form = &mut parts.exports.form;
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
        form.path = format!(
            "{}{}{}",
            file_stem(name),
            form.kind.suffix(),
            form.kind.extension()
        );
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
    let action = browse.then_some(ExportAction::Browse);
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
        video_options(ui, form, parts.plan.as_ref(), name, duration, t);
    }
    action
}

/// A video's options: rate, speed, colours, the span, the readout's title, and what the
/// export will write.
fn video_options(
    ui: &mut egui::Ui,
    form: &mut crate::viewer::state::exports::ExportForm,
    plan: Option<&(FramePlan, usize)>,
    name: &str,
    duration: f64,
    t: Lang,
) {
    let fps = form.fps;
    let slider = egui::Slider::new(&mut form.fps, 0.0..=120.0);
    widgets::fitted_slider(ui, t.tr("export.fps"), fps, slider);
    let speed = form.speed;
    let slider = egui::Slider::new(&mut form.speed, 0.05..=2.0).logarithmic(true);
    widgets::fitted_slider(ui, t.tr("export.speed"), speed, slider)
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
                .hint_text(name)
                .desired_width(200.0),
        )
        .labelled_by(label.id)
        .on_hover_text(t.tr("export.title_tip"));
    });
    if let Some(e) = title_error(&form.title, t) {
        ui.label(egui::RichText::new(e).color(widgets::ERROR));
    }
    // What the export will write, planned for the path as typed (its extension
    // decides the format and so the default rate).
    if let Some((plan, n)) = plan {
        let n = *n;
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

/// Why the readout's title cannot be burnt in (`None`: empty, or one line that fits), in
/// the interface's language.
fn title_error(title: &str, t: Lang) -> Option<String> {
    use crate::cli::ArgError;
    if title.is_empty() {
        return None;
    }
    crate::cli::parse_title(title).err().map(|e| match e {
        ArgError::LongTitle { chars, max } => {
            t.fmt("export.title_long", &[("chars", &chars), ("max", &max)])
        }
        ArgError::TitleControl { found } => {
            let code = format!("U+{:04X}", u32::from(found));
            t.fmt("export.title_control", &[("code", &code)])
        }
        other => other.to_string(),
    })
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

#[cfg(test)]
mod tests {
    use super::{file_stem, percent_done};

    #[test]
    fn the_button_and_the_window_say_the_same_percentage() {
        assert_eq!(percent_done(0.056), 5);
        assert_eq!(percent_done(0.999), 99);
        assert_eq!(percent_done(1.0), 100);
        assert_eq!(percent_done(f32::NAN), 0);
    }

    #[test]
    fn a_name_becomes_a_file_name_without_spaces_or_awkward_characters() {
        assert_eq!(file_stem("My rig (v2)"), "My-rig-v2");
        assert_eq!(file_stem("seed"), "seed");
        assert_eq!(file_stem("  a/b:c  "), "a-b-c");
        assert_eq!(file_stem("六自由度 平台"), "六自由度-平台");
        assert_eq!(file_stem(" () "), "scenario");
    }
}
