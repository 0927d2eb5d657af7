use nalgebra::{Complex, Vector3};

use super::*;
use crate::analysis::workspace;
use crate::model::geometry::GeometryParams;

/// Only the channels a test looks at: every scale 1, tilt off.
fn plain() -> CueingSettings {
    CueingSettings {
        translation_scale: 1.0,
        rotation_scale: 1.0,
        tilt: false,
        ..CueingSettings::default()
    }
}

/// A recording of `motion` held from t = 0, sampled at `times`.
fn held(motion: VehicleMotion, times: &[f64]) -> Vec<(f64, VehicleMotion)> {
    times.iter().map(|&t| (t, motion)).collect()
}

/// Times from 0 to `end` by `h`, and a few uneven ones in between.
fn times(end: f64, h: f64) -> Vec<f64> {
    let mut t: Vec<f64> = (0..)
        .map(|k| f64::from(k) * h)
        .take_while(|&t| t <= end + 1e-12)
        .collect();
    t.extend([0.0137, 1.2345, 2.5e-3 + 3.0]);
    t.sort_by(f64::total_cmp);
    t.dedup();
    t
}

/// `L⁻¹{1 / Π (s − pₖ)}(t)` for distinct poles, by residues: `Σ e^{pₖ t} / Π_{j≠k} (pₖ − pⱼ)`.
fn inverse_laplace(poles: &[Complex<f64>], t: f64) -> f64 {
    poles
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            let d: Complex<f64> = poles
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != k)
                .map(|(_, &q)| p - q)
                .product();
            (p * t).exp() / d
        })
        .sum::<Complex<f64>>()
        .re
}

/// The roots of `s² + 2ζω s + ω²`.
fn second_order_poles(w: f64, z: f64) -> [Complex<f64>; 2] {
    let root = Complex::new(z * z - 1.0, 0.0).sqrt() * w;
    [-z * w + root, -z * w - root]
}

fn pose_coordinates(
    geometry: &Geometry,
    recording: &[(f64, VehicleMotion)],
    settings: &CueingSettings,
) -> Vec<[f64; 6]> {
    cue_recording(
        geometry,
        &Limits::default(),
        &crate::analysis::checks::CheckSettings::default(),
        settings,
        recording,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses
    .iter()
    .map(Pose::to_coordinates)
    .collect()
}

#[test]
fn a_step_of_specific_force_moves_the_platform_as_the_closed_form_says() {
    let g = Geometry::seed();
    let home = g.home_pose().position;
    let force = 2.0;
    let step = VehicleMotion {
        accel: [force, 0.0, 0.0],
        rates_deg_s: [0.0; 3],
    };
    let t = times(10.0, 0.01);
    // Underdamped and overdamped high-passes, with and without the return to neutral.
    for (wn, zeta, wb) in [(2.5, 0.7, 0.5), (2.0, 1.3, 0.2), (3.0, 0.6, 0.0)] {
        let settings = CueingSettings {
            translation_hp_wn: wn,
            translation_hp_zeta: zeta,
            translation_hp_wb: wb,
            ..plain()
        };
        // x(s) = F s²/(s²+2ζωs+ω²) · s/(s+ω_b) · 1/s² · 1/s = F / ((s²+2ζωs+ω²)(s+ω_b)).
        let [p1, p2] = second_order_poles(wn, zeta);
        let poles = [p1, p2, Complex::new(-wb, 0.0)];
        let poses = pose_coordinates(&g, &held(step, &t), &settings);
        let mut largest: f64 = 0.0;
        for (time, c) in t.iter().zip(&poses) {
            let exact = force * inverse_laplace(&poles, *time);
            assert!(
                (c[0] - home.x - exact).abs() < 1e-6,
                "ω {wn} ζ {zeta} ω_b {wb} t {time}: {} vs {exact}",
                c[0] - home.x
            );
            largest = largest.max(exact.abs());
            // Nothing else moves.
            assert!(c[1].abs() < 1e-15 && (c[2] - home.z).abs() < 1e-15);
            assert!(c[3..].iter().all(|a| a.abs() < 1e-15));
        }
        assert!(largest > 0.01, "the step moved the platform {largest} m");
    }
}

#[test]
fn the_return_to_neutral_brings_the_platform_back_and_without_it_a_sustained_force_holds_it_out() {
    let g = Geometry::seed();
    let home = g.home_pose().position;
    let step = VehicleMotion {
        accel: [0.0, 1.0, 0.0],
        rates_deg_s: [0.0; 3],
    };
    let t: Vec<f64> = (0..=6000).map(|k| f64::from(k) * 0.01).collect();
    let back = pose_coordinates(&g, &held(step, &t), &plain());
    assert!((back[6000][1] - home.y).abs() < 1e-6);
    // ω_b = 0: x → F/ω² (the second-order high-pass then a double integration).
    let settings = CueingSettings {
        translation_hp_wb: 0.0,
        ..plain()
    };
    let out = pose_coordinates(&g, &held(step, &t), &settings);
    let wn = settings.translation_hp_wn;
    assert!((out[6000][1] - 1.0 / (wn * wn)).abs() < 1e-9);
}

#[test]
fn tilt_reaches_asin_f_over_g_no_faster_than_its_rate_limit() {
    let g = Geometry::seed();
    let force = 2.0;
    let settings = CueingSettings {
        tilt: true,
        surge: false,
        ..plain()
    };
    let h = 0.01;
    let t: Vec<f64> = (0..=3000).map(|k| f64::from(k) * h).collect();
    let step = VehicleMotion {
        accel: [force, 0.0, 0.0],
        rates_deg_s: [0.0; 3],
    };
    let poses = cue_recording(
        &g,
        &Limits::default(),
        &crate::analysis::checks::CheckSettings::default(),
        &settings,
        &held(step, &t),
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses;
    let pitch: Vec<f64> = poses.iter().map(|p| p.to_coordinates()[4]).collect();
    let limit = settings.tilt_rate_max_deg_s.to_radians() * h;
    let steps: Vec<f64> = pitch.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    assert!(steps.iter().all(|&d| d <= limit + 1e-15));
    // The limit is what holds it back at first: steps at exactly the limit.
    assert!(steps.iter().filter(|&&d| (d - limit).abs() < 1e-12).count() > 100);
    // Steady: nose up by asin(f/g), so that gravity along the platform pushes the occupant
    // back as the forward acceleration would.
    let last = poses[3000];
    let expected = -(force / 9.80665).asin();
    assert!(
        (pitch[3000] - expected).abs() < 1e-12,
        "{} vs {expected}",
        pitch[3000]
    );
    // What the occupant feels once the translation has washed out: the force itself,
    // rendered by the tilt alone.
    let mut steady = Washout::new(&settings);
    steady.hold(&step);
    for _ in 0..3000 {
        steady.advance(h);
    }
    let felt = steady.cue().specific_force();
    assert!(
        (felt[0] - force).abs() < 1e-9 && felt[1].abs() < 1e-12,
        "{felt:?}"
    );
    let gravity_in_platform = last.rotation().transpose() * Vector3::new(0.0, 0.0, -9.80665);
    assert!((gravity_in_platform.x + force).abs() < 1e-9);
    // Lateral force to the left: the platform rolls so that gravity pushes to the right.
    let left = VehicleMotion {
        accel: [0.0, force, 0.0],
        rates_deg_s: [0.0; 3],
    };
    let poses = cue_recording(
        &g,
        &Limits::default(),
        &crate::analysis::checks::CheckSettings::default(),
        &settings,
        &held(left, &t),
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses;
    let gravity = poses[3000].rotation().transpose() * Vector3::new(0.0, 0.0, -9.80665);
    assert!((gravity.y + force).abs() < 1e-9, "{gravity}");
}

#[test]
fn the_rotational_channel_is_the_high_passed_rate_integrated() {
    let g = Geometry::seed();
    let rate = 20.0;
    let step = VehicleMotion {
        accel: [0.0; 3],
        rates_deg_s: [0.0, 0.0, rate],
    };
    let t = times(12.0, 0.02);
    for (wn, zeta) in [(1.0, 1.0), (1.5, 0.5)] {
        let settings = CueingSettings {
            rotation_hp_wn: wn,
            rotation_hp_zeta: zeta,
            ..plain()
        };
        let poses = pose_coordinates(&g, &held(step, &t), &settings);
        let r = rate.to_radians();
        for (time, c) in t.iter().zip(&poses) {
            // θ(s) = R s/(s²+2ζωs+ω²) · 1/s: R t e^{−ωt} when critically damped, else
            // R e^{−ζωt} sin(ω_d t)/ω_d.
            let exact = if zeta == 1.0 {
                r * time * (-wn * time).exp()
            } else {
                let wd = wn * (1.0 - zeta * zeta).sqrt();
                r * (-zeta * wn * time).exp() * (wd * time).sin() / wd
            };
            assert!((c[5] - exact).abs() < 1e-9, "t {time}: {} vs {exact}", c[5]);
        }
    }
}

#[test]
fn tilting_turns_about_the_reference_point_and_switched_off_axes_stay_at_neutral() {
    let g = Geometry::seed();
    let head = [0.05, -0.02, 0.6];
    let settings = CueingSettings {
        tilt: true,
        surge: false,
        sway: false,
        heave: false,
        reference_m: head,
        ..plain()
    };
    let motion = VehicleMotion {
        accel: [3.0, -2.0, 4.0],
        rates_deg_s: [0.0; 3],
    };
    let t: Vec<f64> = (0..=500).map(|k| f64::from(k) * 0.01).collect();
    let poses = cue_recording(
        &g,
        &Limits::default(),
        &crate::analysis::checks::CheckSettings::default(),
        &settings,
        &held(motion, &t),
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses;
    let c = g.pivot();
    let h = Vector3::from(head);
    let home_head = g.home_pose().position + h;
    let last = poses[500];
    assert!(
        last.rpy_degrees()[0].abs() > 1.0 && last.rpy_degrees()[1].abs() > 1.0,
        "{:?}",
        last.rpy_degrees()
    );
    for p in &poses {
        let at = p.position + p.rotation() * (h - c) + c;
        assert!((at - home_head).norm() < 1e-12);
    }
}

#[test]
fn the_limiter_keeps_a_hard_manoeuvre_within_the_stroke() {
    let seed = Geometry::seed();
    let home = seed.leg_lengths(&seed.home_pose());
    let mut params = GeometryParams::seed();
    params.stroke.min = Some(home[0] - 0.06);
    params.stroke.max = Some(home[0] + 0.06);
    let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    // Hard braking and a swerve: 8 m/s² steps, 90°/s rates, every 1.5 s another sign.
    let t: Vec<f64> = (0..=2000).map(|k| f64::from(k) * 0.005).collect();
    let recording: Vec<(f64, VehicleMotion)> = t
        .iter()
        .map(|&time| {
            let sign = if (time / 1.5) as i64 % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let motion = VehicleMotion {
                accel: [8.0 * sign, -6.0 * sign, 4.0],
                rates_deg_s: [60.0 * sign, -45.0, 90.0 * sign],
            };
            (time, motion)
        })
        .collect();
    let limits = Limits::default();
    let free = CueingSettings {
        translation_scale: 1.0,
        rotation_scale: 1.0,
        ..CueingSettings::default()
    };
    let unlimited = cue_recording(
        &g,
        &limits,
        &crate::analysis::checks::CheckSettings::default(),
        &free,
        &recording,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses;
    let outside = unlimited
        .iter()
        .filter(|p| !workspace::pose_within_limits(&g, &limits, p))
        .count();
    assert!(
        outside > 100,
        "the manoeuvre must be hard: {outside} poses outside"
    );
    let limited_settings = CueingSettings {
        workspace_limiter: true,
        ..free
    };
    let limited = cue_recording(
        &g,
        &limits,
        &crate::analysis::checks::CheckSettings::default(),
        &limited_settings,
        &recording,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .poses;
    assert!(
        limited
            .iter()
            .all(|p| workspace::pose_within_limits(&g, &limits, p))
    );
    // Where the cue fits from the start, the limiter changes nothing.
    assert_eq!(limited[..5], unlimited[..5]);
    // The limited motion has no jumps: a step no bigger than the unlimited motion's
    // largest (the cue scaled down moves less, and the scale moves continuously).
    let largest_step = |poses: &[Pose]| {
        poses
            .windows(2)
            .map(|w| (w[1].position - w[0].position).norm())
            .fold(0.0, f64::max)
    };
    assert!(largest_step(&limited) <= 1.5 * largest_step(&unlimited));
}

#[test]
fn the_limited_poses_read_back_from_their_table_are_the_poses_judged() {
    // Held on joint cones of several sizes through a hard manoeuvre: every pose, written
    // as a table row (degrees) and read back, is bit for bit the pose the limiter judged,
    // so it keeps the limits for `stewart check` too — also on their very edge.
    let t: Vec<f64> = (0..=800).map(|k| f64::from(k) * 0.005).collect();
    let recording: Vec<(f64, VehicleMotion)> = t
        .iter()
        .map(|&time| {
            let sign = if time as i64 % 2 == 0 { 1.0 } else { -1.0 };
            let motion = VehicleMotion {
                accel: [9.0 * sign, -7.0 * sign, 3.0],
                rates_deg_s: [50.0 * sign, -30.0, 80.0 * sign],
            };
            (time, motion)
        })
        .collect();
    let settings = CueingSettings {
        translation_scale: 1.0,
        workspace_limiter: true,
        ..CueingSettings::default()
    };
    let g = Geometry::seed();
    let mut held = 0;
    for cone in [38.0, 41.5, 45.0, 47.0] {
        let limits = Limits {
            platform_cone: Some(Angle::from_degrees(cone)),
            ..Limits::default()
        };
        let cued = cue_recording(
            &g,
            &limits,
            &crate::analysis::checks::CheckSettings::default(),
            &settings,
            &recording,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        for (k, p) in cued.poses.iter().enumerate() {
            let back = Pose::from_row(&p.to_row());
            assert_eq!(&back, p, "{cone}°, sample {k}");
            assert!(
                workspace::pose_within_limits(&g, &limits, &back),
                "{cone}°, sample {k}"
            );
        }
        held += cued.scales.iter().filter(|&&s| s < 1.0).count();
    }
    assert!(held > 1000, "the limiter must work at the edge: {held}");
}

#[test]
fn samples_out_of_order_and_unsound_settings_are_refused() {
    let g = Geometry::seed();
    let m = VehicleMotion::default();
    let recording = [(0.0, m), (0.1, m), (0.1, m)];
    assert_eq!(
        cue_recording(
            &g,
            &Limits::default(),
            &crate::analysis::checks::CheckSettings::default(),
            &plain(),
            &recording
        )
        .map(|c| c.poses),
        Err(CueError::Time {
            index: 2,
            t: 0.1,
            previous: 0.1
        })
    );
    // Samples a nanosecond apart would make a pose table no command reads back (its rows
    // must be a microsecond apart): refused where they come in.
    let close = [(1.0, m), (1.0 + 1e-9, m)];
    assert!(matches!(
        cue_recording(
            &g,
            &Limits::default(),
            &crate::analysis::checks::CheckSettings::default(),
            &plain(),
            &close
        ),
        Err(CueError::Time { index: 1, .. })
    ));
    let bad = CueingSettings {
        tilt_lp_wn: -1.0,
        ..plain()
    };
    assert!(matches!(
        cue_recording(&g, &Limits::default(), &crate::analysis::checks::CheckSettings::default(), &bad, &recording[..1]),
        Err(CueError::Settings(p)) if p.key == "cueing.tilt_lp_wn"
    ));
}

/// What a cue writes reads back as a pose table: one sample, or times too fine for their
/// distance from zero, are refused where they come in; times typed to the microsecond are
/// taken; and the model-predictive cue refuses a home pose above the condition-number
/// limit it promises to keep.
#[test]
fn a_cue_writes_only_what_reads_back_and_refuses_what_it_cannot_keep() {
    let g = Geometry::seed();
    let m = VehicleMotion::default();
    let checks = crate::analysis::checks::CheckSettings::default();
    let cue = |samples: &[(f64, VehicleMotion)]| {
        cue_recording(&g, &Limits::default(), &checks, &plain(), samples)
    };
    assert!(matches!(
        cue(&[(0.0, m)]),
        Err(CueError::OneSample { samples: 1 })
    ));
    let fine: Vec<(f64, VehicleMotion)> = (0..300)
        .map(|k| (99_999.0 + 1.1e-6 * f64::from(k), m))
        .collect();
    assert!(matches!(cue(&fine), Err(CueError::TimesTooFine { .. })));
    // Written to the microsecond: 0.000000, 0.000001, … (a hair under 1e-6 apart once read).
    let typed: Vec<(f64, VehicleMotion)> = (0..10)
        .map(|k| {
            (
                format!("{:.6}", f64::from(k) * 1e-6)
                    .parse()
                    .unwrap_or(f64::NAN),
                m,
            )
        })
        .collect();
    let cued = cue(&typed).unwrap_or_else(|e| panic!("{e}"));
    let times: Vec<f64> = typed.iter().map(|s| s.0).collect();
    assert!(cued.to_motion(&times, "typed").is_ok());
    // A servo desk whose home pose is above a condition-number limit of 3.
    let desk = crate::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let tight = crate::analysis::checks::CheckSettings {
        condition_max: 3.0,
        ..desk.checks
    };
    let mpc = CueingSettings {
        algorithm: CueingAlgorithm::Mpc,
        ..desk.cueing.clone()
    };
    let samples: Vec<(f64, VehicleMotion)> = (0..20).map(|k| (0.01 * f64::from(k), m)).collect();
    assert!(matches!(
        cue_recording(&desk.geometry, &desk.limits, &tight, &mpc, &samples),
        Err(CueError::HomeIllConditioned { max: 3.0, .. })
    ));
    assert!(cue_recording(&desk.geometry, &desk.limits, &desk.checks, &mpc, &samples).is_ok());
}

#[test]
fn a_preview_is_the_step_taken_on_a_copy_and_changes_nothing() {
    // With the limiter on (a tight joint cone), and without: the preview h ahead with a motion
    // held is the pose a copy reaches by holding it and advancing h; the cueing itself is
    // where it was.
    for limiter in [false, true] {
        let settings = CueingSettings {
            translation_scale: 1.0,
            workspace_limiter: limiter,
            ..CueingSettings::default()
        };
        let g = Geometry::seed();
        let limits = Limits {
            platform_cone: limiter.then(|| Angle::from_degrees(38.0)),
            ..Limits::default()
        };
        let mut c = Cueing::new(&g, &limits, &settings).unwrap_or_else(|e| panic!("{e}"));
        let braking = VehicleMotion {
            accel: [-7.0, 2.0, 0.0],
            rates_deg_s: [0.0, 0.0, 25.0],
        };
        c.hold(&braking);
        c.advance(0.4);
        let turning = VehicleMotion {
            accel: [1.0, -3.0, 0.5],
            rates_deg_s: [5.0, 0.0, -10.0],
        };
        let before = c.advance(0.0);
        let preview = c.preview(0.025, &turning);
        let mut copy = c.clone();
        copy.hold(&turning);
        assert_eq!(preview, copy.advance(0.025), "limiter {limiter}");
        assert_ne!(preview, before);
        // Nothing moved: the next step is the one it would have been.
        let mut untouched = c.clone();
        assert_eq!(c.advance(0.01), untouched.advance(0.01));
    }
}

#[test]
fn the_limiters_pose_on_a_cones_edge_passes_check_as_its_row_reads_back() {
    // The limiter bisects to the last scale whose pose fits; that pose lies on a limit to
    // the last bits. Over many cues pushed through joint cones (45° and others) and the stroke, the
    // pose it gives, written as a table row and read back as `check --scenario` reads
    // it, is judged within every single-pose limit by `check` (it once read
    // 45.00000000000001° and called the limiter's pose a violation).
    use crate::analysis::checks::{CheckSettings, FindingKind, check_motion};
    use crate::model::trajectory::Samples;
    let s = crate::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let arm = Vector3::zeros();
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut random = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut limited = 0;
    for n in 0..400 {
        // 45°, and cones whose degrees do not come back from radians to the last bit.
        let cone = if n % 2 == 0 {
            45.0
        } else {
            (400.0 + 200.0 * random().abs()).round() / 10.0
        };
        let limits = Limits {
            platform_cone: Some(Angle::from_degrees(cone)),
            base_cone: Some(Angle::from_degrees(cone)),
            ..s.limits
        };
        let cue = Cue {
            position: [0.4 * random(), 0.4 * random(), 0.2 * random()],
            angles: [0.8 * random(), 0.8 * random(), 0.8 * random()],
            ..Cue::default()
        };
        let fits = |k: f64| {
            let pose = pose_at(&s.geometry, arm, &cue, k);
            workspace::pose_within_limits_as_written(&s.geometry, &limits, &pose)
        };
        if !fits(0.0) {
            continue;
        }
        // The limiter's scale, then on to the very last float that fits: the edge itself.
        let mut limiter = Limiter::new(1.0);
        let (mut k, mut out) = (limiter.scale_for(0.0, fits), 1.0);
        while k < 1.0 && fits(k) && !fits(out) {
            let mid = 0.5 * (k + out);
            if mid <= k || mid >= out {
                break;
            }
            if fits(mid) {
                k = mid;
            } else {
                out = mid;
            }
        }
        limited += usize::from(k < 1.0);
        let given = pose_at(&s.geometry, arm, &cue, k);
        let samples = Samples {
            times: vec![0.0],
            poses: vec![Pose::from_row(&given.to_row())],
        };
        let report = check_motion(&s.geometry, &limits, &samples, &CheckSettings::default());
        let broken: Vec<_> = (report.findings.iter())
            .filter(|f| {
                [
                    FindingKind::BaseCone,
                    FindingKind::PlatformCone,
                    FindingKind::StrokeMax,
                    FindingKind::StrokeMin,
                    FindingKind::LegCollision,
                ]
                .contains(&f.kind)
            })
            .collect();
        assert!(broken.is_empty(), "scale {k}: {broken:#?}");
    }
    assert!(limited > 300, "{limited}");
}

#[test]
fn times_a_microsecond_apart_far_from_zero_are_refused_saying_why() {
    // Written 1 µs apart near -1e6 s, the two times read back 0.99999997 µs apart: the
    // refusal quoted two times that look exactly far enough apart, and now says why.
    let e = CueError::Time {
        index: 1,
        t: -999_999.999_992,
        previous: -999_999.999_993,
    };
    let said = e.to_string();
    assert!(said.contains("start the times nearer 0"), "{said}");
    let close = CueError::Time {
        index: 1,
        t: 0.1,
        previous: 0.1,
    };
    assert!(!close.to_string().contains("nearer 0"));
}
