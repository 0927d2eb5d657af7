//! The Link panel: connect a dry run, arm, follow, e-stop by Esc, disconnect; the state
//! shown in words and colours; a refused channel map says why and changes nothing.

use std::time::{Duration, Instant};

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use stewart_app::viewer::state::ViewerState;
use stewart_link::safety::LinkState;

use crate::tall_harness;

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
    assert!(!h.state().link.recent_lines().is_empty());
    // Esc is the e-stop: the platform goes home and the link disarms.
    h.key_press(egui::Key::Escape);
    h.run();
    let after = h.state().link.sender_status().map(|s| s.state);
    assert!(
        matches!(after, Some(LinkState::Stopping | LinkState::Disarmed)),
        "{after:?}"
    );
    until(&mut h, LinkState::Disarmed);
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
