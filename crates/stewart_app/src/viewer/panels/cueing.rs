//! Motion cueing: the algorithm (classical washout or model-predictive) and its settings
//! (the scenario's `[cueing]` table), and, while a vehicle recording plays as the motion,
//! the vehicle's scaled specific force against the one each algorithm makes felt, their
//! errors and the stroke each uses, and the tilt, over time; on its second tab, the
//! objective motion cueing test of the settings shown (gain and phase of the six direct
//! tests against frequency).

use std::sync::PoisonError;

use egui::RichText;
use egui_plot::{Line, LineStyle, PlotPoints, VLine};
use stewart_kinematics::analysis::cueing::compare::CueMeasures;
use stewart_kinematics::io::settings::{self, Group};
use stewart_kinematics::model::cueing_settings::CueingAlgorithm;

use super::plot::leg_colour;
use super::side_plot;
use super::widgets::{edit_error, setting_slider};
use crate::i18n::Lang;
use crate::vehicle_in::live_cue::{CueCounts, TracePoint};
use crate::viewer::state::editor::Editor;
use crate::viewer::state::vehicle::VehicleSource;
use crate::viewer::tools::omct::{OmctKey, OmctTool};

/// Height of each plot, points.
const PLOT_HEIGHT: f32 = 200.0;

/// The panel; `now` is the scenario time shown (the plots' marker); `live`, the link's
/// live vehicle input while it streams one; `omct`, the objective test's job. Returns
/// whether the user asked to open a vehicle motion recording (the file dialog is the
/// window's).
pub(crate) fn show(
    ui: &mut egui::Ui,
    ed: &mut Editor,
    now: f64,
    live: Option<&CueCounts>,
    omct: &mut OmctTool,
) -> bool {
    let t = ed.lang;
    let mut open = false;
    // Whether the recording played is new since the last frame (the panel open or not).
    let seen = ui.make_persistent_id("cueing recording seen");
    let name = ed.doc.cued_vehicle().map(|v| v.name.clone());
    let just_opened =
        name.is_some() && ui.data(|d| d.get_temp::<Option<String>>(seen)) != Some(name.clone());
    ui.data_mut(|d| d.insert_temp(seen, name));
    egui::CollapsingHeader::new(t.tr("cueing.heading"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            // Two tabs: what a recording (or the live input) makes felt, and the test.
            let tab_id = ui.make_persistent_id("cueing tab");
            let mut testing = ui.data(|d| d.get_temp::<bool>(tab_id)).unwrap_or(false);
            ui.horizontal(|ui| {
                ui.selectable_value(&mut testing, false, t.tr("cueing.tab_motion"));
                ui.selectable_value(&mut testing, true, t.tr("cueing.tab_omct"));
            });
            ui.data_mut(|d| d.insert_temp(tab_id, testing));
            if testing {
                omct_tab(ui, ed, omct);
                settings_section(ui, ed);
                edit_error(ui, ed.doc, t, &[Group::Cueing]);
                return;
            }
            let trace: Vec<TracePoint> = live
                .map(|c| {
                    let trace = c.trace.lock().unwrap_or_else(PoisonError::into_inner);
                    trace.iter().copied().collect()
                })
                .unwrap_or_default();
            match ed.doc.cued_vehicle() {
                _ if live.is_some() => {
                    ui.label(t.tr("cueing.live"));
                    plots(ui, &live_channels(&trace), t, None);
                }
                Some(v) => {
                    let file = std::path::Path::new(&v.name)
                        .file_name()
                        .map_or_else(|| v.name.clone(), |f| f.to_string_lossy().into_owned());
                    let playing = ui.label(t.fmt(
                        "cueing.playing",
                        &[("name", &file), ("count", &v.samples.len())],
                    ));
                    // A recording just opened: its plots in sight (the motion it becomes
                    // lays out a keyframe table above, pushing them down by screens).
                    if just_opened {
                        playing.scroll_to_me(Some(egui::Align::Min));
                    }
                    plots(ui, &Channels::of(v), t, Some(now));
                    for c in &v.compared {
                        measures(ui, &c.measures, t);
                    }
                }
                None => {
                    open = ui.button(t.tr("cueing.open_recording")).clicked();
                    ui.label(RichText::new(t.tr("cueing.hint")).small());
                }
            }
            settings_section(ui, ed);
            edit_error(ui, ed.doc, t, &[Group::Cueing]);
        });
    open
}

/// The objective motion cueing test of the settings shown: a button, then the six direct
/// tests' gain and phase against frequency (log scales), the distorted points named.
fn omct_tab(ui: &mut egui::Ui, ed: &mut Editor, tool: &mut OmctTool) {
    let t = ed.lang;
    let scenario = ed.doc.scenario();
    let key = OmctKey {
        geometry: scenario.geometry.clone(),
        limits: scenario.limits,
        cueing: scenario.cueing.clone(),
    };
    ui.label(RichText::new(t.tr("cueing.omct_about")).small());
    ui.horizontal(|ui| {
        let busy = tool.busy();
        if ui
            .add_enabled(!busy, egui::Button::new(t.tr("cueing.omct_run")))
            .on_hover_text(t.tr("cueing.omct_tip"))
            .clicked()
        {
            tool.start(key.clone());
        }
        if busy {
            ui.spinner();
        }
    });
    let Some(outcome) = &tool.latest else {
        return;
    };
    if outcome.key != key {
        ui.label(RichText::new(t.tr("cueing.omct_stale")).color(super::widgets::WARNING));
        return;
    }
    let report = match &outcome.report {
        Ok(r) => r,
        Err(why) => {
            ui.label(RichText::new(why).color(super::widgets::WARNING));
            return;
        }
    };
    let direct: Vec<_> = report.tests.iter().filter(|r| r.test.direct()).collect();
    let points = |values: &dyn Fn(usize) -> Option<f64>| -> PlotPoints<'static> {
        report
            .frequencies
            .iter()
            .enumerate()
            .filter_map(|(k, w)| values(k).map(|v| [w.log10(), v]))
            .collect()
    };
    let decades = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
        // A decade's mark as its value (0.1, 1, 10), the marks between left bare.
        if (mark.value - mark.value.round()).abs() < 1e-9 {
            let v = 10f64.powf(mark.value.round());
            if v < 1e-3 {
                return format!("{v:.0e}");
            }
            let text = format!("{v:.4}");
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            String::new()
        }
    };
    egui_plot::Plot::new("omct gain")
        .height(PLOT_HEIGHT)
        .allow_scroll(false)
        .allow_drag(false)
        .x_axis_label(t.tr("omct.frequency"))
        .y_axis_label(t.tr("omct.gain"))
        .x_axis_formatter(decades)
        .y_axis_formatter(decades)
        .show(ui, |plot| {
            for (k, r) in direct.iter().enumerate() {
                let gain = points(&|i| (r.gain[i] > 0.0).then(|| r.gain[i].log10()));
                plot.line(
                    Line::new(t.tr(OMCT_WORDS[k]), gain)
                        .color(leg_colour(k))
                        .width([3.4, 1.4, 1.4, 4.0, 2.4, 1.0][k]),
                );
            }
        });
    egui_plot::Plot::new("omct phase")
        .height(PLOT_HEIGHT)
        .allow_scroll(false)
        .allow_drag(false)
        .x_axis_label(t.tr("omct.frequency"))
        .y_axis_label(t.tr("omct.phase"))
        .x_axis_formatter(decades)
        .show(ui, |plot| {
            for (k, r) in direct.iter().enumerate() {
                let continuous = r.continuous_phase_deg();
                let phase = points(&|i| continuous[i].is_finite().then_some(continuous[i]));
                plot.line(
                    Line::new(t.tr(OMCT_WORDS[k]), phase)
                        .color(leg_colour(k))
                        .width([3.4, 1.4, 1.4, 4.0, 2.4, 1.0][k]),
                );
            }
        });
    let entries: Vec<side_plot::LegendEntry> = (0..direct.len().min(6))
        .map(|k| side_plot::LegendEntry {
            colour: leg_colour(k),
            words: t.tr(OMCT_WORDS[k]),
            dashed: false,
            width: 2.0,
        })
        .collect();
    side_plot::legend(ui, &entries);
    let distorted: Vec<String> = report
        .tests
        .iter()
        .flat_map(|r| {
            r.distorted
                .iter()
                .zip(&report.frequencies)
                .filter(|(d, _)| **d)
                .map(move |(_, w)| format!("{} {w:.2}", r.test.name()))
        })
        .collect();
    let note = if distorted.is_empty() {
        t.tr("cueing.omct_clean").to_owned()
    } else {
        t.fmt("cueing.omct_distorted", &[("list", &distorted.join(", "))])
    };
    ui.label(RichText::new(note).small());
}

/// The six direct tests' names, as the figure's key says them.
const OMCT_WORDS: [&str; 6] = [
    "omct.surge",
    "omct.sway",
    "omct.heave",
    "omct.roll",
    "omct.pitch",
    "omct.yaw",
];

/// The algorithm's choice and its settings.
fn settings_section(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    egui::CollapsingHeader::new(t.tr("cueing.settings"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            let algorithm = ed.scenario().cueing.algorithm;
            ui.horizontal_wrapped(|ui| {
                ui.label(t.tr("cueing.algorithm"));
                for choice in CueingAlgorithm::ALL {
                    if ui
                        .selectable_label(algorithm == choice, t.tr(algorithm_words(choice)))
                        .clicked()
                        && algorithm != choice
                    {
                        ed.edit(Group::Cueing, |s| {
                            s.cueing.algorithm = choice;
                            Ok(())
                        });
                    }
                }
            });
            let targets: Vec<_> = settings::all()
                .iter()
                .filter(|s| s.group == Group::Cueing && shown_for(&s.key, algorithm))
                .map(|s| s.target)
                .collect();
            for target in targets {
                setting_slider(ui, ed, target);
            }
            let note = match algorithm {
                CueingAlgorithm::Washout => "cueing.limiter_keeps",
                CueingAlgorithm::Mpc => "cueing.mpc_keeps",
            };
            ui.label(RichText::new(t.tr(note)).small());
        });
}

/// The live input's trace as the plots' channels, times counted back from its last sample.
fn live_channels(trace: &[TracePoint]) -> Channels {
    let end = trace.last().map_or(0.0, |p| p.t);
    let times: Vec<f64> = trace.iter().map(|p| p.t - end).collect();
    Channels {
        times: times.clone(),
        vehicle: trace.iter().map(|p| p.vehicle).collect(),
        platform: trace.iter().map(|p| p.platform).collect(),
        other: None,
        tilt_times: times,
        tilt_deg: trace.iter().map(|p| p.tilt_deg).collect(),
    }
}

/// The words naming `algorithm`.
fn algorithm_words(algorithm: CueingAlgorithm) -> &'static str {
    match algorithm {
        CueingAlgorithm::Washout => "cueing.washout",
        CueingAlgorithm::Mpc => "cueing.mpc",
    }
}

/// The washout's own settings (its filters and limiter), by their names in `[cueing]`.
const WASHOUT_ONLY: [&str; 9] = [
    "translation_hp_wn",
    "translation_hp_zeta",
    "translation_hp_wb",
    "tilt_lp_wn",
    "tilt_lp_zeta",
    "rotation_hp_wn",
    "rotation_hp_zeta",
    "workspace_limiter",
    "limiter_recovery_s",
];

/// Whether the slider of setting `key` is shown for `algorithm` (the other's own are not).
fn shown_for(key: &str, algorithm: CueingAlgorithm) -> bool {
    let name = key.split_once('.').map_or(key, |(_, name)| name);
    match algorithm {
        CueingAlgorithm::Washout => !name.starts_with("mpc_") && name != "vestibular",
        CueingAlgorithm::Mpc => !WASHOUT_ONLY.contains(&name),
    }
}

/// One line on how an algorithm did on the recording.
fn measures(ui: &mut egui::Ui, m: &CueMeasures, t: Lang) {
    // The planner has no limiter to engage.
    let key = match m.algorithm {
        CueingAlgorithm::Washout => "cueing.measures",
        CueingAlgorithm::Mpc => "cueing.measures_mpc",
    };
    let line = t.fmt(
        key,
        &[
            ("algorithm", &t.tr(algorithm_words(m.algorithm))),
            ("rmse", &format!("{:.3}", m.force_rmse_xy)),
            ("stroke", &format!("{:.0}", 100.0 * m.stroke_used)),
            ("limiter", &format!("{:.2}", m.limiter_s)),
        ],
    );
    ui.label(RichText::new(line).small());
}

/// What the plots draw, per sample: time, the wanted (or vehicle's) and the felt specific
/// force, the other algorithm's felt force when compared, and the tilt at its own times.
struct Channels {
    times: Vec<f64>,
    vehicle: Vec<[f64; 3]>,
    platform: Vec<[f64; 3]>,
    other: Option<Vec<[f64; 3]>>,
    tilt_times: Vec<f64>,
    tilt_deg: Vec<[f64; 2]>,
}

impl Channels {
    /// A recording's, through both algorithms: the scenario's solid, the other thin.
    fn of(v: &VehicleSource) -> Self {
        let times: Vec<f64> = v.times().collect();
        let mine = &v.compared[0];
        let other = v.compared.get(1);
        Self {
            times: times
                .iter()
                .skip(1)
                .take(mine.felt.len())
                .copied()
                .collect(),
            vehicle: mine.felt.iter().map(|f| f.1).collect(),
            platform: mine.felt.iter().map(|f| f.0).collect(),
            other: other.map(|o| o.felt.iter().map(|f| f.0).collect()),
            tilt_times: times,
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
    let along = |times: &[f64], value: &dyn Fn(usize) -> f64| -> PlotPoints<'static> {
        times
            .iter()
            .enumerate()
            .map(|(k, &time)| [time, value(k)])
            .collect()
    };
    let series = |value: &dyn Fn(usize) -> f64| along(&c.times, value);
    let ink = ui.visuals().text_color();
    let marker = |plot: &mut egui_plot::PlotUi| {
        if let Some(now) = now {
            plot.vline(VLine::new(t.tr("plot.now"), now).color(ink));
        }
    };
    let dashed = LineStyle::dashed_loose();
    side_plot::plot("cueing force", PLOT_HEIGHT, t.tr("plot.time"))
        .y_axis_label(t.tr("cueing.force_axis"))
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
                if let Some(other) = &c.other {
                    let words = ["cueing.other_x", "cueing.other_y"][axis];
                    plot.line(
                        Line::new(t.tr(words), series(&|k| other[k][axis]))
                            .color(colour.gamma_multiply(0.6))
                            .width(1.0),
                    );
                }
            }
            marker(plot);
        });
    let entry = |axis: usize, words: &'static str, dashed: bool| side_plot::LegendEntry {
        colour: leg_colour(axis),
        words: t.tr(words),
        dashed,
        width: if dashed { 1.5 } else { 2.0 },
    };
    let entries = force_legend(c.other.is_some(), t);
    side_plot::legend(ui, &entries);
    let note = if c.other.is_some() {
        "cueing.compared"
    } else {
        "cueing.dashed_solid"
    };
    ui.label(RichText::new(t.tr(note)).small());
    side_plot::plot("cueing tilt", PLOT_HEIGHT, t.tr("plot.time"))
        .y_axis_label(t.tr("cueing.tilt_axis"))
        .show(ui, |plot| {
            for (axis, words) in [(0, "cueing.tilt_roll"), (1, "cueing.tilt_pitch")] {
                plot.line(
                    Line::new(t.tr(words), along(&c.tilt_times, &|k| c.tilt_deg[k][axis]))
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

/// The force plot's legend: each axis's vehicle (dashed) and platform (solid), and the
/// other algorithm's when two are compared.
fn force_legend(compared: bool, t: Lang) -> Vec<side_plot::LegendEntry<'static>> {
    let entry = |axis: usize, words: &'static str, dashed: bool| side_plot::LegendEntry {
        colour: leg_colour(axis),
        words: t.tr(words),
        dashed,
        width: if dashed { 1.5 } else { 2.0 },
    };
    let mut entries = vec![
        entry(0, "cueing.vehicle_x", true),
        entry(0, "cueing.platform_x", false),
        entry(1, "cueing.vehicle_y", true),
        entry(1, "cueing.platform_y", false),
    ];
    if compared {
        for (axis, words) in [(0, "cueing.other_x"), (1, "cueing.other_y")] {
            entries.push(side_plot::LegendEntry {
                colour: leg_colour(axis).gamma_multiply(0.6),
                words: t.tr(words),
                dashed: false,
                width: 1.0,
            });
        }
    }
    entries
}
