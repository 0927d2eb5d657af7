//! Command-line definitions (clap).

use std::ops::RangeInclusive;
use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};
use stewart_kinematics::io::bounds;
use stewart_kinematics::model::link_settings::{LinkFormat, LinkTransport, Word};
use stewart_link::template::Template;

use crate::i18n::Lang;
use crate::shot_scale::ShotScale;

/// Stewart platform studio: inverse kinematics, trajectories and checks for the
/// six-degree-of-freedom Gough–Stewart platform.
#[derive(Debug, Parser)]
// The usage lines say `stewart` whatever the file is called (the end-to-end suites run
// the same program as `stewart-e2e`).
#[command(name = "stewart", bin_name = "stewart", version, about, long_about = None)]
pub(crate) struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub(crate) command: Option<Command>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Leg lengths for a scenario's trajectory or for a table of poses, as CSV.
    Solve(SolveArgs),
    /// The pre-flight check of a scenario's motion: stroke, leg speed and acceleration,
    /// joint cones, leg clearance, near-singular poses, architecture singularity, jumps and
    /// rigid-body consistency, each located by leg and time. Exit status 0 when nothing is
    /// found, 1 when a problem is found, 2 for unusable input.
    Check(CheckArgs),
    /// Forward kinematics: poses from a table of leg lengths, as CSV.
    Fk(FkArgs),
    /// Motion cueing: platform poses from vehicle motion (a CSV of time, specific force
    /// and rotation rates, or a packet capture of a game's telemetry) by classical washout,
    /// as a pose table for `solve --poses`, `check` and `link`; the scenario's `[cueing]`
    /// table sets the filters.
    Cue(CueArgs),
    /// Calibrate a built platform: its joint coordinates and actuator offsets from
    /// measured poses and the leg lengths (or servo angles) commanded for them, by
    /// nonlinear least squares; reports what the measurements determine and writes the
    /// calibrated scenario with its joints as coordinates.
    Calibrate(CalibrateArgs),
    /// Reachable workspace at a fixed orientation (volume, extent, points) and the
    /// orientation range at a position.
    Workspace(WorkspaceArgs),
    /// Leg forces for a payload along the trajectory (static and dynamic), as CSV.
    Forces(ForcesArgs),
    /// Stiffness, mass matrix and natural modes at a pose (the scenario's `[payload]` and
    /// `[dynamics]`): the six frequencies with each mode's motion, as text or JSON.
    Modes(ModesArgs),
    /// The stroke (or servo range) a motion envelope needs: the smallest and largest
    /// value of each leg length (servo angle) over a 6-D box of poses, where each occurs,
    /// and the worst conditioning inside the box.
    Design(DesignArgs),
    /// Render the trajectory headlessly: a PNG sequence (folder), a GIF, an MP4, or an animated glTF scene (.glb, .gltf).
    Render(RenderArgs),
    /// The leg-length plot for a paper: SVG, PDF or PNG.
    Plot(PlotArgs),
    /// The interactive viewer (what `stewart` with no argument opens).
    View(ViewArgs),
    /// Every setting `--set` accepts (the keys of scenario files and the viewer's sliders):
    /// key, current value, unit, slider range, accepted range and default.
    Settings(SettingsArgs),
    /// The scenario's geometry as a C header for controller firmware (Arduino, STM32):
    /// joints, horn and rod lengths, horn directions, servo range, reversal and trims.
    Firmware(FirmwareArgs),
    /// Stream the trajectory's set-points to a controller (serial, UDP, or a dry run),
    /// through the safety supervisor: arming ramp, range and rate limits, Ctrl-C as e-stop.
    Link(LinkArgs),
    /// A stand-in controller for tests and demos: receives frames over UDP or a serial
    /// port, checks their
    /// CRC, sequence and limits, and records them as CSV. Exit status 1 when a frame was
    /// damaged, lost or outside the limits.
    DeviceSim(DeviceSimArgs),
    /// What a game's telemetry brings, live: which format arrives at what rate, with its
    /// numbers decoded into vehicle motion — a check that the game is set up right — and,
    /// with `--out`, the motion as the CSV `stewart cue` reads.
    Telemetry(TelemetryArgs),
}

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
fn parse_model_number(text: &str, max: f64, unit: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && (0.0..=max).contains(&v) => Ok(v),
        Ok(v) => Err(format!(
            "must be a number from 0 to {} {unit}, got {v}",
            bounds::short(max)
        )),
        Err(_) => Err(format!("`{text}` is not a number")),
    }
}

/// The simulated lag's time constant: 0 to 1e6 s (the accepted range of times).
fn parse_lag(text: &str) -> Result<f64, String> {
    parse_model_number(text, bounds::TIME_S, "s")
}

/// The simulated speed limit: up to the wire's whole range (2³¹ units) in a millisecond.
fn parse_wire_speed(text: &str) -> Result<f64, String> {
    parse_model_number(text, WIRE_SPAN * 1e3, "wire units per second")
}

/// The simulated dead band: up to the wire's whole range.
fn parse_dead_band(text: &str) -> Result<f64, String> {
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
pub(crate) fn parse_wire_format(text: &str) -> Result<WireFormatArg, String> {
    // The one rule of the scenario's `link.format`: a template may end in a space.
    if let Some(template) = stewart_kinematics::model::link_settings::template_of_format(text) {
        return Template::parse(template)
            .map(WireFormatArg::Template)
            .map_err(|e| e.to_string());
    }
    match parse_word::<LinkFormat>(text)? {
        LinkFormat::Binary => Ok(WireFormatArg::Binary),
        LinkFormat::Text => Ok(WireFormatArg::Text),
        LinkFormat::Smc3 => Ok(WireFormatArg::Smc3),
        LinkFormat::Odrive => Ok(WireFormatArg::Odrive),
        LinkFormat::Template => {
            Err("a template is written out: template:<255><255>{a1:u16be}…{a6:u16be}".to_owned())
        }
    }
}

/// A choice of the `[link]` table spelled as in files.
pub(crate) fn parse_word<T: Word>(text: &str) -> Result<T, String> {
    T::from_word(text).ok_or_else(|| format!("`{text}` is not one of {}", T::choices()))
}

/// A set-point rate, 10 to 1000 Hz.
pub(crate) fn parse_link_rate(text: &str) -> Result<f64, String> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of hertz"))?;
    let (lo, hi) = stewart_kinematics::model::link_settings::RATES_HZ;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!(
            "the rate must be between {lo} and {hi} Hz, got {text}"
        ))
    }
}

/// A number of seconds for the link, 0 to 1e6.
pub(crate) fn parse_link_seconds(text: &str) -> Result<f64, String> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of seconds"))?;
    if (0.0..=bounds::TIME_S).contains(&v) {
        Ok(v)
    } else {
        Err(format!("seconds must be between 0 and 1e6, got {text}"))
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

/// Arguments of `stewart settings`.
#[derive(Debug, Args)]
pub(crate) struct SettingsArgs {
    /// The scenario whose values to show.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Instead of the table, write the scenario with every joint as coordinates
    /// (`base_joints_m`, `platform_joints_m`): the same platform, ready to edit as built.
    #[arg(long)]
    pub(crate) as_coordinates: bool,
    /// Write the scenario here (whole or not at all) instead of standard output; with
    /// `--as-coordinates`.
    #[arg(long, value_name = "FILE", requires = "as_coordinates")]
    pub(crate) out: Option<PathBuf>,
    /// The table for people, or the settings reference in Markdown (every key by file
    /// section: meaning, unit, slider and accepted ranges, default; the user guide's
    /// docs/guide/settings.md is this, for the seed).
    #[arg(
        long,
        value_enum,
        default_value = "text",
        conflicts_with = "as_coordinates"
    )]
    pub(crate) format: SettingsFormat,
}

/// Forms of `stewart settings`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum SettingsFormat {
    /// A table for the terminal, with the scenario's values.
    Text,
    /// The settings reference, in Markdown.
    Markdown,
}

/// Which scenario to use: a shipped preset or a TOML file (default: the `seed` preset),
/// with settings changed on the way.
#[derive(Debug, Args, Default)]
pub(crate) struct ScenarioArgs {
    /// A shipped preset: seed, paired, circle, figure8, helix, sway, keyframes, servo-desk,
    /// crank-rig, dietmaier.
    #[arg(long, value_name = "NAME", conflicts_with = "scenario")]
    pub(crate) preset: Option<String>,
    /// A scenario file (TOML).
    #[arg(long, value_name = "FILE")]
    pub(crate) scenario: Option<PathBuf>,
    /// Change one setting of the scenario, such as `geometry.base_radius=1.2` or
    /// `trajectory.x.amplitude_m=0.1` (`off` removes an optional limit); repeatable.
    /// `stewart settings` lists every key with its unit, range and default.
    #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
    pub(crate) set: Vec<String>,
}

/// Arguments of `stewart solve`.
#[derive(Debug, Args)]
pub(crate) struct SolveArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Solve these poses instead of the trajectory: a CSV with columns
    /// x,y,z,roll_deg,pitch_deg,yaw_deg (metres, degrees) and optionally t; `-` reads standard input.
    #[arg(long, value_name = "POSES.csv")]
    pub(crate) poses: Option<PathBuf>,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// For a rotary platform: write the angles the servos are commanded — mirrored for
    /// `servo_reversed`, plus `servo_trim_deg` — as cmd1..cmd6 instead of theta1..theta6.
    #[arg(long)]
    pub(crate) commanded: bool,
}

/// Arguments of `stewart cue`.
#[derive(Debug, Args)]
pub(crate) struct CueArgs {
    /// The scenario: a preset or a file (its `[cueing]` table, geometry and limits).
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// The vehicle motion: a CSV with columns t (s), ax, ay, az (m/s², the vehicle's
    /// acceleration in its own frame, gravity excluded) and wx, wy, wz (°/s), or a packet
    /// capture (pcap or pcapng, from Wireshark or tcpdump) of a game's UDP telemetry in any
    /// format the live link reads (Forza, F1 24 and 25, BeamNG, Live for Speed, X-Plane); `-`
    /// reads standard input.
    #[arg(long, value_name = "RECORDING")]
    pub(crate) input: PathBuf,
    /// For a capture: read the datagrams to this UDP port (default: the port whose
    /// datagrams give vehicle motion; the others are counted, never read).
    #[arg(long, allow_hyphen_values = true, value_name = "N")]
    pub(crate) port: Option<u16>,
    /// Write the pose table (t, x, y, z, roll_deg, pitch_deg, yaw_deg) here, whole or not
    /// at all, instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Run both algorithms (the classical washout with its workspace limiter on, and the
    /// model-predictive cueing) on the input with the same scales, rig and limits, and
    /// print how each reproduces what is felt instead of the poses: specific-force error
    /// (RMSE) and shape correlation per axis, rotation-rate error, the false rotation of
    /// tilt, the largest stroke used, the time the limiter held back.
    #[arg(long)]
    pub(crate) compare: bool,
    /// The comparison's format.
    #[arg(long, value_enum, default_value = "text", requires = "compare")]
    pub(crate) format: ReportFormat,
}

/// Report formats of `stewart check`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ReportFormat {
    /// Sentences for people.
    Text,
    /// One JSON object for programs.
    Json,
}

/// Arguments of `stewart check`.
#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Report format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
}

/// Arguments of `stewart design`.
#[derive(Debug, Args)]
pub(crate) struct DesignArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// The box of poses: x, y, z (m) and roll, pitch, yaw (°), each `±A` about home,
    /// `A..B`, or one value; those left out stay at home. Example:
    /// `x=±0.1,y=±0.1,z=0.7..0.9,roll=±10,pitch=±10,yaw=±15`.
    #[arg(long, value_name = "NAME=RANGE,…", allow_hyphen_values = true)]
    pub(crate) envelope: String,
    /// Report format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
}

/// Arguments of `stewart fk`.
#[derive(Debug, Args)]
pub(crate) struct FkArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Leg lengths: a CSV with columns L1..L6 (metres) — or theta1..theta6 (degrees) for a
    /// rotary-servo platform — and optionally t; other columns are ignored; `-` reads
    /// standard input.
    #[arg(long, value_name = "LEGS.csv")]
    pub(crate) legs: PathBuf,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Start every row from the home pose instead of the previous row's pose.
    #[arg(long)]
    pub(crate) cold: bool,
    /// List every assembly mode the search finds for each row (a `row` column names the
    /// input row, from 1, and a `mode` column numbers its modes, highest platform first)
    /// instead of following one branch.
    #[arg(long, conflicts_with = "cold")]
    pub(crate) assembly_modes: bool,
}

/// Arguments of `stewart calibrate`.
#[derive(Debug, Args)]
pub(crate) struct CalibrateArgs {
    /// The platform as designed: a preset or a file (the starting values).
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Measured poses and what was commanded for each: a CSV with columns x, y, z
    /// (metres), roll_deg, pitch_deg, yaw_deg (the scenario's base and platform frames),
    /// and L1..L6 (metres) — or theta1..theta6 (model servo angles in degrees, as
    /// `stewart solve` gives them) for a rotary-servo platform; other columns are
    /// ignored; `-` reads standard input.
    #[arg(long, value_name = "MEASUREMENTS.csv")]
    pub(crate) measurements: PathBuf,
    /// Write the calibrated scenario here (whole or not at all): joints as coordinates,
    /// servo offsets in the trims, leg-length offsets in the link's channel offsets.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Keep a group of parameters at the scenario's values (known from elsewhere);
    /// repeat for several.
    #[arg(long, value_enum, value_name = "GROUP")]
    pub(crate) hold: Vec<HoldGroup>,
}

/// A group of calibration parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum HoldGroup {
    /// The six base joints.
    Base,
    /// The six platform joints.
    Platform,
    /// The six actuator offsets.
    Offsets,
}

/// Three comma-separated finite numbers, such as `0,0,0.8`.
pub(crate) fn parse_triple(text: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let [a, b, c] = parts.as_slice() else {
        return Err(format!("`{text}` is not three comma-separated numbers"));
    };
    let number = |s: &str| -> Result<f64, String> {
        let v: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("{s} is not a finite number"))
        }
    };
    Ok([number(a)?, number(b)?, number(c)?])
}

/// Three numbers, each checked against its accepted range (see `stewart_kinematics::io::bounds`).
fn parse_bounded(
    text: &str,
    ranges: [(&str, RangeInclusive<f64>, &str); 3],
) -> Result<[f64; 3], String> {
    let v = parse_triple(text)?;
    for (x, (name, range, unit)) in v.iter().zip(&ranges) {
        bounds::check(*x, range, unit).map_err(|e| format!("{name} {e}"))?;
    }
    Ok(v)
}

/// ROLL,PITCH,YAW in degrees, each within ±3600°.
pub(crate) fn parse_angles(text: &str) -> Result<[f64; 3], String> {
    let a = || bounds::symmetric(bounds::ANGLE_DEG);
    parse_bounded(
        text,
        [("roll", a(), "°"), ("pitch", a(), "°"), ("yaw", a(), "°")],
    )
}

/// X,Y,Z in metres, each within ±1000 m.
pub(crate) fn parse_position(text: &str) -> Result<[f64; 3], String> {
    let m = || bounds::symmetric(bounds::LENGTH_M);
    parse_bounded(text, [("x", m(), "m"), ("y", m(), "m"), ("z", m(), "m")])
}

/// The inertia tensor's entries in kg·m², IXX,IYY,IZZ,IXY,IXZ,IYZ: three principal
/// moments (each from 0 to 1e6; the products then zero), or all six (products within
/// ±1e6).
pub(crate) fn parse_inertia(text: &str) -> Result<[f64; 6], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 3 && parts.len() != 6 {
        return Err(format!(
            "`{text}` is not three moments IXX,IYY,IZZ or six entries IXX,IYY,IZZ,IXY,IXZ,IYZ"
        ));
    }
    const NAMES: [&str; 6] = ["Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"];
    let mut values = [0.0; 6];
    for (k, s) in parts.iter().enumerate() {
        let v: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
        let range = if k < 3 {
            0.0..=bounds::INERTIA_KG_M2
        } else {
            bounds::symmetric(bounds::INERTIA_KG_M2)
        };
        bounds::check(v, &range, "kg·m²").map_err(|e| format!("{} {e}", NAMES[k]))?;
        values[k] = v;
    }
    Ok(values)
}

/// AZ,EL,DIST: degrees within ±3600°, and a distance above 0 up to 1e4 m.
pub(crate) fn parse_camera(text: &str) -> Result<[f64; 3], String> {
    let a = || bounds::symmetric(bounds::ANGLE_DEG);
    let v = parse_bounded(
        text,
        [
            ("azimuth", a(), "°"),
            ("elevation", a(), "°"),
            ("distance", 0.0..=bounds::CAMERA_DISTANCE_M, "m"),
        ],
    )?;
    if v[2] <= 0.0 {
        return Err(format!("distance must be more than 0 m, got {}", v[2]));
    }
    Ok(v)
}

/// A mass in kilograms: more than 0, at most 1e6.
pub(crate) fn parse_mass(text: &str) -> Result<f64, String> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of kilograms"))?;
    if v.is_finite() && v > 0.0 && v <= bounds::MASS_KG {
        Ok(v)
    } else {
        Err(format!(
            "the mass must be more than 0 and at most 1e6 kg, got {text}"
        ))
    }
}

/// A frame rate: from 0.01 to 1000 frames per second.
pub(crate) fn parse_fps(text: &str) -> Result<f64, String> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of frames per second"))?;
    crate::export::video::check_rate(v)
        .map(|()| v)
        .map_err(|_| {
            format!("the frame rate must be from 0.01 to 1000 frames per second, got {text}")
        })
}

/// Arguments of `stewart workspace`.
#[derive(Debug, Args)]
pub(crate) struct WorkspaceArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Platform orientation ROLL,PITCH,YAW in degrees.
    #[arg(long, value_name = "ROLL,PITCH,YAW", value_parser = parse_angles, default_value = "0,0,0", allow_hyphen_values = true)]
    pub(crate) orientation: [f64; 3],
    /// Columns per side of the grid (the volume's error shrinks as it rises).
    #[arg(long, default_value_t = 400, value_parser = clap::value_parser!(u16).range(2..=4096), allow_hyphen_values = true)]
    pub(crate) resolution: u16,
    /// Position X,Y,Z (metres) at which to report the orientation range (default: home).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_position, allow_hyphen_values = true)]
    pub(crate) position: Option<[f64; 3]>,
    /// Run even when the estimated cost is over the budget (2 minutes, 2 GB of spans);
    /// a long run shows progress and Ctrl-C stops it.
    #[arg(long)]
    pub(crate) no_budget: bool,
    /// Write the workspace boundary points: `.csv` (x,y,z) or `.ply` (for 3D tools).
    #[arg(long, value_name = "FILE.csv|FILE.ply")]
    pub(crate) out: Option<PathBuf>,
    /// Draw a horizontal slice (at the position's height) and a vertical slice (through
    /// its y) coloured by the condition number: `.svg`, `.pdf` or `.png`.
    #[arg(long, value_name = "FILE.svg|FILE.pdf|FILE.png")]
    pub(crate) plot: Option<PathBuf>,
    /// Write the workspace's surface (a closed triangle mesh around the reachable
    /// positions, from the same columns) as a binary PLY file.
    #[arg(long, value_name = "FILE.ply")]
    pub(crate) surface: Option<PathBuf>,
    /// The language of the figure's words: `zh` or `en` (default: the environment's).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
}

/// Arguments of `stewart modes`.
#[derive(Debug, Args)]
pub(crate) struct ModesArgs {
    /// The scenario: a preset or a file, with `[payload]` and `[dynamics]
    /// actuator_stiffness`.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// The pose X,Y,Z,ROLL,PITCH,YAW (metres, degrees); default: home.
    #[arg(long, value_name = "X,Y,Z,ROLL,PITCH,YAW", value_parser = parse_pose, allow_hyphen_values = true)]
    pub(crate) pose: Option<[f64; 6]>,
    /// Also find the lowest natural frequency over the trajectory and where it occurs.
    #[arg(long)]
    pub(crate) along_trajectory: bool,
    /// Report format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
}

/// X,Y,Z,ROLL,PITCH,YAW: metres within ±1000 m, degrees within ±3600°.
pub(crate) fn parse_pose(text: &str) -> Result<[f64; 6], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 6 {
        return Err(format!(
            "`{text}` is not six comma-separated numbers (x, y, z in metres, roll, pitch, yaw in degrees)"
        ));
    }
    let position = parse_position(&parts[..3].join(","))?;
    let angles = parse_angles(&parts[3..].join(","))?;
    Ok([
        position[0],
        position[1],
        position[2],
        angles[0],
        angles[1],
        angles[2],
    ])
}

/// Arguments of `stewart forces`.
#[derive(Debug, Args)]
pub(crate) struct ForcesArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Moving mass in kg (overrides the scenario's `[payload]`).
    #[arg(long, value_name = "KG", allow_hyphen_values = true, value_parser = parse_mass)]
    pub(crate) mass: Option<f64>,
    /// Centre of mass X,Y,Z in the platform frame, metres.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_position, allow_hyphen_values = true)]
    pub(crate) com: Option<[f64; 3]>,
    /// Inertia about the centre of mass, kg·m²: principal moments IXX,IYY,IZZ, or the
    /// tensor's six entries IXX,IYY,IZZ,IXY,IXZ,IYZ (products with their minus sign).
    #[arg(long, value_name = "IXX,IYY,IZZ[,IXY,IXZ,IYZ]", value_parser = parse_inertia, allow_hyphen_values = true)]
    pub(crate) inertia: Option<[f64; 6]>,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
}

/// The smallest frame or window side, pixels.
pub(crate) const MIN_SIDE: u32 = 16;

/// The longest title a readout takes, characters.
pub(crate) const MAX_TITLE_CHARS: usize = 200;

/// A title for the readout: one line of at most [`MAX_TITLE_CHARS`] characters.
pub(crate) fn parse_title(text: &str) -> Result<String, String> {
    let n = text.chars().count();
    if n > MAX_TITLE_CHARS {
        return Err(format!(
            "the title has {n} characters; at most {MAX_TITLE_CHARS} fit a line"
        ));
    }
    if let Some(c) = text.chars().find(|c| c.is_control()) {
        return Err(format!(
            "the title must be one line of text, without control characters (found U+{:04X})",
            u32::from(c)
        ));
    }
    Ok(text.to_owned())
}

/// A language code: `zh` or `en` (`zh-CN`, `zh_CN` and any case accepted).
pub(crate) fn parse_lang(text: &str) -> Result<Lang, String> {
    let code = text.trim().to_ascii_lowercase();
    match code.split(['-', '_', '.']).next() {
        Some("zh") => Ok(Lang::Zh),
        Some("en") => Ok(Lang::En),
        _ => Err(format!(
            "`{text}` is not a language this program speaks: zh (Simplified Chinese) or en (English)"
        )),
    }
}

/// `WxH`, such as `1280x720`.
pub(crate) fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| format!("`{text}` is not a size like 1280x720"))?;
    let side = |s: &str| -> Result<u32, String> {
        let v: u32 = s
            .trim()
            .parse()
            .map_err(|_| format!("`{s}` is not a whole number of pixels"))?;
        let max = stewart_render::offscreen::MAX_SIDE;
        if (MIN_SIDE..=max).contains(&v) {
            Ok(v)
        } else {
            Err(format!("{v} pixels is outside {MIN_SIDE}..={max}"))
        }
    };
    Ok((side(w)?, side(h)?))
}

/// A playback speed against real time, within [`crate::export::video::SPEEDS`].
pub(crate) fn parse_speed(text: &str) -> Result<f64, String> {
    let speeds = crate::export::video::SPEEDS;
    match text.trim().parse::<f64>() {
        Ok(x) if speeds.contains(&x) => Ok(x),
        _ => Err(format!(
            "`{text}` is not a playback speed from {} to {} (times real time)",
            speeds.start(),
            speeds.end()
        )),
    }
}

/// `A..B`, `A..` or `..B`: frame indices from A (default 0) up to, not including, B.
pub(crate) fn parse_frames(text: &str) -> Result<(Option<usize>, Option<usize>), String> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| format!("`{text}` is not a range like 0..100"))?;
    let index = |s: &str| -> Result<Option<usize>, String> {
        if s.trim().is_empty() {
            Ok(None)
        } else {
            s.trim()
                .parse()
                .map(Some)
                .map_err(|_| format!("`{s}` is not a frame number"))
        }
    };
    Ok((index(a)?, index(b)?))
}

/// Arguments of `stewart render`.
#[derive(Debug, Args)]
pub(crate) struct RenderArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// A folder (numbered PNG files), a `.gif` or an `.mp4`; or a `.glb` (or `.gltf`, its
    /// buffer in a `.bin` beside it): the whole trajectory as an animated glTF 2.0 scene
    /// for slides, Blender and web pages (only `--theme` and `--single-colour` apply).
    #[arg(long, value_name = "OUT")]
    pub(crate) out: PathBuf,
    /// Frame size WxH in pixels (up to 3840x2160 and beyond, 4096 a side at most).
    #[arg(long, allow_hyphen_values = true, value_name = "WxH", value_parser = parse_size, default_value = "1280x720")]
    pub(crate) size: (u32, u32),
    /// Frames per second of the output, the motion resampled (default: 25 for a GIF, 50
    /// for an MP4, one frame per trajectory sample for a folder of frames). A GIF's
    /// frame lasts whole hundredths of a second, at least 2: other rates are rounded
    /// to the nearest such one, with a note.
    #[arg(long, value_name = "N", value_parser = parse_fps, allow_hyphen_values = true)]
    pub(crate) fps: Option<f64>,
    /// Only frames A..B (indices, B excluded).
    #[arg(long, value_name = "A..B", value_parser = parse_frames, allow_hyphen_values = true)]
    pub(crate) frames: Option<(Option<usize>, Option<usize>)>,
    /// How fast the motion plays against real time: 0.25 is slow motion (each second of
    /// motion lasts four seconds of video), 2 twice as fast (0.01 to 100; default 1).
    #[arg(long, value_name = "X", value_parser = parse_speed, allow_hyphen_values = true, default_value = "1")]
    pub(crate) speed: f64,
    /// Colours: `dark` for the screen, `light` for slides and papers.
    #[arg(long, value_enum, default_value_t = ThemeName::Dark)]
    pub(crate) theme: ThemeName,
    /// Camera AZ,EL,DIST (degrees, degrees, metres); default: the seed's view framing the platform.
    #[arg(long, value_name = "AZ,EL,DIST", value_parser = parse_camera, allow_hyphen_values = true)]
    pub(crate) camera: Option<[f64; 3]>,
    /// Put the leg-length plot beside the 3D view, with a marker at the frame's time.
    #[arg(long)]
    pub(crate) composite: bool,
    /// Draw the platform's own axes at its centre.
    #[arg(long)]
    pub(crate) platform_axes: bool,
    /// Draw every leg in one colour (by default each leg takes the colour of its curve
    /// in the plot).
    #[arg(long)]
    pub(crate) single_colour: bool,
    /// Leave out the numbered labels (L1…L6, S1…S6) beside the legs.
    #[arg(long)]
    pub(crate) no_labels: bool,
    /// Burn a readout into the frames: a title, the time, the pose and the six leg
    /// lengths or servo angles, top left.
    #[arg(long)]
    pub(crate) overlay: bool,
    /// The readout's title line (default: the scenario's name); implies --overlay.
    #[arg(long, value_name = "TEXT", value_parser = parse_title)]
    pub(crate) title: Option<String>,
    /// The language of the words drawn: `zh` (Simplified Chinese) or `en` (default: the
    /// environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
}

/// The colour themes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ThemeName {
    /// Dark background.
    Dark,
    /// White background (presentation).
    Light,
}

/// Arguments of `stewart plot`.
#[derive(Debug, Args)]
pub(crate) struct PlotArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// `.svg`, `.pdf` or `.png`.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: PathBuf,
    /// The language of the words drawn: `zh` (Simplified Chinese) or `en` (default: the
    /// environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
    /// Plot the actuator forces (servo torques) the scenario's `[payload]` needs along the
    /// motion — weight, inertia, and the legs' parts and friction of `[dynamics]` —
    /// instead of the lengths (angles).
    #[arg(long)]
    pub(crate) forces: bool,
}

/// Arguments of `stewart view`.
#[derive(Debug, Args)]
pub(crate) struct ViewArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Start in the light theme.
    #[arg(long)]
    pub(crate) light: bool,
    /// Start in presentation mode (light colours, large text, control panels hidden).
    #[arg(long)]
    pub(crate) presentation: bool,
    /// Start with every collapsible section of the panels open.
    #[arg(long)]
    pub(crate) expand_panels: bool,
    /// Show the reachable workspace (surface and conditioning slice) from the start.
    #[arg(long)]
    pub(crate) workspace: bool,
    /// Window size WxH in logical pixels (default: the last session's within the screen,
    /// else 85 % of the screen).
    #[arg(long, allow_hyphen_values = true, value_name = "WxH", value_parser = parse_size)]
    pub(crate) size: Option<(u32, u32)>,
    /// Start without the saved session (the last scenario, camera, panels, theme and
    /// window size); it is still saved at exit.
    #[arg(long)]
    pub(crate) fresh: bool,
    /// The interface's language: `zh` (Simplified Chinese) or `en` (default: the last
    /// session's, else the environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
    /// Save the window's image here after `--frames` frames, then exit.
    #[arg(long, value_name = "FILE.png")]
    pub(crate) screenshot: Option<PathBuf>,
    /// Frames to draw before the screenshot.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_hyphen_values = true)]
    pub(crate) frames: u32,
    /// The screenshot's size: `1` as on screen, `2` twice that (text drawn anew, not
    /// upscaled), `4k` 3840 pixels wide.
    #[arg(long, value_name = "1|2|4k", default_value = "1", value_parser = crate::shot_scale::parse, requires = "screenshot")]
    pub(crate) screenshot_scale: ShotScale,
    /// With --screenshot: start from the saved session (a screenshot run otherwise neither
    /// reads nor writes it, so that it does not depend on leftover state).
    #[arg(long, requires = "screenshot", conflicts_with = "fresh")]
    pub(crate) from_session: bool,
    /// Print frame-time statistics (CPU part and total) when the window closes.
    #[arg(long)]
    pub(crate) frame_stats: bool,
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory as _;

    /// The value names of options that take numbers.
    const NUMERIC: [&str; 14] = [
        "S",
        "N",
        "HZ",
        "KG",
        "BITS/S",
        "A..B",
        "AZ,EL,DIST",
        "IXX,IYY,IZZ[,IXY,IXZ,IYZ]",
        "ROLL,PITCH,YAW",
        "X,Y,Z",
        "X,Y,Z,ROLL,PITCH,YAW",
        "WxH",
        "NAME=RANGE,…",
        "KEY=VALUE",
    ];

    #[test]
    fn every_numeric_option_hands_a_negative_number_to_its_own_check() {
        // `--duration -1` must reach the option's check, which names the option and the
        // range, not be taken for an unknown option `-1`.
        let cli = super::Cli::command();
        let mut checked = 0;
        for sub in cli.get_subcommands() {
            for arg in sub.get_arguments() {
                let numeric = arg
                    .get_value_names()
                    .is_some_and(|names| names.iter().any(|n| NUMERIC.contains(&n.as_str())));
                if numeric {
                    checked += 1;
                    assert!(
                        arg.is_allow_hyphen_values_set(),
                        "stewart {} --{}",
                        sub.get_name(),
                        arg.get_id()
                    );
                }
            }
        }
        assert!(checked > 20, "{checked}");
    }
}
