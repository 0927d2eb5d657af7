//! The rotary checks against numbers found another way: the servo Jacobian for rates,
//! brute-force sampling of segments for clearances, the rod's height over its length for
//! the horn cone, and the reach ratio's meaning (a pose lifted past horn + rod).

use nalgebra::Vector3;

use super::{CheckSettings, FindingKind, check_motion};
use crate::model::actuator::Actuator;
use crate::model::angle::Angle;
use crate::model::geometry::{Geometry, GeometryParams};
use crate::model::limits::Limits;
use crate::model::pose::Pose;
use crate::model::rotary::RotaryActuators;
use crate::model::trajectory::Samples;
use crate::solve::servo_closure;
use crate::test_support::servo_geometry;

/// Heave `z(t) = h + amp·sin(2π f t)` sampled every `dt` over `n` samples.
fn heave(g: &Geometry, amp: f64, f: f64, n: usize, dt: f64) -> Samples {
    let times: Vec<f64> = (0..n).map(|k| k as f64 * dt).collect();
    let poses = times
        .iter()
        .map(|&t| {
            let z = g.home_height() + amp * (std::f64::consts::TAU * f * t).sin();
            Pose::new(
                Vector3::new(0.0, 0.0, z),
                Angle::ZERO,
                Angle::ZERO,
                Angle::ZERO,
            )
        })
        .collect();
    Samples { times, poses }
}

fn with_range(g: &Geometry, min: f64, max: f64) -> Geometry {
    let mut p: GeometryParams = g.params().clone();
    let Actuator::Rotary(r) = &p.actuator else {
        panic!("servo geometry")
    };
    let angles = r.horn_angles().map(|a| a.degrees());
    p.actuator = Actuator::Rotary(
        RotaryActuators::new(r.horn_length(), r.rod_length(), angles, Some((min, max)))
            .unwrap_or_else(|e| panic!("{e}")),
    );
    Geometry::new(p).unwrap_or_else(|e| panic!("{e}"))
}

/// The servos of `g`, their angles and the platform joints at the home pose.
fn at_home(g: &Geometry) -> (&RotaryActuators, [Angle; 6], [Vector3<f64>; 6]) {
    let pose = g.home_pose();
    let servos = g.rotary().unwrap_or_else(|| panic!("rotary"));
    let angles = g
        .servo_angles(&pose)
        .and_then(Result::ok)
        .unwrap_or_else(|| panic!("reachable"));
    (servos, angles, g.inverse(&pose).platform_joints)
}

/// Brute-force distance between two segments: the closest of 2001 × 2001 point pairs.
fn sampled_distance(p0: Vector3<f64>, p1: Vector3<f64>, q0: Vector3<f64>, q1: Vector3<f64>) -> f64 {
    let n = 2000;
    let mut best = f64::INFINITY;
    for a in 0..=n {
        let p = p0 + (p1 - p0) * (a as f64 / n as f64);
        for b in 0..=n {
            let q = q0 + (q1 - q0) * (b as f64 / n as f64);
            best = best.min((p - q).norm());
        }
    }
    best
}

#[test]
fn a_clean_motion_reports_servo_ranges_and_reach_margin() {
    let g = servo_geometry();
    let samples = heave(&g, 0.005, 0.5, 201, 0.01);
    let r = check_motion(&g, &Limits::default(), &samples, &CheckSettings::default());
    assert!(r.is_clean(), "{:?}", r.findings);
    let ranges = r
        .servo_ranges_deg
        .unwrap_or_else(|| panic!("rotary report"));
    // Every servo's range holds its angle at each sample, taken from the servo model.
    for pose in &samples.poses {
        let angles = g
            .servo_angles(pose)
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("reachable"));
        for (a, [lo, hi]) in angles.iter().zip(ranges) {
            assert!(a.degrees() >= lo - 1e-12 && a.degrees() <= hi + 1e-12);
        }
    }
    let reach = r.limits.iter().find(|l| l.kind == FindingKind::Unreachable);
    let reach = reach.unwrap_or_else(|| panic!("reach summary"));
    assert!(reach.worst_value < 1.0 && reach.margin > 0.0);
}

#[test]
fn a_platform_lifted_past_horn_and_rod_is_unreachable_not_nan() {
    let g = servo_geometry();
    // Rising from home to 0.2 m: above a + s (0.145 m) over the shafts nothing reaches.
    let times: Vec<f64> = (0..=100).map(|k| f64::from(k) * 0.01).collect();
    let poses = times
        .iter()
        .map(|&t| {
            let z = g.home_height() + (0.2 - g.home_height()) * t;
            Pose::new(
                Vector3::new(0.0, 0.0, z),
                Angle::ZERO,
                Angle::ZERO,
                Angle::ZERO,
            )
        })
        .collect();
    let samples = Samples { times, poses };
    let r = check_motion(&g, &Limits::default(), &samples, &CheckSettings::default());
    let unreachable: Vec<_> = r
        .findings
        .iter()
        .filter(|f| f.kind == FindingKind::Unreachable)
        .collect();
    assert_eq!(unreachable.len(), 6, "{:?}", r.findings);
    for f in &unreachable {
        // The first unreachable sample is the first where some servo has no angle.
        let first = samples
            .times
            .iter()
            .zip(&samples.poses)
            .find(|(_, p)| {
                let joints = g.inverse(p).platform_joints;
                let i = f.legs[0] - 1;
                g.rotary()
                    .map(|s| {
                        servo_closure::servo_angle(s, i, &g.base_joints()[i], &joints[i]).is_err()
                    })
                    .unwrap_or(false)
            })
            .map(|(t, _)| *t);
        assert_eq!(Some(f.first_time), first);
        assert_eq!(f.last_time, 1.0);
        assert_eq!(f.worst_time, 1.0);
        assert!(f.worst_value > 1.0 && f.margin < 0.0);
        // The servo named is the one without an angle (the sentence is the catalogues').
        assert_eq!(f.legs.len(), 1);
    }
    // Nothing else is computed from the missing angles: no NaN anywhere in the report.
    assert!(r.findings.iter().all(|f| !f.worst_value.is_nan()));
    assert!(r.limits.iter().all(|l| !l.worst_value.is_nan()));
}

#[test]
fn servo_range_findings_name_the_servo_and_the_worst_angle() {
    let g = with_range(&servo_geometry(), -3.0, 3.0);
    let samples = heave(&g, 0.01, 0.5, 201, 0.01);
    let r = check_motion(&g, &Limits::default(), &samples, &CheckSettings::default());
    let over: Vec<_> = r
        .findings
        .iter()
        .filter(|f| f.kind == FindingKind::ServoMax)
        .collect();
    assert_eq!(over.len(), 6);
    for f in over {
        let i = f.legs[0] - 1;
        // The worst sample is the largest angle of that servo, from the model directly.
        let worst = samples
            .poses
            .iter()
            .filter_map(|p| g.servo_angles(p).and_then(Result::ok))
            .map(|a| a[i].degrees())
            .fold(f64::NEG_INFINITY, f64::max);
        assert!((f.worst_value - worst).abs() < 1e-12);
        assert!((f.margin - (3.0 - worst)).abs() < 1e-12);
        assert_eq!((f.legs.clone(), f.limit), (vec![i + 1], 3.0));
    }
    assert!(r.findings.iter().any(|f| f.kind == FindingKind::ServoMin));
}

#[test]
fn servo_speed_is_the_jacobian_rate() {
    let g = servo_geometry();
    let (amp, f) = (0.008, 1.0);
    let samples = heave(&g, amp, f, 2001, 0.0005);
    // At t = 0 the heave speed is amp·2πf upward; the servo Jacobian's z column turns it
    // into servo rates.
    let home = g.home_pose();
    let j = g
        .servo_jacobian(&home)
        .and_then(Result::ok)
        .unwrap_or_else(|| panic!("home reachable"));
    let vz = amp * std::f64::consts::TAU * f;
    let expected: Vec<f64> = (0..6)
        .map(|i| (j[(i, 2)] * vz).to_degrees().abs())
        .collect();
    let fastest = expected.iter().cloned().fold(0.0, f64::max);
    let limits = Limits {
        servo_speed_max: Some(0.5 * fastest),
        ..Limits::default()
    };
    let r = check_motion(&g, &limits, &samples, &CheckSettings::default());
    let s = r
        .limits
        .iter()
        .find(|l| l.kind == FindingKind::ServoSpeed)
        .unwrap_or_else(|| panic!("speed summary"));
    assert_eq!(s.unit, "deg/s");
    // At t = 0.5 s the platform passes home going down at the same speed: the central
    // differences of the servo angles there agree with the Jacobian to their O(dt²) error.
    let solutions: Vec<_> = samples.poses.iter().map(|p| g.inverse(p)).collect();
    let servos = g.rotary().unwrap_or_else(|| panic!("rotary"));
    let motion = super::servos::ServoMotion::solve(&g, servos, &solutions);
    let rates = super::rates::per_sample(
        &samples.times,
        &motion.angles_deg,
        crate::analysis::differences::first_difference,
    );
    for i in 0..6 {
        let got = rates[1000][i].abs();
        assert!(
            (got - expected[i]).abs() < 1e-4 * fastest,
            "{got} vs {}",
            expected[i]
        );
    }
    assert!(s.worst_value >= fastest * (1.0 - 1e-4));
    let speed_findings = r
        .findings
        .iter()
        .filter(|f| f.kind == FindingKind::ServoSpeed);
    assert_eq!(speed_findings.count(), 6);
}

#[test]
fn horn_cone_is_the_rods_lean_from_vertical() {
    let g = servo_geometry();
    let samples = heave(&g, 0.0, 1.0, 3, 0.1);
    let (servos, angles, joints) = at_home(&g);
    // The rod rises from the horn tip (height a·sin θ) to the joint (height z); its lean
    // from vertical is acos(rise / s).
    let lean: Vec<f64> = (0..6)
        .map(|i| {
            let rise = joints[i].z - servos.horn_length() * angles[i].radians().sin();
            (rise / servos.rod_length()).acos().to_degrees()
        })
        .collect();
    let most = lean.iter().cloned().fold(0.0, f64::max);
    let limits = Limits {
        base_cone: Some(Angle::from_degrees(most - 0.5)),
        ..Limits::default()
    };
    let r = check_motion(&g, &limits, &samples, &CheckSettings::default());
    let s = r
        .limits
        .iter()
        .find(|l| l.kind == FindingKind::HornCone)
        .unwrap_or_else(|| panic!("cone summary"));
    assert!(
        (s.worst_value - most).abs() < 1e-9,
        "{} vs {most}",
        s.worst_value
    );
    assert!(r.findings.iter().any(|f| f.kind == FindingKind::HornCone));
}

#[test]
fn rod_and_horn_clearances_match_brute_force_distances() {
    let g = servo_geometry();
    let samples = heave(&g, 0.0, 1.0, 2, 0.1);
    let (servos, angles, joints) = at_home(&g);
    let bases = g.base_joints();
    let tips: Vec<Vector3<f64>> = (0..6)
        .map(|i| servos.horn_tip(i, &bases[i], angles[i]))
        .collect();
    // Rods 1 and 2 end at neighbouring platform joints: the closest pair of rods.
    let rods_12 = sampled_distance(tips[0], joints[0], tips[1], joints[1]);
    // Rod 1 and servo 2's horn.
    let rod1_horn2 = sampled_distance(tips[0], joints[0], bases[1], tips[1]);
    let radius = 0.5 * rods_12.max(rod1_horn2) + 1e-3;
    let limits = Limits {
        leg_radius: Some(radius),
        ..Limits::default()
    };
    let r = check_motion(&g, &limits, &samples, &CheckSettings::default());
    let rods = r
        .findings
        .iter()
        .find(|f| f.kind == FindingKind::RodCollision && f.legs == vec![1, 2])
        .unwrap_or_else(|| panic!("rods 1 and 2 collide: {:?}", r.findings));
    // Brute force over 2001² points is within the spacing of the points of the truth.
    assert!(
        (rods.worst_value - rods_12).abs() < 1e-4,
        "{} vs {rods_12}",
        rods.worst_value
    );
    assert!(rods.worst_value <= rods_12 + 1e-12);
    let horn = r
        .findings
        .iter()
        .find(|f| f.kind == FindingKind::RodHornCollision && f.legs == vec![1, 2])
        .unwrap_or_else(|| panic!("rod 1 meets horn 2: {:?}", r.findings));
    assert!((horn.worst_value - rod1_horn2).abs() < 1e-4);
    assert!(horn.limit > 0.0 && horn.margin < 0.0, "{horn:?}");
}

#[test]
fn a_step_in_the_motion_is_a_servo_jump() {
    let g = servo_geometry();
    let mut samples = heave(&g, 0.004, 0.5, 401, 0.005);
    // From sample 250 on the platform sits 5 mm higher: every servo jumps there.
    for p in samples.poses.iter_mut().skip(250) {
        *p = Pose::new(
            p.position + Vector3::new(0.0, 0.0, 0.005),
            Angle::ZERO,
            Angle::ZERO,
            Angle::ZERO,
        );
    }
    let r = check_motion(&g, &Limits::default(), &samples, &CheckSettings::default());
    let jumps: Vec<_> = r
        .findings
        .iter()
        .filter(|f| f.kind == FindingKind::ServoJump)
        .collect();
    assert_eq!(jumps.len(), 6, "{:?}", r.findings);
    assert!(
        jumps
            .iter()
            .all(|f| f.first_time == samples.times[250] && f.unit == "deg")
    );
    // The leg-length checks do not run for servos.
    assert!(r.findings.iter().all(|f| f.kind != FindingKind::Jump));
}
