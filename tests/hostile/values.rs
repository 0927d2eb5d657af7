//! Absurd numbers: every declared setting with overflow values through `--set`, and
//! random values of every numeric option.

use proptest::prelude::*;
use stewart_kinematics::{Scenario, io::settings};

use crate::run::{PRESETS, names, path, run, tempdir};

/// Values that are finite but absurd, or not numbers at all.
const OVERFLOW: [&str; 8] = [
    "1e308",
    "-1e308",
    "1e20",
    "nan",
    "inf",
    "1e-320",
    "-1",
    "18446744073709551615",
];

/// A preset the setting applies to.
fn preset_for(setting: &settings::Setting) -> &'static str {
    PRESETS
        .iter()
        .copied()
        .find(|p| Scenario::preset(p).is_ok_and(|s| setting.applies(&s)))
        .unwrap_or("seed")
}

#[test]
fn every_setting_refuses_overflow_or_stays_finite() {
    // Through the real binary: each key of the catalogue, each overflow value.
    let dir = tempdir();
    let out = path(dir.path(), "out.csv");
    let mut refused = 0;
    for setting in settings::all() {
        let preset = preset_for(setting);
        for value in OVERFLOW {
            let assignment = format!("{}={value}", setting.key);
            let o = run(&[
                "solve",
                "--preset",
                preset,
                "--set",
                &assignment,
                "--out",
                &out,
            ]);
            o.assert_promises();
            if o.code == Some(2) {
                refused += 1;
                assert!(
                    o.stderr.contains(&setting.key),
                    "{}: the error names the key: {}",
                    o.shown(),
                    o.stderr
                );
                assert!(names(dir.path()).is_empty(), "{}", o.shown());
            } else {
                let csv = std::fs::read_to_string(&out).unwrap_or_default();
                crate::run::assert_no_nonfinite(&csv, &o.shown());
                let _ = std::fs::remove_file(&out);
            }
        }
    }
    // Everything but a few harmless cases (a phase of -1°, an offset of 1e-320 m) is refused.
    assert!(
        refused >= settings::all().len() * 5,
        "only {refused} refusals"
    );
}

/// The options that take numbers, each with values from a hostile pool.
fn option_case() -> impl Strategy<Value = Vec<String>> {
    let pick =
        |pool: &'static [&'static str]| (0..pool.len()).prop_map(move |i| pool[i].to_owned());
    const SIZES: &[&str] = &[
        "16x16",
        "0x0",
        "1x1",
        "4097x16",
        "-5x16",
        "16x",
        "x",
        "1e3x16",
        "99999999999x16",
    ];
    const FPS: &[&str] = &["-1", "0", "1e-9", "nan", "inf", "1001", "25", "1e308"];
    const FRAMES: &[&str] = &[
        "0..1",
        "1..0",
        "-1..2",
        "..",
        "0..99999999999",
        "99999999999..",
        "5..5",
    ];
    const TRIPLES: &[&str] = &[
        "0,0,0",
        "1e300,1e300,5",
        "nan,0,1",
        "1,2",
        "-1,-1,-1",
        "0,0,0.5",
        "inf,0,0",
        "1,2,3,4",
    ];
    const CAMERAS: &[&str] = &[
        "135,20,3",
        "1e300,1e300,5",
        "0,0,0",
        "0,0,-1",
        "0,0,1e9",
        "nan,1,1",
    ];
    const RESOLUTIONS: &[&str] = &["-1", "0", "1", "2", "64", "4097", "99999999999", "abc"];
    const MASSES: &[&str] = &["10", "0", "-3", "1e308", "nan", "inf", "1e-320"];
    prop_oneof![
        (pick(SIZES), pick(FPS), pick(FRAMES), pick(CAMERAS)).prop_map(
            |(size, fps, frames, camera)| {
                vec![
                    "render".into(),
                    "--preset".into(),
                    "paired".into(),
                    "--out".into(),
                    "OUT.gif".into(),
                    "--size".into(),
                    size,
                    "--fps".into(),
                    fps,
                    "--frames".into(),
                    frames,
                    "--camera".into(),
                    camera,
                ]
            }
        ),
        (pick(RESOLUTIONS), pick(TRIPLES), pick(TRIPLES)).prop_map(
            |(resolution, orientation, position)| {
                vec![
                    "workspace".into(),
                    "--preset".into(),
                    "seed".into(),
                    "--set".into(),
                    "geometry.leg_min=0.8".into(),
                    "--set".into(),
                    "geometry.leg_max=1.2".into(),
                    "--resolution".into(),
                    resolution,
                    "--orientation".into(),
                    orientation,
                    "--position".into(),
                    position,
                ]
            }
        ),
        (pick(MASSES), pick(TRIPLES), pick(TRIPLES)).prop_map(|(mass, com, inertia)| {
            vec![
                "forces".into(),
                "--preset".into(),
                "paired".into(),
                "--mass".into(),
                mass,
                "--com".into(),
                com,
                "--inertia".into(),
                inertia,
            ]
        }),
        (pick(MASSES), pick(TRIPLES), pick(TRIPLES)).prop_map(|(stiffness, xyz, rpy)| {
            vec![
                "modes".into(),
                "--preset".into(),
                "paired".into(),
                "--set".into(),
                format!("dynamics.actuator_stiffness={stiffness}"),
                "--pose".into(),
                format!("{xyz},{rpy}"),
                "--format".into(),
                "json".into(),
            ]
        }),
    ]
}

proptest! {
    #![proptest_config(crate::run::config())]

    /// Random values of the numeric options: refused in one line naming the option, or
    /// a finite result; an output file only on success.
    #[test]
    fn option_values_are_refused_clearly_or_give_finite_results(args in option_case()) {
        let dir = tempdir();
        let out = path(dir.path(), "out.gif");
        let args: Vec<String> = args
            .into_iter()
            .map(|a| if a == "OUT.gif" { out.clone() } else { a })
            .collect();
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(&refs);
        o.assert_promises();
        if o.code == Some(2) {
            prop_assert!(names(dir.path()).is_empty(), "{} left {:?}", o.shown(), names(dir.path()));
        }
    }
}
