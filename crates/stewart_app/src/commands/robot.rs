//! `stewart robot`: the rig as an MJCF or URDF robot description.

use std::io::Write as _;
use std::process::ExitCode;

use anyhow::{Result, bail};

use crate::cli::{RobotArgs, RobotFormatArg};
use crate::export::robot::{RobotFormat, describe, expected_extension};
use crate::output::Destination;
use crate::source;

/// Run the command.
pub(crate) fn run(args: &RobotArgs) -> Result<ExitCode> {
    let format = match args.format {
        RobotFormatArg::Mjcf => RobotFormat::Mjcf,
        RobotFormatArg::Urdf => RobotFormat::Urdf,
    };
    if args.joint_states.is_some() && format != RobotFormat::Urdf {
        bail!(
            "--joint-states applies to --format urdf (an MJCF file carries its samples as keyframes)"
        );
    }
    let scenario = source::load(&args.scenario)?;
    let inputs = source::inputs(&args.scenario, &scenario);
    let out = Destination::new(&args.out, &inputs)?;
    out.require_file()?;
    let states = match &args.joint_states {
        Some(path) => {
            if std::path::absolute(path).ok() == std::path::absolute(&args.out).ok() {
                bail!(
                    "--joint-states `{}` is the description's own file; choose another",
                    path.display()
                );
            }
            let d = Destination::new(path, &inputs)?;
            d.require_file()?;
            Some(d)
        }
        None => None,
    };
    let folder = crate::appearance::folder_of(&args.scenario);
    let parts = crate::appearance::load(&scenario, &folder)?;
    // URDF names mesh files from its own folder: relative below it, else absolute.
    let out_folder = crate::output::parent_of(&args.out);
    let mesh_files = crate::appearance::rebase(&scenario.appearance, &folder, out_folder);
    let every = args.every as usize;
    let described = source::describe(&args.scenario);
    let files = describe(&scenario, format, every, &parts, &mesh_files, |t| {
        if t.is_finite() {
            format!("{described}: the trajectory at t = {t} s")
        } else {
            described.clone()
        }
    })?;
    // Everything is computed before anything is written.
    out.write_bytes(files.description.as_bytes())?;
    if let (Some(d), Some(text)) = (&states, &files.joint_states) {
        d.write_bytes(text.as_bytes())?;
    }
    let mut err = std::io::stderr();
    let _ = writeln!(
        err,
        "Wrote {} with {} sample{} to {}.",
        match format {
            RobotFormat::Mjcf => "an MJCF model",
            RobotFormat::Urdf => "a URDF robot",
        },
        files.samples,
        if files.samples == 1 { "" } else { "s" },
        args.out.display()
    );
    if !expected_extension(format, &args.out) {
        let _ = writeln!(
            err,
            "Note: {} files usually end in {}.",
            match format {
                RobotFormat::Mjcf => "MJCF",
                RobotFormat::Urdf => "URDF",
            },
            match format {
                RobotFormat::Mjcf => ".xml",
                RobotFormat::Urdf => ".urdf",
            }
        );
    }
    Ok(ExitCode::SUCCESS)
}
