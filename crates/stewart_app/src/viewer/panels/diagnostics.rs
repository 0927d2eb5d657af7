//! Diagnostics: the pre-flight findings along the trajectory, the architecture banner,
//! and the limits and thresholds the checks use.

use egui::RichText;
use stewart_kinematics::settings::{self, Group};

use super::widgets::{ERROR, edit_error, setting_slider};
use crate::i18n::words;
use crate::viewer::state::ViewerState;

/// Findings listed before "and N more".
const LISTED: usize = 12;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.heading(t.tr("diagnostics.heading"));
    if let Some(report) = state.report() {
        if report.architecture.singular {
            ui.label(RichText::new(words::architecture(t, &report.architecture)).color(ERROR));
        }
        if report.findings.is_empty() {
            ui.label(t.tr("diagnostics.none"));
        } else {
            ui.label(t.fmt("diagnostics.count", &[("count", &report.findings.len())]));
            for f in report.findings.iter().take(LISTED) {
                ui.label(RichText::new(format!("• {}", words::finding(t, f))).small());
            }
            if report.findings.len() > LISTED {
                ui.label(t.fmt(
                    "diagnostics.more",
                    &[("count", &(report.findings.len() - LISTED))],
                ));
            }
        }
    }
    egui::CollapsingHeader::new(t.tr("diagnostics.limits"))
        .default_open(state.look.expand_panels)
        .show(ui, |ui| {
            let targets: Vec<_> = settings::all()
                .iter()
                .filter(|s| matches!(s.group, Group::Limits | Group::Checks))
                .map(|s| s.target)
                .collect();
            for target in targets {
                setting_slider(ui, state, target);
            }
            edit_error(ui, state, &[Group::Limits, Group::Checks]);
        });
}
