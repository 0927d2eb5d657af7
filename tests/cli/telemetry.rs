//! `stewart telemetry`: what a game sends, shown a line a second and written as the CSV
//! `stewart cue` reads.

use std::io::{BufRead as _, BufReader};
use std::net::UdpSocket;
use std::process::{Command, Stdio};

use crate::capture::{ethernet_udp, forza, moment, ms, pcap_to_ports};
use crate::{parse_csv, tempdir};

#[test]
fn a_games_datagrams_are_named_counted_and_written_as_vehicle_motion() {
    let dir = tempdir();
    let out = dir.path().join("vehicle.csv");
    let mut child = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args([
            "telemetry",
            "--listen",
            "udp:127.0.0.1:0",
            "--duration",
            "2",
        ])
        .arg("--out")
        .arg(&out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    // The first line says where it listens: the datagrams go there once it does.
    let mut err = BufReader::new(child.stderr.take().unwrap_or_else(|| panic!("no stderr")));
    let mut first = String::new();
    err.read_line(&mut first).unwrap_or_else(|e| panic!("{e}"));
    let at = first
        .trim()
        .strip_prefix("telemetry: listening at ")
        .and_then(|rest| rest.split(' ').next())
        .unwrap_or_else(|| panic!("{first}"))
        .to_owned();
    let socket = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    for k in 150..210 {
        for datagram in forza(k) {
            socket
                .send_to(&datagram, &at)
                .unwrap_or_else(|e| panic!("{e}"));
        }
    }
    socket
        .send_to(b"not telemetry", &at)
        .unwrap_or_else(|e| panic!("{e}"));
    let o = child.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut err, &mut rest).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(o.status.code(), Some(0), "{rest}");
    // A line a second names each format with its count (a loaded machine may read the
    // burst over two seconds: the counts add up).
    let shown = String::from_utf8_lossy(&o.stdout);
    let count = |name: &str| -> usize {
        (shown.lines())
            .filter_map(|l| l.split(&format!("{name} ")).nth(1))
            .filter_map(|rest| rest.split("/s").next()?.parse::<usize>().ok())
            .sum()
    };
    assert_eq!(count("Forza Horizon"), 60, "{shown}");
    assert_eq!(count("unknown"), 1, "{shown}");
    // The last sample (the turn, braking over): no "-0.0" for a zero.
    assert!(
        shown.contains("ax 0.00 ay 3.00 az 0.00 m/s²  wx 0.0 wy 0.0 wz 21.5 °/s"),
        "{shown}"
    );
    assert!(
        rest.contains("61 datagrams, 60 samples of motion kept; 60 Forza Horizon; 1 unreadable"),
        "{rest}"
    );
    // The CSV: the game's clock from its first reading, the motion in our axes — what `stewart cue` reads.
    let text = std::fs::read_to_string(&out).unwrap_or_else(|e| panic!("{e}"));
    let (header, rows) = parse_csv(&text);
    assert_eq!(header, ["t", "ax", "ay", "az", "wx", "wy", "wz"]);
    assert_eq!(rows.len(), 60);
    for (row, k) in rows.iter().zip(150..) {
        let m = moment(k);
        let expected = [
            // The game's clock, counted from the first datagram heard (sample 150).
            f64::from(ms(k) - ms(150)) / 1000.0,
            f64::from(m.forward),
            f64::from(m.left),
            0.0,
            0.0,
            0.0,
            f64::from(m.yaw_rad).to_degrees(),
        ];
        assert_eq!(row[..], expected, "sample {k}");
    }
}

#[test]
fn a_capture_is_read_as_listening_would_and_other_ports_are_not_telemetry() {
    // Forza to 5300, and every tenth sample a 64-byte mDNS-like datagram to 5353 (the
    // length of a Live for Speed OutSim packet, which it must not become).
    let dir = tempdir();
    let capture = dir.path().join("session.pcap");
    let file = pcap_to_ports(|k| {
        let mut out: Vec<(u16, Vec<u8>)> = forza(k).into_iter().map(|d| (5300, d)).collect();
        if k % 10 == 0 {
            out.push((5353, vec![0x11; 64]));
        }
        out
    });
    std::fs::write(&capture, file).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.path().join("vehicle.csv");
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["telemetry", "--input"])
        .arg(&capture)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let said = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{said}");
    assert!(said.contains("telemetry read from port 5300"), "{said}");
    assert!(
        said.contains("not telemetry (other ports, --port chooses): 30 to port 5353"),
        "{said}"
    );
    assert!(
        said.contains("300 datagrams, 300 samples of motion kept; 300 Forza Horizon"),
        "{said}"
    );
    assert!(!said.contains("OutSim"), "{said}");
    // A line per second of the capture's own time, as listening prints.
    let shown = String::from_utf8_lossy(&o.stdout);
    assert!(shown.lines().count() >= 5, "{shown}");
    assert!(
        shown
            .lines()
            .next()
            .is_some_and(|l| l.contains("Forza Horizon 60/s")),
        "{shown}"
    );
    // What it writes, `stewart cue` reads.
    let (_, rows) = parse_csv(&std::fs::read_to_string(&out).unwrap_or_else(|e| panic!("{e}")));
    assert_eq!(rows.len(), 300);
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["cue", "--preset", "paired", "--input"])
        .arg(&out)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // Asked for, the other port is read (as the 64-byte form it happens to have).
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["telemetry", "--port", "5353", "--input"])
        .arg(&capture)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let said = String::from_utf8_lossy(&o.stderr);
    assert!(
        said.contains("telemetry read from port 5353") && said.contains("30 datagrams,"),
        "{said}"
    );
}

#[test]
fn a_capture_with_a_long_silence_is_read_at_once_and_nothing_unreadable_is_written() {
    // Text samples at 0 s and 0.1 s, then one 100 000 s later: one line per second that
    // held datagrams (not 100 000 lines), and every sample within the tables' times.
    let mut file = Vec::new();
    for word in [0xa1b2_c3d4u32, 0x0004_0002, 0, 0, 65535, 1] {
        file.extend(word.to_le_bytes());
    }
    for (sec, usec, text) in [
        (0u32, 0u32, "0,1,0,0,0,0,0"),
        (0, 100_000, "0.1,2,0,0,0,0,0"),
        (100_000, 0, "0.2,3,0,0,0,0,0"),
    ] {
        let frame = ethernet_udp(4123, text.as_bytes());
        file.extend(sec.to_le_bytes());
        file.extend(usec.to_le_bytes());
        file.extend((frame.len() as u32).to_le_bytes());
        file.extend((frame.len() as u32).to_le_bytes());
        file.extend(frame);
    }
    let dir = tempdir();
    let capture = dir.path().join("gap.pcap");
    std::fs::write(&capture, file).unwrap_or_else(|e| panic!("{e}"));
    let started = std::time::Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["telemetry", "--input"])
        .arg(&capture)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(started.elapsed().as_secs() < 20);
    let said = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{said}");
    assert!(String::from_utf8_lossy(&o.stdout).lines().count() <= 3);
    // The sender's clock (0.2 s) goes on after the silence: a new stretch, kept.
    assert!(said.contains("3 samples of motion kept"), "{said}");
    // Nothing arrived on another port: no table of no rows is written.
    let out = dir.path().join("none.csv");
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["telemetry", "--port", "9", "--input"])
        .arg(&capture)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!out.exists());
}

/// Stopped while waiting for a named pipe's reader, a session is kept in a file it names
/// (the rows once went with the stop).
#[test]
fn a_session_stopped_while_its_pipe_waits_for_a_reader_is_kept() {
    let dir = tempdir();
    let capture = dir.path().join("session.pcap");
    let file = pcap_to_ports(|k| forza(k).into_iter().map(|d| (5300, d)).collect());
    std::fs::write(&capture, file).unwrap_or_else(|e| panic!("{e}"));
    let fifo = dir.path().join("rows.csv");
    let made = Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let telemetry = crate::watched::Watched::spawn(
        Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
            .args(["telemetry", "--input"])
            .arg(&capture)
            .arg("--out")
            .arg(&fifo),
    );
    telemetry.wait_for("waiting for a reader of");
    let sent = Command::new("kill")
        .args(["-INT", &telemetry.id().to_string()])
        .status();
    assert!(sent.is_ok_and(|s| s.success()));
    let o = telemetry.finish();
    let said = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{said}");
    let kept = said
        .split("rows are kept in `")
        .nth(1)
        .and_then(|rest| rest.split('`').next())
        .unwrap_or_else(|| panic!("no file named: {said}"));
    let rows = std::fs::read_to_string(kept).unwrap_or_default();
    let _ = std::fs::remove_file(kept);
    assert_eq!(rows.lines().count(), 301, "{said}");
}
