//! The analysis commands' arguments: `solve`, `fk`, `cue`, `check`, `design`, `calibrate`,
//! `workspace`, `modes`, `forces`, `settings`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::pictures::parse_lang;
use super::values::{
    parse_amplitude_scale, parse_angles, parse_frequency, parse_inertia, parse_latency_ms,
    parse_mass, parse_pose, parse_position, parse_width,
};
use super::{ReportFormat, ScenarioArgs};
use crate::i18n::Lang;

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
    #[arg(long, value_name = "RECORDING", required_unless_present = "omct")]
    pub(crate) input: Option<PathBuf>,
    /// For a capture: read the datagrams to this UDP port (default: the port whose
    /// datagrams give vehicle motion; the others are counted, never read).
    #[arg(long, allow_hyphen_values = true, value_name = "N")]
    pub(crate) port: Option<u16>,
    /// Write the pose table (t, x, y, z, roll_deg, pitch_deg, yaw_deg) here — with
    /// `--compare` or `--omct`, the report — whole or not at all, instead of standard
    /// output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// Run both algorithms (the classical washout with its workspace limiter on, and the
    /// model-predictive cueing) on the input with the same scales, rig and limits, and
    /// print how each reproduces what is felt instead of the poses: specific-force error
    /// (RMSE) and shape correlation per axis, rotation-rate error, the false rotation of
    /// tilt, the largest stroke used, the time the limiter held back.
    #[arg(long)]
    pub(crate) compare: bool,
    /// The Objective Motion Cueing Test instead of a recording: the cueing driven by sines
    /// of vehicle motion at twelve frequencies from 0.1 to 15.85 rad/s, and the gain and
    /// phase of what is felt against what the vehicle did, in ten tests (surge, sway,
    /// heave, roll, pitch, yaw; surge-to-pitch, sway-to-roll, pitch-to-surge,
    /// roll-to-sway). With --compare, both algorithms.
    #[arg(long, conflicts_with_all = ["input", "port"])]
    pub(crate) omct: bool,
    /// --omct: multiplies every test's input amplitude (1 m/s², 5 °/s), 0.001 to 10.
    #[arg(long, value_name = "S", requires = "omct", allow_hyphen_values = true, value_parser = parse_amplitude_scale)]
    pub(crate) amplitude_scale: Option<f64>,
    /// --omct: the test frequencies instead of the twelve, rad/s (0.01 to 100), comma
    /// separated.
    #[arg(long, value_name = "W,W,…", requires = "omct", value_delimiter = ',', allow_hyphen_values = true, value_parser = parse_frequency)]
    pub(crate) frequencies: Option<Vec<f64>>,
    /// --omct: a transport delay added to the chain, milliseconds (0 to 1000): the rig's,
    /// as `link` measures it.
    #[arg(long, value_name = "MS", requires = "omct", allow_hyphen_values = true, value_parser = parse_latency_ms)]
    pub(crate) latency_ms: Option<f64>,
    /// --omct: draw the direct tests' gain and phase (a Bode figure): `.svg`, `.pdf` or
    /// `.png`.
    #[arg(long, value_name = "FILE.svg|FILE.pdf|FILE.png", requires = "omct")]
    pub(crate) plot: Option<PathBuf>,
    /// The language of the figure's words: `zh` or `en` (default: the environment's).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang, requires = "plot")]
    pub(crate) lang: Option<Lang>,
    /// The report's format (--compare and --omct).
    #[arg(long, value_enum, default_value = "text")]
    pub(crate) format: ReportFormat,
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
    /// its y) coloured by the condition number: `.svg`, `.pdf` or `.png` (with
    /// `--certified`: the certified boxes the two planes cut, proven reachable green and
    /// undecided amber, under the sampled boundary).
    #[arg(long, value_name = "FILE.svg|FILE.pdf|FILE.png")]
    pub(crate) plot: Option<PathBuf>,
    /// Write the workspace's surface (a closed triangle mesh around the reachable
    /// positions, from the same columns) as a binary PLY file.
    #[arg(long, value_name = "FILE.ply")]
    pub(crate) surface: Option<PathBuf>,
    /// The language of the figure's words: `zh` or `en` (default: the environment's).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
    /// Prove a bracket of the volume instead of sampling it: boxes of positions classed by
    /// interval arithmetic as inner (every position reachable), outer (none) or boundary
    /// (undecided at `--boundary-width`), so that inner ≤ volume ≤ inner + boundary
    /// (legs or servos; on all cores; Ctrl-C ends it with what is decided).
    #[arg(long, conflicts_with_all = ["out", "surface", "no_budget"])]
    pub(crate) certified: bool,
    /// `--certified`: boxes narrower than this on their widest side are not split
    /// further, metres (default: half a hundredth of the platform's size).
    #[arg(long, value_name = "M", requires = "certified", value_parser = parse_width, allow_hyphen_values = true)]
    pub(crate) boundary_width: Option<f64>,
    /// `--certified`: the most boxes to classify (each some microseconds); when spent,
    /// the undecided rest counts as boundary and the answer says so.
    #[arg(long, value_name = "N", requires = "certified", default_value_t = 50_000_000, value_parser = clap::value_parser!(u64).range(1..=10_000_000_000), allow_hyphen_values = true)]
    pub(crate) budget: u64,
    /// `--certified`: report format.
    #[arg(long, value_enum, requires = "certified", default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
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

/// What `singularity --certify` holds free: one coordinate, or the position in a ball.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum FreeCoordinate {
    /// x, metres.
    X,
    /// y, metres.
    Y,
    /// z, metres.
    Z,
    /// Roll, degrees.
    Roll,
    /// Pitch, degrees.
    Pitch,
    /// Yaw, degrees.
    Yaw,
    /// The position in a ball about the pose's (its orientation held), metres.
    Position,
}

/// Arguments of `stewart singularity`.
#[derive(Debug, Args)]
pub(crate) struct SingularityArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// The pose X,Y,Z,ROLL,PITCH,YAW (metres, degrees); default: home.
    #[arg(long, value_name = "X,Y,Z,ROLL,PITCH,YAW", value_parser = parse_pose, allow_hyphen_values = true)]
    pub(crate) pose: Option<[f64; 6]>,
    /// Prove, by interval arithmetic, the widest range about the pose that holds no
    /// singular pose: of the coordinate `--free` names, the others held (or, for
    /// `position`, the widest ball of positions). Exit status 1 when not even the pose
    /// itself can be proven regular.
    #[arg(long, requires = "free")]
    pub(crate) certify: bool,
    /// The coordinate `--certify` frees.
    #[arg(long, value_enum, requires = "certify")]
    pub(crate) free: Option<FreeCoordinate>,
    /// The most boxes the proof may test (each a few microseconds); when spent, the
    /// answer is what is proven so far, and says so.
    #[arg(long, value_name = "N", default_value_t = 2_000_000, value_parser = clap::value_parser!(u64).range(1..=1_000_000_000), allow_hyphen_values = true)]
    pub(crate) budget: u64,
    /// Report format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
}
