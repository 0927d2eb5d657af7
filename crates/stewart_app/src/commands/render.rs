//! `stewart render`: frames, GIF and MP4 of a trajectory, with no display, or the
//! trajectory as an animated glTF scene.

use std::io::Write as _;
use std::process::ExitCode;

use anyhow::Result;
use indicatif::{ProgressBar, ProgressStyle};
use stewart_render::{OrbitCamera, Overlays, Theme};

use crate::cli::{RenderArgs, ThemeName};
use crate::export::encode::FrameSink;
use crate::export::frames::default_camera;
use crate::export::video::{VideoRequest, bytes_in_words, export_video, rate_in_words};
use crate::source;

/// The trajectory as an animated glTF scene (`--out FILE.glb|.gltf`).
fn animation(
    args: &RenderArgs,
    scenario: &stewart_kinematics::Scenario,
    parts: stewart_render::appearance::parts::PartSet,
) -> Result<ExitCode> {
    let inputs = source::inputs_with_parts(&args.scenario, scenario, &parts);
    let request = crate::export::gltf::GltfRequest {
        out: args.out.clone(),
        theme: Theme::from_light(args.theme == ThemeName::Light),
        coloured_legs: !args.single_colour,
        parts,
    };
    let report = crate::export::gltf::export_gltf(scenario, &request, &inputs)?;
    let _ = writeln!(
        std::io::stderr(),
        "Wrote a glTF animation of {} keys for {} moving parts to {} ({}) in {:.2} s.",
        report.samples,
        report.moving,
        args.out.display(),
        bytes_in_words(report.bytes),
        report.seconds
    );
    Ok(ExitCode::SUCCESS)
}

/// Run the command.
pub(crate) fn run(args: &RenderArgs) -> Result<ExitCode> {
    // The output is never one of the inputs (a scenario file named `x.gif`, its pose table,
    // one of its CAD parts).
    let scenario = source::load(&args.scenario)?;
    let parts = crate::appearance::load(&scenario, &crate::appearance::folder_of(&args.scenario))?;
    crate::output::Destination::new(
        &args.out,
        &source::inputs_with_parts(&args.scenario, &scenario, &parts),
    )?;
    if crate::export::gltf::is_gltf(&args.out) {
        return animation(args, &scenario, parts);
    }
    let camera = args.camera.map(|[az, el, dist]| OrbitCamera {
        azimuth_deg: az as f32,
        elevation_deg: el as f32,
        distance: dist as f32,
        ..default_camera(&scenario)
    });
    let request = VideoRequest {
        out: args.out.clone(),
        size: args.size,
        fps: args.fps,
        frames: args.frames.unwrap_or((None, None)),
        theme: Theme::from_light(args.theme == ThemeName::Light),
        camera,
        composite: args.composite,
        overlays: Overlays {
            platform_axes: args.platform_axes,
            coloured_legs: !args.single_colour,
            labels: !args.no_labels,
            ..Overlays::default()
        },
        readout: (args.overlay || args.title.is_some())
            .then(|| args.title.clone().unwrap_or_else(|| scenario.name.clone())),
        lang: crate::i18n::for_command(args.lang, "render"),
        speed: args.speed,
        parts,
    };
    let progress = ProgressBar::new(0);
    progress.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} frames  {per_sec}  {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    // Ctrl-C, SIGTERM and SIGHUP stop the export cleanly: staged files are removed,
    // nothing is half-written.
    let stop = crate::interrupt::flag();
    let report = match export_video(&scenario, &request, &progress, stop) {
        Ok(r) => r,
        Err(e) => {
            progress.abandon();
            return Err(e);
        }
    };
    progress.finish_and_clear();
    let (width, height) = args.size;
    let mut err = std::io::stderr();
    if let Some(note) = report.note {
        let _ = writeln!(err, "Note: {note}.");
    }
    // A video plays for a time; a folder of frames samples the motion at a rate.
    let timing = match FrameSink::from_path(&args.out) {
        FrameSink::Folder(_) => format!("{} frames/s of motion", rate_in_words(report.fps)),
        _ => format!(
            "{} frames/s, plays {:.2} s",
            rate_in_words(report.fps),
            report.duration
        ),
    };
    let _ = writeln!(
        err,
        "Wrote {} frames of {width}×{height} to {} ({timing}, {}) in {:.1} s ({:.1} frames/s) on {}.",
        report.frames,
        args.out.display(),
        bytes_in_words(report.bytes),
        report.seconds,
        report.frames as f64 / report.seconds,
        report.adapter
    );
    Ok(ExitCode::SUCCESS)
}
