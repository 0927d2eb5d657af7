//! The sender on a capturing transport: frames in order with the supervisor's values, a
//! stream that stops home and disarmed, a transport that fails mid-stream, refused rates.

use std::sync::{Arc, Mutex};

use super::*;
use crate::channels::Output;
use crate::frame::{FrameDecoder, ValueUnit};
use crate::safety::{ActuatorLimits, StopMode};
use crate::target::Sample;
use crate::transport::TransportError;

/// What a capture received: (stream time, bytes) per send.
type Sent = Arc<Mutex<Vec<(f64, Vec<u8>)>>>;

/// Keeps what it is given; fails from the `fail_at`-th send on, when set.
struct Capture {
    sent: Sent,
    fail_at: Option<usize>,
}

impl Transport for Capture {
    fn send(&mut self, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        let mut sent = self.sent.lock().unwrap_or_else(PoisonError::into_inner);
        if self.fail_at.is_some_and(|n| sent.len() >= n) {
            return Err(TransportError::Io {
                what: "sending to the test device".to_owned(),
                cause: std::io::Error::other("the device went away"),
            });
        }
        sent.push((t, bytes.to_vec()));
        Ok(())
    }

    fn describe(&self) -> String {
        "capture".to_owned()
    }
}

/// A supervisor of servos within ±60°, no rate limits, at home at 0°.
fn supervisor(ramp_s: f64, stop: StopMode) -> Supervisor {
    let limits = ActuatorLimits {
        range: [(-60.0, 60.0); 6],
        speed: None,
        accel: None,
        jerk: None,
    };
    Supervisor::new(limits, ramp_s, stop, [0.0; 6])
}

fn config(rate_hz: f64, stop_after: Option<f64>) -> SenderConfig {
    SenderConfig {
        rate_hz,
        format: WireFormat::Binary,
        map: ChannelMap::identity(Output::ServoCentidegree),
        supervisor: supervisor(0.05, StopMode::Home { speed: 400.0 }),
        arm_at_start: true,
        stop_after,
        record: None,
        clock: Clock::Wall,
    }
}

fn frames(sent: &[(f64, Vec<u8>)]) -> Vec<(f64, Frame)> {
    let mut d = FrameDecoder::new();
    sent.iter()
        .map(|(t, b)| {
            let f = b.iter().filter_map(|&x| d.push(x)).next();
            (
                *t,
                f.and_then(Result::ok)
                    .unwrap_or_else(|| panic!("not a frame")),
            )
        })
        .collect()
}

#[test]
fn a_stream_ramps_follows_returns_home_and_ends_disarmed() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: None,
    };
    // Servo k goes to 10·(k+1)° … well, 10, 20, … 60.
    let target: Target =
        Box::new(|_t| Ok(Sample::At(std::array::from_fn(|k| 10.0 * (k as f64 + 1.0)))));
    let sender = Sender::spawn(config(200.0, Some(0.2)), target, Box::new(transport))
        .unwrap_or_else(|e| panic!("{e}"));
    let summary = sender.join();
    assert_eq!(summary.failure, None);
    assert_eq!(summary.status.state, LinkState::Disarmed);
    let sent = sent.lock().unwrap_or_else(PoisonError::into_inner).clone();
    let frames = frames(&sent);
    // 0.2 s at 200 Hz, then the way home (60° at 400°/s: 0.15 s, 30 ticks) and a last frame
    // (fewer when a stalled machine made the sender skip deadlines, which it counts).
    let ticks = frames.len() as u64 + summary.status.skipped;
    assert!(ticks > 60 && ticks < 80, "{ticks}");
    for (k, (t, f)) in frames.iter().enumerate() {
        assert_eq!(f.sequence as usize, k);
        assert_eq!(f.unit, ValueUnit::Centidegree);
        // On the deadline grid, one tick apart unless the machine stalled (then later).
        assert!(
            (t * 200.0 - (t * 200.0).round()).abs() < 1e-9,
            "times are the deadlines"
        );
        assert!(k == 0 || *t > frames[k - 1].0);
    }
    // Arming from home, then the target itself (0.05 s ramp: ten ticks).
    assert!(frames[0].1.flags.armed && frames[0].1.values == [0; 6]);
    let at = |k: usize| frames[k].1.values;
    assert_eq!(at(20), [1000, 2000, 3000, 4000, 5000, 6000]);
    // The stop: e-stop flag once, then home at 400°/s (2°, 200 centidegrees, a tick).
    let stop = frames
        .iter()
        .position(|(_, f)| f.flags.estop)
        .unwrap_or_else(|| panic!("no e-stop frame"));
    assert!(frames[stop].0 >= 0.2 - 1e-12 && frames[stop - 1].0 < 0.2 - 1e-12);
    assert_eq!(frames[stop].1.values[5], 6000 - 200);
    // On the way home every frame is armed with the home flag (the controller follows the
    // values home), the e-stop flag only on the first; the values close in on home, and the
    // last armed frame is home exactly (a controller that holds when disarmed is home).
    let way_home = &frames[stop..frames.len() - 1];
    assert!(way_home.len() > 20, "{}", way_home.len());
    let values: Vec<i32> = way_home.iter().map(|f| f.1.values[5]).collect();
    for (i, (_, f)) in way_home.iter().enumerate() {
        assert!(f.flags.armed && f.flags.home, "{f:?}");
        assert_eq!(f.flags.estop, i == 0);
        assert!(
            i == 0 || values[i] < values[i - 1] || values[i] == 0,
            "{values:?}"
        );
    }
    assert_eq!(way_home[way_home.len() - 1].1.values, [0; 6]);
    let last = frames
        .last()
        .map(|f| f.1)
        .unwrap_or_else(|| panic!("no frames"));
    assert_eq!(last.values, [0; 6]);
    assert!(!last.flags.armed && !last.flags.home && !last.flags.estop);
    assert!(summary.status.timing.count as usize >= frames.len());
}

#[test]
fn a_stepped_clock_sends_every_tick_in_turn_and_the_same_frames_as_ticking_by_hand() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: None,
    };
    let wave = |t: f64| {
        Ok(Sample::At(std::array::from_fn(|k| {
            20.0 * (t + k as f64).sin()
        })))
    };
    let mut stepped = config(1000.0, Some(30.0));
    stepped.clock = Clock::Stepped;
    // Thirty seconds of stream, whatever the machine's load: no deadline can be missed.
    let sender = Sender::spawn(stepped, Box::new(wave), Box::new(transport))
        .unwrap_or_else(|e| panic!("{e}"));
    let summary = sender.join();
    assert_eq!(summary.failure, None);
    assert_eq!(summary.status.skipped, 0);
    assert_eq!(summary.status.timing.count, 0, "nothing is timed");
    assert_eq!(summary.status.scheduling, "stepped (no deadlines)");
    let sent = sent.lock().unwrap_or_else(PoisonError::into_inner).clone();
    for (k, (t, _)) in sent.iter().enumerate() {
        assert_eq!(*t, k as f64 * (1.0 / 1000.0), "tick {k}");
    }
    // The same stream ticked by hand, tick by tick: the same bytes.
    let by_hand = Arc::new(Mutex::new(Vec::new()));
    let capture = Capture {
        sent: Arc::clone(&by_hand),
        fail_at: None,
    };
    let mut config = config(1000.0, Some(30.0));
    config.supervisor.arm(0.0, [0.0; 6]);
    let mut stream = Stream::new(config, Box::new(wave), Box::new(capture));
    let mut k = 0;
    while by_hand.lock().unwrap_or_else(PoisonError::into_inner).len() < sent.len() {
        let t = k as f64 * (1.0 / 1000.0);
        if t >= 30.0 && stream.supervisor().state() == LinkState::Armed {
            stream.supervisor().estop();
        }
        stream.tick(t);
        k += 1;
    }
    let by_hand = by_hand
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .clone();
    assert_eq!(sent, by_hand);
    assert!(sent.len() > 30_000, "{}", sent.len());
}

#[test]
fn a_transport_that_fails_disarms_and_ends_the_stream() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: Some(5),
    };
    let target: Target = Box::new(|_t| Ok(Sample::At([5.0; 6])));
    let sender = Sender::spawn(config(500.0, None), target, Box::new(transport))
        .unwrap_or_else(|e| panic!("{e}"));
    let summary = sender.join();
    assert_eq!(
        summary.failure.as_deref(),
        Some("sending to the test device: the device went away; disarmed")
    );
    assert_eq!(summary.status.state, LinkState::Disarmed);
    assert_eq!(summary.status.frames, 5);
}

#[test]
fn an_estop_command_stops_the_platform() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: None,
    };
    let target: Target = Box::new(|_t| Ok(Sample::At([20.0; 6])));
    let mut cfg = config(200.0, None);
    cfg.supervisor = supervisor(0.01, StopMode::Hold);
    let sender = Sender::spawn(cfg, target, Box::new(transport)).unwrap_or_else(|e| panic!("{e}"));
    std::thread::sleep(Duration::from_millis(100));
    sender.command(Command::EStop);
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(sender.status().state, LinkState::Disarmed);
    let summary = sender.stop_and_join();
    assert_eq!(summary.failure, None);
    let sent = sent.lock().unwrap_or_else(PoisonError::into_inner).clone();
    let frames = frames(&sent);
    let stop = frames
        .iter()
        .position(|(_, f)| f.flags.estop)
        .unwrap_or_else(|| panic!("no e-stop frame"));
    // Held where it was, and never armed again.
    assert_eq!(frames[stop].1.values, [2000; 6]);
    assert!(
        frames[stop..]
            .iter()
            .all(|(_, f)| !f.flags.armed && f.values == [2000; 6])
    );
}

#[test]
fn rates_outside_10_to_1000_hz_are_refused() {
    for rate in [0.0, 5.0, 1500.0, f64::NAN] {
        let sent = Arc::new(Mutex::new(Vec::new()));
        let transport = Capture {
            sent,
            fail_at: None,
        };
        let target: Target = Box::new(|_t| Ok(Sample::At([0.0; 6])));
        let e = Sender::spawn(config(rate, None), target, Box::new(transport))
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(
            e.starts_with("the rate must be between 10 and 1000 Hz"),
            "{e}"
        );
    }
}

#[test]
fn a_stall_skips_the_deadlines_it_missed_instead_of_sending_a_burst() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: None,
    };
    // The target takes 40 ms once, at the tick of 0.05 s (eight 5 ms deadlines pass).
    let mut stalled = false;
    let target: Target = Box::new(move |t| {
        if t >= 0.05 && !stalled {
            stalled = true;
            std::thread::sleep(Duration::from_millis(40));
        }
        Ok(Sample::At([1.0; 6]))
    });
    let summary = Sender::spawn(config(200.0, Some(0.15)), target, Box::new(transport))
        .unwrap_or_else(|e| panic!("{e}"))
        .join();
    assert!(summary.status.skipped >= 7, "{:?}", summary.status);
    let sent = sent.lock().unwrap_or_else(PoisonError::into_inner).clone();
    let times: Vec<f64> = sent.iter().map(|(t, _)| *t).collect();
    let after = times
        .iter()
        .position(|&t| t > 0.05 + 1e-9)
        .unwrap_or_else(|| panic!("nothing after the stall"));
    // The first frame after the stall is for a deadline at least 40 ms later, and frames
    // follow one per deadline again: no burst of stale set-points.
    assert!(times[after] >= 0.09 - 1e-9, "{times:?}");
    assert_eq!(summary.status.frames as usize, times.len());
}

#[test]
fn two_stops_taken_in_the_same_tick_are_an_emergency_stop() {
    // However close together: both may wait in the inbox when a tick takes its commands,
    // before the first has turned the supervisor homewards. What the command line sends
    // for two Ctrl-Cs (e-stop and stop, then e-stop), two stops, two e-stops: each pair
    // is an emergency; one of each is not.
    let cases: [(&[Command], bool); 5] = [
        (&[Command::EStop, Command::Stop, Command::EStop], true),
        (&[Command::Stop, Command::Stop], true),
        (&[Command::EStop, Command::EStop], true),
        (&[Command::EStop, Command::Stop], false),
        (&[Command::Stop], false),
    ];
    for (commands, emergency) in cases {
        let mut sv = supervisor(0.05, StopMode::Home { speed: 20.0 });
        sv.arm(0.0, [10.0; 6]);
        let (tx, inbox) = mpsc::channel();
        for c in commands {
            tx.send(*c).unwrap_or_else(|e| panic!("{e}"));
        }
        let mut stopping = false;
        take_commands(&inbox, &mut sv, 0.01, &mut stopping);
        assert_eq!(sv.emergency(), emergency, "{commands:?}");
        assert!(stopping || commands == [Command::EStop, Command::EStop]);
    }
}

#[test]
fn a_second_stop_on_the_way_home_is_an_emergency_stop() {
    let sent = Arc::new(Mutex::new(Vec::new()));
    let transport = Capture {
        sent: Arc::clone(&sent),
        fail_at: None,
    };
    let target: Target = Box::new(|_t| Ok(Sample::At([50.0; 6])));
    let mut cfg = config(200.0, None);
    // Home at 20°/s: 50° takes 2.5 s, so the second stop comes well before home.
    cfg.supervisor = supervisor(0.01, StopMode::Home { speed: 20.0 });
    let sender = Sender::spawn(cfg, target, Box::new(transport)).unwrap_or_else(|e| panic!("{e}"));
    std::thread::sleep(Duration::from_millis(100));
    sender.command(Command::Stop);
    std::thread::sleep(Duration::from_millis(200));
    assert_eq!(sender.status().state, LinkState::Stopping);
    sender.command(Command::Stop);
    let summary = sender.join();
    assert_eq!(summary.failure, None);
    assert!(summary.status.emergency);
    assert_eq!(summary.status.state, LinkState::Disarmed);
    let sent = sent.lock().unwrap_or_else(PoisonError::into_inner).clone();
    let frames = frames(&sent);
    // Two e-stop frames: the first stop's (then armed on the way home), the second's
    // (disarmed where the platform was), then disarmed frames for 250 ms, and the end.
    let stops: Vec<usize> = (0..frames.len())
        .filter(|&k| frames[k].1.flags.estop)
        .collect();
    assert_eq!(stops.len(), 2, "{stops:?}");
    let (first, second) = (stops[0], stops[1]);
    assert!(frames[first].1.flags.home && frames[first].1.flags.armed);
    let left = frames[second].1;
    assert!(!left.flags.armed && !left.flags.home);
    // Left part of the way home, and reported so.
    assert!(left.values[0] > 0 && left.values[0] < 5000, "{left:?}");
    let wire = ChannelMap::identity(Output::ServoCentidegree)
        .wire(&summary.status.values)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(wire, left.values);
    let tail = &frames[second..];
    assert!(
        tail.iter()
            .all(|(_, f)| !f.flags.armed && f.values == left.values)
    );
    let lasted = tail[tail.len() - 1].0 - tail[0].0;
    assert!(
        (EMERGENCY_TAIL_S - 1e-9..EMERGENCY_TAIL_S + 0.05).contains(&lasted),
        "{lasted}"
    );
}
