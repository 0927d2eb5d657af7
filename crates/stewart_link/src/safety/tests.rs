//! The state machine against numbers worked out by hand (the smoothstep ramp, speed and
//! acceleration steps, the way home) and properties over random targets: nothing sent ever
//! leaves the range, speed, acceleration or jerk limits, and a target that moves within
//! them is sent exactly.

use proptest::prelude::*;

use super::*;
use crate::target::{ActuatorMotion, Sample};

const HOME: [f64; 6] = [0.0; 6];

fn limits(speed: Option<f64>, accel: Option<f64>) -> ActuatorLimits {
    ActuatorLimits {
        range: [(-60.0, 60.0); 6],
        speed,
        accel,
        jerk: None,
    }
}

fn supervisor(speed: Option<f64>, accel: Option<f64>, stop: StopMode) -> Supervisor {
    Supervisor::new(limits(speed, accel), 1.0, stop, HOME)
}

#[test]
fn disarmed_sends_the_last_values_unarmed_whatever_the_target() {
    let mut s = supervisor(None, None, StopMode::Hold);
    let t = s.tick(0.0, Ok([10.0; 6]));
    assert_eq!(
        (t.state, t.values, t.armed, t.estop),
        (LinkState::Disarmed, HOME, false, false)
    );
    let t = s.tick(0.1, Ok([20.0; 6]));
    assert_eq!(t.values, HOME);
}

#[test]
fn arming_ramps_along_a_smootherstep_then_follows() {
    let mut s = supervisor(None, None, StopMode::Hold);
    s.arm(0.0, HOME);
    let target = Ok([40.0, -40.0, 10.0, 0.0, 20.0, 30.0]);
    // Half-way in time is half-way in value (smootherstep(0.5) = 0.5); a quarter of the way
    // in time is 53/512 of the way (10u³ − 15u⁴ + 6u⁵ at u = 1/4).
    let t = s.tick(0.25, target.clone());
    assert_eq!(t.state, LinkState::Arming);
    assert!(t.armed);
    assert!(
        (t.values[0] - 40.0 * 53.0 / 512.0).abs() < 1e-12,
        "{:?}",
        t.values
    );
    let t = s.tick(0.5, target.clone());
    assert!((t.values[1] + 20.0).abs() < 1e-12);
    let t = s.tick(1.0, target.clone());
    assert_eq!(t.state, LinkState::Armed);
    assert_eq!(t.values, [40.0, -40.0, 10.0, 0.0, 20.0, 30.0]);
    let t = s.tick(1.01, Ok([41.0; 6]));
    assert_eq!(t.values, [41.0; 6]);
    assert_eq!(t.note, None);
}

#[test]
fn out_of_range_and_unreachable_targets_are_held_with_the_reason() {
    let mut s = supervisor(None, None, StopMode::Hold);
    s.arm(0.0, HOME);
    s.tick(1.0, Ok([5.0; 6]));
    let mut far = [5.0; 6];
    far[3] = 75.0;
    let t = s.tick(1.1, Ok(far));
    assert_eq!(t.values, [5.0; 6]);
    assert_eq!(
        t.note.as_deref(),
        Some(
            "holding the last good set-point: actuator 4 would go to 75.000000, outside its range -60 … 60"
        )
    );
    let t = s.tick(1.2, Err("servo 2 cannot reach its platform joint".into()));
    assert_eq!(t.values, [5.0; 6]);
    assert!(
        t.note
            .is_some_and(|n| n.ends_with("servo 2 cannot reach its platform joint"))
    );
    let t = s.tick(1.3, Ok([f64::NAN; 6]));
    assert_eq!(t.values, [5.0; 6]);
    assert_eq!(t.state, LinkState::Armed);
}

#[test]
fn a_jump_is_approached_at_the_speed_limit() {
    let mut s = supervisor(Some(100.0), None, StopMode::Hold);
    s.arm(0.0, HOME);
    s.tick(1.0, Ok(HOME));
    // 50 units away at 100 units/s, ticks of 0.1 s: 10 units a tick, there in 5 ticks.
    let mut values = Vec::new();
    for k in 1..=6 {
        let t = s.tick(1.0 + 0.1 * f64::from(k), Ok([50.0; 6]));
        values.push(t.values[0]);
        if k < 5 {
            assert!(t.note.is_some_and(|n| n.contains("speed")));
        }
    }
    for (got, want) in values.iter().zip([10.0, 20.0, 30.0, 40.0, 50.0, 50.0]) {
        assert!((got - want).abs() < 1e-9, "{values:?}");
    }
}

#[test]
fn acceleration_is_limited_from_rest() {
    let mut s = supervisor(None, Some(200.0), StopMode::Hold);
    s.arm(0.0, HOME);
    s.tick(1.0, Ok(HOME));
    // From rest at 200 units/s² (the time-optimal plan accelerates until half-way, at 25):
    // ½·200·t² at t = 0.1, 0.2, 0.3 s is 1, 4, 9.
    let got: Vec<f64> = (1..=3)
        .map(|k| s.tick(1.0 + 0.1 * f64::from(k), Ok([50.0; 6])).values[0])
        .collect();
    for (g, w) in got.iter().zip([1.0, 4.0, 9.0]) {
        assert!((g - w).abs() < 1e-9, "{got:?}");
    }
}

#[test]
fn estop_holds_and_disarms_or_returns_home_at_its_speed() {
    let mut s = supervisor(None, None, StopMode::Hold);
    s.arm(0.0, HOME);
    s.tick(1.0, Ok([30.0; 6]));
    s.estop();
    let t = s.tick(1.1, Ok([40.0; 6]));
    assert_eq!(
        (t.state, t.values, t.armed, t.estop),
        (LinkState::Disarmed, [30.0; 6], false, true)
    );
    let t = s.tick(1.2, Ok([40.0; 6]));
    assert_eq!((t.values, t.estop), ([30.0; 6], false));

    let mut s = supervisor(None, None, StopMode::Home { speed: 100.0 });
    s.arm(0.0, HOME);
    s.tick(1.0, Ok([30.0; 6]));
    s.estop();
    // 30 units from home at 100 units/s, ticks of 0.1 s: 20, 10, then exactly 0 sent armed
    // with the home flag (a controller that holds when disarmed gets there), then disarmed.
    let mut seen = Vec::new();
    let mut k = 1;
    loop {
        let t = s.tick(1.0 + 0.1 * f64::from(k), Ok([40.0; 6]));
        seen.push(t.clone());
        if t.state == LinkState::Disarmed || k > 10 {
            break;
        }
        k += 1;
    }
    assert_eq!(seen.len(), 4, "{seen:?}");
    for (t, w) in seen.iter().zip([20.0, 10.0]) {
        assert!((t.values[0] - w).abs() < 1e-9, "{seen:?}");
        assert!(t.armed && t.home);
    }
    assert_eq!(seen[2].values, HOME);
    assert!(seen[2].armed && seen[2].home);
    assert_eq!(
        seen[2].note.as_deref(),
        Some("e-stop: home reached exactly")
    );
    assert_eq!(
        (seen[3].values, seen[3].armed, seen[3].state),
        (HOME, false, LinkState::Disarmed)
    );
}

#[test]
fn a_second_stop_on_the_way_home_disarms_at_once_where_it_is() {
    let mut s = supervisor(None, None, StopMode::Home { speed: 10.0 });
    s.arm(0.0, HOME);
    s.tick(1.0, Ok([30.0; 6]));
    s.estop();
    let t = s.tick(1.1, Ok([30.0; 6]));
    assert!((t.values[0] - 29.0).abs() < 1e-9 && t.home && t.estop);
    s.tick(1.2, Ok([30.0; 6]));
    assert!(!s.emergency());
    s.estop();
    let t = s.tick(1.3, Ok([30.0; 6]));
    assert_eq!(t.state, LinkState::Disarmed);
    assert!(t.estop && !t.armed && !t.home);
    assert!((t.values[0] - 28.0).abs() < 1e-9, "{t:?}");
    assert!(s.emergency());
    assert!(t.note.is_some_and(|n| n.starts_with("second stop")));
    // It stays disarmed where it was, whatever the target.
    let t = s.tick(1.4, Ok([0.0; 6]));
    assert_eq!(
        (t.state, t.estop, t.values),
        (LinkState::Disarmed, false, [28.0; 6])
    );
}

#[test]
fn a_fault_disarms_with_its_message_once() {
    let mut s = supervisor(None, None, StopMode::Hold);
    s.arm(0.0, HOME);
    s.tick(0.5, Ok([10.0; 6]));
    s.fault("the serial port /dev/ttyUSB0 went away");
    let t = s.tick(0.6, Ok([10.0; 6]));
    assert_eq!(t.state, LinkState::Disarmed);
    assert!(!t.armed);
    assert_eq!(
        t.note.as_deref(),
        Some("the serial port /dev/ttyUSB0 went away")
    );
    assert_eq!(s.tick(0.7, Ok([10.0; 6])).note, None);
}

/// Checks the values sent at `times` against the limits from their divided differences
/// (each is an average of the derivative over its span, so it keeps the derivative's
/// bound): first differences the speed, second the acceleration, third the jerk. Values
/// within `slack` units of rounding.
fn within_limits(times: &[f64], values: &[f64], l: &ActuatorLimits) -> Result<(), String> {
    let n = times.len();
    let round = 1e-12 * 64.0;
    let ok = |what: &str, got: f64, max: Option<f64>, h: f64, order: i32| match max {
        Some(max) if got.abs() > max * (1.0 + 1e-9) + round / h.powi(order) => {
            Err(format!("{what} {got} over {max} at t = {}", times[n - 1]))
        }
        _ => Ok(()),
    };
    let d1 = |i: usize| (values[i + 1] - values[i]) / (times[i + 1] - times[i]);
    let d2 = |i: usize| (d1(i + 1) - d1(i)) / (times[i + 2] - times[i]);
    if n >= 2 {
        ok("speed", d1(n - 2), l.speed, times[n - 1] - times[n - 2], 1)?;
    }
    if n >= 3 {
        ok(
            "acceleration",
            2.0 * d2(n - 3),
            l.accel,
            times[n - 1] - times[n - 3],
            2,
        )?;
    }
    if n >= 4 && l.accel.is_some() {
        let d3 = (d2(n - 3) - d2(n - 4)) / (times[n - 1] - times[n - 4]);
        let h = (times[n - 1] - times[n - 4]) / 3.0;
        ok("jerk", 6.0 * d3, l.jerk, h, 3)?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// Whatever the targets (inside, outside, missing, NaN, jumping), the tick lengths and
    /// the stops, what is sent stays in range and within the speed, acceleration and jerk
    /// limits, on every stretch where the platform is driven (from arming until it
    /// disarms).
    #[test]
    fn nothing_sent_leaves_the_limits(
        targets in proptest::collection::vec(
            (proptest::array::uniform6(-200.0f64..200.0), 0u8..10, 0.001f64..0.05), 1..200),
        jerk in proptest::option::of(5_000.0f64..100_000.0),
        stop_at in proptest::option::of(0usize..200),
        second_stop in proptest::option::of(1usize..100),
    ) {
        let limits = ActuatorLimits { jerk, ..limits(Some(150.0), Some(2000.0)) };
        let mut s = Supervisor::new(limits, 0.2, StopMode::Home { speed: 50.0 }, HOME);
        s.arm(0.0, HOME);
        let mut t = 0.0;
        let mut times = vec![0.0];
        let mut sent: Vec<[f64; 6]> = vec![HOME];
        for (k, (values, kind, dt)) in targets.iter().enumerate() {
            t += dt;
            let target = match kind {
                0 => Err("unreachable".into()),
                1 => Ok([f64::NAN; 6]),
                2 => Ok(targets[0].0),
                _ => Ok(*values),
            };
            if stop_at == Some(k) {
                s.estop();
            }
            if stop_at.zip(second_stop).is_some_and(|(a, b)| k == a + b) {
                s.estop();
            }
            let tick = s.tick(t, target);
            for v in tick.values {
                prop_assert!((-60.0..=60.0).contains(&v), "{v}");
            }
            // The generator plans every case (it disarms if it ever cannot).
            let note = tick.note.clone().unwrap_or_default();
            prop_assert!(!note.contains("generator failed"), "{note}");
            if tick.state == LinkState::Disarmed && !tick.armed {
                // Disarmed: the platform is not driven; a stretch ends here.
                times.clear();
                sent.clear();
                continue;
            }
            times.push(t);
            sent.push(tick.values);
            let from = times.len().saturating_sub(4);
            for j in 0..6 {
                let series: Vec<f64> = sent[from..].iter().map(|v| v[j]).collect();
                if let Err(e) = within_limits(&times[from..], &series, &limits) {
                    prop_assert!(false, "actuator {}: {e} ({:?})", j + 1, tick.state);
                }
            }
        }
    }

    /// A target that moves within the limits (a sum of sinusoids using at most 70 % of the
    /// speed, acceleration and jerk) is caught up within 2 s of the arming ramp's end (the
    /// last 30 % of the jerk is all the catching up has: with a low jerk limit it takes over
    /// a second) and from then on, for at least 2 s more, sent exactly, at any rate, with its velocity and acceleration given (a
    /// trajectory: to the solver's precision); estimated from the positions alone (then at 1 kHz under the acceleration
    /// limit alone: a jerk limit needs the trajectory's derivatives), to within 1e-5.
    #[test]
    fn a_target_within_the_limits_is_sent_exactly(
        waves in proptest::array::uniform3((0.05f64..3.0, 0.0f64..6.3, 0.2f64..1.0)),
        offset in -20.0f64..20.0,
        rate in proptest::sample::select(vec![100.0, 200.0, 500.0, 1000.0]),
        jerk in proptest::option::of(1_000.0f64..20_000.0),
        estimated in proptest::bool::ANY,
    ) {
        let rate = if estimated { 1000.0 } else { rate };
        let jerk = if estimated { None } else { jerk };
        let limits = ActuatorLimits { jerk, ..limits(Some(150.0), Some(2000.0)) };
        // Scale so that the sum's bounds (Σ A ω^k) use at most 70 % of each limit.
        let w: Vec<(f64, f64, f64)> = waves
            .iter()
            .map(|&(f, phase, share)| (2.0 * std::f64::consts::PI * f, phase, share))
            .collect();
        let bound = |k: i32| w.iter().map(|(om, _, share)| share * om.powi(k)).sum::<f64>();
        let mut scale = 0.7 * 150.0 / bound(1);
        scale = scale.min(0.7 * 2000.0 / bound(2));
        if let Some(j) = jerk {
            scale = scale.min(0.7 * j / bound(3));
        }
        scale = scale.min(30.0 / w.iter().map(|x| x.2).sum::<f64>());
        let wave = |t: f64, k: i32| -> f64 {
            w.iter()
                .map(|(om, ph, share)| scale * share * om.powi(k) * (om * t + ph + 0.5 * f64::from(k) * std::f64::consts::PI).sin())
                .sum::<f64>()
        };
        let at = |t: f64| offset + wave(t, 0);
        let mut s = Supervisor::new(limits, 0.5, StopMode::Hold, HOME);
        s.arm(0.0, HOME);
        let dt = 1.0 / rate;
        // The ramp lasts as long as the limits need (seconds, when the target moves fast
        // from the start); after it the generator may need a moment to catch the target up
        // (the ramp ends with a jump in jerk; a second and more under a low jerk limit).
        // From then on, it never leaves it.
        let mut armed_at: Option<f64> = None;
        let mut last_off: Option<(f64, [f64; 6], [f64; 6])> = None;
        let mut k = 0;
        loop {
            k += 1;
            let t = k as f64 * dt;
            if armed_at.is_some_and(|a| t > a + 4.0) {
                break;
            }
            prop_assert!(t < 30.0, "never armed");
            let target = [at(t); 6];
            let sample = if estimated {
                Sample::At(target)
            } else {
                Sample::Moving(ActuatorMotion {
                    position: target,
                    velocity: [wave(t, 1); 6],
                    acceleration: [wave(t, 2); 6],
                })
            };
            let tick = s.tick_sample(t, Ok(sample));
            if tick.state == LinkState::Armed && armed_at.is_none() {
                armed_at = Some(t);
            }
            // Given derivatives: the very numbers but for the solver's precision (1e-8
            // relative), and no note; estimated ones: within 1e-5 (a third of a millionth of
            // the 30-unit motion: the parabola's error).
            let tolerance = if estimated { 1e-5 } else { 1e-8 * (1.0 + target[0].abs()) };
            let off = tick.values.iter().zip(&target).any(|(a, b)| (a - b).abs() > tolerance);
            if off || (!estimated && tick.note.is_some() && armed_at.is_some()) {
                last_off = Some((t, tick.values, target));
            }
        }
        let caught_by = armed_at.map_or(0.0, |a| a + 2.0);
        prop_assert!(
            last_off.is_none_or(|(t, ..)| t <= caught_by),
            "off target at {:?}, armed at {:?}",
            last_off,
            armed_at
        );
    }
}

#[test]
fn a_planned_ramp_is_the_one_asked_when_the_limits_allow_it_and_the_closed_form_when_not() {
    // Legs in metres: 0.5 m/s, 5 m/s², no jerk limit; a target at rest 0.1 m away.
    let limits = ActuatorLimits {
        range: [(-1.0, 1.0); 6],
        speed: Some(0.5),
        accel: Some(5.0),
        jerk: None,
    };
    let from = [0.0; 6];
    let still = |_t: f64| Some([0.1; 6]);
    // The case: 1 s asked; the smootherstep's peaks 0.1875 m/s and 0.577 m/s²
    // are well inside: 1 s it is (a quarter of each limit would have needed 1.5 s).
    assert_eq!(planned_ramp(&limits, &from, 1.0, still, 1e-3), Some(1.0));
    // 0.1 s asked: the speed binds, T = 1.875 · 0.1 / (0.95 · 0.5) = 0.395 s, and the
    // acceleration (5.774 · 0.1 / T² = 3.7 m/s²) is then inside.
    let t = planned_ramp(&limits, &from, 0.1, still, 1e-4).unwrap_or(f64::NAN);
    let closed = 1.875 * 0.1 / (PLANNED_SHARE * 0.5);
    assert!((t - closed).abs() < 2e-3 * closed, "{t} vs {closed}");
    // A target swinging at up to 0.2 m/s leaves less room: a longer ramp.
    let moving = |t: f64| Some([0.1 + 0.04 * (5.0 * t).sin(); 6]);
    let longer = planned_ramp(&limits, &from, 0.1, moving, 1e-4).unwrap_or(f64::NAN);
    assert!(longer > t, "{longer} vs {t}");
    // No ramp asked: still a ramp, the shortest the limits allow, never a jump.
    let zero = planned_ramp(&limits, &from, 0.0, still, 1e-4).unwrap_or(f64::NAN);
    assert!((zero - closed).abs() < 2e-3 * closed, "{zero} vs {closed}");
    // A target with no values during the ramp: no plan.
    assert_eq!(
        planned_ramp(&limits, &from, 1.0, |t| (t < 0.5).then_some([0.1; 6]), 1e-3),
        None
    );
}

#[test]
fn a_planned_first_ramp_is_the_arming_time() {
    // A ramp of 1 s asked; 0.3 s planned (the caller checked it against the motion).
    let mut s = supervisor(Some(150.0), Some(2000.0), StopMode::Hold);
    s.plan_first_ramp(0.3);
    s.arm(0.0, [0.0; 6]);
    let mut t = 0.0;
    let mut armed_at = None;
    while t < 2.0 && armed_at.is_none() {
        t += 0.01;
        if s.tick(t, Ok([0.01; 6])).state == LinkState::Armed {
            armed_at = Some(t);
        }
    }
    let armed = armed_at.unwrap_or(f64::NAN);
    assert!((armed - 0.3).abs() < 0.011, "{armed}");
}
