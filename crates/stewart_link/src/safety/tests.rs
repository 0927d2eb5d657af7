//! The state machine against numbers worked out by hand (the smoothstep ramp, speed and
//! acceleration steps) and a property over random targets: nothing sent ever leaves the
//! limits.

use proptest::prelude::*;

use super::*;

const HOME: [f64; 6] = [0.0; 6];

fn limits(speed: Option<f64>, accel: Option<f64>) -> ActuatorLimits {
    ActuatorLimits {
        range: [(-60.0, 60.0); 6],
        speed,
        accel,
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
fn arming_ramps_along_a_smoothstep_then_follows() {
    let mut s = supervisor(None, None, StopMode::Hold);
    s.arm(0.0, HOME);
    let target = Ok([40.0, -40.0, 10.0, 0.0, 20.0, 30.0]);
    // Half-way in time is half-way in value (smoothstep(0.5) = 0.5); a quarter of the way
    // in time is 5/32 of the way (3u² − 2u³ at u = 1/4).
    let t = s.tick(0.25, target.clone());
    assert_eq!(t.state, LinkState::Arming);
    assert!(t.armed);
    assert!(
        (t.values[0] - 40.0 * 5.0 / 32.0).abs() < 1e-12,
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
    let t = s.tick(
        1.2,
        Err("servo 2 cannot reach its platform joint".to_owned()),
    );
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
    // From rest at 200 units/s², ticks of 0.1 s: speeds 20, 40, 60 … so positions 2, 6, 12.
    let got: Vec<f64> = (1..=3)
        .map(|k| s.tick(1.0 + 0.1 * f64::from(k), Ok([50.0; 6])).values[0])
        .collect();
    for (g, w) in got.iter().zip([2.0, 6.0, 12.0]) {
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
    // 30 units from home at 100 units/s, ticks of 0.1 s: 20, 10, 0, then disarmed.
    let mut seen = Vec::new();
    let mut k = 1;
    loop {
        let t = s.tick(1.0 + 0.1 * f64::from(k), Ok([40.0; 6]));
        seen.push((t.values[0], t.state));
        if t.state == LinkState::Disarmed || k > 10 {
            break;
        }
        k += 1;
    }
    let positions: Vec<f64> = seen.iter().map(|p| p.0).collect();
    assert_eq!(seen.len(), 3, "{seen:?}");
    for (g, w) in positions.iter().zip([20.0, 10.0, 0.0]) {
        assert!((g - w).abs() < 1e-9, "{positions:?}");
    }
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

proptest! {
    /// Whatever the targets (inside, outside, missing, NaN) and the tick lengths, what is
    /// sent stays in range and within the speed and acceleration limits.
    #[test]
    fn nothing_sent_leaves_the_limits(
        targets in proptest::collection::vec(
            (proptest::array::uniform6(-200.0f64..200.0), 0u8..10, 0.001f64..0.05), 1..200),
    ) {
        let (speed, accel) = (150.0, 2000.0);
        let mut s = supervisor(Some(speed), Some(accel), StopMode::Home { speed: 50.0 });
        s.arm(0.0, HOME);
        let mut t = 0.0;
        let mut last = HOME;
        let mut velocity = [0.0f64; 6];
        for (k, (values, kind, dt)) in targets.iter().enumerate() {
            t += dt;
            let target = match kind {
                0 => Err("unreachable".to_owned()),
                1 => Ok([f64::NAN; 6]),
                _ => Ok(*values),
            };
            if k == targets.len() / 2 && k % 3 == 0 {
                s.estop();
            }
            let tick = s.tick(t, target);
            for j in 0..6 {
                let v = tick.values[j];
                prop_assert!((-60.0..=60.0).contains(&v), "{v}");
                let speed_now = (v - last[j]) / dt;
                // The range is the hard limit: a stop at its end may brake harder.
                let at_end = v.abs() == 60.0;
                if matches!(tick.state, LinkState::Armed | LinkState::Arming) && !at_end {
                    prop_assert!(speed_now.abs() <= speed * (1.0 + 1e-9), "{speed_now}");
                    prop_assert!(
                        (speed_now - velocity[j]).abs() <= accel * dt * (1.0 + 1e-9) + 1e-9,
                        "accel {}", (speed_now - velocity[j]) / dt
                    );
                }
                velocity[j] = speed_now;
            }
            last = tick.values;
        }
    }
}
