//! Link: send the platform's set-points to hardware. The `[link]` table (transport, port,
//! rate, channel map) while disconnected; once connected, the safety state in big
//! colours, ARM and E-STOP buttons (Esc is the e-stop too), the stream's figures and, for
//! a dry run, the last frames.

use egui::{Color32, RichText};
use stewart_kinematics::link_settings::{
    LinkFormat, LinkOutput, LinkStop, LinkTransport, RATES_HZ, Word,
};
use stewart_link::safety::LinkState;
use stewart_link::transport::list_ports;

use super::widgets;
use crate::viewer::state::ViewerState;

/// The colour of each state: grey, amber, green, red.
pub fn state_colour(state: LinkState) -> Color32 {
    match state {
        LinkState::Disarmed => Color32::from_rgb(120, 120, 120),
        LinkState::Arming => Color32::from_rgb(230, 160, 20),
        LinkState::Armed => Color32::from_rgb(40, 170, 70),
        LinkState::Stopping => Color32::from_rgb(220, 40, 40),
    }
}

/// The state in words.
pub fn state_words(state: LinkState) -> &'static str {
    match state {
        LinkState::Disarmed => "DISARMED",
        LinkState::Arming => "ARMING",
        LinkState::Armed => "ARMED",
        LinkState::Stopping => "STOPPING",
    }
}

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    egui::CollapsingHeader::new("Link to hardware")
        .default_open(state.look.expand_panels || state.link.connected())
        .show(ui, |ui| {
            if state.link.connected() {
                live(ui, state);
            } else {
                settings(ui, state);
                if ui
                    .button(RichText::new("Connect").strong())
                    .on_hover_text("Start the stream, disarmed: nothing moves until ARM")
                    .clicked()
                {
                    state.connect_link();
                }
            }
            widgets::status(ui, &state.link.status);
        });
}

/// The stream: state, ARM, E-STOP, figures.
fn live(ui: &mut egui::Ui, state: &mut ViewerState) {
    let Some(status) = state.link.sender_status() else {
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
                RichText::new(state_words(status.state))
                    .size(28.0)
                    .strong()
                    .color(Color32::WHITE),
            );
        });
    ui.label(state.link.described().unwrap_or_default());
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
        .add(big("E-STOP  (Esc)", Color32::from_rgb(200, 20, 20)))
        .clicked()
    {
        state.link.estop();
    }
    let can_arm = status.state == LinkState::Disarmed && !state.link.stopping();
    if ui
        .add_enabled(can_arm, big("ARM", Color32::from_rgb(30, 140, 60)))
        .on_hover_text("Ramp from where the platform is to the pose shown, then follow it")
        .clicked()
    {
        state.link.arm();
    }
    ui.label(format!(
        "{} frames, {:.1} s; period error p99 {:.0} µs, max {:.0} µs; {}",
        status.frames,
        status.time,
        status.period_error.p99_us,
        status.period_error.max_us,
        status.scheduling
    ));
    if let Some((t, frame)) = &status.telemetry {
        ui.label(format!(
            "Controller reports: {} ({} frames, the last {:.1} s ago)",
            crate::commands::link::telemetry_words(frame),
            status.telemetry_frames,
            (status.time - t).max(0.0)
        ));
    }
    if let Some(note) = &status.note {
        ui.label(RichText::new(note).color(widgets::WARNING));
    }
    let lines = state.link.recent_lines();
    if !lines.is_empty() {
        ui.label("Last frames (dry run):");
        for line in lines.iter().rev().take(4) {
            ui.label(RichText::new(line).monospace().size(10.0));
        }
    }
    let label = if state.link.stopping() {
        "Stopping…"
    } else {
        "Disconnect"
    };
    if ui
        .add_enabled(!state.link.stopping(), egui::Button::new(label))
        .on_hover_text("E-stop, return home or hold as set, disarm, then close the port")
        .clicked()
    {
        state.link.disconnect();
    }
}

/// A combo box over a word choice; returns the new choice when changed.
fn choice<T: Word>(ui: &mut egui::Ui, label: &str, current: T) -> Option<T> {
    let mut chosen = current;
    egui::ComboBox::from_label(label)
        .selected_text(current.word())
        .show_ui(ui, |ui| {
            for (value, word) in T::WORDS {
                ui.selectable_value(&mut chosen, *value, *word);
            }
        });
    (chosen != current).then_some(chosen)
}

/// The `[link]` table.
fn settings(ui: &mut egui::Ui, state: &mut ViewerState) {
    let link = state.scenario().link.clone();
    let rotary = state.scenario().geometry.rotary().is_some();
    if let Some(t) = choice::<LinkTransport>(ui, "Transport", link.transport) {
        state.edit_link(|l| l.transport = t);
    }
    match link.transport {
        LinkTransport::Serial => {
            let mut port = link.port.clone().unwrap_or_default();
            ui.horizontal(|ui| {
                let label = ui.label("Port");
                if ui
                    .text_edit_singleline(&mut port)
                    .labelled_by(label.id)
                    .changed()
                {
                    let port = (!port.trim().is_empty()).then(|| port.trim().to_owned());
                    state.edit_link(|l| l.port = port);
                }
            });
            ui.menu_button("Choose a port…", |ui| match list_ports() {
                Ok(ports) if ports.is_empty() => {
                    ui.label("No serial ports found.");
                }
                Ok(ports) => {
                    for p in ports {
                        if ui.button(format!("{}  {}", p.name, p.kind)).clicked() {
                            state.edit_link(|l| l.port = Some(p.name.clone()));
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
                        .suffix(" baud"),
                )
                .changed()
            {
                state.edit_link(|l| l.baud = baud);
            }
        }
        LinkTransport::Udp => {
            let mut address = link.address.clone().unwrap_or_default();
            ui.horizontal(|ui| {
                let label = ui.label("Address");
                if ui
                    .text_edit_singleline(&mut address)
                    .labelled_by(label.id)
                    .on_hover_text("HOST:PORT, such as 192.168.1.20:9000")
                    .changed()
                {
                    let address = (!address.trim().is_empty()).then(|| address.trim().to_owned());
                    state.edit_link(|l| l.address = address);
                }
            });
        }
        LinkTransport::File => {
            ui.label("Dry run: the frames are shown here; nothing leaves the computer.");
        }
    }
    let mut rate = link.rate_hz;
    if ui
        .add(
            egui::Slider::new(&mut rate, RATES_HZ.0..=RATES_HZ.1)
                .text("rate (Hz)")
                .logarithmic(true),
        )
        .changed()
    {
        state.edit_link(|l| l.rate_hz = rate.round());
    }
    if let Some(f) = choice::<LinkFormat>(ui, "Format", link.format) {
        state.edit_link(|l| l.format = f);
    }
    if rotary {
        if let Some(o) = choice::<LinkOutput>(ui, "Values sent", link.output) {
            state.edit_link(|l| l.output = o);
        }
        if link.output == LinkOutput::Pulse {
            let (mut zero, mut per) = (link.pulse_zero_us, link.pulse_us_per_deg);
            let a = ui.add(egui::Slider::new(&mut zero, 500.0..=2500.0).text("pulse at 0° (µs)"));
            let b = ui.add(egui::Slider::new(&mut per, -20.0..=20.0).text("µs per degree"));
            if a.changed() || b.changed() {
                state.edit_link(|l| (l.pulse_zero_us, l.pulse_us_per_deg) = (zero, per));
            }
        }
    }
    let mut ramp = link.ramp_s;
    if ui
        .add(egui::Slider::new(&mut ramp, 0.0..=10.0).text("arming ramp (s)"))
        .changed()
    {
        state.edit_link(|l| l.ramp_s = ramp);
    }
    if let Some(stop) = choice::<LinkStop>(ui, "On e-stop", link.stop) {
        state.edit_link(|l| l.stop = stop);
    }
    egui::CollapsingHeader::new("Channels").show(ui, |ui| channels(ui, state));
    if let Some(e) = &state.link_error {
        ui.label(RichText::new(format!("Not applied: {e}")).color(widgets::ERROR));
    }
}

/// Channel k: which actuator, scale, offset, reversed.
fn channels(ui: &mut egui::Ui, state: &mut ViewerState) {
    let link = state.scenario().link.clone();
    let unit = if state.scenario().geometry.rotary().is_some() {
        "°"
    } else {
        "m"
    };
    egui::Grid::new("link-channels")
        .striped(true)
        .show(ui, |ui| {
            for head in [
                "ch",
                "actuator",
                "scale",
                &format!("offset ({unit})"),
                "reversed",
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
                    state.edit_link(|l| {
                        (l.actuator[k], l.scale[k], l.offset[k], l.reversed[k]) =
                            (a, scale, offset, reversed);
                    });
                }
                ui.end_row();
            }
        });
}
