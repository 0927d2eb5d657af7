//! `stewart telemetry`: listen where a game sends its telemetry and show, a line a second,
//! which formats arrive at what rate and the motion decoded from them (in our axes: x
//! forward, y left, z up; m/s² and °/s) — the check that a game is set up right — and,
//! with `--out`, write that motion as the CSV `stewart cue` reads. Datagrams are read as
//! the live link reads them (`stewart_link::vehicle::intake`). With `--input`, a packet
//! capture of a session is read the same way, a line per second of its own time, so a
//! recorded session can be checked without the game.

use std::collections::BTreeMap;
use std::io::Write as _;
use std::net::UdpSocket;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Context as _, Result, anyhow, bail};
use stewart_link::vehicle::VehicleSample;
use stewart_link::vehicle::capture;
use stewart_link::vehicle::intake::Intake;
use stewart_link::vehicle::replay::telemetry_port;
use stewart_link::vehicle::timeline::Step;

use crate::cli::TelemetryArgs;
use crate::csv_io::{CsvText, read_input_bytes};
use crate::output::{self, Destination};
use crate::vehicle_in::capture::tally_words;
use crate::vehicle_in::table::VEHICLE_COLUMNS;
use crate::vehicle_in::xplane_rref::RrefSubscription;

/// How long a read waits before the loop looks at the clock and Ctrl-C again.
const POLL: Duration = Duration::from_millis(50);

/// Run the command.
pub(crate) fn run(args: &TelemetryArgs) -> Result<ExitCode> {
    let mut inputs = Vec::new();
    if let Some(input) = &args.input {
        inputs.push(("the capture", input.as_path()));
    }
    // Checked before listening: a session is never recorded only to be refused (a folder,
    // an input, a folder that cannot take a file).
    let out = output::destination(args.out.as_deref(), &inputs)?;
    if let Some(out) = &out {
        out.require_file()?;
        drop(out.staged_file(".check")?);
    }
    let mut heard = Heard {
        keep: out.is_some(),
        ..Heard::default()
    };
    match (&args.input, &args.listen) {
        (Some(input), _) => replay(input, args.port, &mut heard)?,
        (None, Some(listen)) => listen_to(listen, args, &mut heard, out.as_ref())?,
        (None, None) => bail!("give --listen udp:HOST:PORT or --input CAPTURE"),
    }
    write_rows(&heard, out.as_ref())?;
    Ok(ExitCode::SUCCESS)
}

/// Listen at `listen` until `--duration` or Ctrl-C; a named pipe as `out` is opened (its
/// reader waited for) once the address is bound, before anything is heard.
fn listen_to(
    listen: &str,
    args: &TelemetryArgs,
    heard: &mut Heard,
    out: Option<&Destination>,
) -> Result<()> {
    let Some(address) = listen.strip_prefix("udp:") else {
        bail!("--listen takes udp:HOST:PORT (such as udp:0.0.0.0:20777), got `{listen}`");
    };
    let socket =
        UdpSocket::bind(address).with_context(|| format!("cannot listen at `{address}`"))?;
    socket.set_read_timeout(Some(POLL))?;
    let mut xplane = (args.xplane.as_deref())
        .map(|a| RrefSubscription::new(a, args.rate))
        .transpose()?;
    if let Some(out) = out {
        out.hold_open()?;
    }
    let mut err = std::io::stderr();
    let _ = writeln!(
        err,
        "telemetry: listening at {} (Ctrl-C ends)",
        socket.local_addr()?
    );
    let stop = crate::interrupt::flag();
    let start = Instant::now();
    let mut next_line = 1.0;
    let mut buffer = vec![0u8; 65_536];
    loop {
        let now = start.elapsed().as_secs_f64();
        if stop.load(std::sync::atomic::Ordering::Relaxed)
            || args.duration.is_some_and(|d| now >= d)
        {
            break;
        }
        if let Some(x) = xplane.as_mut() {
            x.keep(&socket, Instant::now());
        }
        if let Ok(n) = socket.recv(&mut buffer) {
            heard.take(&buffer[..n], start.elapsed().as_secs_f64());
        }
        if now >= next_line {
            let _ = writeln!(std::io::stdout(), "{}", heard.second(next_line));
            next_line += 1.0;
        }
    }
    if let Some(x) = &xplane {
        x.end(&socket);
    }
    heard.intake.finish();
    let _ = writeln!(err, "telemetry: {}", heard.summary());
    Ok(())
}

/// Read the capture `input`: the datagrams to `port` (default: the port whose datagrams
/// give motion), a line per second of the capture's time.
fn replay(input: &std::path::Path, port: Option<u16>, heard: &mut Heard) -> Result<()> {
    let (bytes, name) = read_input_bytes(input, stewart_kinematics::io::file::FileKind::Capture)?;
    if !capture::is_capture(&bytes) {
        bail!(
            "{name}: not a packet capture (pcap or pcapng): its first bytes are neither format's"
        );
    }
    let capture = capture::read(bytes.as_slice()).map_err(|e| anyhow!("{name}: {e}"))?;
    let port = port.or_else(|| telemetry_port(&capture.datagrams));
    let mut stdout = std::io::stdout().lock();
    let mut next_line = 1.0;
    let mut others: BTreeMap<u16, usize> = BTreeMap::new();
    for d in &capture.datagrams {
        // A line for each second of the capture that held datagrams (a silence of any
        // length is skipped, not printed second by second).
        if d.time_s >= next_line {
            let _ = writeln!(stdout, "{}", heard.second(next_line));
            next_line = d.time_s.floor() + 1.0;
        }
        if Some(d.port) == port {
            heard.take(&d.payload, d.time_s);
        } else {
            *others.entry(d.port).or_default() += 1;
        }
    }
    if !capture.datagrams.is_empty() {
        let _ = writeln!(stdout, "{}", heard.second(next_line));
    }
    heard.intake.finish();
    let words = crate::vehicle_in::capture::capture_words(&capture, port, &others);
    let _ = writeln!(
        std::io::stderr(),
        "telemetry: read from {name}: {}\ntelemetry: {}",
        words.join("; "),
        heard.summary()
    );
    Ok(())
}

/// Write the rows kept, whole or not at all.
fn write_rows(heard: &Heard, out: Option<&Destination>) -> Result<()> {
    let Some(out) = out else {
        return Ok(());
    };
    if heard.rows.is_empty() {
        bail!(
            "no vehicle motion arrived: nothing written to `{}` (a table without rows is \
             not one `stewart cue` reads)",
            out.shown().display()
        );
    }
    let mut csv = CsvText::with_header(&VEHICLE_COLUMNS);
    for row in &heard.rows {
        csv.row(row.iter().copied());
    }
    let text = csv.into_string();
    output::emit_with(Some(out), |w| w.write_all(text.as_bytes())).or_else(|e| {
        // A session is not lost with its output (a pipe's reader gone, a stop while waiting
        // for one): kept beside, written whatever stop was asked for.
        let kept =
            std::env::temp_dir().join(format!("stewart-telemetry-{}.csv", std::process::id()));
        match std::fs::write(&kept, text.as_bytes()) {
            Ok(()) => bail!(
                "{e:#}; the session's {} rows are kept in `{}`",
                heard.rows.len(),
                kept.display()
            ),
            Err(_) => Err(e),
        }
    })
}

/// What has arrived: the rows of motion, and this second's datagrams per format.
#[derive(Default)]
struct Heard {
    /// Whether the rows are kept (for `--out`; else only counted).
    keep: bool,
    intake: Intake,
    rows: Vec<[f64; 7]>,
    /// This second's datagrams per format, and its samples.
    second: BTreeMap<&'static str, usize>,
    samples: usize,
    /// The last sample decoded.
    last: Option<VehicleSample>,
}

impl Heard {
    /// Take one datagram arriving at `arrival` (seconds since listening began).
    fn take(&mut self, bytes: &[u8], arrival: f64) {
        let (format, _, placed) = self.intake.take(bytes, arrival);
        let name = format.map_or("unknown", |f| f.name());
        *self.second.entry(name).or_default() += 1;
        for timed in placed.iter() {
            let s = timed.sample;
            self.last = Some(s);
            self.samples += 1;
            let [ax, ay, az] = s.accel;
            let [wx, wy, wz] = s.rates_deg_s;
            let row = [timed.t, ax, ay, az, wx, wy, wz];
            if !self.keep {
                continue;
            }
            match (timed.step, self.rows.last_mut()) {
                (Step::Same, Some(last)) => *last = row,
                _ => self.rows.push(row),
            }
        }
    }

    /// The line for the second ending at `t`, and a fresh count for the next.
    fn second(&mut self, t: f64) -> String {
        let formats: Vec<String> = (self.second.iter())
            .map(|(name, n)| format!("{name} {n}/s"))
            .collect();
        let line = match (formats.is_empty(), self.last) {
            (true, _) => format!("{t:>5.0} s  nothing arrived"),
            (false, Some(s)) if self.samples > 0 => {
                let [ax, ay, az] = s.accel;
                let [wx, wy, wz] = s.rates_deg_s;
                format!(
                    "{t:>5.0} s  {} ({} samples)  ax {ax:.2} ay {ay:.2} az {az:.2} m/s²  \
                     wx {wx:.1} wy {wy:.1} wz {wz:.1} °/s",
                    formats.join(", "),
                    self.samples
                )
            }
            (false, _) => format!("{t:>5.0} s  {} (no motion in them)", formats.join(", ")),
        };
        self.second.clear();
        self.samples = 0;
        line
    }

    /// What arrived, all along.
    fn summary(&self) -> String {
        let tally = self.intake.tally();
        let mut parts = vec![format!(
            "{} datagrams, {} samples of motion kept",
            tally.datagrams, tally.placed
        )];
        parts.extend(tally_words(tally));
        parts.join("; ")
    }
}
