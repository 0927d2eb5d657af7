//! `stewart link`: a dry run records frames at the deadlines with the trajectory's servo
//! angles once armed; a UDP stream on loopback arrives whole, in order, CRC-checked, and
//! ends home and disarmed; bad options are one clear error.

use std::net::UdpSocket;
use std::time::Duration;

use stewart_link::{Frame, FrameDecoder, ValueUnit};

use crate::watched::Watched;
use crate::{parse_csv, stderr, stdout, stewart};

/// `stewart link` streaming `preset` over UDP to `address` for `duration` seconds at
/// `rate` Hz with an arming ramp of `ramp` seconds.
fn udp_link(
    preset: &str,
    address: &str,
    duration: &str,
    rate: &str,
    ramp: &str,
) -> std::process::Output {
    udp_link_with(preset, address, duration, rate, ramp, &[])
}

/// [`udp_link`] with `extra` options after the others.
fn udp_link_with(
    preset: &str,
    address: &str,
    duration: &str,
    rate: &str,
    ramp: &str,
    extra: &[&str],
) -> std::process::Output {
    let args = [
        "link",
        "--preset",
        preset,
        "--transport",
        "udp",
        "--address",
        address,
        "--duration",
        duration,
        "--rate",
        rate,
        "--ramp",
        ramp,
    ];
    stewart(&[&args[..], extra].concat())
}

/// The frames of a dry-run record: (time, frame) per line.
fn recorded(text: &str) -> Vec<(f64, Frame)> {
    text.lines()
        .map(|line| {
            let (t, hex) = line.split_once('\t').unwrap_or_else(|| panic!("{line}"));
            let mut d = FrameDecoder::new();
            let frame = hex
                .split_whitespace()
                .filter_map(|h| d.push(u8::from_str_radix(h, 16).unwrap_or_default()))
                .next()
                .and_then(Result::ok)
                .unwrap_or_else(|| panic!("not a frame: {line}"));
            (t.parse().unwrap_or(f64::NAN), frame)
        })
        .collect()
}

#[test]
fn a_dry_run_records_the_servo_angles_once_armed() {
    let o = stewart(&[
        "link",
        "--preset",
        "servo-desk",
        "--dry-run",
        // The stream's own clock: a loaded machine's late first tick cannot move the ramp.
        "--instant",
        "--duration",
        "1",
        "--rate",
        "50",
        "--ramp",
        "0.2",
        "--set",
        "limits.servo_accel_max_deg_s2=off",
        "--set",
        "limits.servo_speed_max_deg_s=off",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).starts_with("link: "), "{}", stderr(&o));
    let frames = recorded(&stdout(&o));
    // The servo angles of the same times, from `solve` on a table of the trajectory's poses.
    let solved = stewart(&["solve", "--preset", "servo-desk"]);
    let (header, rows) = parse_csv(&stdout(&solved));
    let theta = header.iter().position(|c| c == "theta1").unwrap_or(7);
    // Each frame carries its deadline's time on the 20 ms grid, in order. A machine that
    // stalls (a loaded CI runner) skips the deadlines it slept through rather than sending
    // late set-points, so a slot may be missing, never repeated or out of place.
    let mut previous = -1.0;
    for (k, (t, f)) in frames.iter().enumerate() {
        assert_eq!(f.sequence as usize, k);
        assert_eq!(f.unit, ValueUnit::Centidegree);
        let slot = t * 50.0;
        assert!(
            (slot - slot.round()).abs() < 1e-6,
            "{t} is off the 20 ms grid"
        );
        assert!(*t > previous, "{t} after {previous}");
        previous = *t;
        // After the ramp (0.2 s: with no rate limit, none lengthens it) and before the stop,
        // the values are the trajectory's angles (the solve table has a sample every 10 ms:
        // t = 0.02 k lands on one).
        if *t >= 0.2 && *t < 1.0 {
            let row = &rows[(t * 100.0).round() as usize];
            assert!((row[0] - t).abs() < 1e-9);
            for i in 0..6 {
                let want = (row[theta + i] * 100.0).round() as i32;
                assert_eq!(f.values[i], want, "t = {t}, servo {}", i + 1);
            }
            assert!(f.flags.armed);
        }
    }
    let compared = frames
        .iter()
        .filter(|(t, _)| (0.2..1.0).contains(t))
        .count();
    assert!(
        compared >= 30,
        "only {compared} of 40 frames between the ramp and the stop"
    );
    // It ends disarmed at home.
    let last = frames
        .last()
        .map(|f| f.1)
        .unwrap_or_else(|| panic!("no frames"));
    assert!(!last.flags.armed);
    assert!(frames.iter().any(|(_, f)| f.flags.estop));
}

#[test]
fn a_udp_stream_arrives_in_order_and_ends_disarmed() {
    let peer = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    // The stream is over when nothing comes for a second.
    peer.set_read_timeout(Some(Duration::from_secs(1)))
        .unwrap_or_else(|e| panic!("{e}"));
    let address = peer
        .local_addr()
        .unwrap_or_else(|e| panic!("{e}"))
        .to_string();
    let receiver = std::thread::spawn(move || {
        let mut frames = Vec::new();
        let mut buf = [0u8; 64];
        while let Ok(n) = peer.recv(&mut buf) {
            let mut d = FrameDecoder::new();
            let f = buf[..n].iter().filter_map(|&b| d.push(b)).next();
            frames.push(
                f.and_then(Result::ok)
                    .unwrap_or_else(|| panic!("bad datagram")),
            );
        }
        frames
    });
    let o = udp_link("paired", &address, "0.5", "200", "0.1");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let frames = receiver
        .join()
        .unwrap_or_else(|_| panic!("receiver failed"));
    assert!(frames.len() > 100, "{}", frames.len());
    for (k, f) in frames.iter().enumerate() {
        assert_eq!(f.sequence as usize, k, "lost or reordered");
        assert_eq!(f.unit, ValueUnit::Micrometre);
        // Every leg length sent is inside the paired preset's stroke (0.55 … 1.30 m).
        assert!(
            f.values.iter().all(|&v| (550_000..=1_300_000).contains(&v)),
            "{f:?}"
        );
    }
    assert!(!frames.last().is_some_and(|f| f.flags.armed));
    assert!(frames.iter().any(|f| f.flags.estop));
}

#[test]
fn a_peer_that_goes_away_disarms_the_link_with_a_clear_error() {
    // A port nobody listens on: loopback answers with "connection refused", which the
    // sender sees on a following send. The port is held on 127.0.0.1 while the link sends
    // to it on 127.0.0.2, so no other test running beside this one can be given it (a
    // wildcard bind of it is refused while it is held).
    let held = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    let port = held.local_addr().unwrap_or_else(|e| panic!("{e}")).port();
    let address = format!("127.0.0.2:{port}");
    let o = udp_link("paired", &address, "2", "100", "2");
    drop(held);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("error: the link stopped: sending to"), "{err}");
    assert!(err.trim_end().ends_with("disarmed"), "{err}");
}

#[test]
fn bad_link_options_are_one_clear_error_and_nothing_is_sent() {
    for (args, expected) in [
        (
            vec!["link", "--transport", "serial"],
            "the serial transport needs a port",
        ),
        (
            vec![
                "link",
                "--transport",
                "serial",
                "--port",
                "/dev/no-such-port",
            ],
            "cannot open the serial port /dev/no-such-port",
        ),
        (
            vec!["link", "--transport", "serial", "--port", "/dev/null"],
            "cannot open the serial port /dev/null",
        ),
        (
            vec!["link", "--transport", "udp", "--address", "127.0.0.1:0"],
            "port 0 names no peer",
        ),
        (
            vec!["link", "--transport", "tcp"],
            "`tcp` is not one of serial, udp, file",
        ),
        (
            vec!["link", "--set", "link.actuator.2=1", "--dry-run"],
            "channels 1 and 2 both carry actuator 1",
        ),
        (
            vec!["link", "--set", "link.output=pulse", "--dry-run"],
            "`link.output = pulse` drives hobby servos",
        ),
        (
            vec!["link", "--transport", "udp"],
            "the UDP transport needs an address",
        ),
        (
            vec!["link", "--transport", "udp", "--address", "nowhere"],
            "`nowhere` is not an address",
        ),
        (
            vec!["link", "--dry-run", "--rate", "0"],
            "the rate must be between 10 and 1000 Hz",
        ),
        (
            vec!["link", "--dry-run", "--set", "link.rate_hz=5"],
            "`link.rate_hz` = 5 refused: must be between 10 and 1000 Hz",
        ),
        (
            vec!["link", "--dry-run", "--rate", "1001"],
            "the rate must be between 10 and 1000 Hz",
        ),
        (
            vec!["link", "--dry-run", "--transport", "udp"],
            "--dry-run sends nothing",
        ),
        (
            vec![
                "link",
                "--instant",
                "--transport",
                "udp",
                "--address",
                "127.0.0.1:9",
            ],
            "--instant is for a dry run: a udp link keeps real time",
        ),
        (
            vec!["link", "--instant", "--loop"],
            "--instant with --loop needs --duration",
        ),
    ] {
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = stderr(&o);
        assert!(err.contains(expected), "{args:?}: {err}");
        // One line, and the system's words said once (not again as a chained cause).
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        let parts: Vec<&str> = err.trim_end().rsplitn(3, ": ").collect();
        assert!(parts.len() < 2 || parts[0] != parts[1], "{err}");
        assert!(stdout(&o).is_empty(), "{args:?} sent something");
    }
}

/// How many frames a `link` run says it sent ("link: N frames to …"), 0 when it says none.
pub fn frames_sent(o: &std::process::Output) -> usize {
    // The summary line `link: N frames to …` (a note on the arming may come before it).
    stderr(o)
        .lines()
        .find(|l| l.starts_with("link: ") && l.contains(" frames to "))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|n| n.parse().ok())
        .unwrap_or(0)
}

/// The deadlines a live stream skipped (`; N deadlines skipped` in its summary; none
/// when it does not say).
pub fn deadlines_skipped(o: &std::process::Output) -> usize {
    stderr(o)
        .lines()
        .find(|l| l.starts_with("link: ") && l.contains(" frames to "))
        .and_then(|l| l.split("; ").find(|p| p.contains(" deadlines skipped")))
        .and_then(|p| p.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0)
}

/// A free loopback port (bound and released; the device simulator binds it next).
pub fn free_port() -> String {
    let s = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    s.local_addr().unwrap_or_else(|e| panic!("{e}")).to_string()
}

/// `stewart device-sim` on UDP `address` in the background, with `extra` options, once it
/// listens.
pub fn device_sim(address: &str, extra: &[&str]) -> Watched {
    device_sim_on(&["--udp", address], extra)
}

/// `stewart device-sim` reading `source` (`--udp ADDR` or `--serial PORT`) in the
/// background, with `extra` options, once it listens.
pub fn device_sim_on(source: &[&str], extra: &[&str]) -> Watched {
    let sim = Watched::spawn(
        std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .arg("device-sim")
            .args(source)
            .args(["--idle", "1", "--duration", "30"])
            .args(extra),
    );
    sim.wait_for("device-sim: listening on");
    sim
}

#[test]
fn the_device_simulator_records_a_whole_stream_and_flags_values_over_its_limits() {
    let address = free_port();
    let sim = device_sim(&address, &["--telemetry"]);
    let o = udp_link("servo-desk", &address, "0.5", "200", "0.1");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // The device's telemetry came back over the same socket.
    assert!(
        stderr(&o).contains("telemetry frames from the controller; the last at"),
        "{}",
        stderr(&o)
    );
    let sent = frames_sent(&o);
    let sim = sim.finish();
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    assert_eq!(sim.status.code(), Some(0), "{log}");
    assert!(
        log.contains(&format!(
            "device-sim: {sent} frames, 0 damaged, 0 lost, 0 out of order, 0 values outside"
        )),
        "{log}"
    );
    let (header, rows) = parse_csv(&String::from_utf8_lossy(&sim.stdout));
    assert_eq!(
        header[..6],
        ["t_s", "seq", "armed", "estop", "home", "unit"].map(String::from)
    );
    assert_eq!(rows.len(), sent);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[1] as usize, k);
    }
    // Limits on the device: ±30° (3000 in 0.01°) is passed by the servo-desk's motion.
    let address = free_port();
    let sim = device_sim(&address, &["--min", "-3000", "--max", "3000"]);
    let o = udp_link("servo-desk", &address, "3", "100", "0.1");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sim = sim.finish();
    assert_eq!(sim.status.code(), Some(1));
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    assert!(!log.contains(" 0 values outside"), "{log}");
}

#[test]
fn the_device_simulator_reads_the_links_text_form() {
    let address = free_port();
    let sim = device_sim(
        &address,
        &["--format", "text", "--text-unit", "centidegree"],
    );
    let o = udp_link_with(
        "servo-desk",
        &address,
        "0.5",
        "100",
        "0.1",
        &["--format", "text"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = frames_sent(&o);
    let sim = sim.finish();
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    // Before: the binary decoder called every line damaged.
    assert!(
        log.contains(&format!(
            "device-sim: {sent} frames, 0 damaged, 0 lost, 0 out of order"
        )),
        "{log}"
    );
    assert_eq!(sim.status.code(), Some(0), "{log}");
    let (_, rows) = parse_csv(&String::from_utf8_lossy(&sim.stdout));
    assert_eq!(rows.len(), sent);
    assert!(sent > 40, "{sent}");
    // Every line armed (S, H) or a stop (E), in the unit given; the end of the run is a stop
    // and then the way home, back where it began.
    assert!(
        rows.iter()
            .all(|r| (r[2] == 1.0) != (r[3] == 1.0) && r[5] == 1.0)
    );
    assert!(
        rows.iter()
            .any(|r| r[3] == 1.0 && r[6..].iter().all(|&v| v == 0.0))
    );
    let (first, last) = (&rows[0], &rows[sent - 1]);
    assert_eq!(last[4], 1.0, "the last line is the way home: {last:?}");
    assert_eq!(first[6..], last[6..]);
    // The binary reader sees the same stream as damaged, not as frames.
    let address = free_port();
    let sim = device_sim(&address, &[]);
    let o = udp_link_with(
        "servo-desk",
        &address,
        "0.2",
        "100",
        "0.1",
        &["--format", "text"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sim = sim.finish();
    assert_eq!(sim.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&sim.stderr).contains("device-sim: 0 frames"));
}

#[test]
fn a_dry_run_into_a_file_never_lands_on_an_input_and_leaves_nothing_half_written() {
    let dir = crate::tempdir();
    let scenario = dir.path().join("s.toml");
    let preset = stewart_kinematics::io::scenario::presets::text("servo-desk")
        .unwrap_or_else(|| panic!("no preset servo-desk"));
    std::fs::write(&scenario, preset).unwrap_or_else(|e| panic!("{e}"));
    let s = scenario.display().to_string();
    let o = stewart(&[
        "link",
        "--scenario",
        &s,
        "--dry-run",
        "--duration",
        "0.1",
        "--out",
        &s,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("it is the scenario file this command reads"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        std::fs::read(&scenario).ok(),
        Some(preset.as_bytes().to_vec())
    );
    let record = dir.path().join("record.txt");
    let r = record.display().to_string();
    let o = stewart(&[
        "link",
        "--scenario",
        &s,
        "--dry-run",
        "--duration",
        "0.1",
        "--out",
        &r,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!recorded(&std::fs::read_to_string(&record).unwrap_or_default()).is_empty());
    // Only the two files: no staged leftovers.
    assert_eq!(
        std::fs::read_dir(dir.path())
            .map(|d| d.count())
            .unwrap_or(0),
        2
    );
    // A full disk stops the stream with one error.
    let o = stewart(&[
        "link",
        "--dry-run",
        "--duration",
        "0.1",
        "--out",
        "/dev/full",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("No space left"), "{}", stderr(&o));
}

#[test]
fn end_to_end_the_device_gets_a_smooth_ramp_never_an_unsafe_value_and_ctrl_c_brings_it_home() {
    // The servo-desk's motion turns its servos beyond ±20°: with the range narrowed to ±20°
    // the link must hold instead of sending those values.
    let narrow = [
        "--set",
        "actuator.servo_min_deg=-20",
        "--set",
        "actuator.servo_max_deg=20",
    ];
    let solved = stewart(&[&["solve", "--preset", "servo-desk"][..], &narrow[..]].concat());
    assert_eq!(solved.status.code(), Some(0), "{}", stderr(&solved));
    let (header, rows) = parse_csv(&stdout(&solved));
    let first = header
        .iter()
        .position(|h| h == "theta1")
        .unwrap_or_else(|| panic!("{header:?}"));
    let widest = rows
        .iter()
        .flat_map(|r| r[first..first + 6].iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    assert!(
        widest > 25.0,
        "the motion stays within ±{widest}°: nothing to refuse"
    );

    let address = free_port();
    let sim = device_sim(&address, &["--min", "-2000", "--max", "2000"]);
    let link = Watched::spawn(
        std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["link", "--preset", "servo-desk", "--transport", "udp"])
            .args(["--address", &address])
            .args(["--rate", "100", "--ramp", "0.5", "--loop"])
            .args(narrow),
    );
    // Held on the first servo for most of a second, then on the next: stopped there.
    link.wait_for("actuator 3 would go to");
    interrupt(link.id());
    let o = link.finish();
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("stopped by the user (e-stop)"),
        "{}",
        stderr(&o)
    );

    let sim = sim.finish();
    let log = String::from_utf8_lossy(&sim.stderr).into_owned();
    // Nothing outside ±20° arrived, none lost or damaged.
    assert_eq!(sim.status.code(), Some(0), "{log}");
    let (_, rows) = parse_csv(&String::from_utf8_lossy(&sim.stdout));
    let values = |r: &Vec<f64>| r[6..12].to_vec();
    // The ramp starts at home and no step is faster than 300°/s (3° a frame at 100 Hz).
    let home = values(&rows[0]);
    for pair in rows.windows(2) {
        for k in 0..6 {
            assert!((pair[1][6 + k] - pair[0][6 + k]).abs() <= 301.0, "{pair:?}");
        }
    }
    // Held: while the motion was beyond the range, the same set-points went out again and
    // again (armed, before the stop) instead of values outside it.
    let held = rows.windows(10).any(|w| {
        w.iter()
            .all(|r| r[2] == 1.0 && r[3] == 0.0 && r[6..12] == w[0][6..12])
    });
    assert!(held, "nothing was held");
    // The stop: one e-stop frame, then armed frames with the home flag, then disarmed at home.
    let stop = rows
        .iter()
        .position(|r| r[3] == 1.0)
        .unwrap_or_else(|| panic!("no e-stop frame"));
    assert_eq!(rows.iter().filter(|r| r[3] == 1.0).count(), 1);
    let last = rows.len() - 1;
    assert!(rows[stop..last].iter().all(|r| r[2] == 1.0 && r[4] == 1.0));
    assert_eq!(rows[last][2], 0.0);
    assert_eq!(values(&rows[last]), home);
}

/// Send SIGINT to the process `pid`.
fn interrupt(pid: u32) {
    let sent = std::process::Command::new("kill")
        .args(["-INT", &pid.to_string()])
        .status()
        .map(|s| s.success());
    assert_eq!(sent.ok(), Some(true));
}

/// `link` on the paired preset at 200 Hz, looping, recording into `record`, once it has
/// followed the motion for 4 s: its legs are centimetres from home, and home is a tenth of
/// the 0.5 m/s limit away, so the way home takes seconds.
fn paired_dry_run_four_seconds_in(record: &std::path::Path) -> Watched {
    let link = Watched::spawn(
        std::process::Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["link", "--preset", "paired", "--dry-run", "--loop"])
            .args(["--rate", "200", "--out"])
            .arg(record),
    );
    // The log's lines: `link: ARMED  4.01 s  …`.
    link.wait_for_line("ARMED, 4 s in", |line| {
        let mut words = line.split_whitespace();
        words.nth(1) == Some("ARMED") && words.next().and_then(|t| t.parse().ok()) >= Some(4.0)
    });
    link
}

#[test]
fn a_second_ctrl_c_on_the_way_home_is_an_emergency_stop() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let record = dir.path().join("frames.txt");
    let link = paired_dry_run_four_seconds_in(&record);
    interrupt(link.id());
    link.wait_for("STOPPING");
    interrupt(link.id());
    let o = link.finish();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    let line = err
        .lines()
        .find(|l| l.starts_with("link: emergency stop"))
        .unwrap_or_else(|| panic!("no emergency line: {err}"));
    assert!(
        line.contains("left at x = ") && line.contains(", L6 = "),
        "{line}"
    );
    let frames = recorded(&std::fs::read_to_string(&record).unwrap_or_default());
    let stops: Vec<usize> = (0..frames.len())
        .filter(|&k| frames[k].1.flags.estop)
        .collect();
    assert_eq!(stops.len(), 2, "{stops:?}");
    // Between the stops the way home (armed, home flag); from the second, disarmed frames
    // with the values where the platform was, for 250 ms, and nothing after.
    assert!(
        frames[stops[0]..stops[1]]
            .iter()
            .all(|(_, f)| f.flags.armed && f.flags.home)
    );
    let tail = &frames[stops[1]..];
    assert!(
        tail.iter()
            .all(|(_, f)| !f.flags.armed && f.values == tail[0].1.values)
    );
    let lasted = tail[tail.len() - 1].0 - tail[0].0;
    assert!((0.25 - 1e-9..0.3).contains(&lasted), "{lasted}");
    // The line names the values of the last frame (µm in the frame, metres in the line).
    let l1 = f64::from(tail[0].1.values[0]) * 1e-6;
    assert!(line.contains(&format!("L1 = {l1:.6} m")), "{line} vs {l1}");
    // Not home: the way home was cut short.
    let home_frame = frames[0].1.values;
    assert_ne!(tail[0].1.values, home_frame);
}

#[test]
fn two_stops_delivered_at_once_are_an_emergency_stop() {
    // `timeout`, a process group or a supervisor can deliver two signals in one breath:
    // SIGINT then SIGTERM (two of one kind may merge in the kernel), both before the
    // link looks. Each stop counts: the second is the emergency stop.
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let record = dir.path().join("frames.txt");
    let link = paired_dry_run_four_seconds_in(&record);
    let pid = link.id().to_string();
    let sent = std::process::Command::new("sh")
        .args(["-c", "kill -INT $0 && kill -TERM $0", &pid])
        .status()
        .map(|s| s.success());
    assert_eq!(sent.ok(), Some(true));
    let o = link.finish();
    let err = stderr(&o);
    assert!(
        err.lines().any(|l| l.starts_with("link: emergency stop")),
        "{err}"
    );
    let frames = recorded(&std::fs::read_to_string(&record).unwrap_or_default());
    let last = frames.last().unwrap_or_else(|| panic!("no frames"));
    assert!(!last.1.flags.armed);
    assert_ne!(last.1.values, frames[0].1.values, "driven home instead");
}

#[test]
fn an_easy_ramp_is_honoured_and_a_longer_one_is_announced_before_it_starts() {
    // The case: paired with its default limits (0.5 m/s, 5 m/s²), a 1 s ramp to a
    // motion centimetres from home. The ramp is planned against the motion's start: 1 s,
    // as asked (the supervisor alone, not foreseeing the motion, took 1.8 s), and from
    // shortly after it the lengths sent are the trajectory's.
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--instant",
        "--rate",
        "200",
        "--duration",
        "2",
        "--ramp",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("arming will take"), "{}", stderr(&o));
    let frames = recorded(&stdout(&o));
    let solved = stewart(&["solve", "--preset", "paired"]);
    let (header, rows) = parse_csv(&stdout(&solved));
    let l1 = header.iter().position(|c| c == "L1").unwrap_or(7);
    let mut compared = 0;
    for (t, f) in &frames {
        if !(1.05..1.9).contains(t) {
            continue;
        }
        let Some(row) = rows.iter().find(|r| (r[0] - t).abs() < 1e-9) else {
            continue;
        };
        for i in 0..6 {
            let want = (row[l1 + i] * 1e6).round() as i32;
            assert!((f.values[i] - want).abs() <= 1, "t = {t}, leg {}", i + 1);
        }
        compared += 1;
    }
    assert!(compared > 50, "{compared}");
    // A ramp the limits cannot give: said, with its time, before the first frame.
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--rate",
        "200",
        "--duration",
        "1",
        "--ramp",
        "0.05",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let first = stderr(&o).lines().next().unwrap_or_default().to_owned();
    assert!(first.starts_with("link: arming will take "), "{first}");
    assert!(first.contains("longer than the 0.05 s asked"), "{first}");
}

#[test]
fn once_armed_the_values_sent_are_the_checked_trajectory() {
    // The case: paired, default limits (0.5 m/s, 5 m/s²), which `check` passes;
    // and the servo-desk with its servo limits (300°/s, 3000°/s²). In the wire's unit: µm
    // per metre, 0.01° per degree.
    for (preset, column, per_unit) in [("paired", "L1", 1e6), ("servo-desk", "theta1", 100.0)] {
        let checked = stewart(&["check", "--preset", preset]);
        assert_eq!(checked.status.code(), Some(0), "{}", stderr(&checked));
        let solved = stewart(&["solve", "--preset", preset]);
        let (header, rows) = parse_csv(&stdout(&solved));
        let first = header.iter().position(|c| c == column).unwrap_or(7);
        let step = rows[1][0] - rows[0][0];
        for rate in ["200", "1000"] {
            // On the stream's own clock (`--instant`): no tick skipped, the ramp on time.
            let o = stewart(&[
                "link",
                "--preset",
                preset,
                "--dry-run",
                "--instant",
                "--rate",
                rate,
            ]);
            assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
            assert!(
                stderr(&o).contains("e-stop: at home, disarmed"),
                "{}",
                stderr(&o)
            );
            let frames = recorded(&stdout(&o));
            let mut compared = 0;
            let mut worst: f64 = 0.0;
            for (t, f) in &frames {
                // After the ramp (2 s asked, a little longer for the limits), until the
                // stop; on the solve table's own sample times.
                let k = (t / step).round() as usize;
                if *t < 3.0 || k + 1 >= rows.len() || (t - rows[k][0]).abs() > 1e-9 {
                    continue;
                }
                for i in 0..6 {
                    let want = rows[k][first + i] * per_unit;
                    worst = worst.max((f64::from(f.values[i]) - want).abs());
                }
                compared += 1;
            }
            assert!(compared > 100, "{preset} at {rate} Hz: {compared}");
            // Within the rounding to the wire's unit.
            assert!(worst <= 0.5 + 1e-6, "{preset} at {rate} Hz: {worst}");
        }
    }
}

/// The simulated actuators' response, computed here from the simulator's own record (the
/// set-points as they arrived, with their times): a first-order lag of `lag_s` integrated
/// exactly over each interval under the set-point held, the step capped at `speed`·Δt, no
/// motion within `dead_band` (wire units). Returns, per sequence number, the positions
/// when that set-point arrived (before it is taken), rounded as the wire rounds.
pub fn model_response_of(
    sim_csv: &str,
    lag_s: f64,
    speed: f64,
    dead_band: f64,
) -> std::collections::HashMap<u16, [f64; 6]> {
    let (_, rows) = parse_csv(sim_csv);
    let mut out = std::collections::HashMap::new();
    let mut state: Option<([f64; 6], [f64; 6], f64)> = None;
    for r in rows {
        let (t, seq) = (r[0], r[1] as u16);
        let armed = r[2] == 1.0 && r[3] == 0.0;
        let values: [f64; 6] = std::array::from_fn(|k| r[6 + k]);
        let (mut x, held, since) = state.unwrap_or((values, values, t));
        let dt = t - since;
        for k in 0..6 {
            let gap = held[k] - x[k];
            if gap.abs() > dead_band {
                let lagged = gap * (1.0 - (-dt / lag_s).exp());
                x[k] += lagged.clamp(-speed * dt, speed * dt);
            }
        }
        out.insert(seq, x.map(f64::round));
        state = Some((x, if armed { values } else { x }, t));
    }
    out
}

/// The measured values of `stewart link --record` (metres) against the model's response to
/// the commanded ones (µm): every answered set-point within one wire unit (the two roundings
/// may fall on either side; the record's times are to the microsecond), and most answered.
pub fn measured_follow_the_model(record: &str, model: &std::collections::HashMap<u16, [f64; 6]>) {
    let (header, rows) = parse_csv(record);
    assert_eq!(header.len(), 15, "{header:?}");
    assert_eq!(header[2], "cmd1_m");
    assert_eq!(header[8], "meas1_m");
    assert!(
        rows.len() * 10 >= model.len() * 9,
        "{} of {}",
        rows.len(),
        model.len()
    );
    let mut lagging = 0.0_f64;
    for r in &rows {
        let seq = r[1] as u16;
        let want = model
            .get(&seq)
            .unwrap_or_else(|| panic!("set-point {seq} answered but never received"));
        for k in 0..6 {
            let measured = r[8 + k] * 1e6;
            assert!(
                (measured - want[k]).abs() <= 1.5,
                "seq {seq}, actuator {}: measured {measured} µm, the model {} µm",
                k + 1,
                want[k]
            );
            lagging = lagging.max((r[2 + k] - r[8 + k]).abs());
        }
        assert!(r[14] >= 0.0 && r[14] < 100.0, "latency {} ms", r[14]);
    }
    // The lag shows: measured differs from commanded by more than rounding somewhere.
    assert!(
        lagging > 1e-4,
        "the measured values equal the commanded ones"
    );
}

#[test]
fn telemetry_over_udp_is_recorded_beside_the_commands_and_follows_the_actuator_model() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let record = dir.path().join("measured.csv");
    let address = free_port();
    let model = [
        "--telemetry",
        "--lag-s",
        "0.05",
        "--speed-max",
        "100000",
        "--dead-band",
        "2",
    ];
    let sim = device_sim(&address, &model);
    let record_path = record.to_str().unwrap_or_default();
    let o = udp_link_with(
        "paired",
        &address,
        "3",
        "200",
        "0.5",
        &["--record", record_path],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("link: telemetry answered "), "{err}");
    assert!(err.contains("(0 unanswered, 0 stale)"), "{err}");
    let sim = sim.finish();
    let sim_csv = String::from_utf8_lossy(&sim.stdout).into_owned();
    let response = model_response_of(&sim_csv, 0.05, 100_000.0, 2.0);
    let recorded = std::fs::read_to_string(&record).unwrap_or_else(|e| panic!("{e}"));
    measured_follow_the_model(&recorded, &response);
}

#[test]
fn a_record_that_cannot_be_written_is_refused_before_anything_is_sent() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let receiver = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    receiver
        .set_read_timeout(Some(Duration::from_millis(300)))
        .unwrap_or_else(|e| panic!("{e}"));
    let address = receiver
        .local_addr()
        .unwrap_or_else(|e| panic!("{e}"))
        .to_string();
    let folder = dir.path().to_str().unwrap_or_default();
    let o = udp_link_with("paired", &address, "0.5", "100", "2", &["--record", folder]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("it is a folder"), "{}", stderr(&o));
    let mut buf = [0u8; 64];
    assert!(receiver.recv(&mut buf).is_err(), "a frame was sent");
    // The dry run's record and the telemetry record in one new file: refused, nothing left.
    let both = dir.path().join("both.txt");
    let both = both.to_str().unwrap_or_default();
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--duration",
        "0.2",
        "--out",
        both,
        "--record",
        both,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("name the same file"), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_dir(dir.path()).map(Iterator::count).ok(),
        Some(0)
    );
    // A bad model option of the simulator is refused by name.
    let o = stewart(&["device-sim", "--udp", "127.0.0.1:0", "--lag-s", "-1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--lag-s"), "{}", stderr(&o));
    let o = stewart(&[
        "device-sim",
        "--udp",
        "127.0.0.1:0",
        "--min",
        "10",
        "--max",
        "0",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("--min 10 is above --max 0"),
        "{}",
        stderr(&o)
    );
}
