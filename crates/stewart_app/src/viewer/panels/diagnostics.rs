//! Diagnostics: the pre-flight findings along the trajectory, the architecture banner,
//! and the limits and thresholds the checks use.

use egui::RichText;
use stewart_kinematics::settings::{self, Group};

use stewart_kinematics::Layout;

use super::widgets::{edit_error, setting_slider};
use crate::i18n::words;
use crate::viewer::state::ViewerState;

/// Findings listed before "and N more".
const LISTED: usize = 12;

/// An architecturally singular geometry: the verdict in one line, why on demand, and a
/// button to the nearest layout that is not singular.
fn singular_note(ui: &mut egui::Ui, state: &mut ViewerState, explanation: String) {
    let t = state.look.lang;
    ui.label(RichText::new(t.tr("diagnostics.singular_line")).color(ui.visuals().warn_fg_color));
    egui::CollapsingHeader::new(t.tr("diagnostics.singular_why"))
        .id_salt("singular-why")
        .show(ui, |ui| ui.label(RichText::new(explanation).small()));
    if let Some((layout, moved)) = state.sound_layout() {
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
            state.set_layout(layout);
        }
    }
}

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.heading(t.tr("diagnostics.heading"));
    let singular = state
        .report()
        .filter(|r| r.architecture.singular)
        .map(|r| words::architecture(t, &r.architecture));
    if let Some(explanation) = singular {
        singular_note(ui, state, explanation);
    }
    let mut jump = None;
    if let Some(report) = state.report() {
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
                        &[("t", &format!("{:.3}", f.worst_time))],
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
    if let Some(time) = jump {
        let start = state.scenario().motion.sampling.start();
        state.playback.mode = crate::viewer::playback::MotionMode::Trajectory;
        state.playback.playing = false;
        state.playback.time = (time - start).clamp(0.0, state.duration());
    }
    egui::CollapsingHeader::new(t.tr("diagnostics.limits"))
        .default_open(state.look.expand_panels)
        .show(ui, |ui| {
            sliders(ui, state, Group::Limits);
            // The checks' own thresholds (rigid-body tolerance, jump ratio and floor, the
            // near-singular condition number) are for those who tune the checks.
            egui::CollapsingHeader::new(t.tr("diagnostics.advanced"))
                .default_open(state.look.expand_panels)
                .show(ui, |ui| sliders(ui, state, Group::Checks));
            edit_error(ui, state, &[Group::Limits, Group::Checks]);
        });
}

/// A slider for every setting of `group`.
fn sliders(ui: &mut egui::Ui, state: &mut ViewerState, group: Group) {
    let targets: Vec<_> = settings::all()
        .iter()
        .filter(|s| s.group == group)
        .map(|s| s.target)
        .collect();
    for target in targets {
        setting_slider(ui, state, target);
    }
}
