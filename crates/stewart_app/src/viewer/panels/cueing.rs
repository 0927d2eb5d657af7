//! Motion cueing: the washout's settings (the scenario's `[cueing]` table), and, while a
//! vehicle recording plays as the motion, the vehicle's specific force against the one the
//! platform makes felt, and the tilt that renders the sustained part, over time.

use std::sync::PoisonError;

use egui::RichText;
use egui_plot::{Line, LineStyle, PlotPoints, VLine};
use stewart_kinematics::io::settings::{self, Group};

use super::plot::leg_colour;
use super::side_plot;
use super::widgets::{edit_error, setting_slider};
use crate::i18n::Lang;
use crate::live_cue::{CueCounts, TracePoint};
use crate::viewer::state::editor::Editor;
use crate::viewer::state::vehicle::VehicleSource;

/// Height of each plot, points.
const PLOT_HEIGHT: f32 = 200.0;

/// The panel; `now` is the scenario time shown (the plots' marker); `live`, the link's
/// live vehicle input while it streams one. Returns whether the user asked to open a
/// vehicle motion recording (the file dialog is the window's).
pub(crate) fn show(ui: &mut egui::Ui, ed: &mut Editor, now: f64, live: Option<&CueCounts>) -> bool {
    let t = ed.lang;
    let mut open = false;
    egui::CollapsingHeader::new(t.tr("cueing.heading"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            let trace: Vec<TracePoint> = live
                .map(|c| {
                    let trace = c.trace.lock().unwrap_or_else(PoisonError::into_inner);
                    trace.iter().copied().collect()
                })
                .unwrap_or_default();
            match ed.doc.cued_vehicle() {
                _ if live.is_some() => {
                    ui.label(t.tr("cueing.live"));
                    let end = trace.last().map_or(0.0, |p| p.t);
                    let channels = Channels {
                        times: trace.iter().map(|p| p.t - end).collect(),
                        vehicle: trace.iter().map(|p| p.vehicle).collect(),
                        platform: trace.iter().map(|p| p.platform).collect(),
                        tilt_deg: trace.iter().map(|p| p.tilt_deg).collect(),
                    };
                    plots(ui, &channels, t, None);
                }
                Some(v) => {
                    let file = std::path::Path::new(&v.name)
                        .file_name()
                        .map_or_else(|| v.name.clone(), |f| f.to_string_lossy().into_owned());
                    ui.label(t.fmt(
                        "cueing.playing",
                        &[("name", &file), ("count", &v.samples.len())],
                    ));
                    plots(ui, &Channels::of(v), t, Some(now));
                }
                None => {
                    open = ui.button(t.tr("cueing.open_recording")).clicked();
                    ui.label(RichText::new(t.tr("cueing.hint")).small());
                }
            }
            egui::CollapsingHeader::new(t.tr("cueing.settings"))
                .default_open(ed.expand)
                .show(ui, |ui| {
                    let targets: Vec<_> = settings::all()
                        .iter()
                        .filter(|s| s.group == Group::Cueing)
                        .map(|s| s.target)
                        .collect();
                    for target in targets {
                        setting_slider(ui, ed, target);
                    }
                    ui.label(RichText::new(t.tr("cueing.limiter_keeps")).small());
                });
            edit_error(ui, ed.doc, t, &[Group::Cueing]);
        });
    open
}

/// What the plots draw, per sample: time, the vehicle's and the platform's specific force,
/// the tilt.
struct Channels {
    times: Vec<f64>,
    vehicle: Vec<[f64; 3]>,
    platform: Vec<[f64; 3]>,
    tilt_deg: Vec<[f64; 2]>,
}

impl Channels {
    /// A recording's, through the washout.
    fn of(v: &VehicleSource) -> Self {
        Self {
            times: v.times().collect(),
            vehicle: v.samples.iter().map(|s| s.1.accel).collect(),
            platform: v.cued.cues.iter().map(|c| c.specific_force()).collect(),
            tilt_deg: v
                .cued
                .cues
                .iter()
                .map(|c| c.tilt.map(f64::to_degrees))
                .collect(),
        }
    }
}

/// The specific-force plot (vehicle dashed, platform solid, x and y) and the tilt plot,
/// with a marker at `now` when given.
fn plots(ui: &mut egui::Ui, c: &Channels, t: Lang, now: Option<f64>) {
    let series = |value: &dyn Fn(usize) -> f64| -> PlotPoints<'static> {
        c.times
            .iter()
            .enumerate()
            .map(|(k, &time)| [time, value(k)])
            .collect()
    };
    let ink = ui.visuals().text_color();
    let marker = |plot: &mut egui_plot::PlotUi| {
        if let Some(now) = now {
            plot.vline(VLine::new(t.tr("plot.now"), now).color(ink));
        }
    };
    let dashed = LineStyle::dashed_loose();
    side_plot::plot("cueing force", PLOT_HEIGHT)
        .y_axis_label(t.tr("cueing.force_axis"))
        .x_axis_label(t.tr("plot.time"))
        .show(ui, |plot| {
            for (axis, colour) in [(0, leg_colour(0)), (1, leg_colour(1))] {
                let words = ["cueing.vehicle_x", "cueing.vehicle_y"][axis];
                plot.line(
                    Line::new(t.tr(words), series(&|k| c.vehicle[k][axis]))
                        .color(colour)
                        .style(dashed),
                );
                let words = ["cueing.platform_x", "cueing.platform_y"][axis];
                plot.line(
                    Line::new(t.tr(words), series(&|k| c.platform[k][axis]))
                        .color(colour)
                        .width(2.0),
                );
            }
            marker(plot);
        });
    let entry = |axis: usize, words: &'static str, dashed: bool| side_plot::Entry {
        colour: leg_colour(axis),
        words: t.tr(words),
        dashed,
        width: if dashed { 1.5 } else { 2.0 },
    };
    side_plot::legend(
        ui,
        &[
            entry(0, "cueing.vehicle_x", true),
            entry(0, "cueing.platform_x", false),
            entry(1, "cueing.vehicle_y", true),
            entry(1, "cueing.platform_y", false),
        ],
    );
    ui.label(RichText::new(t.tr("cueing.dashed_solid")).small());
    side_plot::plot("cueing tilt", PLOT_HEIGHT)
        .y_axis_label(t.tr("cueing.tilt_axis"))
        .x_axis_label(t.tr("plot.time"))
        .show(ui, |plot| {
            for (axis, words) in [(0, "cueing.tilt_roll"), (1, "cueing.tilt_pitch")] {
                plot.line(
                    Line::new(t.tr(words), series(&|k| c.tilt_deg[k][axis]))
                        .color(leg_colour(axis + 2))
                        .width(2.0),
                );
            }
            marker(plot);
        });
    side_plot::legend(
        ui,
        &[
            entry(2, "cueing.tilt_roll", false),
            entry(3, "cueing.tilt_pitch", false),
        ],
    );
}
