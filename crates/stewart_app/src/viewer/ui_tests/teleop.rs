//! Teleoperation in manual mode: held keys and a (synthetic) gamepad move the pose at the
//! set rates, the dead-man button gates the gamepad, a move stops at the edge of the
//! reachable set with a red indicator, and an armed link follows the moves.

use std::time::{Duration, Instant};

use crate::viewer::state::playback::MotionMode;
use crate::viewer::state::teleop::PadState;
use egui_kittest::kittest::Queryable;
use stewart_link::safety::LinkState;

use super::tall_harness;

#[test]
fn held_keys_and_the_gamepad_move_the_pose_and_stop_at_the_stroke() {
    let mut h = tall_harness("seed", 1400.0);
    h.get_by_label("Manual pose").click();
    h.run();
    assert_eq!(h.state().playback.mode, MotionMode::Manual);
    assert!(h.query_by_label("Reachable").is_some());
    let z0 = h.state().pose().position.z;
    h.state_mut().teleop.rates.linear_m_s = 0.1;
    // R held for ten frames of 0.1 s (kittest's frames are 0.25 s; moves take at most
    // 0.1 s a frame): up 0.1 m.
    h.key_down(egui::Key::R);
    for _ in 0..10 {
        h.step();
    }
    h.key_up(egui::Key::R);
    h.step();
    let dz = h.state().pose().position.z - z0;
    assert!((dz - 0.1).abs() < 1e-9, "{dz}");
    // The gamepad moves only while its dead-man button is held.
    let x0 = h.state().pose().position.x;
    let stick_up = PadState {
        left: [0.0, 1.0],
        ..PadState::default()
    };
    h.state_mut().teleop.pad = Some(stick_up);
    for _ in 0..3 {
        h.step();
    }
    assert_eq!(h.state().pose().position.x, x0);
    h.state_mut().teleop.pad = Some(PadState {
        deadman: true,
        ..stick_up
    });
    for _ in 0..3 {
        h.step();
    }
    let dx = h.state().pose().position.x - x0;
    assert!((dx - 0.03).abs() < 1e-9, "{dx}");
    h.state_mut().teleop.pad = None;
    // Up until the legs reach their 1.30 m stroke: the move stops there, the indicator
    // turns red and says why.
    h.key_down(egui::Key::R);
    for _ in 0..60 {
        h.step();
    }
    h.key_up(egui::Key::R);
    h.step();
    let longest = h.state().legs().lengths.into_iter().fold(0.0, f64::max);
    assert!((longest - 1.3).abs() < 1e-6, "{longest}");
    assert!(
        h.query_by_label_contains("Stopped at the edge: leg")
            .is_some()
    );
    h.get_by_label("Home").click();
    h.run();
    assert!(h.query_by_label("Reachable").is_some());
}

#[test]
fn an_armed_link_follows_the_teleoperated_pose() {
    let mut h = tall_harness("seed", 2400.0);
    h.get_by_label("Manual pose").click();
    h.run();
    h.state_mut().edit_link(|l| l.ramp_s = 0.05);
    h.state_mut().connect_link();
    h.state().link.arm();
    let started = Instant::now();
    while h.state().link.sender_status().map(|s| s.state) != Some(LinkState::Armed) {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(10));
        std::thread::sleep(Duration::from_millis(5));
    }
    h.key_down(egui::Key::R);
    for _ in 0..3 {
        h.step();
    }
    h.key_up(egui::Key::R);
    h.step();
    let want = h.state().legs().lengths[0] * 1e6;
    // The dry run's frames reach the raised pose (the supervisor may limit the rate).
    let started = Instant::now();
    loop {
        h.run();
        let last = h
            .state()
            .link
            .recent_lines()
            .last()
            .cloned()
            .unwrap_or_default();
        let bytes: Vec<u8> = last
            .split_whitespace()
            .skip(1)
            .map(|b| u8::from_str_radix(b, 16).unwrap_or(0))
            .collect();
        let first = bytes.get(8..12).map_or(0.0, |b| {
            f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        });
        if (first - want).abs() <= 1.0 {
            break;
        }
        assert!(
            started.elapsed() < Duration::from_secs(10),
            "{first} vs {want}"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    h.state_mut().link.disconnect_now();
}
