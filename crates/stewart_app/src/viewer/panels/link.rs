//! Link: send the platform's set-points to hardware. The `[link]` table (transport, port,
//! rate, channel map) while disconnected; once connected, the safety state in big
//! colours, ARM and E-STOP buttons (Esc is the e-stop too), the stream's figures and, for
//! a dry run, the last frames.

use egui::{Color32, RichText};
use stewart_kinematics::model::actuator::Quantity;
use stewart_kinematics::model::link_settings::{
    LinkFormat, LinkOutput, LinkStop, LinkTransport, RATES_HZ, STARTING_TEMPLATE, Word,
};
use stewart_link::safety::LinkState;
use stewart_link::sender::Status as SenderStatus;
use stewart_link::template::{FieldType, Template, TemplateFault};
use stewart_link::transport::list_ports;

use super::context::PanelContext;
use super::widgets;
use crate::i18n::Lang;
use crate::link_plan::actuator_range;
use crate::viewer::error::ViewerError;
use crate::viewer::state::document::Document;
use crate::viewer::state::live_link::LiveLink;

/// The colour of each state: grey, amber, green, red.
pub(crate) fn state_colour(state: LinkState) -> Color32 {
    match state {
        LinkState::Disarmed => Color32::from_rgb(120, 120, 120),
        LinkState::Arming => Color32::from_rgb(230, 160, 20),
        LinkState::Armed => Color32::from_rgb(40, 170, 70),
        LinkState::Stopping => Color32::from_rgb(220, 40, 40),
    }
}

/// The state in words.
pub(crate) fn state_words(lang: Lang, state: LinkState) -> &'static str {
    lang.tr(match state {
        LinkState::Disarmed => "link.disarmed",
        LinkState::Arming => "link.arming",
        LinkState::Armed => "link.armed",
        LinkState::Stopping => "link.stopping",
    })
}

/// The width of the widest state's words in `lang` at `size` points, strong: a display of
/// the state sized for it never reflows as the state changes.
pub(crate) fn longest_state_width(ui: &egui::Ui, lang: Lang, size: f32) -> f32 {
    let font = egui::FontId::proportional(size);
    [
        LinkState::Disarmed,
        LinkState::Arming,
        LinkState::Armed,
        LinkState::Stopping,
    ]
    .into_iter()
    .map(|state| {
        let words = RichText::new(state_words(lang, state))
            .font(font.clone())
            .strong();
        egui::WidgetText::from(words)
            .into_galley(
                ui,
                Some(egui::TextWrapMode::Extend),
                f32::INFINITY,
                egui::TextStyle::Body,
            )
            .size()
            .x
    })
    .fold(0.0, f32::max)
}

/// The panel: the stream's source and settings while disconnected, the live stream while
/// connected. `link_error`: why the last connection failed; `open`: whether it starts
/// open. Returns whether *Connect* was pressed (the caller connects: that takes the
/// playback too).
pub(crate) fn show(
    ui: &mut egui::Ui,
    link: &mut LiveLink,
    doc: &mut Document,
    link_error: &mut Option<ViewerError>,
    cx: &PanelContext,
) -> bool {
    let (t, open) = (cx.lang, cx.expand);
    let mut connect = false;
    egui::CollapsingHeader::new(t.tr("link.heading"))
        .default_open(open || link.connected())
        .show(ui, |ui| {
            if link.connected() {
                let quantity = doc.scenario().geometry.quantity();
                live(ui, link, quantity, t, open);
            } else {
                source(ui, link, t);
                settings(ui, doc, link_error, t);
                connect = ui
                    .button(RichText::new(t.tr("link.connect")).strong())
                    .on_hover_text(t.tr("link.connect_tip"))
                    .clicked();
            }
            widgets::status(ui, &link.status, t);
        });
    connect
}

/// What the stream follows: the motion the viewer shows, or live vehicle motion arriving
/// over UDP through the scenario's washout.
fn source(ui: &mut egui::Ui, link: &mut LiveLink, t: Lang) {
    let mut live = link.cue_input.is_some();
    ui.horizontal(|ui| {
        ui.label(t.tr("link.source"));
        ui.selectable_value(&mut live, false, t.tr("link.source_motion"));
        ui.selectable_value(&mut live, true, t.tr("link.source_live"))
            .on_hover_text(t.tr("link.source_live_tip"));
    });
    match (live, &mut link.cue_input) {
        (false, input) => *input = None,
        (true, input @ None) => *input = Some(DEFAULT_CUE_INPUT.to_owned()),
        (true, Some(address)) => {
            ui.horizontal(|ui| {
                let label = ui.label(t.tr("link.cue_address"));
                ui.text_edit_singleline(address).labelled_by(label.id);
            });
        }
    }
}

/// Where live vehicle motion is listened for at first.
const DEFAULT_CUE_INPUT: &str = "0.0.0.0:4123";

/// The stream: state, ARM, E-STOP, figures.
/// `quantity`: what the actuators are sent; `open`: the advanced part open at first.
fn live(ui: &mut egui::Ui, link: &mut LiveLink, quantity: Quantity, t: Lang, open: bool) {
    let Some(status) = link.sender_status() else {
        return;
    };
    let colour = state_colour(status.state);
    egui::Frame::new()
        .fill(colour)
        .inner_margin(8.0)
        .corner_radius(4.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(
                RichText::new(state_words(t, status.state))
                    .size(28.0)
                    .strong()
                    .color(Color32::WHITE),
            );
        });
    ui.label(link.described().unwrap_or_default());
    if let Some(cue) = link.cue() {
        cue_input(ui, cue, t);
    }
    let width = ui.available_width();
    let big = |text: &str, fill: Color32| {
        egui::Button::new(
            RichText::new(text)
                .size(22.0)
                .strong()
                .color(Color32::WHITE),
        )
        .fill(fill)
        .min_size(egui::vec2(width, 44.0))
    };
    if ui
        .add(big(t.tr("link.estop"), Color32::from_rgb(200, 20, 20)))
        .on_hover_text(t.tr("link.estop_tip"))
        .clicked()
    {
        link.estop();
    }
    let can_arm = status.state == LinkState::Disarmed && !link.stopping();
    if ui
        .add_enabled(
            can_arm,
            big(t.tr("link.arm"), Color32::from_rgb(30, 140, 60)),
        )
        .on_hover_text(t.tr("link.arm_tip"))
        .clicked()
    {
        link.arm();
    }
    if let Some((at, frame)) = &status.telemetry {
        ui.label(t.fmt(
            "link.telemetry",
            &[
                ("words", &frame.in_words()),
                ("frames", &status.telemetry_frames),
                ("ago", &format!("{:.1}", (status.time - at).max(0.0))),
            ],
        ));
    }
    let st = &status.telemetry_stats;
    if st.frames > 0 {
        tracking_plot(ui, link, quantity, t);
    }
    if let Some(note) = &status.note {
        ui.label(RichText::new(note).color(widgets::WARNING));
    }
    advanced(ui, link, &status, t, open);
    // Pressed again while the platform is on its way home: an emergency stop.
    let (label, tip) = if link.stopping() {
        (t.tr("link.stop_now"), t.tr("link.stop_now_tip"))
    } else {
        (t.tr("link.disconnect"), t.tr("link.disconnect_tip"))
    };
    if ui.button(label).on_hover_text(tip).clicked() {
        link.disconnect();
    }
}

/// The live vehicle input's counts and the formats arriving, with their rates.
fn cue_input(ui: &mut egui::Ui, cue: &crate::vehicle_in::live_cue::CueCounts, t: Lang) {
    let [received, dropped, stalls] = cue.numbers();
    ui.label(t.fmt(
        "link.cue_counts",
        &[
            ("received", &received),
            ("dropped", &dropped),
            ("stalls", &stalls),
        ],
    ));
    let arriving: Vec<String> = (cue.arriving().iter())
        .map(|(format, rate)| {
            let name = format.map_or_else(|| t.tr("link.cue_unknown"), |f| f.name());
            format!("{name} {rate:.0}/s")
        })
        .collect();
    ui.label(if arriving.is_empty() {
        t.tr("link.cue_nothing").to_owned()
    } else {
        t.fmt("link.cue_arriving", &[("formats", &arriving.join(", "))])
    });
}

/// The stream's timing, the telemetry's counts and the last frames' bytes: for those who
/// debug a controller. Open at first when `open`.
fn advanced(ui: &mut egui::Ui, link: &LiveLink, status: &SenderStatus, t: Lang, open: bool) {
    let st = &status.telemetry_stats;
    egui::CollapsingHeader::new(t.tr("link.advanced"))
        .default_open(open)
        .show(ui, |ui| {
            ui.label(t.fmt(
                "link.figures",
                &[
                    ("frames", &status.frames),
                    ("time", &format!("{:.1}", status.time)),
                    ("p99", &format!("{:.0}", status.period_error.p99_us)),
                    ("max", &format!("{:.0}", status.period_error.max_us)),
                    ("scheduling", &scheduling_words(t, &status.scheduling)),
                ],
            ));
            if st.frames > 0 {
                ui.label(t.fmt(
                    "link.telemetry_stats",
                    &[
                        ("answered", &st.answered),
                        ("unanswered", &st.unanswered),
                        ("stale", &st.stale),
                        ("latency", &format!("{:.2}", st.latency_mean_s * 1e3)),
                    ],
                ));
            }
            let lines = link.recent_lines();
            if !lines.is_empty() {
                ui.label(t.tr("link.last_frames"));
                for line in lines.iter().rev().take(4) {
                    ui.label(RichText::new(line).monospace().size(super::SMALLEST_TEXT));
                }
            }
        });
}

/// The tracking error of the last seconds, per actuator (measured minus commanded: mm for
/// legs, degrees for servos), in the actuators' colours.
fn tracking_plot(ui: &mut egui::Ui, link: &LiveLink, q: Quantity, t: Lang) {
    let (scale, unit) = q.fine;
    let rows = link.tracking();
    ui.label(t.fmt("link.tracking", &[("unit", &unit)]));
    // Zero always in sight: an error is read against it, not against its own wobble.
    super::side_plot::plot("link-tracking", 160.0, t.tr("plot.time"))
        .y_axis_label(unit)
        .include_y(0.0)
        .show(ui, |plot| {
            for k in 0..6 {
                let points: egui_plot::PlotPoints = rows
                    .iter()
                    .map(|(time, error)| [*time, error[k] * scale])
                    .collect();
                let name = format!("{}{}", q.letter, k + 1);
                plot.line(egui_plot::Line::new(name, points).color(super::plot::leg_colour(k)));
            }
        });
}

/// How the sender thread is scheduled, in `lang` (the link crate says it in English).
fn scheduling_words(lang: Lang, words: &str) -> String {
    if let Some(rest) = words.strip_prefix("real-time (FIFO ") {
        lang.fmt(
            "link.scheduling_fifo",
            &[("priority", &rest.trim_end_matches(')'))],
        )
    } else if words.starts_with("highest normal priority") {
        lang.tr("link.scheduling_highest").to_owned()
    } else if let Some(why) = words.strip_prefix("normal priority (could not raise it: ") {
        lang.fmt(
            "link.scheduling_normal",
            &[("why", &why.trim_end_matches(')'))],
        )
    } else {
        words.to_owned()
    }
}

/// A combo box over a word choice; returns the new choice when changed.
fn choice<T: Word>(ui: &mut egui::Ui, lang: Lang, label: &str, current: T) -> Option<T> {
    let mut chosen = current;
    let words = |word: &str| lang.tr(&format!("link.word.{word}"));
    egui::ComboBox::from_label(lang.tr(label))
        .selected_text(words(current.word()))
        .show_ui(ui, |ui| {
            for (value, word) in T::WORDS {
                ui.selectable_value(&mut chosen, *value, words(word));
            }
        });
    (chosen != current).then_some(chosen)
}

/// Where the stream goes: a serial port (typed or chosen from those present) and its
/// speed, a UDP address, or nowhere (a dry run to a file).
fn transport(ui: &mut egui::Ui, doc: &mut Document, error: &mut Option<ViewerError>, t: Lang) {
    let link = doc.scenario().link.clone();
    match link.transport {
        LinkTransport::Serial => {
            let mut port = link.port.clone().unwrap_or_default();
            ui.horizontal(|ui| {
                let label = ui.label(t.tr("link.port"));
                if ui
                    .text_edit_singleline(&mut port)
                    .labelled_by(label.id)
                    .changed()
                {
                    let port = (!port.trim().is_empty()).then(|| port.trim().to_owned());
                    *error = doc.edit_link(|l| l.port = port).err();
                }
            });
            ui.menu_button(t.tr("link.choose_port"), |ui| match list_ports() {
                Ok(ports) if ports.is_empty() => {
                    ui.label(t.tr("link.no_ports"));
                }
                Ok(ports) => {
                    for p in ports {
                        if ui.button(format!("{}  {}", p.name, p.kind)).clicked() {
                            *error = doc.edit_link(|l| l.port = Some(p.name.clone())).err();
                            ui.close();
                        }
                    }
                }
                Err(e) => {
                    ui.label(RichText::new(e.to_string()).color(widgets::ERROR));
                }
            });
            let mut baud = link.baud;
            if ui
                .add(
                    egui::DragValue::new(&mut baud)
                        .range(1..=12_000_000)
                        .suffix(t.tr("link.baud_suffix")),
                )
                .changed()
            {
                *error = doc.edit_link(|l| l.baud = baud).err();
            }
        }
        LinkTransport::Udp => {
            let mut address = link.address.clone().unwrap_or_default();
            ui.horizontal(|ui| {
                let label = ui.label(t.tr("link.address"));
                if ui
                    .text_edit_singleline(&mut address)
                    .labelled_by(label.id)
                    .on_hover_text(t.tr("link.address_tip"))
                    .changed()
                {
                    let address = (!address.trim().is_empty()).then(|| address.trim().to_owned());
                    *error = doc.edit_link(|l| l.address = address).err();
                }
            });
        }
        LinkTransport::File => {
            ui.label(t.tr("link.dry_run"));
        }
    }
}

/// The `[link]` table.
fn settings(ui: &mut egui::Ui, doc: &mut Document, error: &mut Option<ViewerError>, t: Lang) {
    let link = doc.scenario().link.clone();
    let outputs = doc.scenario().geometry.actuator().kind().link_outputs();
    if let Some(chosen) = choice::<LinkTransport>(ui, t, "link.transport", link.transport) {
        *error = doc.edit_link(|l| l.transport = chosen).err();
    }
    transport(ui, doc, error, t);
    let mut rate = link.rate_hz;
    if ui
        .add(
            egui::Slider::new(&mut rate, RATES_HZ.0..=RATES_HZ.1)
                .text(t.tr("link.rate"))
                .logarithmic(true),
        )
        .changed()
    {
        *error = doc.edit_link(|l| l.rate_hz = rate.round()).err();
    }
    if let Some(f) = choice::<LinkFormat>(ui, t, "link.format", link.format) {
        // A template chosen for the first time starts as a common board's frame.
        *error = doc
            .edit_link(|l| {
                l.format = f;
                if f == LinkFormat::Template && l.template.is_none() {
                    l.template = Some(STARTING_TEMPLATE.to_owned());
                }
            })
            .err();
    }
    match link.format {
        LinkFormat::Template => template(ui, doc, error, t),
        LinkFormat::Smc3 => board_ports(ui, doc, error, t, 2),
        LinkFormat::Odrive => board_ports(ui, doc, error, t, 3),
        LinkFormat::Binary | LinkFormat::Text => {}
    }
    // The choice shows where the kind offers more than its native unit.
    if outputs.len() > 1 {
        if let Some(o) = choice::<LinkOutput>(ui, t, "link.output", link.output) {
            *error = doc.edit_link(|l| l.output = o).err();
        }
        if link.output == LinkOutput::Pulse {
            let (mut zero, mut per) = (link.pulse_zero_us, link.pulse_us_per_deg);
            let a =
                ui.add(egui::Slider::new(&mut zero, 500.0..=2500.0).text(t.tr("link.pulse_zero")));
            let b =
                ui.add(egui::Slider::new(&mut per, -20.0..=20.0).text(t.tr("link.pulse_per_deg")));
            if a.changed() || b.changed() {
                *error = doc
                    .edit_link(|l| (l.pulse_zero_us, l.pulse_us_per_deg) = (zero, per))
                    .err();
            }
        }
    }
    let mut ramp = link.ramp_s;
    if ui
        .add(egui::Slider::new(&mut ramp, 0.0..=10.0).text(t.tr("link.ramp")))
        .changed()
    {
        *error = doc.edit_link(|l| l.ramp_s = ramp).err();
    }
    if let Some(stop) = choice::<LinkStop>(ui, t, "link.stop", link.stop) {
        *error = doc.edit_link(|l| l.stop = stop).err();
    }
    // A board's own bytes apply no channel map (the link refuses one): ODrive asks for its
    // turns instead.
    match link.format {
        LinkFormat::Binary | LinkFormat::Text => {
            egui::CollapsingHeader::new(t.tr("link.channels"))
                .show(ui, |ui| channels(ui, doc, error, t));
        }
        LinkFormat::Odrive => {
            egui::CollapsingHeader::new(t.tr("link.turns")).show(ui, |ui| turns(ui, doc, error, t));
        }
        LinkFormat::Template | LinkFormat::Smc3 => {}
    }
    if let Some(e) = error {
        widgets::not_applied(ui, e, t);
    }
}

/// The other boards' serial ports (or UDP peers) of a board protocol driving `boards`.
fn board_ports(
    ui: &mut egui::Ui,
    doc: &mut Document,
    error: &mut Option<ViewerError>,
    t: Lang,
    boards: usize,
) {
    let link = doc.scenario().link.clone();
    let serial = match link.transport {
        LinkTransport::Serial => true,
        LinkTransport::Udp => false,
        LinkTransport::File => return,
    };
    for n in 2..=boards {
        let current = match (serial, n) {
            (true, 2) => &link.port2,
            (true, _) => &link.port3,
            (false, 2) => &link.address2,
            (false, _) => &link.address3,
        };
        let mut text = current.clone().unwrap_or_default();
        ui.horizontal(|ui| {
            let key = if serial {
                "link.board_port"
            } else {
                "link.board_address"
            };
            let label = ui.label(t.fmt(key, &[("n", &n)]));
            if ui
                .text_edit_singleline(&mut text)
                .labelled_by(label.id)
                .changed()
            {
                let value = (!text.trim().is_empty()).then(|| text.trim().to_owned());
                *error = doc
                    .edit_link(|l| {
                        *match (serial, n) {
                            (true, 2) => &mut l.port2,
                            (true, _) => &mut l.port3,
                            (false, 2) => &mut l.address2,
                            (false, _) => &mut l.address3,
                        } = value;
                    })
                    .err();
            }
        });
    }
}

/// The output template, edited in place, and a live preview: the bytes it sends at the
/// home pose, or where it is wrong.
fn template(ui: &mut egui::Ui, doc: &mut Document, error: &mut Option<ViewerError>, t: Lang) {
    let mut text = doc.scenario().link.template.clone().unwrap_or_default();
    ui.label(t.tr("link.template_text"));
    let edited = ui
        .add(
            egui::TextEdit::singleline(&mut text)
                .font(egui::TextStyle::Monospace)
                // The width in sight: a long template scrolls inside its field.
                .desired_width(
                    ui.available_width()
                        .min(ui.clip_rect().right() - ui.cursor().min.x),
                ),
        )
        .on_hover_text(t.tr("link.template_tip"))
        .changed();
    if edited {
        let written = stewart_kinematics::model::link_settings::template_text(&text).to_owned();
        *error = doc.edit_link(|l| l.template = Some(written)).err();
    }
    let scenario = doc.scenario();
    let g = &scenario.geometry;
    let home = g.actuator_values_at(&g.home_pose());
    match (Template::parse(&text), home) {
        (Err(e), _) => {
            let what = template_fault_words(&e.fault, t);
            let said = t.fmt(
                "link.template_error",
                &[("column", &e.column), ("what", &what)],
            );
            ui.label(RichText::new(said).color(widgets::ERROR));
        }
        (Ok(template), Ok(values)) => {
            let mut bytes = Vec::new();
            template.encode(&values, &[actuator_range(scenario); 6], &mut bytes);
            ui.label(t.fmt("link.template_preview", &[("count", &bytes.len())]));
            // Hex and text side by side, eight bytes a row: it fits the panel.
            let dump = super::byte_dump::rows(&bytes).join("\n");
            ui.label(RichText::new(dump).monospace());
        }
        // A home pose out of reach is said by the panels that show the pose.
        (Ok(_), Err(_)) => {}
    }
}

/// ODrive: each actuator's motor turns per unit of its value and turns at zero.
fn turns(ui: &mut egui::Ui, doc: &mut Document, error: &mut Option<ViewerError>, t: Lang) {
    let link = doc.scenario().link.clone();
    let unit = doc.scenario().geometry.quantity().unit;
    egui::Grid::new("link-turns").striped(true).show(ui, |ui| {
        for head in [
            t.tr("link.col_actuator"),
            &t.fmt("link.col_turns_per_unit", &[("unit", &unit)]),
            t.tr("link.col_turns_offset"),
        ] {
            ui.label(head);
        }
        ui.end_row();
        for k in 0..6 {
            ui.label(format!("{}", k + 1));
            let mut per = link.turns_per_unit[k];
            let mut offset = link.turns_offset[k];
            let changed = ui.add(egui::DragValue::new(&mut per).speed(0.01)).changed()
                | ui.add(egui::DragValue::new(&mut offset).speed(0.01))
                    .changed();
            if changed {
                *error = doc
                    .edit_link(|l| (l.turns_per_unit[k], l.turns_offset[k]) = (per, offset))
                    .err();
            }
            ui.end_row();
        }
    });
}

/// Channel k: which actuator, scale, offset, reversed.
fn channels(ui: &mut egui::Ui, doc: &mut Document, error: &mut Option<ViewerError>, t: Lang) {
    let link = doc.scenario().link.clone();
    let unit = doc.scenario().geometry.quantity().unit;
    egui::Grid::new("link-channels")
        .striped(true)
        .show(ui, |ui| {
            for head in [
                t.tr("link.col_channel"),
                t.tr("link.col_actuator"),
                t.tr("link.col_scale"),
                &t.fmt("link.col_offset", &[("unit", &unit)]),
                t.tr("link.col_reversed"),
            ] {
                ui.label(head);
            }
            ui.end_row();
            for k in 0..6 {
                ui.label(format!("{}", k + 1));
                let mut a = link.actuator[k];
                let mut scale = link.scale[k];
                let mut offset = link.offset[k];
                let mut reversed = link.reversed[k];
                let changed = ui.add(egui::DragValue::new(&mut a).range(1..=6)).changed()
                    | ui.add(egui::DragValue::new(&mut scale).speed(0.01))
                        .changed()
                    | ui.add(egui::DragValue::new(&mut offset).speed(0.001))
                        .changed()
                    | ui.checkbox(&mut reversed, "").changed();
                if changed {
                    *error = doc
                        .edit_link(|l| {
                            (l.actuator[k], l.scale[k], l.offset[k], l.reversed[k]) =
                                (a, scale, offset, reversed);
                        })
                        .err();
                }
                ui.end_row();
            }
        });
}

/// A template's fault in the interface's language.
fn template_fault_words(fault: &TemplateFault, t: Lang) -> String {
    use TemplateFault as F;
    let key = |k: &str| format!("link.template_fault.{k}");
    let types = FieldType::names();
    match fault {
        F::NotClosed { open, close } => {
            t.fmt(&key("not_closed"), &[("open", open), ("close", close)])
        }
        F::ClosesNothing(c) => t.fmt(&key("closes_nothing"), &[("c", c)]),
        F::NotPrintable(c) => t.fmt(&key("not_printable"), &[("c", &c.escape_default())]),
        F::DecWithoutEnd { actuator } => {
            let field = format!("{{a{}:dec}}", actuator + 1);
            t.fmt(&key("dec_without_end"), &[("field", &field)])
        }
        F::NoActuator => t.tr(&key("no_actuator")).to_owned(),
        F::ByteOver(n) => t.fmt(&key("byte_over"), &[("n", n)]),
        F::NotAByte(text) => t.fmt(&key("not_a_byte"), &[("text", text)]),
        F::NotAField(inside) => {
            let field = format!("{{{inside}}}");
            t.fmt(&key("not_a_field"), &[("field", &field), ("types", &types)])
        }
        F::NoSuchActuator(text) => t.fmt(&key("no_such_actuator"), &[("text", text)]),
        F::NoSuchType(text) => t.fmt(&key("no_such_type"), &[("text", text), ("types", &types)]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One fault of each kind, as the parser gives them.
    fn every_fault() -> Vec<TemplateFault> {
        [
            "<255",
            "}",
            "é",
            "{a1:dec}",
            "<1>",
            "<300>",
            "<x>{a1:u8}",
            "{a1}",
            "{a9:u8}",
            "{a1:u7}",
        ]
        .iter()
        .map(|text| match Template::parse(text) {
            Err(e) => e.fault,
            Ok(_) => panic!("{text} was taken"),
        })
        .collect()
    }

    #[test]
    fn every_template_fault_is_worded_by_each_catalogue() {
        let faults = every_fault();
        let kinds: std::collections::HashSet<_> =
            faults.iter().map(std::mem::discriminant).collect();
        assert_eq!(kinds.len(), 10, "{faults:?}");
        for fault in &faults {
            // English: the parser's own sentence, as the command line says it.
            assert_eq!(template_fault_words(fault, Lang::En), fault.to_string());
            // Chinese: its own sentence, every placeholder filled.
            let zh = template_fault_words(fault, Lang::Zh);
            assert!(
                zh.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
                "{zh}"
            );
            for name in [
                "{open}", "{close}", "{c}", "{field}", "{n}", "{text}", "{types}",
            ] {
                assert!(!zh.contains(name), "{zh}");
            }
        }
    }
}
