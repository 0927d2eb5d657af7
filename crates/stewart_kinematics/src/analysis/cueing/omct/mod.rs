//! The Objective Motion Cueing Test (Advani and Hosman; ICAO Doc 9625, Attachment F;
//! Hosman and Advani, *The Aeronautical Journal* 2016): the whole cueing chain driven by a
//! sine of the vehicle's motion at twelve frequencies, `0.1 · 10^(k/5)` rad/s for
//! k = 0…11 (0.1 to 15.85 rad/s, five a decade), and the gain and phase of what the
//! occupant is given against what the vehicle did, in ten tests:
//!
//! - six direct: surge, sway, heave (the felt specific force over the vehicle's, at the
//!   reference point, in the platform's axes, gravity included, exactly as
//!   [`super::compare`] measures it) and roll, pitch, yaw (the platform's body rate over the
//!   vehicle's);
//! - four cross-couplings: surge-to-pitch and sway-to-roll (the platform's body rate per
//!   vehicle specific force: tilt coordination), pitch-to-surge and roll-to-sway (felt
//!   specific force per vehicle body rate: gravity turned into the platform's axes).
//!
//! Each run is the cueing as it runs live (the model-predictive planner without
//! look-ahead: a vehicle's motion is not known in advance), stepped at no more than a
//! millisecond, a whole number of steps a period, the input held over each step at its
//! value at the step's middle (a held input's half-step lag is gone: under 0.01° at
//! 15.85 rad/s). The output's fundamental comes from a discrete Fourier transform over two
//! whole periods once two periods in a row agree (the transient has died away). A
//! transport delay shifts the output. A test is *distorted* at a frequency where its
//! harmonics (2 to 10) reach [`DISTORTION_SHARE`] of its fundamental (a limit or a clamp
//! acting), or where the workspace limiter held the cue back or the planner's exact check
//! stopped it.
//!
//! The published OMCT amplitude table and Hosman and Advani's fidelity regions are not in
//! any public text available to this project; the default amplitudes are its own
//! ([`DEFAULT_FORCE_AMPLITUDE`], [`DEFAULT_RATE_AMPLITUDE`]), the same at every frequency,
//! and stated with every result.

mod fourier;

use std::f64::consts::TAU;

use nalgebra::Vector3;
use rayon::prelude::*;

use super::compare::felt_at;
use super::{CueError, Cueing, VehicleMotion};
use crate::model::cueing_settings::{CueingAlgorithm, CueingSettings};
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// The test's default amplitude of vehicle specific force, m/s² (about a tenth of g).
pub const DEFAULT_FORCE_AMPLITUDE: f64 = 1.0;

/// The test's default amplitude of vehicle body rate, °/s.
pub const DEFAULT_RATE_AMPLITUDE: f64 = 5.0;

/// Harmonics above this share of the fundamental mark an output distorted.
pub const DISTORTION_SHARE: f64 = 0.05;

/// The longest simulation step, seconds.
pub const LONGEST_STEP_S: f64 = 1e-3;

/// The most test frequencies accepted.
pub const MOST_FREQUENCIES: usize = 60;

/// The lowest and highest test frequencies accepted, rad/s.
pub const FREQUENCY_RANGE: [f64; 2] = [0.01, 100.0];

/// The smallest and largest amplitude scales accepted.
pub const SCALE_RANGE: [f64; 2] = [1e-3, 10.0];

/// The OMCT's twelve frequencies, `0.1 · 10^(k/5)` rad/s.
pub fn frequencies() -> [f64; 12] {
    std::array::from_fn(|k| 0.1 * 10f64.powf(k as f64 / 5.0))
}

/// A vehicle quantity driven, or a platform quantity measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    /// Specific force along x, y or z (0, 1, 2), m/s².
    Force(usize),
    /// Body rate about x, y or z (0, 1, 2), °/s.
    Rate(usize),
}

impl Channel {
    /// The unit, `m/s²` or `°/s`.
    pub fn unit(self) -> &'static str {
        match self {
            Channel::Force(_) => "m/s²",
            Channel::Rate(_) => "°/s",
        }
    }

    /// What the occupant is given: `felt specific force x` … `platform body rate z`.
    pub fn felt_words(self) -> String {
        match self {
            Channel::Force(_) => format!("felt {}", self.words()),
            Channel::Rate(_) => format!("platform {}", self.words()),
        }
    }

    /// `specific force x` … `body rate z`.
    pub fn words(self) -> String {
        match self {
            Channel::Force(i) => format!("specific force {}", ["x", "y", "z"][i]),
            Channel::Rate(i) => format!("body rate {}", ["x", "y", "z"][i]),
        }
    }
}

/// One of the ten tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OmctTest {
    /// Felt over vehicle specific force along x.
    Surge,
    /// Along y.
    Sway,
    /// Along z.
    Heave,
    /// Platform over vehicle body rate about x.
    Roll,
    /// About y.
    Pitch,
    /// About z.
    Yaw,
    /// Platform pitch rate per vehicle specific force along x.
    SurgeToPitch,
    /// Platform roll rate per vehicle specific force along y.
    SwayToRoll,
    /// Felt specific force along x per vehicle pitch rate.
    PitchToSurge,
    /// Felt specific force along y per vehicle roll rate.
    RollToSway,
}

impl OmctTest {
    /// The ten, the six direct first.
    pub const ALL: [OmctTest; 10] = [
        OmctTest::Surge,
        OmctTest::Sway,
        OmctTest::Heave,
        OmctTest::Roll,
        OmctTest::Pitch,
        OmctTest::Yaw,
        OmctTest::SurgeToPitch,
        OmctTest::SwayToRoll,
        OmctTest::PitchToSurge,
        OmctTest::RollToSway,
    ];

    /// `surge` … `roll-to-sway`.
    pub fn name(self) -> &'static str {
        match self {
            OmctTest::Surge => "surge",
            OmctTest::Sway => "sway",
            OmctTest::Heave => "heave",
            OmctTest::Roll => "roll",
            OmctTest::Pitch => "pitch",
            OmctTest::Yaw => "yaw",
            OmctTest::SurgeToPitch => "surge-to-pitch",
            OmctTest::SwayToRoll => "sway-to-roll",
            OmctTest::PitchToSurge => "pitch-to-surge",
            OmctTest::RollToSway => "roll-to-sway",
        }
    }

    /// The vehicle quantity driven.
    pub fn input(self) -> Channel {
        match self {
            OmctTest::Surge | OmctTest::SurgeToPitch => Channel::Force(0),
            OmctTest::Sway | OmctTest::SwayToRoll => Channel::Force(1),
            OmctTest::Heave => Channel::Force(2),
            OmctTest::Roll | OmctTest::RollToSway => Channel::Rate(0),
            OmctTest::Pitch | OmctTest::PitchToSurge => Channel::Rate(1),
            OmctTest::Yaw => Channel::Rate(2),
        }
    }

    /// The platform quantity measured.
    pub fn output(self) -> Channel {
        match self {
            OmctTest::Surge | OmctTest::PitchToSurge => Channel::Force(0),
            OmctTest::Sway | OmctTest::RollToSway => Channel::Force(1),
            OmctTest::Heave => Channel::Force(2),
            OmctTest::Roll | OmctTest::SwayToRoll => Channel::Rate(0),
            OmctTest::Pitch | OmctTest::SurgeToPitch => Channel::Rate(1),
            OmctTest::Yaw => Channel::Rate(2),
        }
    }

    /// Whether the output is the input's own quantity.
    pub fn direct(self) -> bool {
        self.input() == self.output()
    }

    /// The gain's unit: `-` for a direct test, else output per input (`°/s per m/s²`).
    pub fn unit(self) -> String {
        if self.direct() {
            "-".to_owned()
        } else {
            format!("{} per {}", self.output().unit(), self.input().unit())
        }
    }

    /// The gain that is a full response in the test's unit: 1 for a direct test; for the
    /// cross-couplings, a tilt that renders the force (`1/g` rad per m/s², in °/s per
    /// m/s² of rate) or the force a tilt renders (`g` m/s² per rad, per °/s).
    pub fn natural_gain(self) -> f64 {
        let degrees = 180.0 / std::f64::consts::PI;
        match (self.input(), self.output()) {
            (Channel::Force(_), Channel::Rate(_)) => {
                degrees / crate::model::cueing_settings::GRAVITY
            }
            (Channel::Rate(_), Channel::Force(_)) => {
                crate::model::cueing_settings::GRAVITY / degrees
            }
            _ => 1.0,
        }
    }

    /// The default amplitude of its input (its unit: m/s² or °/s).
    pub fn default_amplitude(self) -> f64 {
        match self.input() {
            Channel::Force(_) => DEFAULT_FORCE_AMPLITUDE,
            Channel::Rate(_) => DEFAULT_RATE_AMPLITUDE,
        }
    }
}

/// How the test is run.
#[derive(Clone, Debug, PartialEq)]
pub struct OmctOptions {
    /// The frequencies, rad/s ([`frequencies`] by default).
    pub frequencies: Vec<f64>,
    /// Multiplies every test's default amplitude.
    pub amplitude_scale: f64,
    /// A transport delay added after the cueing, seconds (the rig's, as the link measures
    /// it).
    pub latency_s: f64,
}

impl Default for OmctOptions {
    fn default() -> Self {
        Self {
            frequencies: frequencies().to_vec(),
            amplitude_scale: 1.0,
            latency_s: 0.0,
        }
    }
}

/// Why the test cannot run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OmctError {
    /// The cueing refused its settings, rig or limits.
    #[error(transparent)]
    Cueing(#[from] CueError),
    /// A frequency outside [`FREQUENCY_RANGE`] (or none).
    #[error(
        "the test frequency {0} rad/s is outside {lo} … {hi} rad/s",
        lo = FREQUENCY_RANGE[0],
        hi = FREQUENCY_RANGE[1]
    )]
    Frequency(f64),
    /// No frequency at all.
    #[error("the test needs at least one frequency")]
    NoFrequency,
    /// More than [`MOST_FREQUENCIES`] frequencies.
    #[error("{0} test frequencies: at most {MOST_FREQUENCIES} (the test has twelve)")]
    TooManyFrequencies(usize),
    /// Frequencies not rising.
    #[error("the test frequencies must rise: {1} rad/s follows {0} rad/s")]
    Unordered(f64, f64),
    /// An amplitude scale outside [`SCALE_RANGE`].
    #[error(
        "the amplitude scale {0} is outside {lo} … {hi}",
        lo = SCALE_RANGE[0],
        hi = SCALE_RANGE[1]
    )]
    Scale(f64),
    /// A delay that is negative, not finite, or over a second.
    #[error("the latency {0} s must lie within 0 … 1 s")]
    Latency(f64),
    /// Stopped on request.
    #[error("stopped before the test was complete")]
    Stopped,
}

/// One test at every frequency.
#[derive(Clone, Debug, PartialEq)]
pub struct TestResult {
    /// Which.
    pub test: OmctTest,
    /// The input's amplitude (its unit), the same at every frequency.
    pub amplitude: f64,
    /// Output over input amplitude, per frequency (the test's unit).
    pub gain: Vec<f64>,
    /// The output's phase against the input, degrees within (−180°, 180°] (negative: a
    /// lag), per frequency, whatever the other frequencies; NaN where there is no response
    /// at all (gain 0). [`TestResult::continuous_phase_deg`] draws them as one curve.
    pub phase_deg: Vec<f64>,
    /// The harmonics' share of the fundamental (total harmonic distortion), per frequency.
    pub distortion: Vec<f64>,
    /// Whether the workspace limiter held the cue back (or the planner's exact check
    /// stopped it) while it was measured.
    pub limited: Vec<bool>,
    /// Whether the result is distorted: harmonics above [`DISTORTION_SHARE`] of the
    /// fundamental, or a limit acting.
    pub distorted: Vec<bool>,
}

/// The whole test.
#[derive(Clone, Debug, PartialEq)]
pub struct OmctReport {
    /// The algorithm run.
    pub algorithm: CueingAlgorithm,
    /// The frequencies, rad/s.
    pub frequencies: Vec<f64>,
    /// The transport delay added, seconds.
    pub latency_s: f64,
    /// The ten tests, in [`OmctTest::ALL`]'s order.
    pub tests: Vec<TestResult>,
}

/// The OMCT of the cueing `settings` on `geometry` within `limits`. The runs share the
/// cores; `stop` is asked between periods and ends it with [`OmctError::Stopped`].
pub fn omct(
    geometry: &Geometry,
    limits: &Limits,
    settings: &CueingSettings,
    options: &OmctOptions,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<OmctReport, OmctError> {
    if options.frequencies.is_empty() {
        return Err(OmctError::NoFrequency);
    }
    if options.frequencies.len() > MOST_FREQUENCIES {
        return Err(OmctError::TooManyFrequencies(options.frequencies.len()));
    }
    for &f in &options.frequencies {
        if !(FREQUENCY_RANGE[0]..=FREQUENCY_RANGE[1]).contains(&f) {
            return Err(OmctError::Frequency(f));
        }
    }
    if let Some(w) = options.frequencies.windows(2).find(|w| w[1] <= w[0]) {
        return Err(OmctError::Unordered(w[0], w[1]));
    }
    let scale = options.amplitude_scale;
    if !(SCALE_RANGE[0]..=SCALE_RANGE[1]).contains(&scale) {
        return Err(OmctError::Scale(scale));
    }
    if !(0.0..=1.0).contains(&options.latency_s) {
        return Err(OmctError::Latency(options.latency_s));
    }
    // As live: no look-ahead.
    let settings = CueingSettings {
        mpc_preview: false,
        ..settings.clone()
    };
    // Refused settings are said once, before any run.
    Cueing::new(geometry, limits, &settings)?;
    let jobs: Vec<(OmctTest, usize)> = OmctTest::ALL
        .iter()
        .flat_map(|&t| (0..options.frequencies.len()).map(move |k| (t, k)))
        .collect();
    let runs: Vec<Result<Measured, OmctError>> = jobs
        .par_iter()
        .map(|&(test, k)| {
            let run = Run {
                geometry,
                limits,
                settings: &settings,
                test,
                omega: options.frequencies[k],
                amplitude: scale * test.default_amplitude(),
                latency_s: options.latency_s,
            };
            run.measure(stop)
        })
        .collect();
    let mut tests: Vec<TestResult> = OmctTest::ALL
        .iter()
        .map(|&test| TestResult {
            test,
            amplitude: scale * test.default_amplitude(),
            gain: Vec::new(),
            phase_deg: Vec::new(),
            distortion: Vec::new(),
            limited: Vec::new(),
            distorted: Vec::new(),
        })
        .collect();
    for ((test, _), run) in jobs.iter().zip(runs) {
        let m = run?;
        let r = &mut tests[OmctTest::ALL.iter().position(|t| t == test).unwrap_or(0)];
        r.gain.push(m.gain);
        r.phase_deg.push(m.phase_deg);
        r.distortion.push(m.distortion);
        r.limited.push(m.limited);
        r.distorted
            .push(m.distortion > DISTORTION_SHARE || m.limited);
    }
    Ok(OmctReport {
        algorithm: settings.algorithm,
        frequencies: options.frequencies.clone(),
        latency_s: options.latency_s,
        tests,
    })
}

impl TestResult {
    /// The phases made one curve for a figure: continuous down from the highest
    /// frequency's (as given, within ±180°, where a washout's high-passes have let the
    /// motion through), each within half a turn of the one above it.
    pub fn continuous_phase_deg(&self) -> Vec<f64> {
        let mut phases = self.phase_deg.clone();
        let mut above: Option<f64> = None;
        for p in phases.iter_mut().rev().filter(|p| p.is_finite()) {
            if let Some(a) = above {
                *p -= 360.0 * ((*p - a) / 360.0).round();
            }
            above = Some(*p);
        }
        phases
    }
}

/// One test at one frequency.
struct Run<'a> {
    geometry: &'a Geometry,
    limits: &'a Limits,
    settings: &'a CueingSettings,
    test: OmctTest,
    omega: f64,
    amplitude: f64,
    latency_s: f64,
}

/// What one run measured.
struct Measured {
    gain: f64,
    phase_deg: f64,
    distortion: f64,
    limited: bool,
}

/// Periods run at most before the transient counts as gone, and the simulated time.
const MOST_PERIODS: usize = 400;
const MOST_SECONDS: f64 = 1500.0;

impl Run<'_> {
    /// The vehicle's motion at time `t`.
    fn vehicle(&self, t: f64) -> VehicleMotion {
        let v = self.amplitude * (self.omega * t).sin();
        let mut m = VehicleMotion::default();
        match self.test.input() {
            Channel::Force(i) => m.accel[i] = v,
            Channel::Rate(i) => m.rates_deg_s[i] = v,
        }
        m
    }

    /// Run periods until two in a row give the same fundamental, then measure the last
    /// two.
    fn measure(&self, stop: &(dyn Fn() -> bool + Sync)) -> Result<Measured, OmctError> {
        let n = fourier::steps_per_period(self.omega, LONGEST_STEP_S);
        let h = TAU / self.omega / n as f64;
        let mut cueing = Cueing::new(self.geometry, self.limits, self.settings)?;
        let arm = Vector3::from(self.settings.reference_m) - self.geometry.pivot();
        // The poses at the last three sample times; the output at the middle one.
        let mut poses: [Pose; 3] = [cueing.advance(0.0); 3];
        let mut step = 0usize;
        // The planner's refusals so far (its exact check stopping the platform).
        let stops = |c: &Cueing| c.mpc_counts().map_or(0, |m| m.stops + m.failed);
        let mut stopped = 0;
        // The last two periods' output samples.
        let mut periods: std::collections::VecDeque<Period> = std::collections::VecDeque::new();
        let most = MOST_PERIODS.min(((MOST_SECONDS * self.omega / TAU).ceil() as usize).max(4));
        for count in 1..=most {
            if stop() {
                return Err(OmctError::Stopped);
            }
            let oldest = if periods.len() == 2 {
                periods.pop_front()
            } else {
                None
            };
            let mut period = oldest.unwrap_or_else(|| Period::with_capacity(n));
            period.clear();
            for _ in 0..n {
                // At rest before t = 0; each step's input held at its middle.
                cueing.hold(&self.vehicle((step as f64 + 0.5) * h));
                poses = [poses[1], poses[2], cueing.advance(h)];
                // The output at the middle of the last three poses, t = step · h.
                let t = step as f64 * h;
                let (force, rate) =
                    felt_at(&arm, [t - h, t, t + h], [&poses[0], &poses[1], &poses[2]]);
                let out = match self.test.output() {
                    Channel::Force(i) => force[i],
                    Channel::Rate(i) => rate[i].to_degrees(),
                };
                period.times.push(t);
                period.output.push(out);
                period.limited |= cueing.scale() < 1.0 || stops(&cueing) > stopped;
                stopped = stops(&cueing);
                step += 1;
            }
            periods.push_back(period);
            if count >= 3
                && let [a, b] = [&periods[0], &periods[1]]
                && a.agrees_with(b, self.omega)
            {
                break;
            }
        }
        let times: Vec<f64> = periods
            .iter()
            .flat_map(|p| p.times.iter().copied())
            .collect();
        let output: Vec<f64> = periods
            .iter()
            .flat_map(|p| p.output.iter().copied())
            .collect();
        // The delay: the output at t is what the cue gave at t − d.
        let shifted: Vec<f64> = times.iter().map(|t| t + self.latency_s).collect();
        let y = fourier::component(&shifted, &output, self.omega);
        let input: Vec<f64> = times
            .iter()
            .map(|t| self.amplitude * (self.omega * t).sin())
            .collect();
        let u = fourier::component(&times, &input, self.omega);
        let ratio = divide(y, u);
        // No response at all (rounding's noise on nothing): its phase is none.
        let nothing = 1e-9 * self.amplitude * self.test.natural_gain();
        let responds = output.iter().any(|v| v.abs() > nothing);
        Ok(Measured {
            gain: if responds {
                ratio.0.hypot(ratio.1)
            } else {
                0.0
            },
            phase_deg: if responds {
                ratio.1.atan2(ratio.0).to_degrees()
            } else {
                f64::NAN
            },
            distortion: fourier::harmonic_distortion(&times, &output, self.omega, n, nothing),
            limited: periods.iter().any(|p| p.limited),
        })
    }
}

/// `a / b` for complex numbers as `(re, im)`.
fn divide(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let d = b.0 * b.0 + b.1 * b.1;
    ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
}

/// One period's output samples.
struct Period {
    times: Vec<f64>,
    output: Vec<f64>,
    /// Whether the limiter held the cue back in it.
    limited: bool,
}

impl Period {
    fn with_capacity(n: usize) -> Self {
        Self {
            times: Vec::with_capacity(n),
            output: Vec::with_capacity(n),
            limited: false,
        }
    }

    fn clear(&mut self) {
        self.times.clear();
        self.output.clear();
        self.limited = false;
    }

    /// Whether this period's fundamental and `next`'s agree to a ten-thousandth of its size
    /// (compared as a function of the phase within the period: the same times mod period).
    fn agrees_with(&self, next: &Period, omega: f64) -> bool {
        let a = fourier::component(&self.times, &self.output, omega);
        let b = fourier::component(&next.times, &next.output, omega);
        let size = a.0.hypot(a.1).max(b.0.hypot(b.1));
        let change = (a.0 - b.0).hypot(a.1 - b.1);
        change <= 1e-4 * size || size < 1e-12
    }
}

#[cfg(test)]
mod tests;
