//! Measurements of the live cue, for its test and `benches/cue_lag.rs`: how far a platform
//! fed a slow input (a game at 60 samples a second) lags one fed the same input at 1 kHz,
//! with and without the input predicted between samples.

use std::f64::consts::TAU;

use stewart_kinematics::Scenario;

use crate::vehicle_in::live_cue::LiveCue;

/// The platform's surge (x, metres) at each 1 kHz tick over `seconds`, the vehicle's
/// forward specific force a unit sinusoid of `hz` sampled `rate` times a second, the input
/// predicted `horizon` seconds ahead (0: off); the seed platform, tilt off.
pub fn surge(rate: f64, hz: f64, horizon: f64, seconds: f64) -> Vec<(f64, f64)> {
    let mut scenario = Scenario::seed();
    scenario.cueing.tilt = false;
    scenario.cueing.input_prediction_s = horizon;
    let Ok(mut live) = LiveCue::bind("udp:127.0.0.1:0", &scenario) else {
        return Vec::new();
    };
    let mut k = 0u32;
    (0..(seconds * 1000.0) as u32)
        .map(|tick| {
            let t = f64::from(tick) / 1000.0;
            while f64::from(k) / rate <= t + 1e-12 {
                let ts = f64::from(k) / rate;
                let ax = (TAU * hz * ts).sin();
                live.receive(format!("{ts},{ax},0,0,0,0,0").as_bytes(), t);
                k += 1;
            }
            (t, live.settle(t, 0.001).position.x)
        })
        .collect()
}

/// The phase of `hz` in `trace` from `from` seconds on (a whole number of periods), rad.
pub fn phase(trace: &[(f64, f64)], hz: f64, from: f64) -> f64 {
    let w = TAU * hz;
    let (s, c) = (trace.iter())
        .filter(|(t, _)| *t >= from)
        .fold((0.0, 0.0), |(s, c), (t, x)| {
            (s + x * (w * t).sin(), c + x * (w * t).cos())
        });
    c.atan2(s)
}

/// How far the platform fed `hz` at `rate` samples a second (input predicted `horizon`
/// seconds ahead) lags the same input at 1 kHz, seconds.
pub fn lag(rate: f64, hz: f64, horizon: f64) -> f64 {
    let (seconds, from) = (6.0 / hz + 4.0, 4.0);
    let fine = phase(&surge(1000.0, hz, 0.0, seconds), hz, from);
    let coarse = phase(&surge(rate, hz, horizon, seconds), hz, from);
    (fine - coarse) / (TAU * hz)
}
