use nalgebra::Vector3;

use super::*;
use crate::model::angle::Angle;
use crate::model::geometry::GeometryParams;
use crate::solve::forward::homotopy::SplitMix;
use crate::test_support::{paired_geometry, servo_geometry};

/// A built platform: `nominal`'s joints each moved by up to `mm` millimetres per axis.
fn as_built(nominal: &Geometry, mm: f64, rng: &mut SplitMix) -> Geometry {
    let mut params: GeometryParams = nominal.params().clone();
    let mut moved = |p: &[Vector3<f64>; 6]| {
        p.map(|v| v + Vector3::new(rng.next(), rng.next(), rng.next()) * mm * 1e-3)
    };
    params.base = PlateJoints::Points(moved(nominal.base_joints()));
    params.platform = PlateJoints::Points(moved(nominal.platform_joints()));
    Geometry::new(params).unwrap_or_else(|e| panic!("{e}"))
}

/// `count` poses about `geometry`'s home: within ±`reach` m and ±`tilt_deg` in each
/// rotation (0 for pure translations).
fn poses(
    geometry: &Geometry,
    count: usize,
    reach: f64,
    tilt_deg: f64,
    rng: &mut SplitMix,
) -> Vec<Pose> {
    let h = geometry.home_height();
    (0..count)
        .map(|_| {
            Pose::from_xyz_rpy_deg(
                [
                    rng.next() * reach,
                    rng.next() * reach,
                    h + rng.next() * reach,
                ],
                [
                    rng.next() * tilt_deg,
                    rng.next() * tilt_deg,
                    rng.next() * tilt_deg,
                ],
            )
        })
        .collect()
}

/// Uniform noise of standard deviation `sigma`.
fn noise(sigma: f64, rng: &mut SplitMix) -> f64 {
    rng.next() * sigma * 3f64.sqrt()
}

/// What a linear platform `truth` with length offsets `offsets` was commanded at `poses`,
/// plus noise of `sigma` metres on each length.
fn linear_measurements(
    truth: &Geometry,
    offsets: &[f64; 6],
    poses: &[Pose],
    sigma: f64,
    rng: &mut SplitMix,
) -> Vec<Measurement> {
    poses
        .iter()
        .map(|pose| {
            let real = truth.leg_lengths(pose);
            Measurement {
                pose: *pose,
                commanded: std::array::from_fn(|i| real[i] - offsets[i] + noise(sigma, rng)),
            }
        })
        .collect()
}

fn assert_recovers(
    calibration: &Calibration,
    truth: &Geometry,
    offsets: &[f64; 6],
    within: impl Fn(&Parameter) -> f64,
) {
    for (leg, fit) in calibration.legs.iter().enumerate() {
        let b = truth.base_joints()[leg];
        let a = truth.platform_joints()[leg];
        let expected = [b.x, b.y, b.z, a.x, a.y, a.z, offsets[leg]];
        for (p, want) in fit.parameters.iter().zip(expected) {
            let tolerance = within(p);
            assert!(
                (p.value - want).abs() <= tolerance,
                "{}: {} instead of {want} (±{tolerance:e})",
                p.name,
                p.value
            );
        }
    }
}

#[test]
fn exact_measurements_give_back_the_built_platform_to_the_nanometre() {
    let mut rng = SplitMix(11);
    let nominal = paired_geometry();
    let truth = as_built(&nominal, 5.0, &mut rng);
    let offsets = [0.004, -0.003, 0.0015, 0.0, -0.0045, 0.002];
    let poses = poses(&nominal, 30, 0.08, 12.0, &mut rng);
    let measurements = linear_measurements(&truth, &offsets, &poses, 0.0, &mut rng);
    let c = calibrate(&nominal, &measurements, Held::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_recovers(&c, &truth, &offsets, |_| 1e-9);
    assert!(c.after.rms < 1e-12, "{:?}", c.after);
    // Before: millimetres of misclosure; the calibrated geometry's own leg lengths, less
    // the offsets, are the commanded ones.
    assert!(c.before.rms > 1e-3, "{:?}", c.before);
    for m in &measurements {
        let legs = c.geometry.leg_lengths(&m.pose);
        for (i, leg) in legs.iter().enumerate() {
            assert!((leg - c.offsets[i] - m.commanded[i]).abs() < 1e-10);
        }
    }
    assert!(c.legs.iter().all(|l| l.singular_values.len() == 7));
}

#[test]
fn noisy_measurements_recover_every_parameter_within_its_reported_uncertainty() {
    for seed in [1, 2, 3] {
        let mut rng = SplitMix(seed);
        let nominal = paired_geometry();
        let truth = as_built(&nominal, 4.0, &mut rng);
        let offsets: [f64; 6] = std::array::from_fn(|_| rng.next() * 0.005);
        let poses = poses(&nominal, 60, 0.1, 15.0, &mut rng);
        let sigma = 20e-6;
        let measurements = linear_measurements(&truth, &offsets, &poses, sigma, &mut rng);
        let c =
            calibrate(&nominal, &measurements, Held::default()).unwrap_or_else(|e| panic!("{e}"));
        // Five standard uncertainties: 42 parameters per seed stay inside.
        assert_recovers(&c, &truth, &offsets, |p| {
            5.0 * p
                .uncertainty
                .unwrap_or_else(|| panic!("{} determined", p.name))
        });
        // The residual left is the noise put in (RMS of 360 draws within 20 %), from
        // millimetres before.
        assert!((c.after.rms / sigma - 1.0).abs() < 0.2, "{:?}", c.after);
        assert!(c.before.rms > 20.0 * sigma, "{:?}", c.before);
        // The uncertainties are those of the noise: a few tens of micrometres, not zero.
        for leg in &c.legs {
            for p in &leg.parameters {
                let u = p.uncertainty.unwrap_or(0.0);
                assert!(u > 1e-6 && u < 2e-3, "{} ± {u}", p.name);
            }
        }
    }
}

#[test]
fn pure_translations_cannot_tell_a_base_joint_from_its_platform_joint() {
    let mut rng = SplitMix(5);
    let nominal = paired_geometry();
    let truth = as_built(&nominal, 3.0, &mut rng);
    let poses = poses(&nominal, 40, 0.1, 0.0, &mut rng);
    let measurements = linear_measurements(&truth, &[0.0; 6], &poses, 0.0, &mut rng);
    let error = calibrate(&nominal, &measurements, Held::default())
        .err()
        .unwrap_or_else(|| panic!("refused"));
    let text = error.to_string();
    for combination in [
        "(base1.x + platform1.x)",
        "(base1.y + platform1.y)",
        "(base1.z + platform1.z)",
        "(and likewise for leg 2, 3, 4, 5, 6)",
        "--hold base",
    ] {
        assert!(text.contains(combination), "{combination} in: {text}");
    }
    // Holding the base joints (known from the drawing) makes the rest determined.
    let held = Held {
        base: true,
        ..Held::default()
    };
    let c = calibrate(&nominal, &measurements, held).unwrap_or_else(|e| panic!("{e}"));
    for (leg, fit) in c.legs.iter().enumerate() {
        assert!(
            fit.parameters[..3]
                .iter()
                .all(|p| p.held && p.value == p.nominal)
        );
        assert!(
            fit.parameters[3..]
                .iter()
                .all(|p| !p.held && p.uncertainty.is_some())
        );
        // The platform joint moves by the base joint's error: only a − b is seen.
        let seen =
            truth.platform_joints()[leg] - truth.base_joints()[leg] + nominal.base_joints()[leg];
        for k in 0..3 {
            assert!((fit.parameters[3 + k].value - seen[k]).abs() < 1e-9);
        }
    }
}

#[test]
fn vertical_lifts_cannot_turn_a_platform_joint_about_its_base_joint() {
    // Level poses straight above the centre: a leg's length sees only how far its platform
    // joint is from the base joint horizontally, not in which direction.
    let nominal = paired_geometry();
    let h = nominal.home_height();
    let poses: Vec<Pose> = (0..30)
        .map(|k| Pose::level_at(h - 0.1 + 0.2 * f64::from(k) / 29.0))
        .collect();
    let mut rng = SplitMix(8);
    let measurements = linear_measurements(&nominal, &[0.0; 6], &poses, 0.0, &mut rng);
    let held = Held {
        base: true,
        ..Held::default()
    };
    let text = calibrate(&nominal, &measurements, held)
        .err()
        .unwrap_or_else(|| panic!("refused"))
        .to_string();
    assert!(text.contains("as in (platform1.x"), "{text}");
    assert!(text.contains("platform1.y)"), "{text}");
    assert!(
        !text.contains("offset1") && !text.contains("base1"),
        "{text}"
    );
}

#[test]
fn too_few_poses_are_refused_with_the_count_needed() {
    let mut rng = SplitMix(3);
    let nominal = paired_geometry();
    let poses = poses(&nominal, 7, 0.1, 10.0, &mut rng);
    let measurements = linear_measurements(&nominal, &[0.0; 6], &poses, 0.0, &mut rng);
    let text = calibrate(&nominal, &measurements, Held::default())
        .err()
        .unwrap_or_else(|| panic!("refused"))
        .to_string();
    assert!(text.starts_with("7 measured poses are too few"), "{text}");
    assert!(text.contains("at least 8 poses"), "{text}");
    // With the offsets held, 7 poses suffice for 6 unknowns.
    let held = Held {
        offsets: true,
        ..Held::default()
    };
    assert!(calibrate(&nominal, &measurements, held).is_ok());
    let all = Held {
        base: true,
        platform: true,
        offsets: true,
    };
    assert_eq!(
        calibrate(&nominal, &measurements, all),
        Err(CalibrationError::NothingFree)
    );
}

#[test]
fn servo_platforms_recover_joints_and_horn_offsets_and_the_trims_command_the_real_angles() {
    let mut rng = SplitMix(21);
    let nominal = servo_geometry();
    let truth = as_built(&nominal, 1.5, &mut rng);
    let offsets_deg: [f64; 6] = [2.0, -1.5, 0.5, 3.0, -2.5, 1.0];
    let poses = poses(&nominal, 40, 0.01, 8.0, &mut rng);
    let measurements: Vec<Measurement> = poses
        .iter()
        .map(|pose| {
            let real = truth
                .servo_angles(pose)
                .unwrap_or_else(|| panic!("rotary"))
                .unwrap_or_else(|e| panic!("{e}"));
            Measurement {
                pose: *pose,
                commanded: std::array::from_fn(|i| real[i].radians() - offsets_deg[i].to_radians()),
            }
        })
        .collect();
    let c = calibrate(&nominal, &measurements, Held::default()).unwrap_or_else(|e| panic!("{e}"));
    let offsets = offsets_deg.map(f64::to_radians);
    assert_recovers(&c, &truth, &offsets, |_| 1e-9);
    assert!(c.legs[0].parameters[6].unit == ParameterUnit::Radian);
    // The calibrated scenario commands, for each measured pose, the angle that produced it.
    let servos = c
        .geometry
        .rotary()
        .unwrap_or_else(|| panic!("still rotary"));
    for m in &measurements {
        let model = c
            .geometry
            .servo_angles(&m.pose)
            .unwrap_or_else(|| panic!("rotary"))
            .unwrap_or_else(|e| panic!("{e}"));
        for (i, angle) in model.iter().enumerate() {
            let sent = servos.commanded(i, *angle);
            let before = nominal
                .rotary()
                .unwrap_or_else(|| panic!("rotary"))
                .commanded(i, Angle::from_radians(m.commanded[i]));
            assert!((sent.radians() - before.radians()).abs() < 1e-9);
        }
    }
}

#[test]
fn a_reversed_servo_takes_its_offset_into_the_trim_the_other_way() {
    let nominal = servo_geometry();
    let servos = nominal.rotary().unwrap_or_else(|| panic!("rotary"));
    let mounted = servos
        .clone()
        .with_mounting(
            [true, false, false, false, false, false],
            [10.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        )
        .unwrap_or_else(|e| panic!("{e}"));
    let delta = 2f64.to_radians();
    let trimmed = apply::retrimmed(&mounted, &[delta, delta, 0.0, 0.0, 0.0, 0.0])
        .unwrap_or_else(|e| panic!("{e}"));
    // Reversed: command −θ + trim; to stand at θ it must get −(θ − δ) + 10° = −θ + 12°.
    assert!((trimmed.trims()[0].degrees() - 12.0).abs() < 1e-12);
    assert!((trimmed.trims()[1].degrees() + 2.0).abs() < 1e-12);
}

#[test]
fn the_link_offsets_take_the_length_offsets_so_the_wire_sends_what_produced_each_pose() {
    let mut rng = SplitMix(4);
    let nominal = paired_geometry();
    let truth = as_built(&nominal, 2.0, &mut rng);
    let offsets = [0.003, -0.002, 0.001, 0.0, 0.002, -0.001];
    let poses = poses(&nominal, 20, 0.08, 10.0, &mut rng);
    let measurements = linear_measurements(&truth, &offsets, &poses, 0.0, &mut rng);
    let c = calibrate(&nominal, &measurements, Held::default()).unwrap_or_else(|e| panic!("{e}"));
    let mut scenario = crate::io::scenario::Scenario::seed();
    scenario.geometry = nominal.clone();
    // Channel 1 carries leg 2, mirrored and doubled, with an offset of 1 m; channel 2 leg 1.
    scenario.link.actuator = [2, 1, 3, 4, 5, 6];
    scenario.link.reversed[0] = true;
    scenario.link.scale[0] = 2.0;
    scenario.link.offset[0] = 1.0;
    let calibrated = calibrated_scenario(&scenario, &c, measurements.len());
    let wire = |s: &crate::io::scenario::Scenario, legs: &[f64; 6], k: usize| {
        let leg = usize::from(s.link.actuator[k]) - 1;
        let sign = if s.link.reversed[k] { -1.0 } else { 1.0 };
        sign * s.link.scale[k] * legs[leg] + s.link.offset[k]
    };
    for m in &measurements {
        let model = calibrated.geometry.leg_lengths(&m.pose);
        for k in 0..6 {
            assert!((wire(&calibrated, &model, k) - wire(&scenario, &m.commanded, k)).abs() < 1e-9);
        }
    }
    assert!(
        calibrated
            .description
            .contains("calibrated from 20 measured poses")
    );
    // The written scenario reads back to the same platform.
    let back = crate::io::scenario::Scenario::from_toml_str(
        &calibrated.to_toml(),
        "calibrated.toml",
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        back.geometry.base_joints(),
        calibrated.geometry.base_joints()
    );
    assert_eq!(back.link.offset, calibrated.link.offset);
}

#[test]
fn measurements_of_another_motion_are_refused_rather_than_fitted_by_a_far_away_joint() {
    // The legs of tilted poses, recorded as if the platform had stayed level: with the
    // base held, the best fit sends the platform joints off towards infinity.
    let mut rng = SplitMix(9);
    let nominal = paired_geometry();
    let tilted = poses(&nominal, 30, 0.1, 15.0, &mut rng);
    let measurements: Vec<Measurement> =
        linear_measurements(&nominal, &[0.0; 6], &tilted, 0.0, &mut rng)
            .into_iter()
            .map(|m| Measurement {
                pose: Pose::level_at(0.0).with_position(m.pose.position),
                ..m
            })
            .collect();
    let held = Held {
        base: true,
        ..Held::default()
    };
    let error = calibrate(&nominal, &measurements, held)
        .err()
        .unwrap_or_else(|| panic!("refused"));
    assert!(
        matches!(error, CalibrationError::NotConverged { leg: 1, .. }),
        "{error}"
    );
    assert!(
        error.to_string().contains("do not fit this platform"),
        "{error}"
    );
}
