//! The link's tick: one supervisor tick (six actuators, the trajectory generator included)
//! and one full tick of the sender (supervision, mapping, encoding, a UDP send to a local
//! peer, reading telemetry). Both must stay far under a 1 kHz period (1 ms).
//!
//! `cargo bench -p stewart_link --bench tick`. Criterion gives the means; before it runs,
//! 200 000 single ticks of each are timed one by one for the mean, the 99th percentile and
//! the worst (the figures docs/guide/rig.md quotes, "Tick time").

use std::hint::black_box;

#[path = "support/drained_peer.rs"]
mod support;
use support::drained_peer;

use criterion::{Criterion, criterion_group};
use stewart_link::channels::{ChannelMap, Output};
use stewart_link::safety::{ActuatorLimits, StopMode, Supervisor};
use stewart_link::sender::{Clock, SenderConfig, Stream, WireFormat, time_each};
use stewart_link::target::{ActuatorMotion, Sample, Target};
use stewart_link::transport::Udp;

/// Linear legs (metres) with the `paired` preset's limits and a jerk limit.
fn limits() -> ActuatorLimits {
    ActuatorLimits {
        range: [(0.9, 1.3); 6],
        speed: Some(0.5),
        accel: Some(5.0),
        jerk: Some(100.0),
    }
}

/// A motion of six legs: sines of `amplitude` metres at `hz` around 1.1 m, each leg its
/// own phase.
fn motion(t: f64, (amplitude, hz): (f64, f64)) -> Sample {
    let w = 2.0 * std::f64::consts::PI * hz;
    let phase = |k: usize| w * t + k as f64;
    Sample::Moving(ActuatorMotion {
        position: std::array::from_fn(|k| 1.1 + amplitude * phase(k).sin()),
        velocity: std::array::from_fn(|k| amplitude * w * phase(k).cos()),
        acceleration: std::array::from_fn(|k| -amplitude * w * w * phase(k).sin()),
    })
}

/// The two motions timed: within the limits (2 cm at 0.5 Hz: 13 % of the speed limit,
/// every tick one plan per actuator), and beyond them (15 cm at 2 Hz: nearly four times
/// the speed limit, every tick a search for the earliest meeting).
const MOTIONS: [(&str, (f64, f64)); 2] = [
    ("supervisor_following", (0.02, 0.5)),
    ("supervisor_catching_up", (0.15, 2.0)),
];

/// An armed supervisor at 1 kHz, `seconds` into the motion `wave`.
fn armed(wave: (f64, f64), seconds: f64) -> (Supervisor, f64) {
    let home = [1.1; 6];
    let mut s = Supervisor::new(limits(), 0.5, StopMode::Hold, home);
    s.arm(0.0, home);
    let mut t = 0.0;
    while t < seconds {
        t += 1e-3;
        s.tick_sample(t, Ok(motion(t, wave)));
    }
    (s, t)
}

/// A sender's stream, armed and following, to a local UDP peer that drains what it gets.
fn stream() -> Stream {
    let address = drained_peer();
    let mut supervisor = Supervisor::new(limits(), 0.5, StopMode::Hold, [1.1; 6]);
    supervisor.arm(0.0, [1.1; 6]);
    let config = SenderConfig {
        rate_hz: 1000.0,
        format: WireFormat::Binary,
        map: ChannelMap::identity(Output::LegMicrometre),
        supervisor,
        arm_at_start: true,
        stop_after: None,
        record: None,
        clock: Clock::Wall,
    };
    let target: Target = Box::new(|t| Ok(motion(t, MOTIONS[0].1)));
    let udp = Udp::connect(&address).unwrap_or_else(|e| panic!("{e}"));
    let mut stream = Stream::new(config, target, Box::new(udp));
    for k in 1..=1000 {
        stream.tick(f64::from(k) * 1e-3);
    }
    stream
}

/// The mean, 99th percentile and worst of `n` single calls of `tick(k)`, printed.
fn percentiles(name: &str, n: usize, tick: impl FnMut(usize)) {
    let t = time_each(n, |_| {}, tick);
    println!(
        "{name}: {n} ticks one by one: mean {:.2} µs, p99 {:.0} µs, worst {:.1} µs",
        t.mean_us, t.p99_us, t.max_us
    );
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("link_tick");
    for (name, wave) in MOTIONS {
        let (mut s, mut t) = armed(wave, 1.0);
        group.bench_function(name, |b| {
            b.iter(|| {
                t += 1e-3;
                black_box(s.tick_sample(t, Ok(motion(t, wave))))
            })
        });
    }
    let mut stream = stream();
    let mut t = 1.0;
    group.bench_function("sender_udp_loopback", |b| {
        b.iter(|| {
            t += 1e-3;
            black_box(stream.tick(t))
        })
    });
    group.finish();
}

criterion_group!(benches, bench);

fn main() {
    for (name, wave) in MOTIONS {
        let (mut s, t0) = armed(wave, 1.0);
        percentiles(name, 200_000, |k| {
            let t = t0 + (k + 1) as f64 * 1e-3;
            black_box(s.tick_sample(t, Ok(motion(t, wave))));
        });
    }
    let mut stream = stream();
    percentiles("sender_udp_loopback", 200_000, |k| {
        black_box(stream.tick(1.0 + (k + 1) as f64 * 1e-3));
    });
    benches();
    Criterion::default().configure_from_args().final_summary();
}
