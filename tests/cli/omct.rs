//! `stewart cue --omct`: the Objective Motion Cueing Test from the command line — the JSON
//! report's shape, the washout's known numbers, a transport delay's lag, the Bode figure,
//! and bad input refused in one line each.

use crate::{stderr, stdout, stewart, tempdir};

/// The washout's test on the paired rig, tilt rate limit out of reach, as JSON.
fn report(extra: &[&str]) -> serde_json::Value {
    let args = [
        &[
            "cue",
            "--omct",
            "--preset",
            "paired",
            "--set",
            "cueing.tilt_rate_max_deg_s=360",
            "--format",
            "json",
        ][..],
        extra,
    ]
    .concat();
    let o = stewart(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap_or_else(|e| panic!("{e}: {}", stdout(&o)))
}

#[test]
fn the_json_report_has_ten_tests_at_twelve_frequencies() {
    let v = report(&[]);
    assert_eq!(v["algorithm"], "washout");
    let w: Vec<f64> = v["frequencies_rad_s"]
        .as_array()
        .expect("frequencies")
        .iter()
        .filter_map(serde_json::Value::as_f64)
        .collect();
    assert_eq!(w.len(), 12);
    for (k, f) in w.iter().enumerate() {
        assert!((f - 0.1 * 10f64.powf(k as f64 / 5.0)).abs() < 1e-12, "{f}");
    }
    let names: Vec<&str> = v["tests"]
        .as_array()
        .expect("tests")
        .iter()
        .filter_map(|t| t["name"].as_str())
        .collect();
    assert_eq!(
        names,
        [
            "surge",
            "sway",
            "heave",
            "roll",
            "pitch",
            "yaw",
            "surge-to-pitch",
            "sway-to-roll",
            "pitch-to-surge",
            "roll-to-sway"
        ]
    );
    for t in v["tests"].as_array().expect("tests") {
        for key in ["gain", "phase_deg", "distorted", "harmonic_distortion"] {
            assert_eq!(
                t[key].as_array().map(Vec::len),
                Some(12),
                "{}: {key}",
                t["name"]
            );
        }
        assert!(t["amplitude"].as_f64().is_some() && t["unit"].is_string());
    }
    // Surge at 0.1 rad/s: all tilt, the translation scale (0.5) less the low-pass's droop.
    let surge = &v["tests"][0];
    let g = surge["gain"][0].as_f64().expect("gain");
    assert!((g - 0.4998).abs() < 1e-3, "{g}");
    assert_eq!(v["tests"][6]["unit"], "°/s per m/s²");
    assert_eq!(v["tests"][8]["unit"], "m/s² per °/s");
}

#[test]
fn a_millisecond_of_delay_is_0_908_degrees_at_15_85_rad_s() {
    let at = ["--frequencies", "15.848931924611134"];
    let now = report(&at);
    let late = report(&[&at[..], &["--latency-ms", "1"]].concat());
    assert_eq!(late["latency_ms"], 1.0);
    for (a, b) in now["tests"]
        .as_array()
        .expect("tests")
        .iter()
        .zip(late["tests"].as_array().expect("tests"))
    {
        let lag =
            a["phase_deg"][0].as_f64().expect("phase") - b["phase_deg"][0].as_f64().expect("phase");
        assert!((lag - 0.908).abs() < 1e-3, "{}: {lag}", a["name"]);
    }
}

#[test]
fn the_bode_figure_draws_each_direct_test_for_both_algorithms() {
    let dir = tempdir();
    let svg = dir.path().join("omct.svg");
    let o = stewart(&[
        "cue",
        "--omct",
        "--preset",
        "paired",
        "--set",
        "cueing.algorithm=washout",
        "--compare",
        "--frequencies",
        "1,10",
        "--plot",
        &svg.display().to_string(),
        "--lang",
        "en",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{e}"));
    // Gain and phase of six tests, twice (the planner's dashed).
    assert_eq!(text.matches("<polyline").count(), 24, "{text}");
    assert_eq!(text.matches("stroke-dasharray").count(), 12 + 1);
    for words in [
        "surge",
        "yaw",
        "classical washout",
        "model-predictive",
        "frequency (rad/s)",
    ] {
        assert!(text.contains(words), "{words}");
    }
    // Both reports in the text, the washout's first.
    let out = stdout(&o);
    let (w, m) = (
        out.find("washout cueing").unwrap_or(usize::MAX),
        out.find("mpc cueing").unwrap_or(0),
    );
    assert!(w < m, "{out}");
}

#[test]
fn bad_input_is_one_located_error() {
    for (args, expected) in [
        (
            vec!["cue", "--omct", "--preset", "paired"],
            "preset `paired`: no [cueing] table",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.algorithm=washout",
                "--amplitude-scale",
                "0",
            ],
            "the amplitude scale",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.algorithm=washout",
                "--frequencies",
                "0.1,200",
            ],
            "the frequency",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.algorithm=washout",
                "--frequencies",
                "nan",
            ],
            "the frequency",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.algorithm=washout",
                "--frequencies",
                "2,1",
            ],
            "the test frequencies must rise: 1 rad/s follows 2 rad/s",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.algorithm=washout",
                "--latency-ms",
                "-1",
            ],
            "the latency",
        ),
        (
            vec![
                "cue",
                "--omct",
                "--preset",
                "paired",
                "--set",
                "cueing.translation_scale=-1",
            ],
            "cueing.translation_scale",
        ),
        (
            vec![
                "cue",
                "--preset",
                "paired",
                "--latency-ms",
                "1",
                "--input",
                "x.csv",
            ],
            "--omct",
        ),
        (
            vec![
                "cue", "--preset", "paired", "--input", "x.csv", "--format", "json",
            ],
            "--format json is the report of --compare or --omct",
        ),
    ] {
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(err.contains(expected), "{args:?}: {err}");
        assert!(stdout(&o).is_empty(), "{args:?}");
    }
}

#[test]
fn outputs_that_would_be_lost_are_refused_before_the_test_runs() {
    let dir = tempdir();
    let same = dir.path().join("same.svg");
    let missing = dir.path().join("no-such-folder").join("bode.svg");
    let base = [
        "cue",
        "--omct",
        "--preset",
        "paired",
        "--set",
        "cueing.algorithm=washout",
        "--frequencies",
        "0.01",
    ];
    for (extra, expected) in [
        (
            vec![
                "--out",
                same.to_str().expect("utf-8"),
                "--plot",
                same.to_str().expect("utf-8"),
            ],
            "--out (the report) and --plot (the figure) both name",
        ),
        (
            vec!["--plot", missing.to_str().expect("utf-8")],
            "does not exist",
        ),
        (
            vec!["--out", missing.to_str().expect("utf-8")],
            "does not exist",
        ),
    ] {
        let args = [&base[..], &extra[..]].concat();
        // Refused at once: the test at 0.01 rad/s alone takes seconds, so an error that
        // came after it would come with its output discarded.
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(expected), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains(".stewart-"), "{}", stderr(&o));
        assert!(!same.exists() && !missing.exists());
    }
}
