//! The generator against closed forms: a motion within the limits is followed to the last
//! bit; rest-to-rest steps take the textbook time-optimal durations; the range holds; the
//! target's derivatives are exact for parabolas.

use super::*;

const RANGE: (f64, f64) = (0.5, 1.5);

fn generator(speed: f64, accel: Option<f64>, jerk: Option<f64>) -> Generator {
    Generator::new([Bounds::new(RANGE, Some(speed), accel, jerk); 6])
}

/// Ticks until every actuator is at `goal` (at rest), stepping `dt` with a resting target;
/// checks the limits on the way. Returns the number of ticks.
fn ticks_to(g: &mut Generator, goal: f64, dt: f64) -> usize {
    let target = ActuatorMotion::at_rest([goal; 6]);
    let b = g.bounds()[0];
    for n in 1..100_000 {
        let before = *g.state();
        let reached = g.step(dt, &target, None).unwrap_or_else(|e| panic!("{e}"));
        let m = g.state();
        let v = (m.position[0] - before.position[0]) / dt;
        assert!(v.abs() <= b.speed * (1.0 + 1e-9), "speed {v}");
        assert!(m.acceleration[0].abs() <= b.accel * (1.0 + 1e-9));
        assert!((RANGE.0..=RANGE.1).contains(&m.position[0]));
        if reached.all() && m.velocity[0] == 0.0 {
            assert_eq!(m.position, [goal; 6]);
            return n;
        }
    }
    panic!("never reached {goal}")
}

#[test]
fn a_motion_within_the_limits_is_followed_to_the_last_bit() {
    // 0.1 (1 − cos 2πft) from rest: peak speed 0.2πf·… well inside 0.5 m/s, 5 m/s², 50 m/s³.
    for (jerk, rate) in [
        (None, 200.0),
        (None, 1000.0),
        (Some(50.0), 200.0),
        (Some(50.0), 1000.0),
    ] {
        let mut g = generator(0.5, Some(5.0), jerk);
        let dt = 1.0 / rate;
        let mut history = TargetHistory::default();
        let f = 0.3;
        let at = |t: f64| 1.0 + 0.1 * (1.0 - (2.0 * std::f64::consts::PI * f * t).cos());
        g.rest_at([at(0.0); 6]);
        history.push(0.0, [at(0.0); 6]);
        for k in 1..(5.0 * rate) as usize {
            let t = k as f64 * dt;
            let target = history.push(t, [at(t); 6]);
            let reached = g.step(dt, &target, None).unwrap_or_else(|e| panic!("{e}"));
            // The start needs a jump of acceleration (0.36 m/s²): a jerk-limited platform
            // catches up within a few ticks, and from then on it is on the target.
            if t >= 0.1 {
                assert!(reached.all(), "jerk {jerk:?} at {rate} Hz, t = {t}");
                assert_eq!(g.state().position, [at(t); 6]);
            }
        }
    }
}

#[test]
fn a_step_takes_the_time_optimal_trapezoid() {
    // Rest to rest over 0.4 with v = 0.5, a = 5 (no jerk limit): v²/a = 0.05 < 0.4, so
    // T = D/v + v/a = 0.8 + 0.1 = 0.9 s.
    let dt = 0.001;
    let mut g = generator(0.5, Some(5.0), None);
    g.rest_at([0.6; 6]);
    let n = ticks_to(&mut g, 1.0, dt);
    assert!((n as f64 * dt - 0.9).abs() <= dt + 1e-9, "{n} ticks");
    // A short step never reaches full speed: T = 2√(D/a) = 2√(0.02/5) = 0.12649 s.
    let mut g = generator(0.5, Some(5.0), None);
    g.rest_at([1.0; 6]);
    let n = ticks_to(&mut g, 1.02, dt);
    assert!(
        (n as f64 * dt - 2.0 * (0.02f64 / 5.0).sqrt()).abs() <= dt + 1e-9,
        "{n}"
    );
}

#[test]
fn a_step_with_a_jerk_limit_takes_the_time_optimal_seven_phases() {
    // Rest to rest over 0.4 with v = 0.5, a = 5, j = 100: a²/j = 0.25 ≤ v, and the distance
    // covers the full profile, so T = D/v + v/a + a/j = 0.8 + 0.1 + 0.05 = 0.95 s.
    let dt = 0.001;
    let mut g = generator(0.5, Some(5.0), Some(100.0));
    g.rest_at([0.6; 6]);
    let mut jerks = Vec::new();
    let mut last_a = 0.0;
    let target = ActuatorMotion::at_rest([1.0; 6]);
    let mut n = 0;
    loop {
        n += 1;
        let reached = g.step(dt, &target, None).unwrap_or_else(|e| panic!("{e}"));
        let a = g.state().acceleration[0];
        jerks.push((a - last_a) / dt);
        last_a = a;
        if reached.all() {
            break;
        }
        assert!(n < 10_000);
    }
    assert!((n as f64 * dt - 0.95).abs() <= dt + 1e-9, "{n} ticks");
    let worst = jerks.iter().fold(0.0f64, |m, j| m.max(j.abs()));
    assert!(worst <= 100.0 * (1.0 + 1e-6), "jerk {worst}");
}

#[test]
fn a_speed_limited_step_without_acceleration_limit_moves_at_the_speed() {
    let dt = 0.01;
    let mut g = generator(0.5, None, None);
    g.rest_at([0.6; 6]);
    // 0.4 at 0.5 per second: 0.8 s, 0.005 per tick.
    let n = ticks_to(&mut g, 1.0, dt);
    assert_eq!(n, 80);
}

#[test]
fn the_range_holds_when_the_target_runs_at_its_end() {
    // Moving up at full speed towards a target just inside the top of the range, with a
    // velocity that would carry it out: the plan brakes in time and never leaves.
    let dt = 0.001;
    let mut g = generator(0.5, Some(5.0), Some(100.0));
    g.rest_at([1.3; 6]);
    let mut top = f64::MIN;
    for k in 0..3000 {
        let target = ActuatorMotion {
            position: [RANGE.1; 6],
            velocity: [0.5; 6],
            acceleration: [0.0; 6],
        };
        g.step(dt, &target, None)
            .unwrap_or_else(|e| panic!("{k}: {e}"));
        top = top.max(g.state().position[0]);
    }
    assert!(top <= RANGE.1, "{top}");
    assert!((g.state().position[0] - RANGE.1).abs() < 1e-9);
}

#[test]
fn the_target_history_differentiates_parabolas_exactly_on_uneven_ticks() {
    let p = |t: f64| 0.3 + 0.2 * t - 1.5 * t * t;
    let mut h = TargetHistory::default();
    assert_eq!(
        h.push(0.0, [p(0.0); 6]),
        ActuatorMotion::at_rest([p(0.0); 6])
    );
    // Two samples: the parabola from rest at the first.
    let m = h.push(0.01, [p(0.01); 6]);
    assert!((m.velocity[0] - 2.0 * (p(0.01) - p(0.0)) / 0.01).abs() < 1e-12);
    assert!((m.acceleration[0] - 2.0 * (p(0.01) - p(0.0)) / 1e-4).abs() < 1e-9);
    let _ = h.push(0.013, [p(0.013); 6]);
    let m = h.push(0.02, [p(0.02); 6]);
    assert!((m.velocity[2] - (0.2 - 3.0 * 0.02)).abs() < 1e-10, "{m:?}");
    assert!((m.acceleration[5] + 3.0).abs() < 1e-8, "{m:?}");
    // A time that does not advance replaces the newest sample.
    let m = h.push(0.02, [p(0.02); 6]);
    assert!((m.acceleration[0] + 3.0).abs() < 1e-8);
    h.clear();
    assert_eq!(h.push(1.0, [2.0; 6]), ActuatorMotion::at_rest([2.0; 6]));
}

#[test]
fn a_braking_distance_exactly_the_distance_left_is_planned() {
    // Seen on the servo-desk's way home at 1 kHz: 27.375°/s braking at 3000°/s² with
    // exactly v²/2a = 0.1249° to go, under the 30°/s home speed (the solver failed here).
    let b = Bounds::new((-70.0, 70.0), Some(300.0), Some(3000.0), None);
    let mut g = Generator::new([b; 6]);
    g.state = ActuatorMotion {
        position: [1.266_088_772_998_069_4; 6],
        velocity: [27.374_999_999_984_833; 6],
        acceleration: [-3000.0; 6],
    };
    let home = ActuatorMotion::at_rest([1.390_987_210_497_931; 6]);
    let mut reached = false;
    for _ in 0..50 {
        let r = g.step(0.001_000_000_000_001_222_1, &home, Some(30.0));
        reached = r.unwrap_or_else(|e| panic!("{e}")).all();
        if reached {
            break;
        }
    }
    assert!(reached);
    assert_eq!(g.state().position, home.position);
}
