//! Diagnostics: the pre-flight findings along the trajectory, the architecture banner,
//! and the limits and thresholds the checks use.

use egui::RichText;
use stewart_kinematics::settings::{self, Group};

use super::widgets::{ERROR, edit_error, setting_slider};
use crate::viewer::state::ViewerState;

/// Findings listed before "and N more".
const LISTED: usize = 12;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Diagnostics");
    if let Some(report) = state.report() {
        if report.architecture.singular {
            ui.label(RichText::new(report.architecture.explanation()).color(ERROR));
        }
        if report.findings.is_empty() {
            ui.label("No problem found along the trajectory.");
        } else {
            ui.label(format!(
                "{} problem(s) along the trajectory:",
                report.findings.len()
            ));
            for f in report.findings.iter().take(LISTED) {
                ui.label(RichText::new(format!("• {f}")).small());
            }
            if report.findings.len() > LISTED {
                ui.label(format!("… and {} more", report.findings.len() - LISTED));
            }
        }
    }
    egui::CollapsingHeader::new("Limits and check thresholds")
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
