//! `stewart robot`: the rig as an MJCF or URDF robot description.

use std::io::Write as _;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context as _, Result, bail};

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
    let folder = crate::appearance::folder_of(&args.scenario);
    let parts = crate::appearance::load(&scenario, &folder)?;
    let inputs = source::inputs_with_parts(&args.scenario, &scenario, &parts);
    let out = Destination::new(&args.out, &inputs)?;
    out.require_file()?;
    let states = match &args.joint_states {
        Some(path) => {
            let d = Destination::new(path, &inputs)?;
            d.require_file()?;
            if same_place(d.real(), out.real()) {
                bail!(
                    "--joint-states `{}` is the description's own file `{}`; choose another",
                    path.display(),
                    args.out.display()
                );
            }
            Some(d)
        }
        None => None,
    };
    // URDF names mesh files by their absolute paths (as `file://` URIs).
    let mesh_files = crate::appearance::anchored(&scenario.appearance, &folder);
    let every = args.every as usize;
    let described = source::describe(&args.scenario);
    let files = describe(&scenario, format, every, &parts, &mesh_files, |t| {
        if t.is_finite() {
            format!("{described}: the trajectory at t = {t} s")
        } else {
            described.clone()
        }
    })?;
    // Everything is computed, then staged beside its place, before anything is put in
    // place: a file that cannot be written leaves neither.
    let description = stage(&out, &files.description)?;
    let table = match (&states, &files.joint_states) {
        (Some(d), Some(text)) => Some((d, stage(d, text)?)),
        _ => None,
    };
    out.deliver(description)?;
    if let Some((d, staged)) = table {
        d.deliver(staged)?;
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

/// `text` written whole into a staged file beside `d`'s place.
fn stage(d: &Destination, text: &str) -> Result<tempfile::TempPath> {
    let mut file = d.staged_file(".partial")?;
    file.write_all(text.as_bytes())
        .and_then(|()| file.as_file().sync_all())
        .with_context(|| format!("cannot write `{}`", d.shown().display()))?;
    Ok(file.into_temp_path())
}

/// Whether two paths (their links followed) name one file: the same file name in the
/// same folder once each folder's `..` and links are resolved.
fn same_place(a: &Path, b: &Path) -> bool {
    let place = |p: &Path| {
        let folder = std::fs::canonicalize(crate::output::parent_of(p)).ok()?;
        Some(folder.join(p.file_name()?))
    };
    match (place(a), place(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}
