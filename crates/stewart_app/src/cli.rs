//! Command-line definitions (clap).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

/// Stewart platform studio: inverse kinematics, trajectories and checks for the
/// six-degree-of-freedom Gough–Stewart platform.
#[derive(Debug, Parser)]
#[command(name = "stewart", version, about, long_about = None)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Leg lengths for a scenario's trajectory or for a table of poses, as CSV.
    Solve(SolveArgs),
    /// Check a scenario's motion: rigid-body consistency, stroke limits, leg-length jumps.
    /// Exit status 0 when nothing is found, 1 when a problem is found, 2 for unusable input.
    Check(CheckArgs),
    /// Forward kinematics: poses from a table of leg lengths, as CSV.
    Fk(FkArgs),
    /// Reachable workspace at a fixed orientation (volume, extent, points) and the
    /// orientation range at a position.
    Workspace(WorkspaceArgs),
    /// Leg forces for a payload along the trajectory (static and dynamic), as CSV.
    Forces(ForcesArgs),
}

/// Which scenario to use: a shipped preset or a TOML file (default: the `seed` preset).
#[derive(Debug, Args)]
#[group(multiple = false)]
pub struct ScenarioArgs {
    /// A shipped preset: seed, paired, circle, figure8, helix, sway, keyframes.
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// A scenario file (TOML).
    #[arg(long, value_name = "FILE")]
    pub scenario: Option<PathBuf>,
}

/// Arguments of `stewart solve`.
#[derive(Debug, Args)]
pub struct SolveArgs {
    #[command(flatten)]
    pub scenario: ScenarioArgs,
    /// Solve these poses instead of the trajectory: a CSV with columns
    /// x,y,z,roll_deg,pitch_deg,yaw_deg (metres, degrees) and optionally t; `-` reads standard input.
    #[arg(long, value_name = "POSES.csv")]
    pub poses: Option<PathBuf>,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Report formats of `stewart check`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Sentences for people.
    Text,
    /// One JSON object for programs.
    Json,
}

/// Arguments of `stewart check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub scenario: ScenarioArgs,
    /// Report format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

/// Arguments of `stewart fk`.
#[derive(Debug, Args)]
pub struct FkArgs {
    #[command(flatten)]
    pub scenario: ScenarioArgs,
    /// Leg lengths: a CSV with columns L1..L6 (metres) and optionally t; other columns are
    /// ignored; `-` reads standard input.
    #[arg(long, value_name = "LEGS.csv")]
    pub legs: PathBuf,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Start every row from the home pose instead of the previous row's pose.
    #[arg(long)]
    pub cold: bool,
    /// List every assembly mode the search finds for each row (a `mode` column numbers
    /// them, highest platform first) instead of following one branch.
    #[arg(long, conflicts_with = "cold")]
    pub assembly_modes: bool,
}

/// Three comma-separated finite numbers, such as `0,0,0.8`.
pub fn parse_triple(text: &str) -> Result<[f64; 3], String> {
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

/// Arguments of `stewart workspace`.
#[derive(Debug, Args)]
pub struct WorkspaceArgs {
    #[command(flatten)]
    pub scenario: ScenarioArgs,
    /// Platform orientation ROLL,PITCH,YAW in degrees.
    #[arg(long, value_name = "ROLL,PITCH,YAW", value_parser = parse_triple, default_value = "0,0,0", allow_hyphen_values = true)]
    pub orientation: [f64; 3],
    /// Columns per side of the grid (the volume's error shrinks as it rises).
    #[arg(long, default_value_t = 400, value_parser = clap::value_parser!(u16).range(2..=4096))]
    pub resolution: u16,
    /// Position X,Y,Z (metres) at which to report the orientation range (default: home).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_triple, allow_hyphen_values = true)]
    pub position: Option<[f64; 3]>,
    /// Write the workspace boundary points: `.csv` (x,y,z) or `.ply` (for 3D tools).
    #[arg(long, value_name = "FILE.csv|FILE.ply")]
    pub out: Option<PathBuf>,
}

/// Arguments of `stewart forces`.
#[derive(Debug, Args)]
pub struct ForcesArgs {
    #[command(flatten)]
    pub scenario: ScenarioArgs,
    /// Moving mass in kg (overrides the scenario's `[payload]`).
    #[arg(long, value_name = "KG", allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Centre of mass X,Y,Z in the platform frame, metres.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_triple, allow_hyphen_values = true)]
    pub com: Option<[f64; 3]>,
    /// Principal moments of inertia IXX,IYY,IZZ about the centre of mass, kg·m².
    #[arg(long, value_name = "IXX,IYY,IZZ", value_parser = parse_triple)]
    pub inertia: Option<[f64; 3]>,
    /// Write the CSV here (whole or not at all) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}
