//! Diagnostics: the pre-flight findings along the trajectory, the architecture banner,
//! and the limits and thresholds the checks use.

use egui::RichText;
use stewart_kinematics::io::settings::{self, Group};

use stewart_kinematics::model::layout::Layout;

use super::widgets::{edit_error, setting_slider};
use crate::i18n::words;
use crate::viewer::state::editor::Editor;

/// Findings listed before "and N more".
const LISTED: usize = 12;

/// An architecturally singular geometry: the verdict in one line, why on demand, and a
/// button to the nearest layout that is not singular.
fn singular_note(ui: &mut egui::Ui, ed: &mut Editor, explanation: String) {
    let t = ed.lang;
    ui.label(RichText::new(t.tr("diagnostics.singular_line")).color(ui.visuals().warn_fg_color));
    egui::CollapsingHeader::new(t.tr("diagnostics.singular_why"))
        .id_salt("singular-why")
        .show(ui, |ui| ui.label(RichText::new(explanation).small()));
    if let Some((layout, moved)) = ed.doc.sound_layout() {
        let Layout::Paired {
            base_separation_deg,
            platform_separation_deg,
        } = layout
        else {
            return;
        };
        let words = t.fmt(
            "diagnostics.singular_fix",
            &[
                ("base", &format!("{base_separation_deg:.0}")),
                ("platform", &format!("{platform_separation_deg:.0}")),
            ],
        );
        if ui
            .button(words)
            .on_hover_text(t.fmt(
                "diagnostics.singular_fix_tip",
                &[("moved", &format!("{moved:.0}"))],
            ))
            .clicked()
        {
            ed.set_layout(layout);
        }
    }
}

/// The panel. Returns the time (seconds from the trajectory's start) of the finding
/// clicked, to be shown paused.
pub(crate) fn show(ui: &mut egui::Ui, ed: &mut Editor) -> Option<f64> {
    let t = ed.lang;
    ui.heading(t.tr("diagnostics.heading"));
    let singular = ed
        .doc
        .report()
        .filter(|r| r.architecture.singular)
        .map(|r| words::architecture(t, &r.architecture));
    if let Some(explanation) = singular {
        singular_note(ui, ed, explanation);
    }
    let mut jump = None;
    if let Some(report) = ed.doc.report() {
        if report.findings.is_empty() {
            ui.label(t.tr("diagnostics.none"));
        } else {
            ui.label(t.fmt("diagnostics.count", &[("count", &report.findings.len())]));
            // Each finding is a link to its worst moment: playback pauses there.
            for f in report.findings.iter().take(LISTED) {
                let link = ui
                    .link(format!("• {}", words::finding(t, f)))
                    .on_hover_text(t.fmt(
                        "diagnostics.jump_tip",
                        &[("t", &words::time_text(f.worst_time))],
                    ));
                if link.clicked() {
                    jump = Some(f.worst_time);
                }
            }
            if report.findings.len() > LISTED {
                ui.label(t.fmt(
                    "diagnostics.more",
                    &[("count", &(report.findings.len() - LISTED))],
                ));
            }
        }
    }
    let jump = jump.map(|time| time - ed.scenario().motion.sampling.start());
    egui::CollapsingHeader::new(t.tr("diagnostics.limits"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            sliders(ui, ed, Group::Limits);
            // The checks' own thresholds (rigid-body tolerance, jump ratio and floor, the
            // near-singular condition number) are for those who tune the checks.
            egui::CollapsingHeader::new(t.tr("diagnostics.advanced"))
                .default_open(ed.expand)
                .show(ui, |ui| sliders(ui, ed, Group::Checks));
            edit_error(ui, ed.doc, t, &[Group::Limits, Group::Checks]);
        });
    jump
}

/// A slider for every setting of `group`.
fn sliders(ui: &mut egui::Ui, ed: &mut Editor, group: Group) {
    let targets: Vec<_> = settings::all()
        .iter()
        .filter(|s| s.group == group)
        .map(|s| s.target)
        .collect();
    for target in targets {
        setting_slider(ui, ed, target);
    }
}
