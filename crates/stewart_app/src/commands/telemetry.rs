//! `stewart telemetry`: listen where a game sends its telemetry and show, a line a second,
//! which formats arrive at what rate and the motion decoded from them (in our axes: x
//! forward, y left, z up; m/s² and °/s) — the check that a game is set up right — and,
//! with `--out`, write that motion as the CSV `stewart cue` reads. Datagrams are read as
//! the live link reads them (one `Decoder`, the live link's sample clock).

use std::collections::BTreeMap;
use std::io::Write as _;
use std::net::UdpSocket;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Context as _, Result, bail};
use stewart_link::vehicle::{Decoder, Reading, VehicleSample};

use crate::cli::TelemetryArgs;
use crate::csv_io::CsvText;
use crate::live_cue::{SampleClock, Step};
use crate::output;
use crate::vehicle_table::VEHICLE_COLUMNS;
use crate::xplane_rref::RrefSubscription;

/// How long a read waits before the loop looks at the clock and Ctrl-C again.
const POLL: Duration = Duration::from_millis(50);

/// Run the command.
pub(crate) fn run(args: &TelemetryArgs) -> Result<ExitCode> {
    let out = output::destination(args.out.as_deref(), &[])?;
    let Some(address) = args.listen.strip_prefix("udp:") else {
        bail!(
            "--listen takes udp:HOST:PORT (such as udp:0.0.0.0:20777), got `{}`",
            args.listen
        );
    };
    let socket =
        UdpSocket::bind(address).with_context(|| format!("cannot listen at `{address}`"))?;
    socket.set_read_timeout(Some(POLL))?;
    let mut xplane = (args.xplane.as_deref())
        .map(|a| RrefSubscription::new(a, args.rate))
        .transpose()?;
    let mut err = std::io::stderr();
    let _ = writeln!(
        err,
        "telemetry: listening at {} (Ctrl-C ends)",
        socket.local_addr()?
    );
    let stop = crate::interrupt::flag();
    let mut heard = Heard {
        keep: out.is_some(),
        ..Heard::default()
    };
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
            let mut stdout = std::io::stdout();
            let _ = writeln!(stdout, "{}", heard.second(next_line));
            next_line += 1.0;
        }
    }
    if let Some(x) = &xplane {
        x.end(&socket);
    }
    let _ = writeln!(err, "telemetry: {}", heard.summary());
    if let Some(out) = &out {
        let mut csv = CsvText::with_header(&VEHICLE_COLUMNS);
        for row in &heard.rows {
            csv.row(row.iter().copied());
        }
        let text = csv.into_string();
        output::emit_with(Some(out), |w| w.write_all(text.as_bytes()))?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What has arrived: the rows of motion, and this second's datagrams per format.
#[derive(Default)]
struct Heard {
    /// Whether the rows are kept (for `--out`; else only counted).
    keep: bool,
    decoder: Decoder,
    clock: SampleClock,
    rows: Vec<[f64; 7]>,
    /// This second's datagrams per format, and its samples.
    second: BTreeMap<&'static str, usize>,
    samples: usize,
    /// The last sample decoded.
    last: Option<VehicleSample>,
    /// All along: samples kept, datagrams, unreadable ones, stale samples, menus.
    kept: usize,
    datagrams: usize,
    malformed: usize,
    stale: usize,
    idle: usize,
}

impl Heard {
    /// Take one datagram arriving at `arrival` (seconds since listening began).
    fn take(&mut self, bytes: &[u8], arrival: f64) {
        self.datagrams += 1;
        let decoded = self.decoder.decode(bytes);
        let name = decoded.format.map_or("unknown", |f| f.name());
        *self.second.entry(name).or_default() += 1;
        let sample = match decoded.reading {
            Ok(Reading::Sample(s)) => s,
            Ok(Reading::Idle) => {
                self.idle += 1;
                return;
            }
            Ok(Reading::Ignored) => return,
            Err(_) => {
                self.malformed += 1;
                return;
            }
        };
        self.last = Some(sample);
        self.samples += 1;
        let time = sample.t.unwrap_or(arrival);
        let [ax, ay, az] = sample.accel;
        let [wx, wy, wz] = sample.rates_deg_s;
        let row = [time, ax, ay, az, wx, wy, wz];
        match self.clock.step(sample.t, arrival) {
            Step::First | Step::By(_) => {
                self.kept += 1;
                if self.keep {
                    self.rows.push(row);
                }
            }
            Step::Same => {
                if let Some(last) = self.rows.last_mut() {
                    *last = row;
                }
            }
            Step::Stale => self.stale += 1,
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
        format!(
            "{} datagrams, {} samples of motion kept, {} unreadable, {} older than the one \
             before, {} in the game's menus or pause",
            self.datagrams, self.kept, self.malformed, self.stale, self.idle
        )
    }
}
