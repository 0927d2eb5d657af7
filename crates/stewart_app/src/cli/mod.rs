//! Command-line definitions (clap): the program, its commands, the arguments every
//! command shares, and [`ArgError`], the one error a value is refused with. Each group of
//! commands has its arguments and value parsers in a file of its own.

mod analysis;
mod arg_error;
mod link;
mod pictures;
mod robot;
mod values;

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

pub(crate) use analysis::{
    CalibrateArgs, CheckArgs, CueArgs, DesignArgs, FkArgs, ForcesArgs, FreeCoordinate, HoldGroup,
    ModesArgs, SettingsArgs, SettingsFormat, SingularityArgs, SolveArgs, WorkspaceArgs,
};
pub(crate) use arg_error::ArgError;
pub(crate) use link::{
    DeviceSimArgs, FirmwareArgs, LinkArgs, TelemetryArgs, WireFormatArg, WireUnit,
};
pub(crate) use pictures::{PlotArgs, RenderArgs, ThemeName, ViewArgs, parse_title};
pub(crate) use robot::{RobotArgs, RobotFormatArg};

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
    /// How near a pose is to singularity (its conditioning), and with `--certify --free
    /// COORDINATE` the widest range about it proven free of singularity by interval
    /// arithmetic: every pose inside, not only sampled ones (linear legs).
    Singularity(SingularityArgs),
    /// The stroke (or servo range) a motion envelope needs: the smallest and largest
    /// value of each leg length (servo angle) over a 6-D box of poses, where each occurs,
    /// and the worst conditioning inside the box.
    Design(DesignArgs),
    /// Render the trajectory headlessly: a PNG sequence (folder), a GIF, an MP4, or an animated glTF scene (.glb, .gltf).
    Render(RenderArgs),
    /// The leg-length plot for a paper: SVG, PDF or PNG.
    Plot(PlotArgs),
    /// The rig as a robot description: MJCF for MuJoCo (loops closed by equality
    /// constraints, a position actuator per leg, a keyframe per sample) or URDF for ROS
    /// (open chains, with the joints' values per sample as CSV).
    Robot(RobotArgs),
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

/// Report formats of `stewart check`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ReportFormat {
    /// Sentences for people.
    Text,
    /// One JSON object for programs.
    Json,
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
