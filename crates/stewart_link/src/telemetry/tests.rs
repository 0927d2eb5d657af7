//! Matching telemetry to set-points: rows with both values and the latency; gaps counted as
//! unanswered; reordered, late and unknown answers counted as stale.

use std::time::{Duration, Instant};

use super::*;
use crate::channels::Output;
use crate::frame::{Flags, FrameKind, ValueUnit};

fn telemetry(sequence: u16, values: [i32; 6]) -> Frame {
    Frame {
        kind: FrameKind::Telemetry,
        sequence,
        flags: Flags {
            armed: true,
            ..Flags::default()
        },
        unit: ValueUnit::Micrometre,
        values,
    }
}

#[test]
fn answers_are_matched_gaps_are_unanswered_and_late_or_reordered_ones_stale() {
    let map = ChannelMap::identity(Output::LegMicrometre);
    let mut m = Matcher::default();
    let start = Instant::now();
    let at = |ms: u64| start + Duration::from_millis(ms);
    for k in 0..10u16 {
        m.sent(
            k,
            f64::from(k) * 0.01,
            at(u64::from(k) * 10),
            [1.0 + f64::from(k) * 1e-3; 6],
        );
    }
    // Set-point 0 answered 2 ms later, measured 2 µm short.
    let row = m
        .answer(&telemetry(0, [999_998; 6]), at(2), &map)
        .unwrap_or_else(|| panic!("no row"));
    assert_eq!(row.sequence, 0);
    assert_eq!(row.commanded, [1.0; 6]);
    assert!(row.measured.iter().all(|v| (v - 0.999_998).abs() < 1e-12));
    assert!((row.latency_s - 0.002).abs() < 1e-9);
    // 1 and 2 never answered; 3 is.
    assert!(
        m.answer(&telemetry(3, [1_003_000; 6]), at(33), &map)
            .is_some()
    );
    // 2 arrives after 3: reordered, stale. 4 answered 150 ms late: stale.
    assert!(
        m.answer(&telemetry(2, [1_002_000; 6]), at(34), &map)
            .is_none()
    );
    assert!(
        m.answer(&telemetry(4, [1_004_000; 6]), at(190), &map)
            .is_none()
    );
    // 60 was never sent.
    assert!(m.answer(&telemetry(60, [0; 6]), at(200), &map).is_none());
    let s = m.stats();
    assert_eq!((s.frames, s.answered, s.unanswered, s.stale), (5, 2, 2, 3));
    assert!((s.latency_mean_s - 0.0025).abs() < 1e-9);
    assert!((s.latency_max_s - 0.003).abs() < 1e-9);
}

#[test]
fn sequence_numbers_wrap() {
    let map = ChannelMap::identity(Output::LegMicrometre);
    let mut m = Matcher::default();
    let now = Instant::now();
    for k in [65_534u16, 65_535, 0, 1] {
        m.sent(k, 0.0, now, [1.0; 6]);
    }
    for k in [65_534u16, 65_535, 0, 1] {
        assert!(
            m.answer(&telemetry(k, [1_000_000; 6]), now, &map).is_some(),
            "{k}"
        );
    }
    assert_eq!(m.stats().unanswered, 0);
    assert_eq!(m.stats().stale, 0);
}
