//! One tick of live motion cueing at 1 kHz: the washout and the workspace limiter alone,
//! then a whole sender tick that follows them (actuator values, supervisor, encoding, a
//! UDP send to a local peer), and the same with the vehicle motion arriving over UDP
//! (`LiveCue`: reading and decoding one datagram a tick too; the datagram is sent before
//! each timed tick, outside the time).
//!
//! The model-predictive cueing the same way: one planning step (a solve and 10 ms of its
//! plan, as `stewart cue` makes them), and the whole live sender tick with it (the
//! solves on the planner's thread, the tick following the plans).
//!
//! `cargo bench -p stewart_app --bench cue_tick`. Before criterion's means, 100 000
//! single ticks of each are timed one by one for the mean, the 99th percentile and the
//! worst (the figures docs/guide/rig.md quotes, "Live telemetry").

use std::hint::black_box;
use std::net::UdpSocket;
use std::time::Instant;

mod support;

use criterion::{Criterion, criterion_group};
use stewart_app::link_plan::LinkPlan;
use stewart_app::vehicle_in::live_cue::LiveCue;
use stewart_kinematics::Scenario;
use stewart_kinematics::analysis::cueing::{Cueing, VehicleMotion};
use stewart_link::sender::{Stream, time_each};
use stewart_link::target::{Sample, Target, TargetError};
use stewart_link::transport::Udp;
use support::{drained_peer, limited_seed};

/// The same platform cued by the model-predictive planner.
fn scenario_mpc() -> Scenario {
    let mut s = limited_seed();
    stewart_kinematics::io::settings::apply_all(&mut s, ["cueing.algorithm=mpc"])
        .unwrap_or_else(|e| panic!("{e}"));
    s
}

/// A manoeuvre: braking and turning, each channel its own sine.
fn vehicle(t: f64) -> VehicleMotion {
    VehicleMotion {
        accel: [
            6.0 * (0.7 * t).sin(),
            3.0 * (1.1 * t).sin(),
            1.0 * (2.0 * t).sin(),
        ],
        rates_deg_s: [
            20.0 * (0.9 * t).sin(),
            10.0 * (1.3 * t).sin(),
            30.0 * (0.5 * t).sin(),
        ],
    }
}

/// A sender stream to a local UDP peer (drained on its own thread) following `target`.
fn stream(scenario: &Scenario, target: Target) -> Stream {
    let address = drained_peer();
    let plan = LinkPlan::new(scenario).unwrap_or_else(|e| panic!("{e}"));
    let mut config = plan.sender_config(true, None);
    config.rate_hz = 1000.0;
    let udp = Udp::connect(&address).unwrap_or_else(|e| panic!("{e}"));
    let mut stream = Stream::new(config, target, Box::new(udp));
    for k in 1..=1000 {
        stream.tick(f64::from(k) * 1e-3);
    }
    stream
}

/// The cue computed in the target itself (no input socket).
fn computed_target(scenario: &Scenario) -> Target {
    let mut cueing = Cueing::new(&scenario.geometry, &scenario.limits, &scenario.cueing)
        .unwrap_or_else(|e| panic!("{e}"));
    let geometry = scenario.geometry.clone();
    let mut last = 0.0;
    Box::new(move |t| {
        let pose = cueing.advance(t - last);
        last = t;
        cueing.hold(&vehicle(t));
        geometry
            .actuator_values_at(&pose)
            .map(Sample::At)
            .map_err(TargetError::source)
    })
}

/// The cue from datagrams arriving at a `LiveCue`, and a function that sends the
/// sample of tick `k` to it.
fn live_target(scenario: &Scenario) -> (Target, impl FnMut(usize)) {
    let live = LiveCue::bind("udp:127.0.0.1:0", scenario).unwrap_or_else(|e| panic!("{e}"));
    let to = live.local_addr().unwrap_or_else(|e| panic!("{e}"));
    let socket = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    let send = move |k: usize| {
        let t = k as f64 * 1e-3;
        let v = vehicle(t);
        let [ax, ay, az] = v.accel;
        let [wx, wy, wz] = v.rates_deg_s;
        let line = format!("{t},{ax},{ay},{az},{wx},{wy},{wz}");
        socket
            .send_to(line.as_bytes(), to)
            .unwrap_or_else(|e| panic!("{e}"));
    };
    (
        LinkPlan::new(scenario)
            .unwrap_or_else(|e| panic!("{e}"))
            .cue_target(live),
        send,
    )
}

/// The mean, 99th percentile and worst of `n` single calls of `tick(k)`, each after an
/// untimed `before(k)`, printed.
fn percentiles(name: &str, n: usize, before: impl FnMut(usize), tick: impl FnMut(usize)) {
    let t = time_each(n, before, tick);
    println!(
        "{name}: {n} ticks one by one: mean {:.2} µs, p99 {:.0} µs, worst {:.1} µs",
        t.mean_us, t.p99_us, t.max_us
    );
}

fn bench(c: &mut Criterion) {
    let s = limited_seed();
    let mut group = c.benchmark_group("cue_tick");
    let mut cueing =
        Cueing::new(&s.geometry, &s.limits, &s.cueing).unwrap_or_else(|e| panic!("{e}"));
    let mut t = 0.0;
    group.bench_function("washout_and_limiter", |b| {
        b.iter(|| {
            t += 1e-3;
            cueing.hold(&vehicle(t));
            black_box(cueing.advance(1e-3))
        })
    });
    let mut computed = stream(&s, computed_target(&s));
    let mut t = 1.0;
    group.bench_function("cue_supervisor_encode_send", |b| {
        b.iter(|| {
            t += 1e-3;
            black_box(computed.tick(t))
        })
    });
    let (target, mut send) = live_target(&s);
    let mut live = stream(&s, target);
    let mut k = 0;
    group.bench_function("live_udp_cue_supervisor_encode_send", |b| {
        b.iter_custom(|iterations| {
            let mut total = std::time::Duration::ZERO;
            for _ in 0..iterations {
                k += 1;
                send(k);
                let started = Instant::now();
                black_box(live.tick(1.0 + k as f64 * 1e-3));
                total += started.elapsed();
            }
            total
        })
    });
    let m = scenario_mpc();
    let mut planner =
        Cueing::new(&m.geometry, &m.limits, &m.cueing).unwrap_or_else(|e| panic!("{e}"));
    let mut t = 0.0;
    group.bench_function("mpc_solve_and_10_ms", |b| {
        b.iter(|| {
            t += 1e-2;
            planner.hold(&vehicle(t));
            black_box(planner.advance(1e-2))
        })
    });
    let (target, mut send) = live_target(&m);
    let mut live = stream(&m, target);
    let mut k = 0;
    group.bench_function("mpc_live_udp_cue_supervisor_encode_send", |b| {
        b.iter_custom(|iterations| {
            let mut total = std::time::Duration::ZERO;
            for _ in 0..iterations {
                k += 1;
                send(k);
                let started = Instant::now();
                black_box(live.tick(1.0 + k as f64 * 1e-3));
                total += started.elapsed();
            }
            total
        })
    });
    group.finish();
}

criterion_group!(benches, bench);

fn main() {
    let s = limited_seed();
    let mut cueing =
        Cueing::new(&s.geometry, &s.limits, &s.cueing).unwrap_or_else(|e| panic!("{e}"));
    percentiles(
        "washout_and_limiter",
        100_000,
        |_| {},
        |k| {
            cueing.hold(&vehicle(k as f64 * 1e-3));
            black_box(cueing.advance(1e-3));
        },
    );
    let mut computed = stream(&s, computed_target(&s));
    percentiles(
        "cue_supervisor_encode_send",
        100_000,
        |_| {},
        |k| {
            black_box(computed.tick(1.0 + (k + 1) as f64 * 1e-3));
        },
    );
    let (target, send) = live_target(&s);
    let mut live = stream(&s, target);
    percentiles("live_udp_cue_supervisor_encode_send", 100_000, send, |k| {
        black_box(live.tick(1.0 + (k + 1) as f64 * 1e-3));
    });
    let m = scenario_mpc();
    let mut planner =
        Cueing::new(&m.geometry, &m.limits, &m.cueing).unwrap_or_else(|e| panic!("{e}"));
    percentiles(
        "mpc_solve_and_10_ms",
        20_000,
        |_| {},
        |k| {
            planner.hold(&vehicle(k as f64 * 1e-2));
            black_box(planner.advance(1e-2));
        },
    );
    let (target, send) = live_target(&m);
    let mut live = stream(&m, target);
    percentiles(
        "mpc_live_udp_cue_supervisor_encode_send",
        100_000,
        send,
        |k| {
            black_box(live.tick(1.0 + (k + 1) as f64 * 1e-3));
        },
    );
    benches();
    Criterion::default().configure_from_args().final_summary();
}
