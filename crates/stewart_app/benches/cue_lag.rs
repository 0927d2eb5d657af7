//! How smooth and how late a game's slow input reaches the platform (issue #44, "smooth at
//! the rig's rate"): the phase lag of a sinusoidal input sent at 60 samples a second behind
//! the same input at 1 kHz, held between samples and predicted (`[cueing]
//! input_prediction_s`, one sample ahead), at 0.5, 1 and 2 Hz — computed tick by tick,
//! deterministic; then the end-to-end latency from a datagram's arrival on the cue port to
//! the first 1 kHz tick that carries it, over loopback in real time.
//!
//! `cargo bench -p stewart_app --bench cue_lag` prints the tables docs/guide/rig.md quotes.

use std::net::UdpSocket;
use std::time::{Duration, Instant};

use stewart_app::vehicle_in::live_cue::LiveCue;
use stewart_app::vehicle_in::live_cue::measure::lag;
use stewart_kinematics::Scenario;

fn main() {
    println!("| input | 60 Hz, held | 60 Hz, predicted 1/60 s |");
    println!("|---|---|---|");
    for hz in [0.5, 1.0, 2.0] {
        let held = lag(60.0, hz, 0.0);
        let predicted = lag(60.0, hz, 1.0 / 60.0);
        println!(
            "| {hz} Hz | {:.1} ms ({:.1}°) | {:.1} ms ({:.1}°) |",
            1e3 * held,
            360.0 * hz * held,
            1e3 * predicted,
            360.0 * hz * predicted
        );
    }
    latency();
}

/// A step of the input about every 50 ms, sent by another thread at times unrelated to the
/// ticks, while a loop ticks at 1 kHz on absolute deadlines: the time from each send to the
/// tick that takes it (whose pose is the first to carry it).
fn latency() {
    let Ok(mut live) = LiveCue::bind("udp:127.0.0.1:0", &Scenario::seed()) else {
        println!("latency: cannot listen on loopback");
        return;
    };
    let (Ok(at), Ok(sender)) = (live.local_addr(), UdpSocket::bind("127.0.0.1:0")) else {
        println!("latency: no loopback");
        return;
    };
    let sends = std::sync::Arc::new(std::sync::Mutex::new(std::collections::VecDeque::new()));
    let log = std::sync::Arc::clone(&sends);
    let steps = 300u32;
    let thread = std::thread::spawn(move || {
        for k in 1..=steps {
            // 50.37 ms apart: the sends drift through every phase of the 1 ms tick.
            std::thread::sleep(Duration::from_micros(50_370));
            let ax = if k % 2 == 0 { 3.0 } else { -3.0 };
            let t = f64::from(k) * 0.05037;
            if let Ok(mut l) = log.lock() {
                l.push_back(Instant::now());
            }
            let _ = sender.send_to(format!("{t},{ax},0,0,0,0,0").as_bytes(), at);
        }
    });
    let start = Instant::now();
    let period = Duration::from_millis(1);
    let mut latencies = Vec::new();
    let mut before = live.samples_taken();
    for tick in 1..steps * 51 + 200 {
        let deadline = start + period * tick;
        if let Some(wait) = deadline.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
        live.tick(start.elapsed().as_secs_f64());
        // The tick that took the sample: its pose is the first to carry it.
        let now = live.samples_taken();
        for _ in before..now {
            let sent = sends.lock().ok().and_then(|mut l| l.pop_front());
            if let Some(at_send) = sent {
                latencies.push(at_send.elapsed().as_secs_f64() * 1e3);
            }
        }
        before = now;
    }
    let _ = thread.join();
    latencies.sort_by(f64::total_cmp);
    let n = latencies.len();
    if n == 0 {
        println!("latency: no sample arrived");
        return;
    }
    let mean = latencies.iter().sum::<f64>() / n as f64;
    let p99 = latencies[(n * 99 / 100).min(n - 1)];
    println!();
    println!("| datagram → first tick carrying it (1 kHz, {n} steps) | mean | p99 | max |");
    println!("|---|---|---|---|");
    println!(
        "| loopback, this machine | {mean:.2} ms | {p99:.2} ms | {:.2} ms |",
        latencies[n - 1]
    );
}
