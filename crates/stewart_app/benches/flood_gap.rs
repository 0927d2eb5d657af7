//! The 1 kHz live-cue stream under a local datagram flood: as many datagrams as one
//! thread can send to the cue's port (vehicle samples, and every fourth a 60 kB datagram
//! of junk) while the sender streams the cued set-points to a local peer.
//!
//! First the figure the rig guide quotes: a real sender thread (raised priority where the
//! system allows, said below) streams for three seconds under the flood, and the largest
//! gap between two set-points sent, the 99th percentile of the period error and the
//! deadlines skipped are printed. Then criterion times one tick of the stream while the
//! flood goes on (its cost bounds the gap: a tick reads at most 64 datagrams and a fifth
//! of its period).
//!
//! `cargo bench -p stewart_app --bench flood_gap`.

use std::hint::black_box;
use std::net::{SocketAddr, UdpSocket};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Duration;

mod support;

use criterion::{Criterion, criterion_group};
use stewart_app::link_plan::LinkPlan;
use stewart_app::vehicle_in::live_cue::LiveCue;
use stewart_kinematics::Scenario;
use stewart_link::sender::{Sender, Stream};
use stewart_link::transport::Udp;
use support::{drained_peer, limited_seed};

/// A flood of datagrams to `to` until `done`; counts what it sent in `sent`.
fn flood(to: SocketAddr, done: Arc<AtomicBool>, sent: Arc<AtomicU64>) {
    std::thread::spawn(move || {
        let socket = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        let junk = vec![b'7'; 60_000];
        let mut k: u64 = 0;
        while !done.load(Ordering::Relaxed) {
            let sample = format!("{},-3,0.5,0,0,0,10", k as f64 * 1e-4);
            let bytes = if k.is_multiple_of(4) {
                &junk[..]
            } else {
                sample.as_bytes()
            };
            if socket.send_to(bytes, to).is_ok() {
                sent.fetch_add(1, Ordering::Relaxed);
            }
            k += 1;
        }
    });
}

/// Three seconds of the real sender at 1 kHz under the flood: its timing, printed.
fn stream_under_flood(scenario: &Scenario) {
    let plan = LinkPlan::new(scenario).unwrap_or_else(|e| panic!("{e}"));
    let live = LiveCue::bind("udp:127.0.0.1:0", scenario).unwrap_or_else(|e| panic!("{e}"));
    let to = live.local_addr().unwrap_or_else(|e| panic!("{e}"));
    let mut config = plan.sender_config(true, Some(3.0));
    config.rate_hz = 1000.0;
    let udp = Udp::connect(&drained_peer()).unwrap_or_else(|e| panic!("{e}"));
    let done = Arc::new(AtomicBool::new(false));
    let sent = Arc::new(AtomicU64::new(0));
    flood(to, Arc::clone(&done), Arc::clone(&sent));
    let sender = Sender::spawn(config, plan.cue_target(live), Box::new(udp))
        .unwrap_or_else(|e| panic!("{e}"));
    let summary = sender.join();
    done.store(true, Ordering::Relaxed);
    let s = summary.status;
    println!(
        "flood_gap: {} set-points in {:.2} s under a flood of {} datagrams ({}); largest gap between set-points at most {:.2} ms (1 ms and the largest period error), period error p99 {:.0} µs, deadlines skipped {}{}",
        s.frames,
        s.time,
        sent.load(Ordering::Relaxed),
        s.scheduling,
        (1000.0 + s.period_error.max_us) / 1000.0,
        s.period_error.p99_us,
        s.skipped,
        summary
            .failure
            .map_or_else(String::new, |f| format!("; failed: {f}")),
    );
}

fn bench(c: &mut Criterion) {
    let s = limited_seed();
    for _ in 0..3 {
        stream_under_flood(&s);
    }
    // One tick of the same stream, timed by criterion while the flood goes on.
    let plan = LinkPlan::new(&s).unwrap_or_else(|e| panic!("{e}"));
    let live = LiveCue::bind("udp:127.0.0.1:0", &s).unwrap_or_else(|e| panic!("{e}"));
    let to = live.local_addr().unwrap_or_else(|e| panic!("{e}"));
    let mut config = plan.sender_config(true, None);
    config.rate_hz = 1000.0;
    let udp = Udp::connect(&drained_peer()).unwrap_or_else(|e| panic!("{e}"));
    let mut stream = Stream::new(config, plan.cue_target(live), Box::new(udp));
    let done = Arc::new(AtomicBool::new(false));
    flood(to, Arc::clone(&done), Arc::new(AtomicU64::new(0)));
    // Armed and following before the timing starts.
    let mut t = 0.0;
    for _ in 0..2000 {
        t += 1e-3;
        stream.tick(t);
    }
    let mut group = c.benchmark_group("flood_gap");
    group.measurement_time(Duration::from_secs(5));
    group.bench_function("live_tick_under_flood", |b| {
        b.iter(|| {
            t += 1e-3;
            black_box(stream.tick(t))
        })
    });
    group.finish();
    done.store(true, Ordering::Relaxed);
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
}
