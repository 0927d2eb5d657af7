use super::*;
use crate::io::scenario::presets;
use crate::model::trajectory::Trajectory;

fn preset(name: &str) -> Scenario {
    Scenario::preset(name).unwrap_or_else(|e| panic!("{e}"))
}

/// The value at a dotted key such as `geometry.base_angles_deg[2]` in TOML text, read
/// with the toml crate alone (independently of the settings' accessors).
fn lookup(text: &str, key: &str) -> Option<f64> {
    let mut value: toml::Value = toml::from_str(text).unwrap_or_else(|e| panic!("{e}"));
    for part in key.split('.') {
        let (name, indexes) = match part.split_once('[') {
            Some((name, rest)) => (
                name,
                rest.trim_end_matches(']')
                    .split("][")
                    .filter_map(|i| i.parse::<usize>().ok())
                    .collect(),
            ),
            None => (part, Vec::new()),
        };
        value = value.get(name)?.clone();
        for i in indexes {
            value = value.get(i)?.clone();
        }
    }
    value
        .as_float()
        .or_else(|| value.as_integer().map(|i| i as f64))
}

#[test]
fn keys_are_unique_and_every_target_is_declared() {
    let mut keys: Vec<&str> = all().iter().map(|s| s.key.as_str()).collect();
    let n = keys.len();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(keys.len(), n, "duplicate keys");
    for s in all() {
        assert_eq!(of(s.target).key, s.key);
        assert!(s.range.start() < s.range.end(), "{}", s.key);
    }
}

#[test]
fn every_key_is_the_path_of_its_value_in_the_scenario_file() {
    // For every preset, each setting that applies reads the number the file holds at
    // its key; an absent optional setting is absent from the file.
    for name in presets::names() {
        let scenario = preset(name);
        let text = scenario.to_toml();
        let mut checked = 0;
        for s in all().iter().filter(|s| s.applies(&scenario)) {
            let in_file = lookup(&text, &s.key);
            match (s.get(&scenario), in_file) {
                (Some(v), Some(f)) => {
                    assert!(
                        (v - f).abs() <= 1e-12 * v.abs().max(1.0),
                        "{name} {}: {v} vs {f}",
                        s.key
                    );
                    checked += 1;
                }
                (None, None) => assert!(s.optional(), "{name} {}", s.key),
                // Defaults the writer leaves out (start 0, default checks) still read back.
                (Some(_), None) => {
                    let back = Scenario::from_toml_str(&text, name, None)
                        .unwrap_or_else(|e| panic!("{e}"));
                    assert_eq!(s.get(&back), s.get(&scenario), "{name} {}", s.key);
                }
                (None, Some(f)) => panic!("{name} {}: file has {f}, setting reads nothing", s.key),
            }
        }
        assert!(
            checked >= 20,
            "{name}: only {checked} keys found in the file"
        );
    }
}

#[test]
fn a_value_set_survives_the_file_round_trip() {
    let cases = [
        ("seed", "geometry.base_radius", 1.25),
        ("seed", "geometry.platform_angles_deg[3]", 200.0),
        ("seed", "pivot.offset_m[2]", 0.1),
        ("seed", "trajectory.pitch.phase_deg", -30.0),
        ("seed", "trajectory.z.offset_m", 0.85),
        ("seed", "trajectory.samples", 501.0),
        ("seed", "trajectory.duration_s", 12.5),
        ("circle", "trajectory.radius_m", 0.05),
        ("sway", "trajectory.tilt_deg", 7.5),
        ("helix", "trajectory.z_end_m", 0.95),
        ("paired", "limits.platform_cone_deg", 40.0),
        ("paired", "checks.jump_ratio", 8.0),
    ];
    for (name, key, value) in cases {
        let mut scenario = preset(name);
        let setting = find(key).unwrap_or_else(|e| panic!("{e}"));
        setting
            .set(&mut scenario, Some(value))
            .unwrap_or_else(|e| panic!("{e}"));
        let back = Scenario::from_toml_str(&scenario.to_toml(), name, None)
            .unwrap_or_else(|e| panic!("{e}"));
        let read = setting.get(&back).unwrap_or(f64::NAN);
        assert!((read - value).abs() < 1e-12, "{name} {key}: {read}");
        // Angles pass through radians and may differ from the typed degrees in the last bit.
        let in_file = lookup(&scenario.to_toml(), key).unwrap_or(f64::NAN);
        assert!((in_file - value).abs() < 1e-12, "{name} {key}: {in_file}");
    }
}

#[test]
fn settings_change_what_they_name() {
    let mut s = Scenario::seed();
    find("trajectory.x.amplitude_m")
        .and_then(|k| k.set(&mut s, Some(0.0)))
        .unwrap_or_else(|e| panic!("{e}"));
    find("trajectory.y.amplitude_m")
        .and_then(|k| k.set(&mut s, Some(0.0)))
        .unwrap_or_else(|e| panic!("{e}"));
    // With x and y still, the platform centre stays on the axis.
    for k in 0..50 {
        let p = s.motion.trajectory.pose_at(k as f64 * 0.2).position;
        assert!(p.x.abs() < 1e-15 && p.y.abs() < 1e-15);
    }
    find("geometry.home_height")
        .and_then(|k| k.set(&mut s, Some(1.0)))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.geometry.home_pose().position.z, 1.0);
    // Twenty samples over 2 s: a step of 2/19 s.
    apply_all(&mut s, ["trajectory.duration_s=2", "trajectory.samples=20"])
        .unwrap_or_else(|e| panic!("{e}"));
    assert!((s.motion.sampling.step() - 2.0 / 19.0).abs() < 1e-15);
    let mut helix = preset("helix");
    apply_all(&mut helix, ["trajectory.duration_s=4"]).unwrap_or_else(|e| panic!("{e}"));
    // The helix now reaches its end height at 4 s.
    let end = helix.motion.trajectory.pose_at(4.0).position.z;
    assert!((end - 0.9).abs() < 1e-12, "{end}");
}

#[test]
fn refused_values_leave_the_scenario_unchanged_and_say_why() {
    let cases = [
        (
            "geometry.base_radius=-1",
            "`geometry.base_radius` = -1 refused: -1 is outside the accepted range above 0 … 1000 m",
        ),
        ("geometry.leg_min=2", "`geometry.leg_min` = 2 refused"),
        ("geometry.base_radius=off", "it cannot be switched off"),
        ("geometry.platform_angles_deg[1]=50", "refused"),
        ("trajectory.x.amplitude_m=nan", "it must be a finite number"),
        (
            "geometry.base_radius=1e400",
            "`geometry.base_radius` = 1e400 refused: it must be a finite number",
        ),
        (
            "geometry.leg_max=-inf",
            "`geometry.leg_max` = -inf refused: it must be a finite number",
        ),
        ("trajectory.samples=2.5", "it must be a whole number"),
        ("trajectory.samples=1", "outside the accepted range 2 … 1e7"),
        (
            "trajectory.duration_s=0",
            "0 is outside the accepted range above 0 … 1e6 s",
        ),
        (
            "trajectory.radius_m=0.1",
            "`trajectory.radius_m` does not apply to a `sinusoid` trajectory",
        ),
        (
            "limits.base_cone_deg=200",
            "200 is outside the accepted range above 0 and below 180 °",
        ),
        (
            "checks.jump_ratio=-3",
            "-3 is outside the accepted range above 0 … 1e12",
        ),
        ("geometry.radius=1", "unknown setting `geometry.radius`"),
        ("geometry.base_radius", "is not KEY=VALUE"),
        (
            "geometry.base_radius=big",
            "`geometry.base_radius` = big refused: it must be a number",
        ),
        (
            "cueing.tilt=yes",
            "`cueing.tilt` = yes refused: it is a switch: true or false",
        ),
        (
            "cueing.tilt=nan",
            "`cueing.tilt` = nan refused: it is a switch: true or false",
        ),
        (
            "limits.leg_speed_max_m_s=fast",
            "it must be a number, or `off`",
        ),
    ];
    for (text, expected) in cases {
        let mut s = preset("paired");
        let before = s.clone();
        // A good assignment first: it too must be undone by the refusal that follows.
        let e = apply_all(&mut s, ["geometry.home_height=0.9", text]).err();
        let message = e.map(|e| e.to_string()).unwrap_or_default();
        assert!(message.contains(expected), "{text}: {message}");
        assert_eq!(s, before, "{text}");
    }
}

#[test]
fn optional_settings_switch_on_and_off() {
    let mut s = preset("seed");
    let speed = find("limits.leg_speed_max_m_s").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(speed.get(&s), None);
    apply_all(&mut s, ["limits.leg_speed_max_m_s=0.3"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.limits.leg_speed_max, Some(0.3));
    apply_all(&mut s, ["limits.leg_speed_max_m_s=off"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.limits.leg_speed_max, None);
}

#[test]
fn defaults_are_the_seed_and_the_presets() {
    let seed = Scenario::seed();
    for s in all() {
        if let (Some(d), true) = (s.default_for(&seed), s.applies(&seed)) {
            let v = s.get(&seed).unwrap_or(f64::NAN);
            assert!((v - d).abs() < 1e-12, "{}: default {d}, seed {v}", s.key);
        }
    }
    // Switching the seed to a circle gives the circle preset's motion.
    let mut s = Scenario::seed();
    switch_trajectory(&mut s, TrajectoryChoice::Circle);
    assert_eq!(s.motion.trajectory, preset("circle").motion.trajectory);
    for choice in TrajectoryChoice::ALL {
        switch_trajectory(&mut s, choice);
        assert_eq!(TrajectoryChoice::of(&s.motion.trajectory), choice);
        let back =
            Scenario::from_toml_str(&s.to_toml(), "x", None).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            back.motion.trajectory.kind_name(),
            s.motion.trajectory.kind_name()
        );
        if let Trajectory::Keyframes(k) = &s.motion.trajectory {
            assert_eq!(k.time_span(), (0.0, 10.0));
        }
    }
}

#[test]
fn labels_carry_their_units() {
    assert_eq!(
        find("geometry.base_radius").map(Setting::label_with_unit),
        Ok("base radius (m)".to_owned())
    );
    assert_eq!(
        find("trajectory.roll.amplitude_deg").map(Setting::label_with_unit),
        Ok("roll amplitude (°)".to_owned())
    );
    assert_eq!(
        find("trajectory.samples").map(Setting::label_with_unit),
        Ok("samples".to_owned())
    );
}

#[test]
fn values_outside_the_accepted_range_are_refused_by_set_and_by_files() {
    let mut s = preset("seed");
    let before = s.clone();
    let e = find("trajectory.duration_s")
        .and_then(|k| k.set(&mut s, Some(1e308)))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "`trajectory.duration_s` = 1e308 refused: 1e308 is outside the accepted range above 0 … 1e6 s"
    );
    assert_eq!(s, before);
    let e = find("trajectory.samples")
        .and_then(|k| k.set(&mut s, Some(18446744073709551615.0)))
        .unwrap_err();
    assert!(
        e.to_string().contains("outside the accepted range 2 … 1e7"),
        "{e}"
    );
    // A file may hold what no slider offers: the same range applies, located.
    let text: String = s
        .to_toml()
        .lines()
        .map(|l| {
            if l.starts_with("base_radius") {
                "base_radius = 1e300\n".to_owned()
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    let e = Scenario::from_toml_str(&text, "big.toml", None).unwrap_err();
    let line = 1 + text[..text.find("1e300").unwrap_or(0)]
        .matches('\n')
        .count();
    assert_eq!(
        e.to_string(),
        format!(
            "big.toml, line {line}, column 15: `geometry.base_radius` 1e300 is outside the accepted range above 0 … 1000 m"
        )
    );
}

#[test]
fn the_extremes_of_every_accepted_range_keep_every_number_finite() {
    // For each preset and each setting, its smallest and largest accepted value (where
    // the model accepts it at all): the sampled poses, leg lengths and conditioning stay
    // finite. This is what the accepted ranges are for.
    let mut tried = 0;
    for name in presets::names() {
        let base = preset(name);
        for setting in all().iter().filter(|s| s.applies(&base)) {
            for v in [*setting.accepted.start(), *setting.accepted.end()] {
                if setting.unit == Unit::Count && v > 1e4 {
                    continue; // ten million samples: slow here, and no different in kind
                }
                let mut s = base.clone();
                if setting.set(&mut s, Some(v)).is_err() {
                    continue;
                }
                tried += 1;
                let samples = s.motion.sample();
                for (k, pose) in samples.poses.iter().enumerate().step_by(97) {
                    let legs = s.geometry.inverse(pose);
                    let c = s.geometry.conditioning(pose);
                    assert!(
                        samples.times[k].is_finite()
                            && pose.is_finite()
                            && legs.lengths.iter().all(|l| l.is_finite())
                            && c.singular_values.iter().all(|v| v.is_finite()),
                        "{name}: {} = {v} gives a non-finite value at sample {k}",
                        setting.key
                    );
                }
            }
        }
    }
    assert!(tried > 200, "only {tried} extreme values were accepted");
}

#[test]
fn actuator_settings_read_the_file_and_round_trip_on_a_rotary_scenario() {
    let text = std::fs::read_to_string(format!(
        "{}/tests/fixtures/rotary.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let mut s =
        Scenario::from_toml_str(&text, "rotary.toml", None).unwrap_or_else(|e| panic!("{e}"));
    let keys: Vec<&Setting> = all()
        .iter()
        .filter(|k| k.key.starts_with("actuator."))
        .collect();
    assert_eq!(keys.len(), 22);
    for k in &keys {
        assert!(k.applies(&s), "{}", k.key);
        match lookup(&text, &k.key) {
            Some(v) => assert_eq!(k.get(&s), Some(v), "{}", k.key),
            // Trims the file leaves out are zero, and servos it does not reverse are not.
            None => assert_eq!(k.get(&s), Some(0.0), "{}", k.key),
        }
    }
    apply_all(
        &mut s,
        [
            "actuator.horn_length_m=0.03",
            "actuator.horn_angles_deg[4]=140",
            "actuator.servo_min_deg=off",
            "actuator.servo_trim_deg[1]=-4.5",
            "actuator.servo_reversed[2]=true",
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let back =
        Scenario::from_toml_str(&s.to_toml(), "again", None).unwrap_or_else(|e| panic!("{e}"));
    let r = back
        .geometry
        .rotary()
        .unwrap_or_else(|| panic!("not rotary"));
    assert_eq!(r.horn_length(), 0.03);
    assert_eq!(r.horn_angles()[4].degrees(), 140.0);
    assert_eq!(r.range(), None);
    assert_eq!(r.trims()[1].degrees(), -4.5);
    assert_eq!(r.reversed(), &[false, false, true, false, false, false]);
    // One end of an absent range makes it symmetric.
    apply_all(&mut s, ["actuator.servo_max_deg=70"]).unwrap_or_else(|e| panic!("{e}"));
    let range = s.geometry.rotary().and_then(|r| r.range());
    assert_eq!(
        range.map(|(a, b)| (a.degrees(), b.degrees())),
        Some((-70.0, 70.0))
    );
    // Refusals name the rule; the linear seed has no servos at all.
    let e = apply_all(&mut s, ["actuator.rod_length_m=0.01"]).unwrap_err();
    assert!(e.to_string().contains("must be shorter than"), "{e}");
    let mut seed = preset("seed");
    let e = apply_all(&mut seed, ["actuator.horn_length_m=0.03"]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`actuator.horn_length_m` applies to rotary platforms only (`[actuator] kind = \"rotary\"`)"
    );
    // Leg limits belong to linear legs: refused on servos, and not listed for them.
    let e = apply_all(&mut s, ["geometry.leg_max=0.2"]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`geometry.leg_max` applies to linear legs only; a rotary platform has servo limits instead"
    );
    assert!(
        !find("limits.leg_speed_max_m_s")
            .unwrap_or_else(|e| panic!("{e}"))
            .applies(&s)
    );
    apply_all(&mut s, ["limits.servo_speed_max_deg_s=250"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.limits.servo_speed_max, Some(250.0));
    let e = apply_all(&mut seed, ["limits.servo_speed_max_deg_s=250"]).unwrap_err();
    assert!(
        e.to_string().contains("applies to rotary platforms only"),
        "{e}"
    );
}

#[test]
fn every_joint_coordinate_is_a_setting_and_editing_one_makes_the_plate_coordinates() {
    let mut s = preset("seed");
    // On a circle, the coordinates are read from it.
    let y = find("geometry.base_joints_m[2][1]").unwrap_or_else(|e| panic!("{e}"));
    let expected = s.geometry.base_joints()[2].y;
    assert_eq!(y.get(&s), Some(expected));
    assert!(find("geometry.base_radius").is_ok_and(|r| r.applies(&s)));
    apply_all(&mut s, ["geometry.base_joints_m[2][1]=0.45"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.geometry.base_joints()[2].y, 0.45);
    // The other joints did not move; the platform is still on its circle.
    let seed = preset("seed");
    for i in [0, 1, 3, 4, 5] {
        assert_eq!(s.geometry.base_joints()[i], seed.geometry.base_joints()[i]);
    }
    assert!(s.geometry.params().platform.circle().is_some());
    // The base's circle keys no longer apply, and say why when set.
    let radius = find("geometry.base_radius").unwrap_or_else(|e| panic!("{e}"));
    assert!(!radius.applies(&s));
    let err = apply_all(&mut s, ["geometry.base_radius=1.2"]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "`geometry.base_radius` does not apply: the base joints are given as coordinates (`geometry.base_joints_m`); set those instead"
    );
    // Written and read back: the file holds the coordinate form, read by the toml crate.
    let text = s.to_toml();
    assert_eq!(lookup(&text, "geometry.base_joints_m[2][1]"), Some(0.45));
    assert_eq!(lookup(&text, "geometry.base_radius"), None);
    assert_eq!(lookup(&text, "geometry.platform_radius"), Some(0.6));
    // Coordinates refused like the file reader refuses them.
    let err = apply_all(&mut s, ["geometry.base_joints_m[4][0]=nan"]).unwrap_err();
    assert!(err.to_string().contains("finite"), "{err}");
    let same = format!(
        "geometry.platform_joints_m[1][0]={}",
        s.geometry.platform_joints()[0].x
    );
    let mut twins = s.clone();
    apply_all(
        &mut twins,
        [same.as_str(), "geometry.platform_joints_m[1][1]=0.123"],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let same_y = format!(
        "geometry.platform_joints_m[1][1]={}",
        s.geometry.platform_joints()[0].y
    );
    let err = apply_all(&mut twins, [same_y.as_str()]).unwrap_err();
    assert!(err.to_string().contains("coincide"), "{err}");
}

#[test]
fn a_scenario_as_coordinates_is_the_same_platform() {
    for name in presets::names() {
        let s = preset(name);
        let c = s.as_coordinates();
        assert!(c.geometry.params().base.circle().is_none());
        assert!(c.geometry.params().platform.circle().is_none());
        assert_eq!(c.geometry.base_joints(), s.geometry.base_joints());
        assert_eq!(c.geometry.platform_joints(), s.geometry.platform_joints());
        let back = Scenario::from_toml_str(&c.to_toml(), "c.toml", None)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(back.geometry, c.geometry, "{name}");
        let pose = s.geometry.home_pose();
        assert_eq!(
            back.geometry.leg_lengths(&pose),
            s.geometry.leg_lengths(&pose)
        );
    }
}

#[test]
fn slider_ranges_follow_the_platforms_size() {
    let by_key = |key: &str| {
        all()
            .iter()
            .find(|s| s.key == key)
            .unwrap_or_else(|| panic!("{key}"))
    };
    let radius = by_key("geometry.base_radius");
    let seed = preset("seed");
    // The seed keeps the declared range.
    let r = radius.range_for(&seed);
    assert!(
        (r.start() - 0.05).abs() < 1e-12 && (r.end() - 3.0).abs() < 1e-12,
        "{r:?}"
    );
    // A desk platform (its radii in centimetres) gets a range of its size: its radius
    // sits well inside, not pinned at the left end.
    let desk = preset("servo-desk");
    let r = radius.range_for(&desk);
    let v = radius.get(&desk).unwrap_or_default();
    let share = (v - r.start()) / (r.end() - r.start());
    assert!(*r.end() < 1.0, "{r:?}");
    assert!((0.1..0.9).contains(&share), "{v} in {r:?}: {share}");
    // The stroke spans half to twice the home leg length (the seed's legs are 1.0 m at
    // home: 0.5 to 2.0 m instead of 0.05 to 4 m).
    let max = by_key("geometry.leg_max").range_for(&seed);
    let home = seed.geometry.leg_lengths(&seed.geometry.home_pose())[0];
    assert!((max.start() - 0.5 * home).abs() < 1e-9, "{max:?}");
    assert!((max.end() - 2.0 * home).abs() < 1e-9, "{max:?}");
    // A value outside is inside the range offered.
    let mut wide = seed.clone();
    radius
        .set(&mut wide, Some(40.0))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(*radius.range_for(&wide).end(), 40.0);
    // Angles are not lengths: unchanged.
    let phase = by_key("trajectory.pitch.phase_deg");
    assert_eq!(phase.range_for(&desk), phase.range);
}

#[test]
fn the_quantity_limits_are_the_stroke_or_the_servo_range() {
    use crate::model::actuator::ActuatorKind;
    let keys = |kind| quantity_limit_targets(kind).map(|t| of(t).key.clone());
    assert_eq!(
        keys(ActuatorKind::Linear),
        ["geometry.leg_min", "geometry.leg_max"]
    );
    assert_eq!(
        keys(ActuatorKind::Rotary),
        ["actuator.servo_min_deg", "actuator.servo_max_deg"]
    );
}

#[test]
fn cueing_settings_take_numbers_and_switches_and_refuse_what_cannot_work() {
    let mut s = Scenario::seed();
    apply_all(
        &mut s,
        [
            "cueing.tilt=false",
            "cueing.yaw=off",
            "cueing.workspace_limiter=true",
            "cueing.translation_hp_wn=3.5",
            "cueing.reference_m[2]=0.4",
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let c = &s.cueing;
    assert!(!c.tilt && !c.yaw && c.pitch && c.workspace_limiter);
    assert_eq!((c.translation_hp_wn, c.reference_m[2]), (3.5, 0.4));
    assert_eq!(find("cueing.tilt").map(|t| t.get(&s)), Ok(Some(0.0)));
    assert_eq!(find("cueing.pitch").map(|t| t.get(&s)), Ok(Some(1.0)));
    let refused = |text: &str| {
        let mut t = s.clone();
        let e = apply_all(&mut t, [text]).err();
        assert_eq!(t, s, "{text} changed the scenario");
        e.map(|e| e.to_string()).unwrap_or_default()
    };
    assert!(refused("cueing.tilt=2").contains("switch"));
    assert!(
        refused("cueing.tilt_lp_wn=-1").contains("-1 is outside the accepted range above 0 … "),
        "{}",
        refused("cueing.tilt_lp_wn=-1")
    );
    assert!(refused("cueing.translation_scale=off").contains("cannot be switched off"));
    // Words are taken in any case, as the switches' are.
    let mut upper = s.clone();
    apply_all(&mut upper, ["cueing.algorithm=MPC"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        upper.cueing.algorithm,
        crate::model::cueing_settings::CueingAlgorithm::Mpc
    );
    // A rule of another key is named with that key (the step bounds the solve interval).
    let other = refused("cueing.mpc_step_s=0.005");
    assert!(
        other.starts_with(
            "`cueing.mpc_step_s` = 0.005 refused: `cueing.mpc_solve_interval_s` must be"
        ),
        "{other}"
    );
    // One's own is not named twice.
    let own = refused("cueing.mpc_horizon_steps=1");
    assert_eq!(
        own,
        "`cueing.mpc_horizon_steps` = 1 refused: 1 is outside the accepted range 2 … 40"
    );
    assert!(refused("cueing.washout=1").contains("unknown setting"));
}

#[test]
fn dynamics_settings_are_read_written_and_refused_by_key() {
    let mut seed = preset("seed");
    apply_all(
        &mut seed,
        [
            "dynamics.actuator_stiffness=2e7",
            "dynamics.cylinder_mass_kg=1.5",
            "dynamics.rod_com_m=0.2",
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(seed.dynamics.actuator_stiffness, Some(2e7));
    assert_eq!(seed.dynamics.cylinder_mass_kg, 1.5);
    assert_eq!(
        find("dynamics.rod_com_m").map(|s| s.get(&seed)),
        Ok(Some(0.2))
    );
    // The file holds what the settings say.
    let text = seed.to_toml();
    assert_eq!(lookup(&text, "dynamics.cylinder_mass_kg"), Some(1.5));
    // The stiffness may be removed; the other values cannot be switched off.
    apply_all(&mut seed, ["dynamics.actuator_stiffness=off"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(seed.dynamics.actuator_stiffness, None);
    let refused = |s: &mut Scenario, text: &str| match apply_all(s, [text]) {
        Ok(()) => panic!("{text} accepted"),
        Err(e) => e.to_string(),
    };
    assert_eq!(
        refused(&mut seed, "dynamics.actuator_stiffness=0"),
        "`dynamics.actuator_stiffness` = 0 refused: 0 is outside the accepted range above 0 … 1e12 N/m"
    );
    assert_eq!(
        refused(&mut seed, "dynamics.rod_mass_kg=-2"),
        "`dynamics.rod_mass_kg` = -2 refused: -2 is outside the accepted range 0 … 1e6 kg"
    );
    assert_eq!(
        refused(&mut seed, "dynamics.rod_mass_kg=off"),
        "`dynamics.rod_mass_kg` = off refused: it cannot be switched off"
    );
    assert!(refused(&mut seed, "dynamics.horn_mass_kg=0.1").contains("rotary platforms only"));
    let mut desk = preset("servo-desk");
    assert!(refused(&mut desk, "dynamics.cylinder_mass_kg=1").contains("linear legs only"));
    apply_all(&mut desk, ["dynamics.horn_mass_kg=0.01"]).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(desk.dynamics.horn_mass_kg, 0.01);
    // Stiffness and friction are in the units of the platform's actuators.
    let stiffness = find("dynamics.actuator_stiffness").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(stiffness.unit.symbol_for(ActuatorKind::Linear), "N/m");
    assert_eq!(stiffness.unit.symbol_for(ActuatorKind::Rotary), "N·m/rad");
}

#[test]
fn the_accepted_range_shown_leaves_out_what_the_model_always_refuses() {
    // `stewart settings` and the tooltips show each setting's accepted range: a sign the
    // model itself refuses on every preset the setting applies to (a negative radius, a
    // zero stiffness) must lie outside it, or on an end shown as excluded.
    let presets: Vec<Scenario> = presets::names().map(preset).collect();
    let mut checked = 0;
    for setting in all() {
        let applying: Vec<&Scenario> = presets.iter().filter(|s| setting.applies(s)).collect();
        if applying.is_empty() || setting.unit == Unit::Switch || setting.unit == Unit::Count {
            continue;
        }
        for v in [-1.0, 0.0] {
            let always_refused = applying.iter().all(|s| {
                let mut s = (*s).clone();
                setting.target.set(&mut s, Some(v)).is_err()
            });
            if !always_refused {
                continue;
            }
            checked += 1;
            let shown_accepted = setting.accepted.contains(&v)
                && !(setting.min_excluded && v == *setting.accepted.start());
            assert!(
                !shown_accepted,
                "{}: {v} is always refused but shown as accepted ({})",
                setting.key,
                setting.accepted_words()
            );
        }
    }
    assert!(checked > 30, "{checked}");
}

#[test]
fn a_stiffness_switched_on_starts_at_a_typical_actuators_and_servos_get_their_own_range() {
    let stiffness = find("dynamics.actuator_stiffness").unwrap_or_else(|e| panic!("{e}"));
    let legs = Scenario::seed();
    assert_eq!(stiffness.default_for(&legs), None, "absent until given");
    assert_eq!(stiffness.value_when_switched_on(&legs), 2.0e7);
    assert_eq!(stiffness.range_for(&legs), 1e3..=1e8);
    let servos = preset("servo-desk");
    assert_eq!(stiffness.value_when_switched_on(&servos), 50.0);
    assert_eq!(stiffness.range_for(&servos), 1.0..=1e5);
    // The typical value is accepted as it is.
    let mut s = servos.clone();
    stiffness
        .set(&mut s, Some(stiffness.value_when_switched_on(&servos)))
        .unwrap_or_else(|e| panic!("{e}"));
    // A limit without a default still switches on at its declared top.
    let clearance = all()
        .iter()
        .find(|s| s.optional() && s.unit != Unit::Stiffness && s.default_for(&legs).is_none())
        .unwrap_or_else(|| panic!("an optional limit"));
    assert_eq!(
        clearance.value_when_switched_on(&legs),
        *clearance.range.end()
    );
}

#[test]
fn every_refusal_outside_a_settings_range_names_that_settings_own_printed_rule() {
    // For each preset and each setting that applies to it: a value just past either end
    // of the range `stewart settings` prints (or on an end printed as excluded) is refused
    // as that setting, quoting that range — never another key's rule, nor a unit's range
    // wider or narrower than the one printed. And each printed end itself, when not
    // excluded, is not refused for being outside a range.
    let mut tried = 0;
    for name in presets::names() {
        let scenario = preset(name);
        let kind = scenario.geometry.actuator().kind();
        for setting in all().iter().filter(|s| s.applies(&scenario)) {
            if setting.target.actuator_kind().is_some_and(|k| k != kind) {
                continue;
            }
            let (lo, hi) = (*setting.accepted.start(), *setting.accepted.end());
            let past = |v: f64, down: bool| {
                let step = (v.abs() * 1e-9).max(1e-9);
                if down { v - step } else { v + step }
            };
            let below = if setting.min_excluded {
                lo
            } else {
                past(lo, true)
            };
            let above = if setting.max_excluded {
                hi
            } else {
                past(hi, false)
            };
            let rule = setting.accepted_words_for(kind);
            for v in [below, above] {
                let mut s = scenario.clone();
                match setting.set(&mut s, Some(v)) {
                    Err(SettingError::Invalid { key, reason, .. }) => {
                        assert_eq!(key, setting.key, "{name}: {v}");
                        if setting.unit == Unit::Count && v.fract() != 0.0 {
                            assert!(reason.contains(&rule), "{name} {key}={v}: {reason}");
                        } else if setting.unit != Unit::Switch {
                            assert!(
                                reason.contains(&format!("outside the accepted range {rule}")),
                                "{name} {key}={v}: {reason}"
                            );
                        }
                    }
                    other => panic!("{name} {}={v}: {other:?}", setting.key),
                }
                assert_eq!(s, scenario, "{name} {}={v} changed it", setting.key);
                tried += 1;
            }
            for v in [lo, hi] {
                let excluded =
                    (v == lo && setting.min_excluded) || (v == hi && setting.max_excluded);
                if excluded || !v.is_finite() {
                    continue;
                }
                let mut s = scenario.clone();
                if let Err(e) = setting.set(&mut s, Some(v)) {
                    assert!(
                        !e.to_string().contains("accepted range"),
                        "{name} {}={v}: an end printed as accepted is refused as outside: {e}",
                        setting.key
                    );
                }
            }
        }
    }
    assert!(tried > 1000, "{tried}");
}
