//! Scenario parsing: presets, round trips and located errors.

use super::*;
use crate::model::trajectory::{Interpolation, Sampling, Trajectory};

const GEOMETRY: &str = "[geometry]
base_radius = 1.0
platform_radius = 0.6
home_height = 0.8
base_angles_deg = [0, 60, 120, 180, 240, 300]
platform_angles_deg = [30, 90, 150, 210, 270, 330]
";

fn parse(text: &str) -> Result<Scenario, ScenarioError> {
    Scenario::from_toml_str(text, "s.toml", None)
}

fn error(text: &str) -> String {
    match parse(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn every_preset_loads_and_samples_finite_poses() {
    for name in presets::names() {
        let s = Scenario::preset(name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.name, name);
        let samples = s.motion.sample();
        assert!(samples.len() >= 2);
        assert!(samples.poses.iter().all(|p| p.is_finite()), "{name}");
    }
    for kind in [
        "sinusoid",
        "circle",
        "figure8",
        "helix",
        "sway",
        "keyframes",
    ] {
        assert!(
            presets::PRESETS
                .iter()
                .any(|(_, text)| text.contains(&format!("kind = \"{kind}\""))),
            "no preset of kind {kind}"
        );
    }
}

#[test]
fn seed_preset_is_the_article_bit_for_bit() {
    let preset = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let code = Scenario::seed();
    assert_eq!(preset.geometry.base_joints(), code.geometry.base_joints());
    assert_eq!(
        preset.geometry.platform_joints(),
        code.geometry.platform_joints()
    );
    assert_eq!(preset.motion.sampling, Sampling::SEED);
    assert_eq!(preset.motion.sample(), code.motion.sample());
    assert_eq!(
        preset.geometry.stroke(),
        crate::model::geometry::StrokeLimits::new(0.55, 1.30)
    );
}

#[test]
fn a_file_without_trajectory_uses_the_seed_motion_at_its_home_height() {
    let s = parse(&GEOMETRY.replace("0.8", "0.9")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.name, "s");
    assert_eq!(s.motion, Motion::seed(0.9));
}

#[test]
fn scenarios_round_trip_through_toml() {
    for name in presets::names() {
        let s = Scenario::preset(name).unwrap_or_else(|e| panic!("{e}"));
        let text = s.to_toml();
        let back = parse(&text).unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        assert_eq!(back.geometry.params().stroke, s.geometry.params().stroke);
        assert_eq!(back.motion.sampling, s.motion.sampling);
        assert_eq!(back.checks, s.checks);
        assert_eq!(back.payload, s.payload);
        assert_eq!(back.limits.leg_radius, s.limits.leg_radius);
        assert_eq!(back.limits.leg_speed_max, s.limits.leg_speed_max);
        let cone = |l: &Limits| l.base_cone.map(|a| a.degrees());
        assert_eq!(
            cone(&back.limits).map(|d| (d * 1e9).round()),
            cone(&s.limits).map(|d| (d * 1e9).round())
        );
        for (a, b) in back
            .motion
            .sample()
            .poses
            .iter()
            .zip(s.motion.sample().poses.iter())
        {
            assert!((a.position - b.position).norm() < 1e-15, "{name}");
            assert!((a.yaw - b.yaw).radians().abs() < 1e-15, "{name}");
        }
    }
    // A pivot survives too.
    let text = format!("{GEOMETRY}[pivot]\noffset_m = [0.0, 0.1, 0.25]\n");
    let s = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.geometry.pivot(), nalgebra::Vector3::new(0.0, 0.1, 0.25));
    assert_eq!(
        parse(&s.to_toml())
            .unwrap_or_else(|e| panic!("{e}"))
            .geometry
            .pivot(),
        s.geometry.pivot()
    );
}

#[test]
fn shapes_read_their_keys_and_default_to_home_height() {
    let s = parse(&format!(
        "{GEOMETRY}[trajectory]\nkind = \"circle\"\nradius_m = 0.1\nfrequency_hz = 0.5\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    match s.motion.trajectory {
        Trajectory::Circle(c) => assert_eq!((c.radius, c.frequency_hz, c.z), (0.1, 0.5, 0.8)),
        other => panic!("{other:?}"),
    }
}

#[test]
fn pose_table_trajectory_reads_the_csv_next_to_the_scenario() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(
        dir.path().join("poses.csv"),
        "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n0.5,0.05,0,0.8,0,0,5\n1,0.1,0,0.8,0,0,10\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("s.toml");
    std::fs::write(
        &path,
        format!("{GEOMETRY}[trajectory]\nkind = \"pose_table\"\nfile = \"poses.csv\"\n"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let s = Scenario::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.motion.sampling.len(), 3);
    let samples = s.motion.sample();
    assert_eq!(samples.times, vec![0.0, 0.5, 1.0]);
    assert!((samples.poses[1].yaw.degrees() - 5.0).abs() < 1e-12);
    match &s.motion.trajectory {
        Trajectory::Keyframes(k) => assert_eq!(k.interpolation(), Interpolation::Linear),
        other => panic!("{other:?}"),
    }
    // A bad cell in the table is reported with both locations.
    std::fs::write(
        dir.path().join("poses.csv"),
        "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n1,0.1,0,oops,0,0,10\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let e = Scenario::load(&path).unwrap_err().to_string();
    assert!(
        e.ends_with("poses.csv, line 3, column `z`: `oops` is not a number"),
        "{e}"
    );
    assert!(
        e.contains("s.toml, line 9, column 8: in the pose table: "),
        "{e}"
    );
}

#[test]
fn errors_name_the_line_and_the_value() {
    assert_eq!(
        error(&GEOMETRY.replace("base_radius = 1.0", "base_radius = -1.0")),
        "s.toml, line 2, column 15: `base_radius` must be positive, got -1"
    );
    assert_eq!(
        error(&GEOMETRY.replace("home_height = 0.8", "home_height = nan")),
        "s.toml, line 4, column 15: `home_height` must be a finite number, got NaN"
    );
    assert_eq!(
        error(&GEOMETRY.replace("[30, 90, 150, 210, 270, 330]", "[30, 90, 150, 210, 270]")),
        "s.toml, line 6, column 23: `platform_angles_deg` must list 6 angles (one per leg), got 5"
    );
    assert_eq!(
        error(&GEOMETRY.replace("[0, 60, 120, 180, 240, 300]", "[0, 60, 120, 180, 240, 360]")),
        "s.toml, line 5, column 19: base joints 1 and 6 coincide (both at 0°): the six joints of a plate must be distinct"
    );
    assert_eq!(
        error(&format!("{GEOMETRY}leg_min = 1.2\nleg_max = 0.9\n")),
        "s.toml, line 8, column 11: `leg_min` (1.2 m) must be less than `leg_max` (0.9 m)"
    );
    let unknown = error(&format!("{GEOMETRY}leg_maximum = 1.0\n"));
    assert!(
        unknown.starts_with("s.toml, line 7, column 1: unknown field `leg_maximum`"),
        "{unknown}"
    );
    let syntax = error("[geometry\nbase_radius = 1");
    assert!(
        syntax.starts_with("s.toml, line 1, column 10: "),
        "{syntax}"
    );
    let missing = error("[geometry]\nbase_radius = 1.0\n");
    assert!(
        missing.starts_with("s.toml, line 1, column 1: missing field `home_height`"),
        "{missing}"
    );
    let wrong_type = error(&GEOMETRY.replace("platform_radius = 0.6", "platform_radius = \"0.6\""));
    assert!(
        wrong_type.starts_with("s.toml, line 3, column 19: invalid type: string"),
        "{wrong_type}"
    );
}

#[test]
fn trajectory_errors_name_the_key() {
    let t = |body: &str| error(&format!("{GEOMETRY}[trajectory]\n{body}"));
    assert_eq!(
        t("kind = \"sinusoid\"\nradius_m = 0.1\n"),
        "s.toml, line 9, column 12: `trajectory.radius_m` is not used by trajectory kind `sinusoid` (it uses: x, y, z, roll, pitch, yaw)"
    );
    assert_eq!(
        t("kind = \"circle\"\nfrequency_hz = 0.5\n"),
        "s.toml, line 8, column 8: `trajectory.radius_m` is required by trajectory kind `circle` but missing"
    );
    assert_eq!(
        t("kind = \"circle\"\nradius_m = inf\nfrequency_hz = 0.5\n"),
        "s.toml, line 9, column 12: `trajectory.radius_m` must be a finite number, got inf"
    );
    assert_eq!(
        t("kind = \"circle\"\nradius_m = 0.1\nfrequency_hz = 0.5\nsamples = 1\n"),
        "s.toml, line 11, column 11: `trajectory.samples` must be a whole number from 2 to 10000000, got 1"
    );
    assert_eq!(
        t("kind = \"circle\"\nradius_m = 0.1\nfrequency_hz = 0.5\nduration_s = -3\n"),
        "s.toml, line 11, column 14: `duration_s` must be a positive finite number of seconds, got -3"
    );
    assert!(
        t("kind = \"spiral\"\n").starts_with("s.toml, line 8, column 8: unknown variant `spiral`")
    );
    assert_eq!(
        t("kind = \"sinusoid\"\n[trajectory.roll]\namplitude_deg = nan\n"),
        "s.toml, line 9, column 1: `trajectory.roll.amplitude_deg` must be a finite number, got NaN"
    );
    assert_eq!(
        t("kind = \"keyframes\"\nkeys = [\n {t_s = 0, z_m = 0.8},\n {t_s = 0, z_m = 0.9},\n]\n"),
        "s.toml, line 11, column 2: key 2 is at t = 0 s, not after the previous key's 0 s: times must increase"
    );
    let missing_file = t("kind = \"pose_table\"\nfile = \"nowhere.csv\"\n");
    assert!(missing_file.starts_with("s.toml, line 9, column 8: `trajectory.file` names `nowhere.csv`, which cannot be opened"), "{missing_file}");
    assert_eq!(
        Scenario::preset("spiral").unwrap_err().to_string(),
        "preset `spiral`: no preset is called `spiral` (presets: seed, paired, circle, figure8, helix, sway, keyframes, servo-desk, crank-rig, dietmaier)"
    );
}

#[test]
fn a_rotary_scenario_reads_and_writes_back_the_same() {
    let text = std::fs::read_to_string(format!(
        "{}/tests/fixtures/rotary.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let s = Scenario::from_toml_str(&text, "rotary.toml", None).unwrap_or_else(|e| panic!("{e}"));
    let servos = s.geometry.rotary().unwrap_or_else(|| panic!("not rotary"));
    assert_eq!((servos.horn_length(), servos.rod_length()), (0.025, 0.12));
    assert_eq!(servos.horn_angles()[2].degrees(), 15.0);
    let range = servos.range().map(|(a, b)| (a.degrees(), b.degrees()));
    assert_eq!(range, Some((-80.0, 80.0)));
    let back =
        Scenario::from_toml_str(&s.to_toml(), "again.toml", None).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.geometry, s.geometry);
    // Linear files are untouched: no [actuator] table is written for them.
    let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    assert!(!seed.to_toml().contains("[actuator]"));
    assert!(seed.geometry.rotary().is_none());
}

#[test]
fn rate_limits_belong_to_their_actuator_kind() {
    let rotary = std::fs::read_to_string(format!(
        "{}/tests/fixtures/rotary.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let lines = rotary.lines().count();
    let e = error(&format!("{rotary}\n[limits]\nleg_speed_max_m_s = 0.5\n"));
    assert_eq!(
        e,
        format!(
            "s.toml, line {}, column 21: `limits.leg_speed_max_m_s` applies to linear legs only; a rotary platform takes `servo_speed_max_deg_s`, `servo_accel_max_deg_s2` and `servo_jerk_max_deg_s3`",
            lines + 3
        )
    );
    let e = error(&format!(
        "{GEOMETRY}[limits]\nservo_accel_max_deg_s2 = 900\n"
    ));
    assert_eq!(
        e,
        "s.toml, line 8, column 26: `limits.servo_accel_max_deg_s2` applies to rotary platforms only (`[actuator] kind = \"rotary\"`)"
    );
    let s = parse(&format!(
        "{rotary}\n[limits]\nservo_speed_max_deg_s = 300\nservo_accel_max_deg_s2 = 5000\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        (s.limits.servo_speed_max, s.limits.servo_accel_max),
        (Some(300.0), Some(5000.0))
    );
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.limits, s.limits);
}

#[test]
fn the_link_table_reads_writes_back_and_names_bad_values() {
    use crate::model::link_settings::{LinkOutput, LinkTransport};
    let s = parse(&format!(
        "{GEOMETRY}[link]\ntransport = \"serial\"\nport = \"/dev/ttyACM0\"\nbaud = 1000000\nrate_hz = 500\noutput = \"pulse\"\nactuator = [2, 1, 3, 4, 5, 6]\nreversed = [true, false, false, false, false, true]\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.link.transport, LinkTransport::Serial);
    assert_eq!(s.link.port.as_deref(), Some("/dev/ttyACM0"));
    assert_eq!((s.link.baud, s.link.rate_hz), (1_000_000, 500.0));
    assert_eq!(s.link.output, LinkOutput::Pulse);
    assert_eq!(s.link.actuator, [2, 1, 3, 4, 5, 6]);
    // Keys not written keep their defaults.
    assert_eq!(s.link.pulse_zero_us, 1500.0);
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.link, s.link);
    // A scenario without a link writes no [link] table.
    assert!(
        !parse(GEOMETRY)
            .map(|s| s.to_toml())
            .unwrap_or_default()
            .contains("[link]")
    );
    assert_eq!(
        error(&format!("{GEOMETRY}[link]\nrate_hz = 5000\n")),
        "s.toml, line 8, column 11: `link.rate_hz` must be between 10 and 1000 Hz, got 5000"
    );
    assert_eq!(
        error(&format!(
            "{GEOMETRY}[link]\nactuator = [1, 2, 3, 4, 5, 1]\n"
        )),
        "s.toml, line 8, column 28: `link.actuator[5]` channels 1 and 6 both carry actuator 1: each actuator needs its own channel"
    );
    assert!(
        error(&format!("{GEOMETRY}[link]\ntransport = \"tcp\"\n"))
            .starts_with("s.toml, line 8, column 13: unknown variant `tcp`"),
    );
    assert!(
        error(&format!("{GEOMETRY}[link]\nscale = [1, 1]\n"))
            .starts_with("s.toml, line 8, column 9: "),
    );
}

#[test]
fn the_cueing_table_reads_writes_back_and_names_bad_values() {
    let s = parse(&format!(
        "{GEOMETRY}[cueing]\ntranslation_scale = 0.8\ntilt = false\nyaw = false\nreference_m = [0.0, 0.1, 0.5]\nworkspace_limiter = true\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.cueing.translation_scale, 0.8);
    assert!(!s.cueing.tilt && !s.cueing.yaw && s.cueing.roll);
    assert_eq!(s.cueing.reference_m, [0.0, 0.1, 0.5]);
    assert!(s.cueing.workspace_limiter);
    // Keys not written keep their defaults.
    assert_eq!(s.cueing.rotation_hp_wn, 1.0);
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.cueing, s.cueing);
    assert!(
        !parse(GEOMETRY)
            .map(|s| s.to_toml())
            .unwrap_or_default()
            .contains("[cueing]")
    );
    assert_eq!(
        error(&format!("{GEOMETRY}[cueing]\ntilt_lp_wn = -2\n")),
        "s.toml, line 8, column 14: `cueing.tilt_lp_wn` must be a positive number of at most 1000, got -2"
    );
    assert!(
        error(&format!("{GEOMETRY}[cueing]\nwashout = 1\n"))
            .starts_with("s.toml, line 8, column 1: unknown field `washout`"),
    );
    assert!(
        error(&format!("{GEOMETRY}[cueing]\ntilt = 3\n")).starts_with("s.toml, line 8, column 8: "),
    );
}

#[test]
fn the_dynamics_table_and_a_full_inertia_tensor_read_write_back_and_name_bad_values() {
    let s = parse(&format!(
        "{GEOMETRY}[payload]\nmass_kg = 50.0\ninertia_kg_m2 = [3.0, 4.0, 5.0, -0.2, 0.1, -0.3]\n[dynamics]\nactuator_stiffness = 2e7\nactuator_friction = 40.0\ncylinder_mass_kg = 1.5\nrod_com_m = 0.2\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let inertia = s.payload.map(|p| p.inertia).unwrap_or_default();
    // Ixx, Iyy, Izz, Ixy, Ixz, Iyz.
    assert_eq!(
        inertia,
        nalgebra::Matrix3::new(3.0, -0.2, 0.1, -0.2, 4.0, -0.3, 0.1, -0.3, 5.0)
    );
    assert_eq!(s.dynamics.actuator_stiffness, Some(2e7));
    assert_eq!(s.dynamics.actuator_friction, 40.0);
    assert_eq!(s.dynamics.cylinder_mass_kg, 1.5);
    assert_eq!(s.dynamics.rod_com_m, 0.2);
    // Keys not written are zero.
    assert_eq!(s.dynamics.horn_mass_kg, 0.0);
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}\n{}", s.to_toml()));
    assert_eq!(back.dynamics, s.dynamics);
    assert_eq!(back.payload, s.payload);
    let plain = parse(GEOMETRY).map(|s| s.to_toml()).unwrap_or_default();
    assert!(!plain.contains("[dynamics]"), "{plain}");
    for (table, want) in [
        (
            "[dynamics]\nactuator_stiffness = 0\n",
            "s.toml, line 8, column 22: `dynamics.actuator_stiffness` must be a positive stiffness of at most 1e12, got 0",
        ),
        (
            "[dynamics]\nrod_mass_kg = -1.0\n",
            "s.toml, line 8, column 15: `dynamics.rod_mass_kg` must be a mass in kg from 0 to 1e6, got -1",
        ),
        (
            "[payload]\nmass_kg = 5.0\ninertia_kg_m2 = [1.0, 2.0, 3.0, 4.0]\n",
            "s.toml, line 9, column 17: `payload.inertia_kg_m2` takes 3 principal moments (Ixx, Iyy, Izz) or 6 values (Ixx, Iyy, Izz, Ixy, Ixz, Iyz), got 4",
        ),
    ] {
        assert_eq!(error(&format!("{GEOMETRY}{table}")), want);
    }
    // A tensor that no body has (not positive semi-definite).
    let not_definite = error(&format!(
        "{GEOMETRY}[payload]\nmass_kg = 5.0\ninertia_kg_m2 = [1.0, 1.0, 1.0, 2.0, 0.0, 0.0]\n"
    ));
    assert!(
        not_definite.contains("positive semi-definite"),
        "{not_definite}"
    );
    assert!(
        error(&format!("{GEOMETRY}[dynamics]\nhorn_mass = 1\n"))
            .starts_with("s.toml, line 8, column 1: unknown field `horn_mass`"),
    );
}

/// The seed's platform with both plates written as coordinates (from its circles).
const COORDINATES: &str = "[geometry]
home_height = 0.8
base_joints_m = [
  [1.0, 0.0, 0.0],
  [0.5, 0.8660254037844386, 0.0],
  [-0.5, 0.8660254037844387, 0.0],
  [-1.0, 0.0, 0.0],
  [-0.5, -0.8660254037844386, 0.0],
  [0.5, -0.8660254037844387, 0.0],
]
platform_joints_m = [[0.52, 0.3, 0.0], [0.0, 0.6, 0.0], [-0.52, 0.3, 0.0], [-0.52, -0.3, 0.0], [0.0, -0.6, 0.0], [0.52, -0.3, 0.05]]
";

#[test]
fn joints_given_as_coordinates_are_read_checked_and_written_back() {
    let s = parse(COORDINATES).unwrap_or_else(|e| panic!("{e}"));
    let seed = parse(GEOMETRY).unwrap_or_else(|e| panic!("{e}"));
    for i in 0..6 {
        assert!((s.geometry.base_joints()[i] - seed.geometry.base_joints()[i]).norm() < 1e-15);
    }
    assert_eq!(s.geometry.platform_joints()[5].z, 0.05);
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.geometry, s.geometry);
    assert!(s.to_toml().contains("base_joints_m"), "{}", s.to_toml());
    assert!(!s.to_toml().contains("base_radius"));

    // One form per plate: mixing them names both keys, at the circle key's line.
    let mixed =
        error(&COORDINATES.replace("home_height = 0.8", "home_height = 0.8\nbase_radius = 1.0"));
    assert_eq!(
        mixed,
        "s.toml, line 3, column 15: `base_radius` and `base_joints_m` both describe the base joints: give either their coordinates or a radius and angles, not both"
    );
    // Each plate may use either form.
    let one_each = format!(
        "[geometry]\nhome_height = 0.8\nbase_radius = 1.0\nbase_angles_deg = [0, 60, 120, 180, 240, 300]\n{}",
        &COORDINATES[COORDINATES.find("platform_joints_m").unwrap_or(0)..]
    );
    assert!(parse(&one_each).is_ok());
    // Five points, a point of two numbers, a NaN, two points at one place.
    let five = error(&COORDINATES.replace("  [1.0, 0.0, 0.0],\n", ""));
    assert!(
        five.starts_with("s.toml, line 3, column 17: `base_joints_m` must list 6 points [x, y, z] (one per leg), got 5"),
        "{five}"
    );
    let two = error(&COORDINATES.replace("[-1.0, 0.0, 0.0]", "[-1.0, 0.0]"));
    assert_eq!(
        two,
        "s.toml, line 7, column 3: `base_joints_m[3]` must be a point [x, y, z] in metres, got 2 numbers"
    );
    let nan = error(&COORDINATES.replace("[-1.0, 0.0, 0.0]", "[-1.0, nan, 0.0]"));
    assert_eq!(
        nan,
        "s.toml, line 7, column 10: `base_joints_m[3][1]` must be a finite number, got NaN"
    );
    let same = error(&COORDINATES.replace("[-1.0, 0.0, 0.0]", "[1.0, 0.0, 0.0]"));
    assert_eq!(
        same,
        "s.toml, line 7, column 3: base joints 1 and 4 coincide (both at (1, 0, 0) m): the six joints of a plate must be distinct"
    );
    // A plate with neither form, or half a circle.
    let neither = error(
        "[geometry]\nhome_height = 0.8\nbase_radius = 1.0\nbase_angles_deg = [0, 60, 120, 180, 240, 300]\n",
    );
    assert!(
        neither.contains(
            "`platform_joints_m` is missing: give the platform joints as `platform_joints_m`"
        ),
        "{neither}"
    );
    let half = error(&COORDINATES.replace(
        "base_joints_m = [",
        "base_radius = 1.0\nplatform_angles_deg = [1, 2, 3, 4, 5, 6]\nxbase_joints_m = [",
    ));
    assert!(half.contains("unknown field `xbase_joints_m`"), "{half}");
}

#[test]
fn a_fixed_size_array_with_a_value_too_many_or_too_few_is_refused_not_cut() {
    for (table, want) in [
        (
            "[payload]\nmass_kg = 10\ninertia_kg_m2 = [1, 1, 1]\ncom_m = [0, 0, 0.1, 5]\n",
            "expected 3 values, got 4",
        ),
        (
            "[pivot]\noffset_m = [0, 0, 0.1, 0]\n",
            "expected 3 values, got 4",
        ),
        (
            "[cueing]\nreference_m = [0, 0]\n",
            "expected 3 values, got 2",
        ),
        (
            "[link]\nscale = [1, 1, 1, 1, 1, 1, 7]\n",
            "expected 6 values, got 7",
        ),
        (
            "[link]\nreversed = [true, false, false, false, false, false, true]\n",
            "expected 6 values, got 7",
        ),
    ] {
        let e = error(&format!("{GEOMETRY}{table}"));
        assert!(e.contains(want), "{table}: {e}");
        assert!(e.contains(", line "), "{table}: {e}");
    }
}

#[test]
fn the_appearance_table_reads_writes_back_and_names_bad_values() {
    use crate::model::appearance::{Colour, MeshScale, Part};
    let s = parse(&format!(
        "{GEOMETRY}[appearance.base]\nfile = \"parts/base.stl\"\nscale = \"mm\"\n\n[appearance.rod]\nfile = \"rod.glb\"\nscale = 0.5\nrotation_deg = [90, 0, 0]\noffset_m = [0, 0.01, 0]\ncolour = \"#c0c0c0\"\n"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let base = s
        .appearance
        .part(Part::Base)
        .unwrap_or_else(|| panic!("base"));
    assert_eq!(
        (base.file.as_str(), base.scale),
        ("parts/base.stl", MeshScale::Millimetre)
    );
    let rod = s
        .appearance
        .part(Part::Rod)
        .unwrap_or_else(|| panic!("rod"));
    assert_eq!(rod.scale, MeshScale::Factor(0.5));
    assert_eq!(rod.rotation_deg, [90.0, 0.0, 0.0]);
    assert_eq!(rod.colour, Some(Colour([0xc0, 0xc0, 0xc0])));
    assert!(s.appearance.part(Part::Platform).is_none());
    let back = parse(&s.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.appearance, s.appearance);
    assert!(
        !parse(GEOMETRY)
            .map(|s| s.to_toml())
            .unwrap_or_default()
            .contains("[appearance")
    );
    assert_eq!(
        error(&format!(
            "{GEOMETRY}[appearance.rod]\nfile = \"rod.stl\"\noffset_m = [0, 0, 1e9]\n"
        )),
        "s.toml, line 9, column 12: `appearance.rod.offset_m` each coordinate must be a finite number within ±100 m, got 1000000000"
    );
    let bad_scale = error(&format!(
        "{GEOMETRY}[appearance.rod]\nfile = \"rod.stl\"\nscale = \"feet\"\n"
    ));
    assert!(
        bad_scale.starts_with("s.toml, line 9, column 9: ")
            && bad_scale.contains("`feet` is not mm, cm, m, in"),
        "{bad_scale}"
    );
    assert!(
        error(&format!("{GEOMETRY}[appearance.wheel]\nfile = \"w.stl\"\n"))
            .contains("unknown field `wheel`"),
    );
}
