//! `stewart modes` and `stewart forces` with the `[dynamics]` table.

use super::{stderr, stdout, stewart, tempdir, write};

/// The seed's sizes on a paired layout, with a payload and heavy legs.
const PLATFORM: &str = r#"name = "heavy"
[geometry]
base_radius = 1.0
platform_radius = 0.6
home_height = 0.8
base_angles_deg = [350, 10, 110, 130, 230, 250]
platform_angles_deg = [320, 40, 80, 160, 200, 280]
[payload]
mass_kg = 60.0
com_m = [0.0, 0.0, 0.1]
inertia_kg_m2 = [3.0, 3.0, 5.0, 0.0, 0.1, 0.0]
"#;

const DYNAMICS: &str = "[dynamics]
actuator_stiffness = 2.0e7
actuator_friction = 50.0
cylinder_mass_kg = 2.0
cylinder_com_m = 0.2
cylinder_inertia_kg_m2 = 0.05
rod_mass_kg = 1.0
rod_com_m = 0.25
rod_inertia_kg_m2 = 0.02
";

fn scenario(dir: &std::path::Path, text: &str) -> String {
    write(dir, "s.toml", text)
}

fn json(o: &std::process::Output) -> serde_json::Value {
    serde_json::from_str(&stdout(o)).unwrap_or_else(|e| panic!("{e}: {}", stdout(o)))
}

#[test]
fn modes_report_six_ascending_frequencies_with_their_motion() {
    let dir = tempdir();
    let s = scenario(dir.path(), &format!("{PLATFORM}{DYNAMICS}"));
    let o = stewart(&["modes", "--scenario", &s]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(
        text.starts_with("Natural modes of `heavy` at x +0.0000 y +0.0000 z 0.8000 m"),
        "{text}"
    );
    assert_eq!(text.matches(" Hz ").count(), 6, "{text}");
    // The vertical mode is pure heave at home (the layout is symmetric about z).
    assert!(text.contains("z +1.00\n"), "{text}");

    let o = stewart(&["modes", "--scenario", &s, "--format", "json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = json(&o);
    let f: Vec<f64> = v["frequencies_hz"]
        .as_array()
        .map(|a| a.iter().filter_map(serde_json::Value::as_f64).collect())
        .unwrap_or_default();
    assert_eq!(f.len(), 6);
    assert!(f.windows(2).all(|w| w[0] <= w[1]) && f[0] > 0.0, "{f:?}");
    for key in ["stiffness", "mass_matrix", "modes"] {
        let rows = v[key].as_array().map_or(0, Vec::len);
        assert_eq!(rows, 6, "{key}");
        assert!(
            v[key]
                .as_array()
                .into_iter()
                .flatten()
                .all(|r| r.as_array().map_or(0, Vec::len) == 6)
        );
    }
    // Each mode a unit vector; the stiffness symmetric, its heave term positive.
    for m in v["modes"].as_array().into_iter().flatten() {
        let n: f64 = m
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(serde_json::Value::as_f64)
            .map(|c| c * c)
            .sum();
        assert!((n - 1.0).abs() < 1e-12, "{m}");
    }
    let k = |i: usize, j: usize| v["stiffness"][i][j].as_f64().unwrap_or(f64::NAN);
    assert!(
        (k(0, 4) - k(4, 0)).abs() <= 1e-9 * k(2, 2).abs(),
        "{}",
        v["stiffness"]
    );
    assert!(k(2, 2) > 0.0);
    // The mass matrix's translational block is the moving mass: payload plus the legs'
    // parts that move with the platform (more than the payload, less than everything).
    let m00 = v["mass_matrix"][0][0].as_f64().unwrap_or(f64::NAN);
    assert!(m00 > 60.0 && m00 < 60.0 + 6.0 * 3.0, "{m00}");
    assert_eq!(v["axes"][3], "rx");
    assert!(v.get("lowest_along_trajectory").is_none());

    let o = stewart(&[
        "modes",
        "--scenario",
        &s,
        "--format",
        "json",
        "--along-trajectory",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let lowest = &json(&o)["lowest_along_trajectory"];
    let lowest_f = lowest["frequency_hz"].as_f64().unwrap_or(f64::NAN);
    // The seed motion passes through home, so the lowest is at most home's.
    assert!(lowest_f <= f[0] * (1.0 + 1e-12), "{lowest_f} vs {}", f[0]);
    assert!(lowest["time_s"].as_f64().is_some() && lowest["pose"]["z"].as_f64().is_some());
}

#[test]
fn a_stiffer_actuator_raises_every_frequency_by_its_square_root() {
    let dir = tempdir();
    let s = scenario(dir.path(), &format!("{PLATFORM}{DYNAMICS}"));
    let at = |k: &str| {
        let set = format!("dynamics.actuator_stiffness={k}");
        let o = stewart(&[
            "modes",
            "--scenario",
            &s,
            "--set",
            &set,
            "--pose",
            "0.05,-0.02,0.85,3,-2,10",
            "--format",
            "json",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        json(&o)["frequencies_hz"]
            .as_array()
            .map(|a| {
                a.iter()
                    .filter_map(serde_json::Value::as_f64)
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default()
    };
    let (soft, stiff) = (at("1e6"), at("4e6"));
    for (a, b) in soft.iter().zip(&stiff) {
        assert!((b / a - 2.0).abs() < 1e-9, "{a} → {b}");
    }
}

#[test]
fn modes_refuse_what_they_cannot_use_with_one_located_error() {
    let dir = tempdir();
    let cases = [
        (
            PLATFORM.to_owned(),
            vec![],
            "actuator stiffness is not given",
        ),
        (
            PLATFORM.replace("inertia_kg_m2 = [3.0, 3.0, 5.0, 0.0, 0.1, 0.0]\n", ""),
            vec!["--set", "dynamics.actuator_stiffness=1e6"],
            "the mass matrix is not positive definite",
        ),
        (
            PLATFORM
                .split("[payload]")
                .next()
                .unwrap_or_default()
                .to_owned(),
            vec![],
            "has no [payload] table",
        ),
        (
            format!("{PLATFORM}{DYNAMICS}"),
            vec!["--set", "dynamics.actuator_stiffness=-5"],
            "`dynamics.actuator_stiffness` = -5 refused",
        ),
        (
            format!("{PLATFORM}{DYNAMICS}"),
            vec!["--pose", "0,0,0.8,0,0"],
            "is not six comma-separated numbers",
        ),
        (
            format!("{PLATFORM}{DYNAMICS}"),
            vec!["--pose", "0,0,NaN,0,0,0"],
            "NaN is not a finite number",
        ),
        (
            format!(
                "{PLATFORM}{}",
                DYNAMICS.replace("rod_mass_kg = 1.0", "rod_mass_kg = -1.0")
            ),
            vec![],
            "line 18, column 15: `dynamics.rod_mass_kg` must be a mass in kg from 0 to 1e6, got -1",
        ),
    ];
    for (text, extra, want) in cases {
        let s = scenario(dir.path(), &text);
        let mut args = vec!["modes", "--scenario", s.as_str()];
        args.extend(extra);
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
        let err = stderr(&o);
        assert!(err.contains(want), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(stdout(&o).is_empty());
    }
}

#[test]
fn forces_add_the_legs_and_friction_of_the_dynamics_table() {
    let dir = tempdir();
    let bare = scenario(dir.path(), PLATFORM);
    let before = stdout(&stewart(&["forces", "--scenario", &bare]));
    let heavy = write(dir.path(), "heavy.toml", &format!("{PLATFORM}{DYNAMICS}"));
    let o = stewart(&["forces", "--scenario", &heavy]);
    assert!(o.status.success(), "{}", stderr(&o));
    let after = stdout(&o);
    let row = |text: &str, k: usize| -> Vec<f64> {
        text.lines()
            .nth(k + 1)
            .unwrap_or_default()
            .split(',')
            .filter_map(|c| c.parse().ok())
            .collect()
    };
    // The legs' weight adds to every static force (the legs lean inwards and carry part
    // of their own weight at the platform joint).
    let (light, weighty) = (row(&before, 100), row(&after, 100));
    assert_eq!(light.len(), 13);
    let sum = |r: &[f64], cols: std::ops::Range<usize>| r[cols].iter().sum::<f64>();
    assert!(
        sum(&weighty, 1..7) > sum(&light, 1..7) + 1.0,
        "{light:?}\n{weighty:?}"
    );
    // Zero leg masses and friction: the forces are those of the payload alone, to the bit.
    let zero = write(
        dir.path(),
        "zero.toml",
        &format!("{PLATFORM}[dynamics]\nactuator_stiffness = 1e6\n"),
    );
    assert_eq!(stdout(&stewart(&["forces", "--scenario", &zero])), before);
}

#[test]
fn the_guides_modes_example_prints_what_the_guide_shows() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../examples/scenarios/heavy-legs.toml"
    );
    let readme = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../docs/guide/analysis.md"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let o = stewart(&["modes", "--scenario", file]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert_eq!(text.lines().count(), 7);
    for line in text.lines() {
        assert!(readme.contains(line), "the guide lacks: {line}");
    }
}

#[test]
fn plot_forces_draws_the_actuator_forces_for_a_paper() {
    let dir = tempdir();
    let s = scenario(dir.path(), &format!("{PLATFORM}{DYNAMICS}"));
    let svg = dir.path().join("forces.svg");
    let out = svg.display().to_string();
    let o = stewart(&[
        "plot",
        "--scenario",
        &s,
        "--forces",
        "--out",
        &out,
        "--lang",
        "en",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(text.matches("<polyline").count(), 6);
    assert!(text.contains("Leg forces — heavy"), "{text}");
    assert!(text.contains("Leg force F (N)") && text.contains(">F6</text>"));
    assert!(
        !text.contains("stroke-dasharray"),
        "no stroke limits on a force plot"
    );
    // Without a payload: one located error, nothing written.
    let bare = write(
        dir.path(),
        "bare.toml",
        PLATFORM.split("[payload]").next().unwrap_or_default(),
    );
    let none = dir.path().join("none.svg");
    let o = stewart(&[
        "plot",
        "--scenario",
        &bare,
        "--forces",
        "--out",
        &none.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("has no [payload] table"),
        "{}",
        stderr(&o)
    );
    assert!(!none.exists());
}

#[test]
fn forces_take_a_whole_inertia_tensor_on_the_command_line_too() {
    let dir = tempdir();
    // PLATFORM's payload has the tensor (3, 3, 5, 0, 0.1, 0): the same numbers given on
    // the command line to a platform without that tensor give the same forces, byte for byte.
    let from_file = stdout(&stewart(&[
        "forces",
        "--scenario",
        &scenario(dir.path(), PLATFORM),
    ]));
    let plain = write(
        dir.path(),
        "plain.toml",
        &PLATFORM.replace(
            "inertia_kg_m2 = [3.0, 3.0, 5.0, 0.0, 0.1, 0.0]",
            "inertia_kg_m2 = [1.0, 1.0, 1.0]",
        ),
    );
    let o = stewart(&["forces", "--scenario", &plain, "--inertia", "3,3,5,0,0.1,0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), from_file);
    for (bad, want) in [
        ("1,2,3,4", "is not three moments IXX,IYY,IZZ or six entries"),
        ("1,1,1,2e7,0,0", "Ixy"),
        ("-1,1,1", "Ixx"),
    ] {
        let o = stewart(&["forces", "--scenario", &plain, "--inertia", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(stderr(&o).contains(want), "{bad}: {}", stderr(&o));
    }
}

#[test]
fn modes_say_when_the_pose_is_singular() {
    let dir = tempdir();
    let s = scenario(dir.path(), &format!("{PLATFORM}{DYNAMICS}"));
    // The platform down in the base plane: the legs lie flat and hold nothing vertically.
    let o = stewart(&["modes", "--scenario", &s, "--pose", "0,0,0,0,0,0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("The pose is singular: 3 direction(s) have no stiffness there"),
        "{}",
        stdout(&o)
    );
    let home = stdout(&stewart(&["modes", "--scenario", &s]));
    assert!(!home.contains("singular"), "{home}");
}
