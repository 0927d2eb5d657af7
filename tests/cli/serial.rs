//! `stewart link` over a serial line: a pseudo-terminal pair made by `socat` stands in for
//! the cable; `stewart device-sim --serial` is the controller at the other end.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::link::device_sim_on;
use crate::watched::Watched;
use crate::{parse_csv, stderr, stewart};

/// Two connected pseudo-terminals, `a` and `b`; the pair goes when this is dropped.
pub(crate) struct PtyPair {
    socat: Child,
    pub(crate) a: PathBuf,
    pub(crate) b: PathBuf,
    _dir: tempfile::TempDir,
}

impl PtyPair {
    pub(crate) fn new() -> Self {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        let end = |p: &Path| format!("pty,raw,echo=0,link={}", p.display());
        let socat = Command::new("socat")
            .args([end(&a), end(&b)])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("socat (scripts/setup.sh installs it): {e}"));
        let started = Instant::now();
        while !(a.exists() && b.exists()) {
            assert!(
                started.elapsed() < Duration::from_secs(10),
                "socat made no pty pair"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        Self {
            socat,
            a,
            b,
            _dir: dir,
        }
    }

    pub(crate) fn path(p: &Path) -> &str {
        p.to_str().unwrap_or_else(|| panic!("{p:?}"))
    }

    /// Unplug the cable.
    fn cut(&mut self) {
        let _ = self.socat.kill();
        let _ = self.socat.wait();
    }
}

impl Drop for PtyPair {
    fn drop(&mut self) {
        self.cut();
    }
}

/// `stewart link` of `preset` to serial `port` for `duration` s at `rate` Hz.
fn serial_link(preset: &str, port: &str, duration: &str, rate: &str) -> std::process::Output {
    stewart(&[
        "link",
        "--preset",
        preset,
        "--transport",
        "serial",
        "--port",
        port,
        "--baud",
        "1000000",
        "--duration",
        duration,
        "--rate",
        rate,
        "--ramp",
        "0.2",
    ])
}

#[test]
fn a_stream_over_a_serial_line_arrives_whole_in_order_and_ends_home_disarmed() {
    let pair = PtyPair::new();
    let sim = device_sim_on(
        &["--serial", PtyPair::path(&pair.b), "--baud", "1000000"],
        &["--telemetry"],
    );
    let o = serial_link("servo-desk", PtyPair::path(&pair.a), "1", "500");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = crate::link::frames_sent(&o);
    assert!(sent > 500, "{}", stderr(&o));
    // The device answered every frame with telemetry; the last came back disarmed, at home.
    let told = stderr(&o);
    let line = told
        .lines()
        .find(|l| l.contains("telemetry frames from the controller"))
        .unwrap_or_else(|| panic!("no telemetry: {told}"));
    let count: usize = line
        .split_whitespace()
        .nth(1)
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    assert!(count + 5 >= sent && count <= sent, "{line}");
    let sim = sim.finish();
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    assert_eq!(sim.status.code(), Some(0), "{log}");
    assert!(
        log.contains(&format!("device-sim: {sent} frames, 0 damaged, 0 lost")),
        "{log}"
    );
    let (_, rows) = parse_csv(&String::from_utf8_lossy(&sim.stdout));
    assert_eq!(rows.len(), sent);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[1] as usize, k, "sequence");
        // Unit 1: hundredths of a degree; every angle inside the servo-desk's ±70°.
        assert_eq!(row[5], 1.0);
        assert!(row[6..12].iter().all(|v| v.abs() <= 7000.0), "{row:?}");
    }
    // Armed from the first frame, disarmed on the last.
    assert_eq!((rows[0][2], rows[sent - 1][2]), (1.0, 0.0));
}

#[test]
fn a_cable_pulled_mid_stream_disarms_with_a_clear_error() {
    let mut pair = PtyPair::new();
    let port = PtyPair::path(&pair.a).to_owned();
    let link = Watched::spawn(
        Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["link", "--preset", "paired", "--transport", "serial"])
            .args(["--port", &port, "--baud", "1000000", "--duration", "10"])
            .args(["--rate", "100", "--ramp", "0.2"]),
    );
    // Mid-stream: armed and following the motion.
    link.wait_for("link: ARMED");
    pair.cut();
    let o = link.finish();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("error: the link stopped: writing to "),
        "{err}"
    );
    assert!(err.trim_end().ends_with("disarmed"), "{err}");
}

#[test]
fn a_rate_the_line_cannot_carry_is_refused_before_anything_is_sent() {
    let pair = PtyPair::new();
    let o = stewart(&[
        "link",
        "--transport",
        "serial",
        "--port",
        PtyPair::path(&pair.a),
        "--baud",
        "9600",
        "--rate",
        "100",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("100 Hz does not fit") && stderr(&o).contains("at most 28 Hz"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn telemetry_over_a_serial_line_follows_the_actuator_model() {
    use crate::link::{measured_follow_the_model, model_response_of};
    let pair = PtyPair::new();
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let record = dir.path().join("measured.csv");
    let sim = device_sim_on(
        &["--serial", PtyPair::path(&pair.b), "--baud", "1000000"],
        &["--telemetry", "--lag-s", "0.08", "--speed-max", "50000"],
    );
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--transport",
        "serial",
        "--port",
        PtyPair::path(&pair.a),
        "--baud",
        "1000000",
        "--duration",
        "2",
        "--rate",
        "100",
        "--ramp",
        "0.3",
        "--record",
        record.to_str().unwrap_or_default(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sim = sim.finish();
    let sim_csv = String::from_utf8_lossy(&sim.stdout).into_owned();
    let response = model_response_of(&sim_csv, 0.08, 50_000.0, 0.0);
    let recorded = std::fs::read_to_string(&record).unwrap_or_else(|e| panic!("{e}"));
    measured_follow_the_model(&recorded, &response);
}
