//! The Motion cueing panel: a vehicle recording dropped on the window plays through the
//! washout, the panel plots what the platform makes felt, and its settings cue it again.

use egui_kittest::kittest::Queryable;
use stewart_kinematics::cueing::{VehicleMotion, cue_recording};
use stewart_kinematics::settings;

use crate::files::drop_file;

/// Braking at 5 m/s² from 1 to 3 s with a turn, every 20 ms for 5 s.
fn braking() -> (String, Vec<(f64, VehicleMotion)>) {
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    let mut samples = Vec::new();
    for k in 0..=250 {
        let t = f64::from(k) * 0.02;
        let ax = if (1.0..3.0).contains(&t) { -5.0 } else { 0.0 };
        let wz = if (2.0..4.0).contains(&t) { 15.0 } else { 0.0 };
        text.push_str(&format!("{t},{ax},0,0,0,0,{wz}\n"));
        let motion = VehicleMotion {
            accel: [ax, 0.0, 0.0],
            rates_deg_s: [0.0, 0.0, wz],
        };
        samples.push((t, motion));
    }
    (text, samples)
}

#[test]
fn a_vehicle_recording_plays_through_the_washout_and_follows_its_settings() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("braking.csv");
    let (text, samples) = braking();
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    let mut h = crate::tall_harness("seed", 2400.0);
    let before = h.state().scenario().clone();
    drop_file(&mut h, &path);
    assert!(
        h.query_by_label_contains("Cued 251 samples of vehicle motion over 5.00 s")
            .is_some(),
        "{:?}",
        h.state().files.status
    );
    // The motion is the poses `stewart cue` computes, through the samples' times.
    let scenario = h.state().scenario().clone();
    let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
    let cue = |s: &stewart_kinematics::Scenario| {
        cue_recording(&s.geometry, &s.limits, &s.cueing, &samples)
            .map(|c| c.to_motion(&times, "x").unwrap_or_else(|e| panic!("{e}")))
            .unwrap_or_else(|e| panic!("{e}"))
    };
    assert_eq!(scenario.motion.trajectory, cue(&scenario).trajectory);
    assert_eq!(scenario.motion.sampling.len(), 251);
    // The panel, opened: the recording and its plots.
    h.get_by_label("Motion cueing").click();
    h.run();
    crate::look(&mut h, "cueing.png");
    assert!(
        h.query_by_label_contains("Playing braking.csv: 251 samples")
            .is_some()
    );
    // A washout setting cues it again, as one edit.
    let scale = settings::find("cueing.translation_scale").unwrap_or_else(|e| panic!("{e}"));
    h.state_mut().editor().apply(scale, Some(1.0));
    h.run();
    let edited = h.state().scenario().clone();
    assert_eq!(edited.cueing.translation_scale, 1.0);
    assert_ne!(edited.motion, scenario.motion);
    assert_eq!(edited.motion.trajectory, cue(&edited).trajectory);
    // Undo: the scale and the motion come back together, and the recording with them
    // (it once vanished: the panel asked for a CSV and edits no longer cued it); redo
    // likewise; once more undone: the seed's motion.
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &scenario);
    assert!(
        h.state().doc.cued_vehicle().is_some(),
        "undo dropped the recording"
    );
    assert!(
        h.query_by_label_contains("Playing braking.csv: 251 samples")
            .is_some()
    );
    h.state_mut().redo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &edited);
    assert!(
        h.state().doc.cued_vehicle().is_some(),
        "redo dropped the recording"
    );
    h.state_mut().undo_edit();
    h.run();
    assert!(h.state().doc.cued_vehicle().is_some());
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &before);
    // With another motion playing, a washout edit leaves the motion alone.
    h.state_mut().editor().apply(scale, Some(0.8));
    assert_eq!(h.state().scenario().motion, before.motion);
}
