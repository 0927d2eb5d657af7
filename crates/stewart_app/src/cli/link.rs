//! The link's commands' arguments (`link`, `telemetry`, `device-sim`, `firmware`) and the
//! values they take: wire formats and units, rates, seconds, the simulated device's model.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use stewart_kinematics::ground::bounds;
use stewart_kinematics::model::link_settings::{LinkFormat, LinkTransport, Word};
use stewart_link::template::Template;

use super::{ArgError, ScenarioArgs};

/// Arguments of `stewart telemetry`.
#[derive(Debug, Args)]
pub(crate) struct TelemetryArgs {
    /// Listen here, `udp:HOST:PORT` (the port the game sends to: Forza's choice, F1 20777,
    /// BeamNG 4444, Live for Speed's OutSim port, X-Plane's reply port; port 0: any free
    /// port, printed on standard error).
    #[arg(
        long,
        value_name = "udp:HOST:PORT",
        required_unless_present = "input",
        conflicts_with = "input"
    )]
    pub(crate) listen: Option<String>,
    /// Read a packet capture (pcap or pcapng, from Wireshark or tcpdump) instead of
    /// listening: the same decoder, the same summary, a line per second of its time.
    #[arg(long, value_name = "CAPTURE", conflicts_with_all = ["duration", "xplane"])]
    pub(crate) input: Option<PathBuf>,
    /// With `--input`: read the datagrams to this UDP port (default: the port whose
    /// datagrams give vehicle motion; the others are counted, never read).
    #[arg(long, allow_hyphen_values = true, value_name = "N", requires = "input")]
    pub(crate) port: Option<u16>,
    /// Write the decoded vehicle motion (t, ax, ay, az, wx, wy, wz) here when listening
    /// ends, whole or not at all.
    #[arg(long, value_name = "VEHICLE.csv")]
    pub(crate) out: Option<PathBuf>,
    /// Stop after this many seconds (else at Ctrl-C).
    #[arg(long, allow_hyphen_values = true, value_name = "S", value_parser = parse_link_seconds)]
    pub(crate) duration: Option<f64>,
    /// Ask X-Plane at this address (its port is 49000) for the datarefs of motion by
    /// `RREF`, at `--rate` a second, again every few seconds (X-Plane forgets them when
    /// it restarts), and stop them at the end.
    #[arg(long, value_name = "HOST:PORT")]
    pub(crate) xplane: Option<String>,
    /// The rate asked of X-Plane, a second.
    #[arg(long, allow_hyphen_values = true, value_name = "HZ", default_value = "60", value_parser = parse_link_rate)]
    pub(crate) rate: f64,
}

/// Arguments of `stewart device-sim`.
#[derive(Debug, Args)]
pub(crate) struct DeviceSimArgs {
    /// Listen here, HOST:PORT (port 0: any free port, printed on standard error).
    #[arg(long, value_name = "HOST:PORT", conflicts_with = "serial")]
    pub(crate) udp: Option<String>,
    /// Read this serial port instead (a pseudo-terminal stands in for a cable in tests).
    #[arg(long, value_name = "PORT")]
    pub(crate) serial: Option<String>,
    /// The serial line speed, bits per second.
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "BITS/S",
        default_value = "115200"
    )]
    pub(crate) baud: u32,
    /// Write the record here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// End after this many seconds without a datagram (once the first has come).
    #[arg(long, allow_hyphen_values = true, value_name = "S", default_value = "2", value_parser = parse_link_seconds)]
    pub(crate) idle: f64,
    /// End after this many seconds in any case.
    #[arg(long, allow_hyphen_values = true, value_name = "S", default_value = "600", value_parser = parse_link_seconds)]
    pub(crate) duration: f64,
    /// Smallest value accepted on any channel, in the wire's unit (µm, 0.01° or µs).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub(crate) min: Option<i32>,
    /// Largest value accepted on any channel, in the wire's unit.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub(crate) max: Option<i32>,
    /// Answer each set-point with a telemetry frame (kind 02): its sequence number, the
    /// flags received, and where the simulated actuators are (the values received when no
    /// model option is given), as a controller reporting what it measured would.
    #[arg(long)]
    pub(crate) telemetry: bool,
    /// The simulated actuators' first-order lag: time constant, seconds (0: none).
    #[arg(long, allow_hyphen_values = true, value_name = "S", default_value = "0", value_parser = parse_lag)]
    pub(crate) lag_s: f64,
    /// The simulated actuators' speed limit, wire units per second (µm/s, 0.01°/s, µs/s).
    #[arg(long, allow_hyphen_values = true, value_name = "N", value_parser = parse_wire_speed)]
    pub(crate) speed_max: Option<f64>,
    /// The simulated actuators do not move while the set-point is this close, wire units.
    #[arg(long, allow_hyphen_values = true, value_name = "N", default_value = "0", value_parser = parse_dead_band)]
    pub(crate) dead_band: f64,
    /// The wire format to expect: binary frames, the text lines of `link --format text`,
    /// an output template's bytes (`template:<255><255>{a1:u16be}…`, as `link` was given
    /// it; recorded with unit 3: the template's numbers, 0 to the type's largest), or one
    /// board of `smc3` (unit 4: its numbers, 0–1023) or `odrive` (unit 5: millionths of a
    /// turn) — which one, `--board`.
    #[arg(long, value_parser = parse_wire_format, default_value = "binary", value_name = "FORMAT")]
    pub(crate) format: WireFormatArg,
    /// With `--format smc3` or `odrive`: which board this is (1 to 3; SMC3's second board
    /// carries actuators 4–6, ODrive's second 3–4 and third 5–6).
    #[arg(long, value_parser = clap::value_parser!(u8).range(1..=3), default_value = "1")]
    pub(crate) board: u8,
    /// The unit this controller's text lines are in (the text form does not say).
    #[arg(long, value_enum, default_value_t = WireUnit::Micrometre)]
    pub(crate) text_unit: WireUnit,
}

/// The unit of a frame's values, as `device-sim --text-unit` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum WireUnit {
    /// Leg lengths, micrometres.
    Micrometre,
    /// Servo angles, hundredths of a degree.
    Centidegree,
    /// Servo pulse widths, microseconds.
    Microsecond,
}

/// A model option: a finite number, not negative.
fn parse_model_number(text: &str, max: f64, unit: &str) -> Result<f64, ArgError> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && (0.0..=max).contains(&v) => Ok(v),
        Ok(v) => Err(ArgError::out_of_range(
            None,
            format!("a number from 0 to {} {unit}", bounds::short(max)),
            v,
        )),
        Err(_) => Err(ArgError::not_a(text, "a number")),
    }
}

/// The simulated lag's time constant: 0 to 1e6 s (the accepted range of times).
fn parse_lag(text: &str) -> Result<f64, ArgError> {
    parse_model_number(text, bounds::TIME_S, "s")
}

/// The simulated speed limit: up to the wire's whole range (2³¹ units) in a millisecond.
fn parse_wire_speed(text: &str) -> Result<f64, ArgError> {
    parse_model_number(text, WIRE_SPAN * 1e3, "wire units per second")
}

/// The simulated dead band: up to the wire's whole range.
fn parse_dead_band(text: &str) -> Result<f64, ArgError> {
    parse_model_number(text, WIRE_SPAN, "wire units")
}

/// The span of a wire value (a 32-bit signed number), in its units.
const WIRE_SPAN: f64 = 2_147_483_648.0;

/// Arguments of `stewart link`. Each option overrides the scenario's `[link]` table.
#[derive(Debug, Args)]
pub(crate) struct LinkArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// List the serial ports the system offers and exit.
    #[arg(long)]
    pub(crate) list_ports: bool,
    /// Measure the sender's timing: stream to a receiver on UDP loopback at 500 Hz and
    /// 1 kHz (or --rate) for --duration seconds each (default 10) and print the period
    /// error and wake-up lateness (mean, p99, max).
    #[arg(long, conflicts_with_all = ["list_ports", "dry_run", "transport", "out", "record"])]
    pub(crate) bench: bool,
    /// Where to send: serial, udp, or file (a dry run).
    #[arg(long, value_parser = parse_word::<LinkTransport>)]
    pub(crate) transport: Option<LinkTransport>,
    /// The serial port (`/dev/ttyUSB0`, `COM3`; see --list-ports).
    #[arg(long, value_name = "PORT")]
    pub(crate) port: Option<String>,
    /// The serial line speed, bits per second (default 115200).
    #[arg(long, allow_hyphen_values = true, value_name = "BITS/S")]
    pub(crate) baud: Option<u32>,
    /// The UDP peer, HOST:PORT.
    #[arg(long, value_name = "HOST:PORT")]
    pub(crate) address: Option<String>,
    /// The second board's serial port (`--format smc3`: actuators 4–6; `odrive`: 3–4).
    #[arg(long, value_name = "PORT")]
    pub(crate) port2: Option<String>,
    /// The third board's serial port (`--format odrive`: actuators 5–6).
    #[arg(long, value_name = "PORT")]
    pub(crate) port3: Option<String>,
    /// The second board's UDP peer, HOST:PORT (board protocols over UDP).
    #[arg(long, value_name = "HOST:PORT")]
    pub(crate) address2: Option<String>,
    /// The third board's UDP peer, HOST:PORT.
    #[arg(long, value_name = "HOST:PORT")]
    pub(crate) address3: Option<String>,
    /// Record the dry run here instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Set-points per second, 10 to 1000 (default 100).
    #[arg(long, allow_hyphen_values = true, value_name = "HZ", value_parser = parse_link_rate)]
    pub(crate) rate: Option<f64>,
    /// Seconds to stream (default: the trajectory's duration; with --loop, until Ctrl-C).
    #[arg(long, allow_hyphen_values = true, value_name = "S", value_parser = parse_link_seconds)]
    pub(crate) duration: Option<f64>,
    /// Play the trajectory again and again.
    #[arg(long = "loop")]
    pub(crate) repeat: bool,
    /// Send nothing anywhere: record what would be sent (the same as `--transport file`).
    #[arg(long)]
    pub(crate) dry_run: bool,
    /// A dry run on the stream's own clock: every tick in turn, written at once instead of
    /// in real time (the same bytes a live stream sends on an idle machine, none skipped
    /// however loaded this one is).
    #[arg(long, conflicts_with_all = ["cue", "bench", "list_ports", "record"])]
    pub(crate) instant: bool,
    /// binary (34-byte frames with a CRC, docs/PROTOCOL.md), text (`S,seq,v1,…,v6`
    /// lines), smc3 (two SMC3 boards: `[A hi lo]` frames, 0–1023, on --port and --port2),
    /// odrive (three two-axis ODrives: `p axis turns turns/s 0` lines, on --port, --port2,
    /// --port3; `link.turns_per_unit`, `link.turns_offset`), or an output template for a
    /// hobby board, as FlyPT Mover and SimTools write them: `template:<255><255>{a1:u16be}{a2:u16be}{a3:u16be}{a4:u16be}{a5:u16be}{a6:u16be}<10><13>`
    /// (`<N>` a byte; `{aK:T}` actuator K scaled from its range to T = u8, u10be, u12be,
    /// u16be, u16le, u24be, u32be, dec or dec3; other printable characters as they are).
    #[arg(long, value_parser = parse_wire_format, value_name = "FORMAT")]
    pub(crate) format: Option<WireFormatArg>,
    /// Seconds of the arming ramp from home to the trajectory (default 2).
    #[arg(long, allow_hyphen_values = true, value_name = "S", value_parser = parse_link_seconds)]
    pub(crate) ramp: Option<f64>,
    /// Record each set-point the controller answered with telemetry here (CSV: time,
    /// sequence, six commanded and six measured values, round-trip latency).
    #[arg(long, value_name = "FILE.csv")]
    pub(crate) record: Option<PathBuf>,
    /// Follow live vehicle motion instead of the trajectory: UDP datagrams at this address
    /// (`udp:HOST:PORT`; a game's telemetry — Forza Data Out, F1 24 and 25, BeamNG MotionSim,
    /// Live for Speed OutSim, X-Plane DATA or RREF — or the generic text
    /// `t,ax,ay,az,wx,wy,wz` or seven little-endian f32) through the scenario's `[cueing]`
    /// washout, until Ctrl-C or `--duration`.
    #[arg(long, value_name = "udp:HOST:PORT", conflicts_with_all = ["repeat", "bench", "list_ports"])]
    pub(crate) cue: Option<String>,
    /// With `--cue`: ask X-Plane at this address (its port is 49000) for the datarefs of
    /// motion by `RREF`, at the link's rate, renewed every few seconds and stopped at the
    /// end.
    #[arg(long, value_name = "HOST:PORT", requires = "cue")]
    pub(crate) xplane: Option<String>,
}

/// A wire format named on the command line.
#[derive(Clone, Debug)]
pub(crate) enum WireFormatArg {
    /// The 34-byte frames.
    Binary,
    /// `S,seq,…` lines.
    Text,
    /// An output template's bytes.
    Template(Template),
    /// SMC3 boards' frames.
    Smc3,
    /// ODrive boards' lines.
    Odrive,
}

impl WireFormatArg {
    /// The value of `link.format` that says it (`template:…` sets the template too).
    pub(crate) fn setting(&self) -> String {
        match self {
            WireFormatArg::Binary => LinkFormat::Binary.word().to_owned(),
            WireFormatArg::Text => LinkFormat::Text.word().to_owned(),
            WireFormatArg::Template(t) => format!("template:{}", t.text()),
            WireFormatArg::Smc3 => LinkFormat::Smc3.word().to_owned(),
            WireFormatArg::Odrive => LinkFormat::Odrive.word().to_owned(),
        }
    }
}

/// `binary`, `text`, or `template:…` (the template checked, its column named when refused).
pub(crate) fn parse_wire_format(text: &str) -> Result<WireFormatArg, ArgError> {
    // The one rule of the scenario's `link.format`: a template may end in a space.
    if let Some(template) = stewart_kinematics::model::link_settings::template_of_format(text) {
        return Template::parse(template)
            .map(WireFormatArg::Template)
            .map_err(ArgError::Template);
    }
    match parse_word::<LinkFormat>(text)? {
        LinkFormat::Binary => Ok(WireFormatArg::Binary),
        LinkFormat::Text => Ok(WireFormatArg::Text),
        LinkFormat::Smc3 => Ok(WireFormatArg::Smc3),
        LinkFormat::Odrive => Ok(WireFormatArg::Odrive),
        LinkFormat::Template => Err(ArgError::TemplateNotWritten),
    }
}

/// A choice of the `[link]` table spelled as in files.
pub(crate) fn parse_word<T: Word>(text: &str) -> Result<T, ArgError> {
    T::from_word(text).ok_or_else(|| ArgError::not_a(text, format!("one of {}", T::choices())))
}

/// A set-point rate, 10 to 1000 Hz.
pub(crate) fn parse_link_rate(text: &str) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number of hertz"))?;
    let (lo, hi) = stewart_kinematics::model::link_settings::RATES_HZ;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(ArgError::out_of_range(
            Some("the rate"),
            format!("between {lo} and {hi} Hz"),
            text,
        ))
    }
}

/// A number of seconds for the link, 0 to 1e6.
pub(crate) fn parse_link_seconds(text: &str) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number of seconds"))?;
    if (0.0..=bounds::TIME_S).contains(&v) {
        Ok(v)
    } else {
        Err(ArgError::out_of_range(
            Some("seconds"),
            "between 0 and 1e6",
            text,
        ))
    }
}

/// Arguments of `stewart firmware`.
#[derive(Debug, Args)]
pub(crate) struct FirmwareArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Write the header here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
}
