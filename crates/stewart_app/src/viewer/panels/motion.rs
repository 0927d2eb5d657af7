//! Motion: the manual pose's six sliders, or the trajectory's kind, sampling and every
//! number of that kind (sinusoid channels, shape parameters, keyframes).

use stewart_kinematics::io::settings::{
    ChannelKey, Group, SamplingKey, SettingTarget, ShapeKey, TrajectoryChoice, Unit,
};
use stewart_kinematics::model::trajectory::{
    CHANNEL_NAMES, Interpolation, Keyframe, Keyframes, Trajectory, Wave,
};
use stewart_kinematics::{Pose, Scenario};

use super::context::PanelContext;
use super::widgets::{self, edit_error, setting_slider};
use crate::i18n::{Lang, words};
use crate::viewer::state::Teleop;
use crate::viewer::state::document::Document;
use crate::viewer::state::editor::Editor;
use crate::viewer::state::playback::{MotionMode, Playback};
use crate::viewer::state::teleop;
use crate::viewer::tools::assembly::NoMode;
use crate::viewer::tools::reach::ReachCache;

/// The manual pose's sliders: name, unit and reach either side of home (z: of the home
/// height), in the pose's coordinate order x, y, z, roll, pitch, yaw.
const POSE_SLIDERS: [(&str, Unit, f64); 6] = [
    ("x", Unit::Metre, 0.3),
    ("y", Unit::Metre, 0.3),
    ("z", Unit::Metre, 0.3),
    ("roll", Unit::Degree, 30.0),
    ("pitch", Unit::Degree, 30.0),
    ("yaw", Unit::Degree, 120.0),
];

/// What the Motion panel edits and reads: the document and playback (the trajectory's
/// settings, the mode, the manual pose), teleoperation's rates and edge, the reach cache of
/// the manual sliders, and the assembly mode shown.
pub(crate) struct MotionParts<'a> {
    /// The scenario being edited.
    pub(crate) doc: &'a mut Document,
    /// The mode and the manual pose.
    pub(crate) playback: &'a mut Playback,
    /// The keyboard and gamepad rates, and where a move stopped.
    pub(crate) teleop: &'a mut Teleop,
    /// The reachable part of each manual slider.
    pub(crate) reach: &'a mut ReachCache,
    /// The assembly mode shown (its index and the number of modes), if any.
    pub(crate) assembly_shown: Option<(usize, usize)>,
    /// Why the last *next assembly mode* found none.
    pub(crate) assembly_error: Option<&'a NoMode>,
    /// The frame's context: the language, whether sections start open, the pose shown.
    pub(crate) cx: &'a PanelContext,
}

/// The panel. Returns whether *Next assembly mode* was pressed (the caller finds it).
pub(crate) fn show(ui: &mut egui::Ui, mut parts: MotionParts) -> bool {
    let t = parts.cx.lang;
    ui.heading(t.tr("motion.heading"));
    ui.horizontal(|ui| {
        ui.selectable_value(
            &mut parts.playback.mode,
            MotionMode::Trajectory,
            t.tr("motion.trajectory"),
        );
        ui.selectable_value(
            &mut parts.playback.mode,
            MotionMode::Manual,
            t.tr("motion.manual"),
        );
    });
    let next = assembly_modes(ui, &parts);
    match parts.playback.mode {
        MotionMode::Manual => manual(ui, &mut parts),
        MotionMode::Trajectory => trajectory(
            ui,
            &mut Editor::new(parts.doc, parts.playback, t, parts.cx.expand),
        ),
    }
    edit_error(ui, parts.doc, t, &[Group::Trajectory]);
    next
}

/// The button that shows the next assembly mode of the legs shown, and which one it is.
/// Returns whether it was pressed.
fn assembly_modes(ui: &mut egui::Ui, parts: &MotionParts) -> bool {
    let t = parts.cx.lang;
    let mut next = false;
    ui.horizontal(|ui| {
        next = ui
            .button(t.tr("motion.next_mode"))
            .on_hover_text(t.tr("motion.next_mode_tip"))
            .clicked();
        let shown = parts.assembly_shown.filter(|_| {
            parts.playback.mode == MotionMode::Manual && parts.assembly_error.is_none()
        });
        if let Some((k, n)) = shown {
            ui.label(t.fmt("motion.mode_of", &[("k", &(k + 1)), ("n", &n)]));
        }
    });
    if let Some(why) = parts.assembly_error {
        let text = match why {
            NoMode::Singular => t.tr("motion.modes_singular").to_owned(),
            NoMode::Unreachable(why) => t.fmt("motion.no_modes", &[("why", why)]),
            NoMode::Solver(why) => t.fmt("motion.no_modes", &[("why", why)]),
            NoMode::NoRealPose => t.fmt("motion.no_modes", &[("why", &"no real pose")]),
        };
        ui.colored_label(ui.visuals().warn_fg_color, text);
    }
    next
}

fn manual(ui: &mut egui::Ui, parts: &mut MotionParts) {
    let t = parts.cx.lang;
    let scenario = parts.doc.scenario();
    let home = scenario.geometry.home_pose().to_coordinates();
    let mut c = parts.playback.manual.to_coordinates();
    // Each slider's bounds in pose coordinates, and the part of them reachable with the
    // other coordinates held.
    let bounds: [[f64; 2]; 6] = std::array::from_fn(|k| {
        let (_, unit, reach) = POSE_SLIDERS[k];
        let reach = if unit == Unit::Degree {
            reach.to_radians()
        } else {
            reach
        };
        [home[k] - reach, home[k] + reach]
    });
    let reachable =
        parts
            .reach
            .sliders(&scenario.geometry, &scenario.limits, &parts.cx.pose, bounds);
    let certified = parts
        .reach
        .certified(&scenario.geometry, &parts.cx.pose, bounds);
    for (k, (name, unit, reach)) in POSE_SLIDERS.into_iter().enumerate() {
        let angular = unit == Unit::Degree;
        let mut value = if angular { c[k].to_degrees() } else { c[k] };
        let centre = if angular {
            home[k].to_degrees()
        } else {
            home[k]
        };
        let label = format!("{} ({})", words::coordinate(t, name), unit.symbol());
        let to_slider = |v: f64| if angular { v.to_degrees() } else { v };
        if ui
            .add(egui::Slider::new(&mut value, centre - reach..=centre + reach).text(label))
            .on_hover_text(t.tr("motion.reach_tip"))
            .changed()
        {
            c[k] = if angular { value.to_radians() } else { value };
        }
        // Under the rail: the reachable part of the slider's range.
        let handle = ui.spacing().interact_size.y / 2.5;
        ui.add_space(-ui.spacing().item_spacing.y);
        ui.horizontal(|ui| {
            ui.add_space(handle);
            widgets::range_bar(
                ui,
                [centre - reach, centre + reach],
                reachable[k].map(|r| r.map(to_slider)),
                certified[k].map(|r| r.map(to_slider)),
                value,
                ui.spacing().slider_width - 2.0 * handle,
            );
        });
    }
    parts.playback.manual = Pose::from_coordinates(c);
    determinant(ui, scenario, &parts.cx.pose, t);
    if ui
        .button(t.tr("motion.home"))
        .on_hover_text(t.tr("motion.home_tip"))
        .clicked()
    {
        parts.playback.manual = scenario.geometry.home_pose();
        parts.teleop.blocked = None;
    }
    reach(ui, scenario, parts.playback.manual, parts.teleop, t);
    ui.label(t.tr("motion.keys"))
        .on_hover_text(t.tr("motion.keys_tip"));
    let rates = &mut parts.teleop.rates;
    ui.add(
        egui::Slider::new(&mut rates.linear_m_s, 0.001..=1.0)
            .logarithmic(true)
            .text(t.tr("motion.move_rate")),
    );
    ui.add(egui::Slider::new(&mut rates.angular_deg_s, 1.0..=90.0).text(t.tr("motion.turn_rate")));
    if let Some(words) = &parts.teleop.pad_words {
        ui.label(words);
    }
}

/// The reachability indicator: green while the pose can be taken, red with the reason
/// when a move stopped at the edge or the pose is out of reach.
/// How far from singular the pose shown is: the normalised Jacobian's determinant (the
/// product of its singular values), beside home's — twist towards ±90° and watch it fall.
fn determinant(ui: &mut egui::Ui, scenario: &Scenario, pose: &Pose, t: Lang) {
    let g = &scenario.geometry;
    let det = |p: &Pose| g.conditioning(p).singular_values.iter().product::<f64>();
    let (now, home) = (det(pose), det(&g.home_pose()));
    let words = t.fmt(
        "motion.determinant",
        &[
            ("now", &format!("{now:.4}")),
            ("home", &format!("{home:.4}")),
        ],
    );
    ui.label(words)
        .on_hover_text(t.tr("motion.determinant_tip"));
}

fn reach(ui: &mut egui::Ui, scenario: &Scenario, manual: Pose, teleop: &Teleop, t: Lang) {
    let now = teleop::unreachable(&scenario.geometry, &manual);
    let (colour, words) = match (now, &teleop.blocked) {
        (Some(why), _) => (
            widgets::ERROR,
            t.fmt("motion.out_of_reach", &[("why", &why.words(t))]),
        ),
        (None, Some(why)) => (
            widgets::ERROR,
            t.fmt("motion.at_edge", &[("why", &why.words(t))]),
        ),
        (None, None) => (widgets::OK, t.tr("motion.reachable").to_owned()),
    };
    ui.label(egui::RichText::new(words).color(colour).strong());
}

fn trajectory(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    let current = TrajectoryChoice::of(&ed.scenario().motion.trajectory);
    egui::ComboBox::from_label(t.tr("motion.kind"))
        .selected_text(words::trajectory_choice(t, current))
        .show_ui(ui, |ui| {
            for choice in TrajectoryChoice::ALL {
                if ui
                    .selectable_label(choice == current, words::trajectory_choice(t, choice))
                    .clicked()
                {
                    ed.switch_trajectory(choice);
                }
            }
        });
    for key in [
        SamplingKey::Duration,
        SamplingKey::Samples,
        SamplingKey::Start,
    ] {
        setting_slider(ui, ed, SettingTarget::Sampling(key));
    }
    match ed.scenario().motion.trajectory {
        Trajectory::Sinusoid(_) => sinusoid(ui, ed),
        Trajectory::Keyframes(_) => keyframes(ui, ed),
        _ => {
            for key in [
                ShapeKey::Radius,
                ShapeKey::AmplitudeX,
                ShapeKey::AmplitudeY,
                ShapeKey::Frequency,
                ShapeKey::Z,
                ShapeKey::ZStart,
                ShapeKey::ZEnd,
                ShapeKey::Tilt,
            ] {
                setting_slider(ui, ed, SettingTarget::Shape(key));
            }
        }
    }
}

fn sinusoid(ui: &mut egui::Ui, ed: &mut Editor) {
    let t = ed.lang;
    for (i, name) in CHANNEL_NAMES.into_iter().enumerate() {
        let name = words::coordinate(t, name);
        egui::CollapsingHeader::new(t.fmt("motion.channel", &[("axis", &name)]))
            .default_open(i == 0 || ed.expand)
            .show(ui, |ui| {
                for key in [
                    ChannelKey::Amplitude,
                    ChannelKey::Frequency,
                    ChannelKey::Phase,
                    ChannelKey::Offset,
                ] {
                    setting_slider(ui, ed, SettingTarget::Channel(i, key));
                }
                let wave = match ed.scenario().motion.trajectory {
                    Trajectory::Sinusoid(s) => s.channels().get(i).map(|(_, c)| c.wave),
                    _ => None,
                };
                if let Some(wave) = wave {
                    let mut chosen = wave;
                    ui.horizontal(|ui| {
                        ui.label(t.fmt("motion.wave", &[("axis", &name)]));
                        ui.selectable_value(&mut chosen, Wave::Sin, "sin");
                        ui.selectable_value(&mut chosen, Wave::Cos, "cos");
                    });
                    if chosen != wave {
                        ed.edit(Group::Trajectory, |s| {
                            if let Trajectory::Sinusoid(sinusoid) = &mut s.motion.trajectory
                                && let Some(channel) = sinusoid.channels_mut().into_iter().nth(i)
                            {
                                channel.wave = chosen;
                            }
                            Ok(())
                        });
                    }
                }
            });
    }
}

/// Keyframe rows in sight at once; more scroll.
const KEY_ROWS_SHOWN: usize = 12;

/// The table of `keys` (time and pose, editable); whether one was changed.
fn key_table(ui: &mut egui::Ui, t: Lang, keys: &mut [Keyframe]) -> bool {
    let mut changed = false;
    egui::Grid::new("keyframes").striped(true).show(ui, |ui| {
        let mut heads = vec!["t (s)".to_owned()];
        for (k, name) in words::COORDINATES.into_iter().enumerate() {
            let unit = if k < 3 { "m" } else { "°" };
            heads.push(format!("{} ({unit})", words::coordinate(t, name)));
        }
        let columns: Vec<egui::Id> = heads.into_iter().map(|head| ui.label(head).id).collect();
        ui.end_row();
        for key in keys.iter_mut() {
            let mut c = key.pose.to_coordinates();
            let t = ui.add(egui::DragValue::new(&mut key.t).speed(0.05));
            changed |= t.labelled_by(columns[0]).changed();
            for (i, value) in c.iter_mut().enumerate() {
                let column = columns[i + 1];
                if i < 3 {
                    let cell = ui.add(egui::DragValue::new(value).speed(0.002).max_decimals(4));
                    changed |= cell.labelled_by(column).changed();
                } else {
                    let mut deg = value.to_degrees();
                    let cell = ui.add(egui::DragValue::new(&mut deg).speed(0.1).max_decimals(2));
                    if cell.labelled_by(column).changed() {
                        *value = deg.to_radians();
                        changed = true;
                    }
                }
            }
            key.pose = Pose::from_coordinates(c);
            ui.end_row();
        }
    });
    changed
}

/// The keys as an editable table: time and pose of each, the interpolation, add and
/// remove. An edit that breaks the keys (times out of order) is refused with its reason.
fn keyframes(ui: &mut egui::Ui, ed: &mut Editor) {
    let Trajectory::Keyframes(k) = &ed.scenario().motion.trajectory else {
        return;
    };
    let t = ed.lang;
    let mut keys: Vec<Keyframe> = k.keys().to_vec();
    let mut interpolation = k.interpolation();
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label(t.tr("motion.interpolation"));
        for (value, label) in [
            (Interpolation::Linear, "motion.linear"),
            (Interpolation::Smoothstep, "motion.smoothstep"),
            (Interpolation::Cubic, "motion.cubic"),
        ] {
            changed |= ui
                .selectable_value(&mut interpolation, value, t.tr(label))
                .changed();
        }
    });
    // A long table (a recording played as poses) is shown a page at a time: a table that
    // scrolled inside the side panel took the wheel from it.
    let rows = page_of_rows(ui, t, keys.len());
    changed |= key_table(ui, t, &mut keys[rows]);
    ui.horizontal(|ui| {
        if ui
            .button(t.tr("motion.add_key"))
            .on_hover_text(t.tr("motion.add_key_tip"))
            .clicked()
            && let Some(last) = keys.last().copied()
        {
            keys.push(Keyframe {
                t: last.t + 1.0,
                ..last
            });
            changed = true;
        }
        if ui
            .add_enabled(keys.len() > 1, egui::Button::new(t.tr("motion.remove_key")))
            .on_hover_text(t.tr("motion.remove_key_tip"))
            .clicked()
        {
            keys.pop();
            changed = true;
        }
    });
    if changed {
        ed.edit(Group::Trajectory, |s| {
            let k = Keyframes::new(keys, interpolation)?;
            s.motion.trajectory = Trajectory::Keyframes(k);
            Ok(())
        });
    }
}

/// The rows of a `len`-row table on the page shown ([`KEY_ROWS_SHOWN`] a page), with the
/// page controls above it when there is more than one page (kept in egui's memory).
fn page_of_rows(ui: &mut egui::Ui, t: Lang, len: usize) -> std::ops::Range<usize> {
    let pages = len.div_ceil(KEY_ROWS_SHOWN).max(1);
    let id = ui.scope_id().with("keyframe page");
    let mut page: usize = ui.data(|d| d.get_temp(id)).unwrap_or(0);
    page = page.min(pages - 1);
    if pages > 1 {
        let shown = page;
        let first = shown * KEY_ROWS_SHOWN;
        let last = (first + KEY_ROWS_SHOWN).min(len);
        ui.horizontal(|ui| {
            let targets = [
                ("«", 0, shown > 0),
                ("‹", shown.saturating_sub(1), shown > 0),
                ("", 0, false),
                ("›", (shown + 1).min(pages - 1), shown + 1 < pages),
                ("»", pages - 1, shown + 1 < pages),
            ];
            for (words, to, enabled) in targets {
                if words.is_empty() {
                    ui.label(t.fmt(
                        "motion.rows_of",
                        &[("first", &(first + 1)), ("last", &last), ("count", &len)],
                    ));
                } else if ui
                    .add_enabled(enabled, egui::Button::new(words).small())
                    .clicked()
                {
                    page = to;
                }
            }
        });
    }
    ui.data_mut(|d| d.insert_temp(id, page));
    let first = page * KEY_ROWS_SHOWN;
    first..(first + KEY_ROWS_SHOWN).min(len)
}
