//! The Link panel: connect a dry run, arm, follow, e-stop by Esc, disconnect; the state
//! shown in words and colours; a refused channel map says why and changes nothing.

use std::time::{Duration, Instant};

use crate::viewer::error::ViewerError;
use crate::viewer::state::ViewerState;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable};
use stewart_kinematics::model::link_settings::{LinkFormat, LinkTransport};
use stewart_link::safety::LinkState;

use super::tall_harness;

/// Draw until the link's state is `want` (the sender runs on its own thread).
fn until(h: &mut Harness<'static, ViewerState>, want: LinkState) {
    let started = Instant::now();
    loop {
        h.run();
        let now = h.state().link.sender_status().map(|s| s.state);
        if now == Some(want) {
            // Draw once more so that the panels show it.
            h.run();
            return;
        }
        assert!(
            started.elapsed() < Duration::from_secs(15),
            "still {now:?}, waiting for {want:?}"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

#[test]
fn a_dry_run_connects_disarmed_arms_stops_on_escape_and_disconnects() {
    let mut h = tall_harness("seed", 2400.0);
    h.state_mut().edit_link(|l| l.ramp_s = 0.1);
    h.get_by_label("Link to hardware").click();
    h.run();
    assert!(
        h.query_by_label("Dry run: the frames are shown here; nothing leaves the computer.")
            .is_some()
    );
    h.get_by_label("Connect").click();
    until(&mut h, LinkState::Disarmed);
    // In the panel and in the badge over the view.
    assert_eq!(h.query_all_by_label("DISARMED").count(), 2);
    // The state and an e-stop also float over the view.
    assert_eq!(h.query_all_by_label("E-STOP  (Esc)").count(), 2);
    h.get_by_label("ARM").click();
    until(&mut h, LinkState::Armed);
    assert_eq!(h.query_all_by_label("ARMED").count(), 2);
    badge_reads_on_one_line(&h, "ARMED");
    assert!(!h.state().link.recent_lines().is_empty());
    // Esc is the e-stop, and only that while a link is connected: presentation mode stays.
    h.state_mut().look.presentation = true;
    h.run();
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(h.state().look.presentation);
    h.state_mut().look.presentation = false;
    // The sender takes the e-stop at its next tick: wait for it, not for luck.
    until(&mut h, LinkState::Disarmed);
    // Back to the longer word after the shorter one: still one line.
    badge_reads_on_one_line(&h, "DISARMED");
    let note = h
        .state()
        .link
        .sender_status()
        .and_then(|s| s.note)
        .unwrap_or_default();
    assert!(note.contains("e-stop"), "{note}");
    h.get_by_label("Disconnect").click();
    let started = Instant::now();
    while h.state().link.connected() {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(15));
        std::thread::sleep(Duration::from_millis(10));
    }
    h.run();
    let ended = h.state().link.status.clone();
    assert!(
        ended
            .as_ref()
            .is_some_and(|s| s.as_ref().is_ok_and(|m| m.contains("ended disarmed"))),
        "{ended:?}"
    );
    assert!(h.query_by_label("Connect").is_some());
}

#[test]
fn the_badge_reads_on_one_line_through_every_state_in_chinese() {
    let mut h = tall_harness("seed", 2400.0);
    h.state_mut().look.lang = crate::i18n::Lang::Zh;
    h.state_mut().edit_link(|l| l.ramp_s = 0.1);
    h.state_mut().connect_link();
    until(&mut h, LinkState::Disarmed);
    badge_reads_on_one_line(&h, "未使能");
    h.state().link.arm();
    until(&mut h, LinkState::Armed);
    badge_reads_on_one_line(&h, "已使能");
    h.state().link.estop();
    until(&mut h, LinkState::Disarmed);
    badge_reads_on_one_line(&h, "未使能");
    h.state_mut().link.disconnect_now();
}

#[test]
fn a_refused_link_edit_says_why_and_changes_nothing() {
    let mut h = tall_harness("seed", 1600.0);
    let before = h.state().scenario().link.clone();
    h.state_mut().edit_link(|l| l.actuator[3] = 1);
    h.get_by_label("Link to hardware").click();
    h.run();
    assert_eq!(h.state().scenario().link, before);
    assert!(
        h.query_by_label_contains("channels 1 and 4 both carry actuator 1")
            .is_some()
    );
}

/// A controller on a local UDP port that answers every set-point with telemetry whose
/// values are the set-point's less `short` (wire units): a platform that lags behind.
fn lagging_controller(short: i32) -> (String, std::thread::JoinHandle<()>) {
    use stewart_link::{Frame, FrameDecoder, FrameKind};
    let socket = std::net::UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    socket
        .set_read_timeout(Some(Duration::from_millis(1500)))
        .unwrap_or_else(|e| panic!("{e}"));
    let address = socket
        .local_addr()
        .unwrap_or_else(|e| panic!("{e}"))
        .to_string();
    let handle = std::thread::spawn(move || {
        let mut buf = [0u8; 256];
        while let Ok((n, from)) = socket.recv_from(&mut buf) {
            let mut d = FrameDecoder::new();
            for &b in &buf[..n] {
                if let Some(Ok(f)) = d.push(b) {
                    let answer = Frame {
                        kind: FrameKind::Telemetry,
                        values: f.values.map(|v| v - short),
                        ..f
                    };
                    let _ = socket.send_to(&answer.encode(), from);
                }
            }
        }
    });
    (address, handle)
}

#[test]
fn telemetry_shows_the_measured_ghost_and_the_tracking_error_and_a_second_stop_is_an_emergency() {
    let (address, controller) = lagging_controller(2000);
    let mut h = tall_harness("paired", 2400.0);
    h.state_mut().edit_link(|l| {
        l.transport = LinkTransport::Udp;
        l.address = Some(address.clone());
        l.ramp_s = 0.1;
        l.rate_hz = 200.0;
    });
    h.state_mut().playback.playing = false;
    h.get_by_label("Link to hardware").click();
    h.run();
    h.get_by_label("Connect").click();
    until(&mut h, LinkState::Disarmed);
    h.get_by_label("ARM").click();
    until(&mut h, LinkState::Armed);
    let started = Instant::now();
    while h.state().link.tracking().len() < 100 {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(15), "no telemetry");
        std::thread::sleep(Duration::from_millis(10));
    }
    h.run();
    // Every leg measured 2 mm short: the tracking error says −2 mm, the ghost sits lower.
    let (_, error) = *h
        .state()
        .link
        .tracking()
        .back()
        .unwrap_or_else(|| panic!("empty"));
    for e in error {
        // To the wire's rounding of the commanded value (half a micrometre).
        assert!((e + 0.002).abs() <= 0.5e-6 + 1e-12, "{e}");
    }
    let measured = h
        .state()
        .link
        .measured_pose()
        .unwrap_or_else(|| panic!("no measured pose"));
    let shown = h.state().pose();
    assert!(
        measured.position.z < shown.position.z - 1e-3,
        "{measured:?} vs {shown:?}"
    );
    let theme = stewart_render::Theme::DARK;
    let plates = h.state().draw_list(&theme).plates.len();
    assert_eq!(plates, 3, "base, platform and the ghost");
    assert!(
        h.query_by_label_contains("Tracking error, measured − commanded (mm)")
            .is_some()
    );
    // The counts are behind "Advanced", closed at first.
    assert!(
        h.query_by_label_contains("set-points answered, 0 unanswered")
            .is_none()
    );
    h.get_by_label_contains("Advanced: timing").click();
    h.run();
    assert!(
        h.query_by_label_contains("set-points answered, 0 unanswered")
            .is_some()
    );
    if let Some(dir) = std::env::var_os("STEWART_LOOK_DIR") {
        let image = h.render().unwrap_or_else(|e| panic!("{e}"));
        image
            .save(std::path::Path::new(&dir).join("link-telemetry.png"))
            .unwrap_or_else(|e| panic!("{e}"));
    }
    // Disconnect starts the way home; pressed again, an emergency stop.
    h.get_by_label("Disconnect").click();
    until(&mut h, LinkState::Stopping);
    h.get_by_label("Stop now (emergency)").click();
    let started = Instant::now();
    while h.state().link.connected() {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(15));
        std::thread::sleep(Duration::from_millis(10));
    }
    let ended = h.state().link.status.clone().and_then(Result::err);
    assert!(
        matches!(ended, Some(ViewerError::LinkEmergency { .. })),
        "{ended:?}"
    );
    let words = ended.map(|e| e.to_string()).unwrap_or_default();
    assert!(words.starts_with("Emergency stop"), "{words}");
    assert!(words.contains("Left at x = "), "{words}");
    let _ = controller.join();
}

/// The Link panel's choices read as words, not the file's raw keys (before: `file`,
/// `binary`, `native`).
#[test]
fn the_link_panels_choices_read_as_words() {
    let mut state = ViewerState::new(
        stewart_kinematics::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}")),
    );
    state.look.expand_panels = true;
    let h = super::harness_with(state, 3600.0);
    // A combo box shows its choice as its value.
    let shown = |words: &str| {
        h.root().children_recursive().any(|n| {
            let a = n.accesskit_node();
            a.value().is_some_and(|v| v == words) || a.label().is_some_and(|l| l == words)
        })
    };
    for words in [
        "Dry run (shown in this panel)",
        "Binary frames (34 bytes, CRC)",
        "Servo angle (0.01°)",
    ] {
        assert!(shown(words), "no `{words}`");
    }
    for raw in ["file", "binary", "native"] {
        assert!(!shown(raw), "`{raw}` shown");
    }
}

#[test]
fn an_output_template_is_chosen_edited_and_previewed_as_bytes() {
    let mut state = ViewerState::new(
        stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    state.look.expand_panels = true;
    // Tall enough for the whole side panel: the combo's list opens on screen.
    let mut h = super::harness_with(state, 7000.0);
    h.get_by_role_and_label(egui::accesskit::Role::ComboBox, "Format")
        .click();
    h.run();
    h.get_by_label("Output template (a board's own bytes)")
        .click();
    h.run();
    let link = h.state().scenario().link.clone();
    assert_eq!(link.format, LinkFormat::Template);
    let starting = "<255><255>{a1:u16be}{a2:u16be}{a3:u16be}{a4:u16be}{a5:u16be}{a6:u16be}<10><13>";
    assert_eq!(link.template.as_deref(), Some(starting));
    // The preview: the bytes at home, computed here from the paired preset's home legs
    // and stroke (0.55 to 1.3 m) as the template says.
    let g = &h.state().scenario().geometry;
    let home = g.leg_lengths(&g.home_pose());
    let mut bytes = vec![0xff, 0xff];
    for leg in home {
        let n = ((leg - 0.55) / (1.3 - 0.55) * 65535.0).round() as u32;
        bytes.extend([(n >> 8) as u8, (n & 0xff) as u8]);
    }
    bytes.extend([0x0a, 0x0d]);
    assert!(
        h.query_by_label("At home (16 bytes), in hex and as text:")
            .is_some()
    );
    // Two rows of eight, each in hex and as text.
    let hex = |row: &[u8]| {
        row.iter()
            .map(|b| format!("{b:02X}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let shown = h
        .get_by_label_contains(&hex(&bytes[..8]))
        .value()
        .unwrap_or_default();
    let rows: Vec<&str> = shown.lines().collect();
    assert_eq!(rows.len(), 2, "{shown}");
    assert!(
        rows[0].starts_with(&hex(&bytes[..8])) && rows[1].starts_with(&hex(&bytes[8..])),
        "{shown}"
    );
    assert!(rows[1].ends_with("··"), "the line end as text: {shown}");
    // Within the side panel.
    let right = h.get_by_label_contains(&hex(&bytes[..8])).rect().right();
    assert!(
        right <= h.state().look.side_width,
        "the preview runs to {right}"
    );
    super::look(&mut h, "link-template.png");
    // Typed into: a fault is said at its column, and the link keeps the text typed.
    let field = || {
        egui_kittest::kittest::By::new()
            .role(egui::accesskit::Role::TextInput)
            .value(starting)
    };
    h.get(field()).focus();
    h.run();
    h.get(field()).type_text("{a9:u8}");
    h.run();
    let typed = h
        .state()
        .scenario()
        .link
        .template
        .clone()
        .unwrap_or_default();
    let column = typed.find("{a9:u8}").map(|i| i + 1);
    assert!(column.is_some(), "{typed}");
    let said = format!(
        "Template column {}: `a9` names no actuator",
        column.unwrap_or_default()
    );
    assert!(h.query_by_label_contains(&said).is_some(), "no `{said}`");
}

#[test]
fn a_board_protocol_asks_for_each_boards_port() {
    let mut state = ViewerState::new(
        stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    state.look.expand_panels = true;
    state.edit_link(|l| l.transport = LinkTransport::Serial);
    // Tall enough for the whole side panel: the combo's list opens on screen.
    let mut h = super::harness_with(state, 7000.0);
    h.get_by_role_and_label(egui::accesskit::Role::ComboBox, "Format")
        .click();
    h.run();
    h.get_by_label("ODrive (three two-axis boards, in turns)")
        .click();
    h.run();
    assert_eq!(h.state().scenario().link.format, LinkFormat::Odrive);
    assert!(h.query_by_label("Board 2's port").is_some());
    h.get_by_label("Board 3's port").focus();
    h.run();
    h.get_by_label("Board 3's port").type_text("/dev/ttyACM2");
    h.run();
    let link = h.state().scenario().link.clone();
    assert_eq!(link.port3.as_deref(), Some("/dev/ttyACM2"));
    assert_eq!(link.port2, None);
    // The turns take the channel map's place (which a board format does not apply).
    assert!(h.query_by_label("Turns (ODrive)").is_some());
    assert!(h.query_by_label("Channels").is_none());
}

/// A `[link]` edit goes through the same path as every other: refused when unsound,
/// undone by Ctrl+Z (before: it bypassed undo).
#[test]
fn a_link_edit_is_undone_like_any_other() {
    let mut state = ViewerState::new(
        stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    let before = state.scenario().link.clone();
    state.edit_link(|l| l.rate_hz = 250.0);
    assert_eq!(state.scenario().link.rate_hz, 250.0);
    state.edit_link(|l| l.rate_hz = 1e9);
    assert!(state.link_error.is_some());
    assert_eq!(state.scenario().link.rate_hz, 250.0);
    assert!(state.undo_edit());
    assert_eq!(state.scenario().link, before);
}

#[test]
fn live_vehicle_motion_is_a_source_the_link_follows_and_the_cueing_panel_plots() {
    let mut h = tall_harness("seed", 2400.0);
    h.state_mut().edit_link(|l| l.ramp_s = 0.1);
    h.get_by_label("Link to hardware").click();
    h.run();
    h.get_by_label("Live vehicle motion").click();
    h.run();
    // The address to listen at, editable; a free port for the test.
    let port = std::net::UdpSocket::bind("127.0.0.1:0")
        .and_then(|s| s.local_addr())
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(h.query_by_label("Listen at").is_some());
    h.state_mut().link.cue_input = Some(port.to_string());
    h.get_by_label("Connect").click();
    until(&mut h, LinkState::Disarmed);
    h.get_by_label("ARM").click();
    until(&mut h, LinkState::Armed);
    // A vehicle braking hard, then two datagrams that are not samples.
    let sender = std::net::UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    for k in 0..60 {
        let t = f64::from(k) * 0.02;
        let line = format!("{t},-6,0,0,0,0,10");
        sender
            .send_to(line.as_bytes(), port)
            .unwrap_or_else(|e| panic!("{e}"));
        std::thread::sleep(Duration::from_millis(5));
    }
    sender
        .send_to(b"hello", port)
        .unwrap_or_else(|e| panic!("{e}"));
    sender
        .send_to(b"1,2,3", port)
        .unwrap_or_else(|e| panic!("{e}"));
    let started = Instant::now();
    while h.state().link.cue().map(|c| c.numbers()) != Some([60, 2, 0]) {
        h.run();
        assert!(
            started.elapsed() < Duration::from_secs(15),
            "{:?}",
            h.state().link.cue().map(|c| c.numbers())
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    h.run();
    assert!(
        h.query_by_label("Live input: 60 samples, 2 dropped, 0 stalls")
            .is_some()
    );
    // The formats arriving are named, with their rate, once a second of them is counted.
    while h
        .state()
        .link
        .cue()
        .is_some_and(|c| c.arriving().is_empty())
    {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(30), "no rates");
        std::thread::sleep(Duration::from_millis(10));
    }
    h.run();
    assert!(
        h.query_by_label_contains("Arriving: generic text")
            .is_some()
    );
    // The platform moved off home: braking surges it back.
    let values = h.state().link.sender_status().map(|s| s.values);
    let home = h
        .state()
        .scenario()
        .geometry
        .leg_lengths(&h.state().scenario().geometry.home_pose());
    assert!(values.is_some_and(|v| v != home), "{values:?}");
    // The view, the readouts, the Legs panel and the plot show what is commanded, not the
    // trajectory paused behind it.
    commanded_is_shown(&mut h);
    assert!(
        h.state().plot_rolls(),
        "the plot rolls the commanded values"
    );
    // The badge says so, on one line per state.
    assert!(h.query_by_label("The view: the commanded pose").is_some());
    badge_reads_on_one_line(&h, "ARMED");
    // The Cueing panel plots the live input.
    h.get_by_label("Motion cueing").click();
    h.run();
    assert!(
        h.query_by_label_contains("Live vehicle motion from the link")
            .is_some()
    );
    super::look(&mut h, "cueing-live.png");
    h.get_by_label("Disconnect").click();
    let started = Instant::now();
    while h.state().link.connected() {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(30));
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Wait until the view shows a commanded pose away from the pose the viewer plays, then
/// check in that frame: the pose shown gives the values sent (forward kinematics, checked
/// by inverse kinematics), the Legs panel shows them, and the plot's newest sample is them.
fn commanded_is_shown(h: &mut Harness<'static, ViewerState>) {
    let started = Instant::now();
    loop {
        h.run();
        let s = h.state();
        if let Some((pose, values)) = s.link.commanded() {
            let played = s.played_pose();
            let apart = (pose.position - played.position).norm();
            if apart > 1e-3 {
                assert_eq!(s.pose(), pose, "the view shows the commanded pose");
                let lengths = s.scenario().geometry.leg_lengths(&s.pose());
                for (l, v) in lengths.iter().zip(values) {
                    assert!((l - v).abs() < 1e-9, "{lengths:?} {values:?}");
                }
                let shown = format!("{:.4} m", lengths[0]);
                // Two legs may show the same length: any one of them will do.
                assert!(
                    h.query_all_by_label(&shown).next().is_some(),
                    "Legs panel: {shown}"
                );
                // The window moves time on before each frame: the plot's history takes the
                // commanded values.
                h.state_mut().advance(0.01);
                let newest = h.state().playback.history.entries().last().map(|e| e.1);
                let newest = newest.unwrap_or_else(|| panic!("the plot has no sample"));
                for (n, v) in newest.iter().zip(values) {
                    assert!((n - v).abs() < 1e-9, "the plot's newest sample {newest:?}");
                }
                return;
            }
        }
        assert!(
            started.elapsed() < Duration::from_secs(15),
            "the view never showed a commanded pose away from the paused trajectory"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// The state reads on one line in the badge (20 points: a line is about 23 px high, two
/// are over 45) and in the panel (28 points: a line is about 32 px high).
fn badge_reads_on_one_line(h: &Harness<'static, ViewerState>, words: &str) {
    let heights: Vec<f32> = h
        .query_all_by_label(words)
        .map(|n| n.rect().height())
        .collect();
    assert!(!heights.is_empty(), "{words} is shown");
    for height in heights {
        assert!(height < 40.0, "{words}: {height} px high, wrapped");
    }
}

/// Armed on live vehicle motion on the seed, whose layout is singular (forward kinematics
/// of the values sent finds no pose), every frame shows what is commanded, the pose the
/// cue asks for, and never the trajectory paused behind the stream.
#[test]
fn a_live_cue_on_the_seed_shows_the_commanded_pose_in_every_frame() {
    let mut h = tall_harness("seed", 800.0);
    h.state_mut().edit_link(|l| l.ramp_s = 0.1);
    let port = std::net::UdpSocket::bind("127.0.0.1:0")
        .and_then(|s| s.local_addr())
        .unwrap_or_else(|e| panic!("{e}"));
    h.state_mut().link.cue_input = Some(port.to_string());
    h.state_mut().connect_link();
    until(&mut h, LinkState::Disarmed);
    h.state().link.arm();
    until(&mut h, LinkState::Armed);
    // A vehicle braking and turning, a sample every 10 ms on a thread of its own.
    let done = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let player = {
        let done = std::sync::Arc::clone(&done);
        std::thread::spawn(move || {
            let sender = std::net::UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
            let mut k = 0u32;
            while !done.load(std::sync::atomic::Ordering::Relaxed) {
                let t = f64::from(k) * 0.01;
                let line = format!("{t},-4,2,0,0,0,{}", 20.0 * (2.0 * t).sin());
                let _ = sender.send_to(line.as_bytes(), port);
                k += 1;
                std::thread::sleep(Duration::from_millis(10));
            }
        })
    };
    // Frames until 100 samples have come, each showing the commanded pose.
    let started = Instant::now();
    let mut frames = 0;
    let mut away = 0;
    while h.state().link.cue().map_or(0, |c| c.numbers()[0]) < 100 {
        h.run();
        let s = h.state();
        let (pose, _) = s.link.commanded().unwrap_or_else(|| {
            panic!(
                "frame {frames}: no commanded pose ({:?})",
                s.link.commanded_from
            )
        });
        assert_eq!(s.pose(), pose, "frame {frames} shows another pose");
        if (pose.position - s.played_pose().position).norm() > 1e-3 {
            away += 1;
        }
        frames += 1;
        if frames % 6 == 0 {
            super::look(&mut h, &format!("seed-live-cue-{frames}.png"));
        }
        assert!(
            started.elapsed() < Duration::from_secs(30),
            "{frames} frames"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    done.store(true, std::sync::atomic::Ordering::Relaxed);
    let _ = player.join();
    assert!(
        away > 0,
        "{away} of {frames} frames away from the trajectory"
    );
    h.state_mut().link.disconnect_now();
}
