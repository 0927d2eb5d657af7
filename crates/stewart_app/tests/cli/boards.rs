//! Hobby boards' formats: an output template's bytes are the solved legs scaled into the
//! template's numbers, and `device-sim` reads the same frames back over UDP and over a
//! serial line (a pseudo-terminal pair).

use stewart_link::template::{FieldType, Template, TemplateDecoder, TemplateFrame};

use crate::link::{device_sim, device_sim_on, frames_sent, free_port};
use crate::serial::PtyPair;
use crate::{parse_csv, stderr, stdout, stewart, tempdir};

/// Six 16-bit big-endian legs between two 0xFF bytes and a line end: a common board's
/// frame (AASD drives behind an Arduino).
const TEMPLATE: &str =
    "template:<255><255>{a1:u16be}{a2:u16be}{a3:u16be}{a4:u16be}{a5:u16be}{a6:u16be}<10><13>";

/// The paired preset's stroke, metres (`geometry.leg_min`, `geometry.leg_max`).
const STROKE: (f64, f64) = (0.55, 1.3);

/// The frames in `bytes`.
fn frames(bytes: &[u8]) -> Vec<TemplateFrame> {
    let template = TEMPLATE.trim_start_matches("template:");
    let mut d = TemplateDecoder::new(Template::parse(template).unwrap_or_else(|e| panic!("{e}")));
    d.push(bytes);
    let mut out = Vec::new();
    while let Some(f) = d.next_frame() {
        out.push(f);
    }
    assert_eq!(d.skipped(), 0, "bytes outside any frame");
    out
}

#[test]
fn a_templates_bytes_are_the_solved_legs_scaled_from_the_stroke() {
    let dir = tempdir();
    let out = dir.path().join("frames.bin");
    let rate = 200.0;
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--rate",
        "200",
        "--format",
        TEMPLATE,
        "--out",
        &out.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bytes = std::fs::read(&out).unwrap_or_else(|e| panic!("{e}"));
    // Exactly the frames, nothing between them: what the board reads.
    assert_eq!(bytes.len() % 16, 0);
    let sent = frames(&bytes);
    assert_eq!(sent.len() * 16, bytes.len());
    assert_eq!(sent.len(), frames_sent(&o));
    let solved = stewart(&["solve", "--preset", "paired"]);
    let (header, rows) = parse_csv(&stdout(&solved));
    let first = header.iter().position(|c| c == "L1").unwrap_or(7);
    let step = rows[1][0] - rows[0][0];
    let (mut compared, mut worst) = (0, 0.0f64);
    for (k, frame) in sent.iter().enumerate() {
        // Armed from the first tick: frame k at k/rate. After the ramp, until the stop,
        // on the solve table's own times.
        let t = k as f64 / rate;
        let row = (t / step).round() as usize;
        if t < 3.0 || row + 1 >= rows.len() || (t - rows[row][0]).abs() > 1e-9 {
            continue;
        }
        for i in 0..6 {
            let leg = rows[row][first + i];
            let exact = (leg - STROKE.0) / (STROKE.1 - STROKE.0) * 65535.0;
            let n = frame[i].unwrap_or_else(|| panic!("frame {k}: no leg {}", i + 1));
            worst = worst.max((f64::from(n) - exact).abs());
        }
        compared += 1;
    }
    assert!(compared > 100, "{compared}");
    // Within the rounding to the template's steps (and the solve table's 1e-9 m text).
    assert!(worst <= 0.5 + 1e-3, "{worst}");
    // The ends of the stroke are the ends of the numbers.
    let t = Template::parse("{a1:u16be}").unwrap_or_else(|e| panic!("{e}"));
    let mut end = Vec::new();
    t.encode(&[STROKE.1; 6], &[STROKE; 6], &mut end);
    assert_eq!(end, [0xff, 0xff]);
    assert_eq!(FieldType::U16Be.largest(), 65535);
}

/// The numbers `device-sim` recorded (unit 3: a template's), per frame.
fn recorded_numbers(sim: &std::process::Output, sent: usize) -> Vec<[f64; 6]> {
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    assert!(
        log.contains(&format!("device-sim: {sent} frames, 0 damaged, 0 lost")),
        "{log}"
    );
    assert_eq!(sim.status.code(), Some(0), "{log}");
    let (header, rows) = parse_csv(&String::from_utf8_lossy(&sim.stdout));
    assert_eq!(header[5], "unit");
    assert!(rows.iter().all(|r| r[5] == 3.0));
    rows.iter()
        .map(|r| std::array::from_fn(|k| r[6 + k]))
        .collect()
}

/// The numbers of a dry run of the same stream (the stream is the same tick by tick).
fn dry_run_numbers(extra: &[&str]) -> Vec<[f64; 6]> {
    let dir = tempdir();
    let out = dir.path().join("frames.bin");
    let path = out.display().to_string();
    let args = [
        &[
            "link",
            "--preset",
            "paired",
            "--dry-run",
            "--format",
            TEMPLATE,
        ][..],
        extra,
        &["--out", &path],
    ]
    .concat();
    let o = stewart(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bytes = std::fs::read(&out).unwrap_or_else(|e| panic!("{e}"));
    frames(&bytes)
        .iter()
        .map(|f| f.map(|n| f64::from(n.unwrap_or(0))))
        .collect()
}

#[test]
fn device_sim_reads_a_templates_frames_over_udp_as_they_were_sent() {
    let address = free_port();
    let sim = device_sim(&address, &["--format", TEMPLATE]);
    let timing = ["--duration", "1", "--rate", "100", "--ramp", "0.2"];
    let o = stewart(
        &[
            &["link", "--preset", "paired", "--transport", "udp"][..],
            &["--address", &address, "--format", TEMPLATE],
            &timing,
        ]
        .concat(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = frames_sent(&o);
    assert!(sent > 50, "{sent}");
    let sim = sim.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    let got = recorded_numbers(&sim, sent);
    assert_eq!(got, dry_run_numbers(&timing));
}

#[test]
fn device_sim_reads_a_templates_frames_over_a_serial_line() {
    let pair = PtyPair::new();
    let sim = device_sim_on(
        &["--serial", PtyPair::path(&pair.b), "--baud", "1000000"],
        &["--format", TEMPLATE],
    );
    let timing = ["--duration", "1", "--rate", "200", "--ramp", "0.2"];
    let o = stewart(
        &[
            &["link", "--preset", "paired", "--transport", "serial"][..],
            &["--port", PtyPair::path(&pair.a), "--baud", "1000000"],
            &["--format", TEMPLATE],
            &timing,
        ]
        .concat(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = frames_sent(&o);
    let sim = sim.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    let got = recorded_numbers(&sim, sent);
    assert_eq!(got, dry_run_numbers(&timing));
}

#[test]
fn a_bad_template_is_one_error_naming_its_column() {
    for (template, said) in [
        (
            "template:<255>{a7:u16be}",
            "template column 6: `a7` names no actuator",
        ),
        (
            "template:{a1:u17}",
            "template column 1: `u17` is not a type",
        ),
        (
            "template:<300>{a1:u8}",
            "template column 1: <300> is over 255",
        ),
        ("template:<255><10>", "no actuator"),
        ("template", "a template is written out"),
    ] {
        let o = stewart(&[
            "link",
            "--preset",
            "paired",
            "--dry-run",
            "--format",
            template,
        ]);
        assert_eq!(o.status.code(), Some(2), "{template}");
        assert!(stderr(&o).contains(said), "{template}: {}", stderr(&o));
        assert!(stdout(&o).is_empty(), "{template}: sent something");
    }
    // The same template in a scenario file is refused when the link is planned.
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--set",
        "link.template={a9:u8}",
        "--set",
        "link.format=template",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("link.template: template column 1: `a9` names no actuator"),
        "{}",
        stderr(&o)
    );
}
