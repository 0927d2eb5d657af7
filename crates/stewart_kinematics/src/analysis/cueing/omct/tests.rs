use std::f64::consts::PI;

use super::*;
use crate::model::cueing_settings::GRAVITY;

fn never() -> bool {
    false
}

/// A complex number as `(re, im)`.
type C = (f64, f64);

fn mul(a: C, b: C) -> C {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

fn div(a: C, b: C) -> C {
    let d = b.0 * b.0 + b.1 * b.1;
    ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
}

fn add(a: C, b: C) -> C {
    (a.0 + b.0, a.1 + b.1)
}

fn scale(a: C, k: f64) -> C {
    (a.0 * k, a.1 * k)
}

/// `s² + 2ζω s + ω²` at `s`.
fn second(s: C, w: f64, z: f64) -> C {
    add(add(mul(s, s), scale(s, 2.0 * z * w)), (w * w, 0.0))
}

/// The washout's transfer function of `test` at `s = iω`, from the filters alone.
fn washout(settings: &CueingSettings, test: OmctTest, omega: f64) -> C {
    let s = (0.0, omega);
    let c = settings;
    let (kt, kr) = (c.translation_scale, c.rotation_scale);
    let s2 = mul(s, s);
    let s3 = mul(s2, s);
    // Felt over vehicle force through the translational channel: k_t s³/((s²+…)(s+ω_b)).
    let translation = scale(
        div(
            s3,
            mul(
                second(s, c.translation_hp_wn, c.translation_hp_zeta),
                add(s, (c.translation_hp_wb, 0.0)),
            ),
        ),
        kt,
    );
    // The tilt's low-passed force: k_t ω_t²/(s²+…).
    let tilt = scale(
        div(
            (c.tilt_lp_wn.powi(2), 0.0),
            second(s, c.tilt_lp_wn, c.tilt_lp_zeta),
        ),
        kt,
    );
    // The rotational channel's angle per rate: k_r s/(s²+…).
    let angle = scale(div(s, second(s, c.rotation_hp_wn, c.rotation_hp_zeta)), kr);
    let degrees = 180.0 / PI;
    match test {
        OmctTest::Surge | OmctTest::Sway => add(translation, tilt),
        OmctTest::Heave => translation,
        OmctTest::Roll | OmctTest::Pitch | OmctTest::Yaw => mul(s, angle),
        // Pitch nose-up (negative) for a forward force, roll right-side-down for a force to
        // the left: the tilt `∓asin(f/g)`, its rate in °/s per m/s².
        OmctTest::SurgeToPitch => scale(mul(s, tilt), -degrees / GRAVITY),
        OmctTest::SwayToRoll => scale(mul(s, tilt), degrees / GRAVITY),
        // Gravity along the turned platform: −g θ along x for pitch θ, +g φ along y for roll
        // φ; per °/s of vehicle rate.
        OmctTest::PitchToSurge => scale(angle, -GRAVITY / degrees),
        OmctTest::RollToSway => scale(angle, GRAVITY / degrees),
    }
}

fn linear_washout() -> CueingSettings {
    CueingSettings {
        // The tilt rate limit out of reach, the limiter off.
        tilt_rate_max_deg_s: 360.0,
        workspace_limiter: false,
        reference_m: [0.1, -0.05, 0.3],
        ..CueingSettings::default()
    }
}

#[test]
fn every_washout_test_is_its_filters_transfer_function() {
    // All ten tests at the twelve frequencies against the filters' own transfer functions
    // (the tilt rate limit out of reach, the limiter off, a tenth of the default
    // amplitudes: the small-angle regime the transfer functions describe).
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let settings = linear_washout();
    let options = OmctOptions {
        amplitude_scale: 0.1,
        ..OmctOptions::default()
    };
    let report = omct(&s.geometry, &Limits::default(), &settings, &options, &never).expect("runs");
    assert_eq!(report.frequencies.len(), 12);
    assert!((report.frequencies[11] - 15.848_931_924_611_13).abs() < 1e-12);
    let (mut worst_gain, mut worst_phase) = (0.0f64, 0.0f64);
    for r in &report.tests {
        for (k, &omega) in report.frequencies.iter().enumerate() {
            let exact = washout(&settings, r.test, omega);
            let gain = exact.0.hypot(exact.1);
            let phase = exact.1.atan2(exact.0).to_degrees();
            let mut dphase = r.phase_deg[k] - phase;
            dphase -= 360.0 * (dphase / 360.0).round();
            assert!(
                (r.gain[k] - gain).abs() <= 1e-3 * gain,
                "{} at {omega}: gain {} vs {gain}",
                r.test.name(),
                r.gain[k]
            );
            assert!(
                dphase.abs() <= 0.05,
                "{} at {omega}: phase {} vs {phase}",
                r.test.name(),
                r.phase_deg[k]
            );
            assert!(
                !r.distorted[k],
                "{} at {omega}: {}",
                r.test.name(),
                r.distortion[k]
            );
            worst_gain = worst_gain.max((r.gain[k] - gain).abs() / gain);
            worst_phase = worst_phase.max(dphase.abs());
        }
    }
    // The issue asks 1 % and 0.5°; the run gives about 0.03 % and 0.016°.
    assert!(worst_gain < 1e-3 && worst_phase < 0.05);
}

#[test]
fn on_every_kind_of_rig_within_its_own_limits_the_washout_s_report_is_its_filters() {
    // Linear (seed, paired) and rotary (servo-desk, crank-rig) rigs, each within its own
    // strokes, servo ranges and cones: at small amplitudes nothing clips, and every test
    // at the ends and middle of the range is still the filters' transfer function.
    let settings = linear_washout();
    let options = OmctOptions {
        frequencies: vec![0.1, 1.0, 15.848_931_924_611_13],
        amplitude_scale: 0.05,
        latency_s: 0.0,
    };
    for name in ["seed", "paired", "servo-desk", "crank-rig"] {
        let s = crate::io::scenario::Scenario::preset(name).expect("preset");
        let report = omct(&s.geometry, &s.limits, &settings, &options, &never).expect("runs");
        for r in &report.tests {
            for (k, &omega) in report.frequencies.iter().enumerate() {
                let exact = washout(&settings, r.test, omega);
                let gain = exact.0.hypot(exact.1);
                let mut dphase = r.phase_deg[k] - exact.1.atan2(exact.0).to_degrees();
                dphase -= 360.0 * (dphase / 360.0).round();
                let what = format!("{name}, {} at {omega}", r.test.name());
                assert!(!r.distorted[k], "{what}: {}", r.distortion[k]);
                assert!(
                    (r.gain[k] - gain).abs() <= 1e-3 * gain,
                    "{what}: {}",
                    r.gain[k]
                );
                assert!(dphase.abs() <= 0.05, "{what}: {}", r.phase_deg[k]);
            }
        }
    }
}

#[test]
fn a_millisecond_of_delay_adds_its_lag_and_nothing_else() {
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let settings = linear_washout();
    let run = |latency_s: f64| {
        let options = OmctOptions {
            frequencies: vec![15.848_931_924_611_13],
            amplitude_scale: 0.1,
            latency_s,
        };
        omct(&s.geometry, &Limits::default(), &settings, &options, &never).expect("runs")
    };
    let (now, late) = (run(0.0), run(0.001));
    for (a, b) in now.tests.iter().zip(&late.tests) {
        let mut lag = a.phase_deg[0] - b.phase_deg[0];
        lag -= 360.0 * (lag / 360.0).round();
        // ω d in degrees: 15.849 rad/s × 1 ms = 0.908°.
        assert!((lag - 0.908_0).abs() < 5e-4, "{}: {lag}", a.test.name());
        assert!((a.gain[0] - b.gain[0]).abs() <= 1e-12 * a.gain[0]);
    }
}

#[test]
fn the_planner_is_deterministic_undistorted_when_small_and_holds_sustained_force_by_tilt() {
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let settings = CueingSettings {
        algorithm: CueingAlgorithm::Mpc,
        ..CueingSettings::default()
    };
    let run = |frequencies: Vec<f64>| {
        let options = OmctOptions {
            frequencies,
            amplitude_scale: 0.2,
            latency_s: 0.0,
        };
        omct(&s.geometry, &s.limits, &settings, &options, &never).expect("runs")
    };
    let a = run(vec![0.25, 2.5]);
    assert_eq!(a.algorithm, CueingAlgorithm::Mpc);
    // The same run again (alone, on other threads): the same numbers to the last bit.
    let again = run(vec![2.5]);
    for (x, y) in a.tests.iter().zip(&again.tests) {
        let bits = |g: f64, p: f64| (g.to_bits(), p.to_bits());
        assert_eq!(
            bits(x.gain[1], x.phase_deg[1]),
            bits(y.gain[0], y.phase_deg[0]),
            "{}",
            x.test.name()
        );
    }
    for r in &a.tests {
        for (k, d) in r.distorted.iter().enumerate() {
            assert!(
                !d,
                "{} at {}: {}",
                r.test.name(),
                a.frequencies[k],
                r.distortion[k]
            );
        }
    }
    // At 0.25 rad/s a platform cannot translate a sustained force: what surge feels there
    // is tilt (gravity along the tilted platform), nearly the whole scaled force, the
    // platform's pitch rate following it (surge-to-pitch): tilting to render f needs a
    // pitch of f/g, its rate per m/s² at ω is ω/g rad/s.
    let k_t = settings.translation_scale;
    let surge = &a.tests[0];
    assert!(surge.gain[0] > 0.9 * k_t, "{:?}", surge.gain);
    let to_pitch = &a.tests[6];
    assert_eq!(to_pitch.test, OmctTest::SurgeToPitch);
    let tilt_rate = k_t * 0.25 / GRAVITY * 180.0 / PI;
    assert!(
        (to_pitch.gain[0] - tilt_rate).abs() < 0.1 * tilt_rate,
        "{:?} vs {tilt_rate}",
        to_pitch.gain
    );
    // Heave, which no platform sustains, is cued as it changes: a real share of the
    // scaled force at 2.5 rad/s, leading by less than a quarter period.
    let heave = &a.tests[2];
    assert_eq!(heave.test, OmctTest::Heave);
    assert!(heave.gain[1] > 0.2 * k_t, "{:?}", heave.gain);
    assert!(heave.phase_deg[1].abs() < 90.0, "{:?}", heave.phase_deg);
}

#[test]
fn a_limit_acting_is_called_distortion() {
    // The tilt rate limited to 1°/s against a 2 m/s² surge at 0.4 rad/s: the tilt turns
    // at its limit, clipped.
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let settings = CueingSettings {
        tilt_rate_max_deg_s: 1.0,
        ..CueingSettings::default()
    };
    let options = OmctOptions {
        frequencies: vec![0.398_107_170_553_497_3],
        amplitude_scale: 2.0,
        latency_s: 0.0,
    };
    let r = omct(&s.geometry, &Limits::default(), &settings, &options, &never).expect("runs");
    assert!(r.tests[0].distorted[0], "{:?}", r.tests[0].distortion);
    assert!(r.tests[0].distortion[0] > DISTORTION_SHARE);
    // Yaw has no tilt: clean.
    assert!(!r.tests[5].distorted[0], "{:?}", r.tests[5].distortion);
}

#[test]
fn bad_options_are_one_error_each() {
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let settings = CueingSettings::default();
    let with = |o: OmctOptions| omct(&s.geometry, &s.limits, &settings, &o, &never).map(|_| ());
    let base = OmctOptions::default;
    assert_eq!(
        with(OmctOptions {
            frequencies: vec![0.001],
            ..base()
        }),
        Err(OmctError::Frequency(0.001))
    );
    assert!(
        with(OmctOptions {
            frequencies: vec![f64::NAN],
            ..base()
        })
        .is_err()
    );
    assert_eq!(
        with(OmctOptions {
            frequencies: vec![],
            ..base()
        }),
        Err(OmctError::NoFrequency)
    );
    assert_eq!(
        with(OmctOptions {
            amplitude_scale: 0.0,
            ..base()
        }),
        Err(OmctError::Scale(0.0))
    );
    assert_eq!(
        with(OmctOptions {
            amplitude_scale: f64::INFINITY,
            ..base()
        }),
        Err(OmctError::Scale(f64::INFINITY))
    );
    assert_eq!(
        with(OmctOptions {
            latency_s: -0.001,
            ..base()
        }),
        Err(OmctError::Latency(-0.001))
    );
    let stopped = omct(&s.geometry, &s.limits, &settings, &base(), &|| true);
    assert_eq!(stopped.map(|_| ()), Err(OmctError::Stopped));
}

#[test]
fn a_phase_is_within_half_a_turn_whatever_the_other_frequencies() {
    // The surge test at 0.1 rad/s lags by about 2°, alone or among others; the figure's
    // curve is continuous down from the highest frequency.
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let run = |frequencies: Vec<f64>| {
        let options = OmctOptions {
            frequencies,
            amplitude_scale: 0.1,
            latency_s: 0.0,
        };
        omct(
            &s.geometry,
            &Limits::default(),
            &linear_washout(),
            &options,
            &never,
        )
        .expect("runs")
    };
    let alone = run(vec![0.1]);
    let among = run(frequencies().to_vec());
    for (a, b) in alone.tests.iter().zip(&among.tests) {
        assert_eq!(
            a.phase_deg[0].to_bits(),
            b.phase_deg[0].to_bits(),
            "{}",
            a.test.name()
        );
        assert!(
            b.phase_deg
                .iter()
                .all(|p| p.is_nan() || (-180.0..=180.0).contains(p))
        );
        let continuous = b.continuous_phase_deg();
        for w in continuous.windows(2) {
            assert!(w[0].is_nan() || w[1].is_nan() || (w[1] - w[0]).abs() <= 180.0);
        }
    }
    assert!(
        (-3.0..0.0).contains(&alone.tests[0].phase_deg[0]),
        "{:?}",
        alone.tests[0].phase_deg
    );
}

#[test]
fn frequencies_that_do_not_rise_or_are_too_many_are_refused() {
    let s = crate::io::scenario::Scenario::preset("paired").expect("preset");
    let run = |frequencies: Vec<f64>| {
        let options = OmctOptions {
            frequencies,
            ..OmctOptions::default()
        };
        omct(&s.geometry, &s.limits, &linear_washout(), &options, &never)
    };
    assert_eq!(
        run(vec![2.0, 1.0]).err(),
        Some(OmctError::Unordered(2.0, 1.0))
    );
    assert_eq!(
        run(vec![1.0, 1.0]).err(),
        Some(OmctError::Unordered(1.0, 1.0))
    );
    let many: Vec<f64> = (0..=MOST_FREQUENCIES)
        .map(|k| 1.0 + k as f64 * 0.01)
        .collect();
    assert_eq!(
        run(many).err(),
        Some(OmctError::TooManyFrequencies(MOST_FREQUENCIES + 1))
    );
}
