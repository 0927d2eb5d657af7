//! Certified analysis from the command line: `stewart singularity --certify --free`
//! (ranges proven free of singularity — Fichter's torsion singularity found on a planar
//! layout and on a real product's, PI's H-811.I2, nothing ever proven for the seed's
//! singular one, servo rigs' ranges) and `stewart workspace --certified` (a volume bracket
//! holding the sampled volume, for legs and servos).

use crate::{stderr, stdout, stewart};

/// PI's H-811.I2 (the example scenario).
fn h811() -> String {
    format!(
        "{}/../examples/scenarios/pi-h811.toml",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn json(args: &[&str]) -> (Option<i32>, serde_json::Value) {
    let o = stewart(args);
    let v = serde_json::from_str(&stdout(&o))
        .unwrap_or_else(|e| panic!("{args:?}: {e}: {}", stderr(&o)));
    (o.status.code(), v)
}

#[test]
fn the_paired_layout_is_proven_free_up_to_its_torsion_singularity() {
    let (code, v) = json(&[
        "singularity",
        "--preset",
        "paired",
        "--certify",
        "--free",
        "yaw",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0));
    let [lo, hi] = [0, 1].map(|k| v["interval"][k].as_f64().expect("number"));
    assert!(
        (-90.0..-89.0).contains(&lo) && (89.0..90.0).contains(&hi),
        "{v}"
    );
    assert_eq!(v["unit"], "deg");
    let (code, v) = json(&[
        "singularity",
        "--preset",
        "paired",
        "--certify",
        "--free",
        "position",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0));
    assert!(v["radius_m"].as_f64().expect("radius") > 0.1, "{v}");
}

#[test]
fn a_real_hexapod_pis_h811_is_proven_free_through_its_travel_up_to_fichters_torsion() {
    // PI's own joint coordinates (examples/scenarios/pi-h811.toml says where from): pairs
    // on two circles, the platform's turned 60° against the base's, as Fichter's platform.
    let (code, v) = json(&[
        "singularity",
        "--scenario",
        &h811(),
        "--certify",
        "--free",
        "yaw",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{v}");
    let [lo, hi] = [0, 1].map(|k| v["interval"][k].as_f64().expect("number"));
    assert!(
        (-90.0..-89.0).contains(&lo) && (89.0..90.0).contains(&hi),
        "{v}"
    );
    // PI's published θz travel, ±21°, lies inside; and the whole motion (that sweep) is
    // proven pose by pose as part of the range.
    assert!(lo < -21.0 && hi > 21.0, "{v}");
}

#[test]
fn servo_rigs_are_proven_free_too() {
    for (preset, expected) in [("servo-desk", 56.018), ("crank-rig", 44.922)] {
        let (code, v) = json(&[
            "singularity",
            "--preset",
            preset,
            "--certify",
            "--free",
            "yaw",
            "--format",
            "json",
        ]);
        assert_eq!(code, Some(0), "{v}");
        let [lo, hi] = [0, 1].map(|k| v["interval"][k].as_f64().expect("number"));
        // Symmetric layouts: symmetric ranges, ending where the servo Jacobian's sampled
        // determinant first changes sign (the kinematics tests find it pose by pose).
        assert!((lo + hi).abs() < 1e-9, "{v}");
        assert!((hi - expected).abs() < 1e-3, "{preset}: {v}");
    }
}

#[test]
fn the_seed_is_never_certified_and_says_so_with_exit_status_1() {
    for free in ["yaw", "x", "position"] {
        let (code, v) = json(&[
            "singularity",
            "--preset",
            "seed",
            "--certify",
            "--free",
            free,
            "--format",
            "json",
        ]);
        assert_eq!(code, Some(1), "{free}");
        let key = if free == "position" {
            "radius_m"
        } else {
            "interval"
        };
        assert!(v[key].is_null(), "{free}: {v}");
    }
    let o = stewart(&[
        "singularity",
        "--preset",
        "seed",
        "--certify",
        "--free",
        "roll",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("Nothing proven free of singularity"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn a_spent_budget_servos_and_a_missing_coordinate_are_said() {
    let (code, v) = json(&[
        "singularity",
        "--preset",
        "paired",
        "--certify",
        "--free",
        "yaw",
        "--budget",
        "3",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0));
    assert_eq!(v["cut_short"], true, "{v}");
    let o = stewart(&["singularity", "--preset", "paired", "--certify"]);
    assert_eq!(o.status.code(), Some(2));
    let o = stewart(&[
        "singularity",
        "--preset",
        "paired",
        "--certify",
        "--free",
        "yaw",
        "--budget",
        "0",
    ]);
    assert_eq!(o.status.code(), Some(2));
    // Without --certify: the conditioning at the pose.
    let o = stewart(&[
        "singularity",
        "--preset",
        "paired",
        "--pose",
        "0,0,0.8,0,0,45",
    ]);
    assert!(
        o.status.success() && stdout(&o).contains("condition number"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn the_certified_workspace_brackets_the_sampled_volume() {
    let pi = h811();
    for (scenario, width) in [
        (["--preset", "paired"], "0.02"),
        (["--preset", "servo-desk"], "0.002"),
        (["--scenario", pi.as_str()], "0.0005"),
    ] {
        let (code, v) = json(
            &[
                &["workspace"][..],
                &scenario,
                &["--certified", "--boundary-width", width, "--format", "json"],
            ]
            .concat(),
        );
        assert_eq!(code, Some(0));
        let inner = v["inner_m3"].as_f64().expect("inner");
        let boundary = v["boundary_m3"].as_f64().expect("boundary");
        let o = stewart(&[&["workspace"][..], &scenario, &["--resolution", "200"]].concat());
        let text = stdout(&o);
        let volume: f64 = text
            .split("volume ")
            .nth(1)
            .and_then(|t| t.split(' ').next())
            .and_then(|t| t.parse().ok())
            .expect("the grid's volume");
        assert!(
            inner > 0.0 && inner <= volume && volume <= inner + boundary,
            "{scenario:?}: {inner} {boundary} {volume}"
        );
    }
    for refused in [
        vec![
            "workspace",
            "--preset",
            "seed",
            "--set",
            "geometry.leg_max=off",
            "--certified",
        ],
        vec![
            "workspace",
            "--preset",
            "paired",
            "--certified",
            "--boundary-width",
            "0",
        ],
        vec![
            "workspace",
            "--preset",
            "paired",
            "--certified",
            "--boundary-width",
            "1e-300",
        ],
        vec!["workspace", "--preset", "paired", "--format", "json"],
        vec![
            "workspace",
            "--preset",
            "paired",
            "--certified",
            "--plot",
            "x.txt",
        ],
        vec![
            "workspace",
            "--preset",
            "paired",
            "--certified",
            "--surface",
            "x.ply",
        ],
    ] {
        let o = stewart(&refused);
        assert_eq!(o.status.code(), Some(2), "{refused:?}: {}", stderr(&o));
    }
}

#[test]
fn the_certified_slices_are_drawn_under_the_sampled_boundary() {
    let dir = crate::tempdir();
    let svg = dir.path().join("certified.svg");
    let o = stewart(&[
        "workspace",
        "--preset",
        "servo-desk",
        "--certified",
        "--boundary-width",
        "0.002",
        "--plot",
        &svg.display().to_string(),
        "--lang",
        "en",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("Wrote the slices to"), "{}", stdout(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{e}"));
    let group = text
        .split(r#"<g class="certified""#)
        .nth(1)
        .and_then(|g| g.split("</g>").next())
        .expect("the certified boxes");
    // Both classes drawn, in the figure's key's colours, and the sampled boundary over them.
    let green = group.matches(r##"fill="#3CA05A""##).count();
    let amber = group.matches(r##"fill="#F2A900""##).count();
    assert!(green > 10 && amber > 10, "{green} {amber}");
    assert_eq!(text.matches(r#"<g class="certified""#).count(), 2);
    assert_eq!(text.matches(r#"class="boundary""#).count(), 2);
    for words in [
        "Certified workspace of servo-desk",
        "proven reachable",
        "undecided",
        "sampled boundary",
    ] {
        assert!(text.contains(words), "{words}");
    }
}
