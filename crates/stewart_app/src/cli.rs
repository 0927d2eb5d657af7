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
