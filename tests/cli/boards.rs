//! Hobby boards' formats: an output template's bytes are the solved legs scaled into the
//! template's numbers, and `device-sim` reads the same frames back over UDP and over a
//! serial line (a pseudo-terminal pair).

use stewart_link::template::{FieldType, Template, TemplateDecoder, TemplateFrame};

use crate::link::{deadlines_skipped, device_sim, device_sim_on, frames_sent, free_port};
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
        "--instant",
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
        // Armed from the first tick: frame k at k/rate (on the stream's own clock, none
        // skipped). After the ramp, until the stop, on the solve table's own times.
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

/// The numbers of a dry run of the same stream on its own clock (the stream is the same
/// tick by tick).
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
            "--instant",
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

/// What the device read is the dry run's stream, frame for frame, when the live stream kept
/// every deadline. A machine so loaded that it skipped some (the link says how many) sent
/// fewer frames, each for its own time; while the platform follows the motion (after the
/// ramp, before the stop) those are the motion's values at that time exactly, so the
/// device read the dry run's frames of that stretch in order, less at most the skipped.
fn same_as_a_dry_run(link: &std::process::Output, got: &[[f64; 6]], timing: &[&str]) {
    let all = dry_run_numbers(timing);
    let skipped = deadlines_skipped(link);
    if skipped == 0 {
        assert_eq!(got, all);
        return;
    }
    let value = |name: &str| -> f64 {
        let at = timing
            .iter()
            .position(|a| *a == name)
            .unwrap_or_else(|| panic!("{name}"));
        timing[at + 1].parse().unwrap_or_else(|e| panic!("{e}"))
    };
    let (rate, ramp, duration) = (value("--rate"), value("--ramp"), value("--duration"));
    let following = &all[(ramp * rate) as usize + 1..(duration * rate) as usize];
    let (mut from, mut found) = (0, 0);
    for frame in got {
        if let Some(at) = following[from..].iter().position(|f| f == frame) {
            from += at + 1;
            found += 1;
        }
    }
    assert!(
        found + skipped >= following.len(),
        "{found} of {} frames while following, {skipped} deadlines skipped",
        following.len()
    );
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
    let sim = sim.finish();
    let got = recorded_numbers(&sim, sent);
    same_as_a_dry_run(&o, &got, &timing);
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
    let sim = sim.finish();
    let got = recorded_numbers(&sim, sent);
    same_as_a_dry_run(&o, &got, &timing);
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
    // The same template given by `--set` is refused as that `--set`, before any work.
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
        stderr(&o).contains(
            "--set `link.template={a9:u8}`: `link.template` refused: template column 1: `a9` names no actuator"
        ),
        "{}",
        stderr(&o)
    );
}

/// The lines of a board protocol's dry run for `port` (1-based): (time, line).
fn dry_run_lines(format: &str, port: usize, extra: &[&str]) -> Vec<(f64, String)> {
    let o = stewart(
        &[
            &[
                "link",
                "--preset",
                "paired",
                "--dry-run",
                "--format",
                format,
            ][..],
            extra,
        ]
        .concat(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    stdout(&o)
        .lines()
        .filter_map(|l| {
            let mut parts = l.splitn(3, '\t');
            let (t, p, rest) = (parts.next()?, parts.next()?, parts.next()?);
            (p == format!("port {port}")).then(|| (t.parse().unwrap_or(f64::NAN), rest.to_owned()))
        })
        .collect()
}

#[test]
fn smc3_boards_get_the_legs_scaled_to_1023_and_are_enabled_once() {
    // Board 1 carries legs 1–3, board 2 legs 4–6: five-byte frames [A hi lo][B hi lo]
    // [C hi lo] each tick, [ena] first.
    let rate = 200.0;
    let timing = ["--rate", "200"];
    let solved = stewart(&["solve", "--preset", "paired"]);
    let (header, rows) = parse_csv(&stdout(&solved));
    let first = header.iter().position(|c| c == "L1").unwrap_or(7);
    let step = rows[1][0] - rows[0][0];
    for port in [1, 2] {
        let lines = dry_run_lines("smc3", port, &timing);
        let bytes = |hex: &str| -> Vec<u8> {
            hex.split_whitespace()
                .map(|h| u8::from_str_radix(h, 16).unwrap_or_else(|e| panic!("{e}")))
                .collect()
        };
        assert!(bytes(&lines[0].1).starts_with(b"[ena]"), "{:?}", lines[0]);
        let enables = lines.iter().filter(|(_, l)| bytes(l).starts_with(b"[ena]"));
        assert_eq!(enables.count(), 1, "enabled once");
        let (mut compared, mut worst) = (0, 0.0f64);
        for (t, hex) in &lines {
            let b = bytes(hex);
            let frames = &b[b.len() - 15..];
            let row = (t / step).round() as usize;
            if *t < 3.0 || row + 1 >= rows.len() || (t - rows[row][0]).abs() > 1e-9 {
                continue;
            }
            for (c, frame) in frames.chunks(5).enumerate() {
                assert_eq!([frame[0], frame[1], frame[4]], [b'[', b'A' + c as u8, b']']);
                let n = u16::from_be_bytes([frame[2], frame[3]]);
                assert!(n <= 1023);
                let leg = rows[row][first + 3 * (port - 1) + c];
                let exact = (leg - STROKE.0) / (STROKE.1 - STROKE.0) * 1023.0;
                worst = worst.max((f64::from(n) - exact).abs());
            }
            compared += 1;
        }
        assert!(compared > 100, "{compared}");
        assert!(worst <= 0.5 + 1e-3, "board {port}: {worst}");
        let _ = rate;
    }
}

#[test]
fn odrive_boards_get_turns_and_are_put_in_closed_loop_then_idle() {
    // 20 turns per metre, −20 turns at 1 m: leg L is 20·L − 20 turns.
    let set = [
        "--set",
        "link.turns_per_unit.1=20",
        "--set",
        "link.turns_offset.1=-20",
    ];
    let lines = dry_run_lines("odrive", 1, &[&["--rate", "100"][..], &set].concat());
    assert_eq!(lines[0].1, "w axis0.requested_state 8");
    assert_eq!(lines[1].1, "w axis1.requested_state 8");
    let last = &lines[lines.len() - 2..];
    assert_eq!(last[0].1, "w axis0.requested_state 1", "idle at the end");
    let solved = stewart(&["solve", "--preset", "paired"]);
    let (header, rows) = parse_csv(&stdout(&solved));
    let l1 = header.iter().position(|c| c == "L1").unwrap_or(7);
    let step = rows[1][0] - rows[0][0];
    let mut compared = 0;
    for (t, line) in &lines {
        let words: Vec<&str> = line.split(' ').collect();
        if words[..2] != ["p", "0"] {
            continue;
        }
        let row = (t / step).round() as usize;
        if *t < 3.0 || row + 1 >= rows.len() || (t - rows[row][0]).abs() > 1e-9 {
            continue;
        }
        let turns: f64 = words[2].parse().unwrap_or(f64::NAN);
        let want = 20.0 * rows[row][l1] - 20.0;
        // Six decimals on the wire.
        assert!((turns - want).abs() <= 5e-7 + 1e-9, "{line}: {want}");
        assert_eq!(words[4], "0", "no torque feed-forward");
        compared += 1;
    }
    assert!(compared > 100, "{compared}");
}

#[test]
fn board_formats_need_a_range_apply_no_channel_map_and_let_go_only_at_home() {
    // No stroke: every leg would scale from 0–1000 m (all at the bottom): refused.
    for format in ["smc3", "odrive", "template:{a1:u16be}"] {
        let o = stewart(&[
            "link",
            "--preset",
            "paired",
            "--dry-run",
            "--format",
            format,
            "--set",
            "geometry.leg_min=off",
        ]);
        assert_eq!(o.status.code(), Some(2), "{format}");
        assert!(
            stderr(&o).contains("scales each actuator from its range: set both `geometry.leg_min` and `geometry.leg_max`"),
            "{format}: {}",
            stderr(&o)
        );
        assert!(stdout(&o).is_empty());
    }
    // A channel map the format would not apply: refused, not ignored.
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--dry-run",
        "--format",
        "smc3",
        "--set",
        "link.reversed.2=true",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("applies no channel map: leave `link.reversed` at its default"),
        "{}",
        stderr(&o)
    );
    // ODrive: idle (no torque) only once the way home has ended there; a stop that holds
    // leaves the axes in closed loop where they are.
    let idle = |stop: &str| {
        dry_run_lines(
            "odrive",
            1,
            &["--duration", "1", "--set", &format!("link.stop={stop}")],
        )
        .iter()
        .filter(|(_, l)| l.ends_with("requested_state 1"))
        .count()
    };
    assert_eq!(idle("home"), 2);
    assert_eq!(idle("hold"), 0);
}

/// `link` of the paired preset in board `format` (2 or 3 boards) over `transport` (`serial`
/// on pty pairs, or `udp`), a `device-sim` standing in for each board: the frames sent, and
/// each board's record (rows of numbers), each read without damage.
fn boards_end_to_end(format: &str, boards: usize, transport: &str) -> (usize, Vec<Vec<Vec<f64>>>) {
    let serial = transport == "serial";
    let pairs: Vec<PtyPair> = (0..boards)
        .filter(|_| serial)
        .map(|_| PtyPair::new())
        .collect();
    let addresses: Vec<String> = (0..boards).map(|_| free_port()).collect();
    let sims: Vec<_> = (1..=boards)
        .map(|n| {
            let board = ["--format", format, "--board", &n.to_string()].map(str::to_owned);
            let board: Vec<&str> = board.iter().map(String::as_str).collect();
            if serial {
                let port = PtyPair::path(&pairs[n - 1].b);
                device_sim_on(&["--serial", port, "--baud", "1000000"], &board)
            } else {
                device_sim(&addresses[n - 1], &board)
            }
        })
        .collect();
    let mut args: Vec<String> = ["link", "--preset", "paired", "--transport", transport]
        .into_iter()
        .chain([
            "--format",
            format,
            "--duration",
            "1",
            "--rate",
            "100",
            "--ramp",
            "0.2",
        ])
        .map(str::to_owned)
        .collect();
    for n in 1..=boards {
        let suffix = if n == 1 { String::new() } else { n.to_string() };
        let (flag, end) = match serial {
            true => (
                format!("--port{suffix}"),
                PtyPair::path(&pairs[n - 1].a).to_owned(),
            ),
            false => (format!("--address{suffix}"), addresses[n - 1].clone()),
        };
        args.extend([flag, end]);
    }
    if serial {
        args.extend(["--baud".to_owned(), "1000000".to_owned()]);
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = stewart(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = frames_sent(&o);
    let records = sims
        .into_iter()
        .map(|sim| {
            let sim = sim.finish();
            let log = String::from_utf8_lossy(&sim.stderr).into_owned();
            assert!(
                log.contains(&format!("device-sim: {sent} frames, 0 damaged")),
                "{log}"
            );
            parse_csv(&String::from_utf8_lossy(&sim.stdout)).1
        })
        .collect();
    (sent, records)
}

#[test]
fn device_sim_reads_each_smc3_board_over_serial_and_over_udp() {
    for transport in ["serial", "udp"] {
        let (_, records) = boards_end_to_end("smc3", 2, transport);
        for (board, rows) in records.iter().enumerate() {
            // Unit 4; armed from the first frame ([ena] came first); this board's columns
            // within 0–1023, the other board's empty.
            let (mine, others) = if board == 0 {
                (6..9, 9..12)
            } else {
                (9..12, 6..9)
            };
            for r in rows {
                assert_eq!((r[2], r[5]), (1.0, 4.0), "{transport}");
                assert!(
                    r[mine.clone()].iter().all(|v| (0.0..=1023.0).contains(v)),
                    "{r:?}"
                );
                assert!(r[others.clone()].iter().all(|&v| v == 0.0), "{r:?}");
            }
        }
    }
}

#[test]
fn device_sim_reads_each_odrive_board_over_udp_and_over_serial() {
    for transport in ["udp", "serial"] {
        let (_, records) = boards_end_to_end("odrive", 3, transport);
        for (board, rows) in records.iter().enumerate() {
            // Unit 5, millionths of a turn: with one turn per metre, the legs in
            // micrometres, in this board's two columns.
            let mine = 6 + 2 * board..8 + 2 * board;
            for r in rows {
                assert_eq!(r[5], 5.0, "{transport}");
                let legs = &r[mine.clone()];
                assert!(
                    legs.iter().all(|v| (550_000.0..=1_300_000.0).contains(v)),
                    "{r:?}"
                );
            }
        }
    }
    // A missing board's port is one clear error before anything is sent.
    let o = stewart(&[
        "link",
        "--preset",
        "paired",
        "--transport",
        "udp",
        "--format",
        "odrive",
        "--address",
        &free_port(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("drives 3 boards: give board 2's port too"),
        "{}",
        stderr(&o)
    );
}

/// A template whose frame ends in a space (a board that reads space-ended numbers).
const SPACED: &str = "<255>{a1:u16be}{a2:u16be}{a3:u16be}{a4:u16be}{a5:u16be}{a6:u16be} ";

/// The bytes of a short dry run of the paired preset with `args` (a scenario or `--set`s),
/// on the stream's own clock (`--instant`: every tick in turn, none skipped however
/// loaded the machine, so that two runs give the same frames).
fn dry_run_bytes(args: &[&str]) -> Vec<u8> {
    let dir = tempdir();
    let out = dir.path().join("frames.bin");
    let path = out.display().to_string();
    let timing = [
        "--duration",
        "0.1",
        "--rate",
        "100",
        "--ramp",
        "0.05",
        "--instant",
    ];
    let o = stewart(&[&["link", "--dry-run"][..], args, &timing, &["--out", &path]].concat());
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    std::fs::read(&out).unwrap_or_else(|e| panic!("{e}"))
}

/// The paired preset with `[link]` written in a file, in `dir`.
fn paired_file_with_link(dir: &std::path::Path, link: &str) -> String {
    let preset = include_str!("../../assets/presets/paired.toml");
    let path = dir.join("paired-board.toml");
    std::fs::write(&path, format!("{preset}\n[link]\n{link}\n")).unwrap_or_else(|e| panic!("{e}"));
    path.display().to_string()
}

#[test]
fn a_template_is_read_the_same_from_every_place_it_is_written() {
    let dir = tempdir();
    let file = paired_file_with_link(
        dir.path(),
        // Written with a space before it too: dropped here as everywhere.
        &format!("format = \"template\"\ntemplate = \"  {SPACED}\""),
    );
    let from_file = dry_run_bytes(&["--scenario", &file]);
    // Seven bytes and twelve, then the space: every frame ends in it.
    assert_eq!(from_file.len() % 14, 0, "{}", from_file.len());
    assert!(from_file.chunks(14).all(|f| f[0] == 255 && f[13] == b' '));
    let format = format!("template:{SPACED}");
    let set_format = format!("link.format={format}");
    let set_template = format!("link.template={SPACED}");
    for args in [
        &["--preset", "paired", "--format", &format][..],
        &["--preset", "paired", "--set", &set_format],
        &[
            "--preset",
            "paired",
            "--set",
            &set_template,
            "--set",
            "link.format=template",
        ],
    ] {
        assert_eq!(dry_run_bytes(args), from_file, "{args:?}");
    }
    // And the stand-in board given the same template on its command line reads every
    // frame the file's link sends (a dropped space damaged all of them).
    let address = free_port();
    let sim = device_sim(&address, &["--format", &format]);
    let o = stewart(&[
        "link",
        "--scenario",
        &file,
        "--transport",
        "udp",
        "--address",
        &address,
        "--duration",
        "0.5",
        "--rate",
        "100",
        "--ramp",
        "0.1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let sent = frames_sent(&o);
    assert!(sent > 20, "{sent}");
    let sim = sim.finish();
    assert!(
        stderr(&sim).contains(&format!("device-sim: {sent} frames, 0 damaged, 0 lost")),
        "{}",
        stderr(&sim)
    );
}

#[test]
fn a_bad_template_in_a_file_is_refused_at_its_line_by_every_command() {
    let dir = tempdir();
    let file = paired_file_with_link(dir.path(), "template = \"<255>{a7:u16be}\"");
    let line = std::fs::read_to_string(&file)
        .unwrap_or_else(|e| panic!("{e}"))
        .lines()
        .position(|l| l.starts_with("template"))
        .map(|k| k + 1)
        .unwrap_or_else(|| panic!("no template line"));
    for command in [&["check"][..], &["solve"], &["link", "--dry-run"]] {
        let o = stewart(&[command, &["--scenario", &file]].concat());
        assert_eq!(o.status.code(), Some(2), "{command:?}");
        let said = stderr(&o);
        assert!(
            said.contains(&format!("paired-board.toml, line {line}"))
                && said.contains("`link.template` template column 6: `a7` names no actuator"),
            "{command:?}: {said}"
        );
    }
}
