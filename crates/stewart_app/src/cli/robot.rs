//! The arguments of `stewart robot`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::ScenarioArgs;

/// Robot description formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum RobotFormatArg {
    /// MuJoCo's MJCF: the loops closed by equality constraints, one position actuator per
    /// leg, one keyframe per sample.
    Mjcf,
    /// ROS's URDF: a virtual chain to the platform and each leg an open chain; with
    /// `--joint-states`, every joint's value per sample.
    Urdf,
}

/// Arguments of `stewart robot`.
#[derive(Debug, Args)]
pub(crate) struct RobotArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// `mjcf` (MuJoCo) or `urdf` (ROS).
    #[arg(long, value_enum)]
    pub(crate) format: RobotFormatArg,
    /// The description's file (`.xml` for MJCF, `.urdf` for URDF).
    #[arg(long, value_name = "FILE")]
    pub(crate) out: PathBuf,
    /// URDF only: also write `t` and one column per movable joint (by its URDF name),
    /// one row per sample, as CSV.
    #[arg(long, value_name = "STATES.csv")]
    pub(crate) joint_states: Option<PathBuf>,
    /// Export every N-th sample of the trajectory (keyframes, joint-state rows), from the
    /// first (default 1: all).
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=1_000_000), allow_hyphen_values = true)]
    pub(crate) every: u32,
}
