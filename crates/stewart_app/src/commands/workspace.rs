//! `stewart workspace`: reachable positions at a fixed orientation, orientation ranges.

use std::fmt::Write as _;
use std::process::ExitCode;
use stewart_kinematics::analysis::workspace;

use std::io::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Result, anyhow, bail};
use indicatif::{ProgressBar, ProgressStyle};
use nalgebra::Vector3;
use stewart_kinematics::analysis::workspace::{
    Axis, BUDGET_BYTES, BUDGET_SECONDS, ConstantOrientationWorkspace, WorkspaceControl,
    WorkspaceError,
};
use stewart_kinematics::{Angle, Geometry, Pose, Scenario, model::limits::Limits};

use crate::cli::WorkspaceArgs;
use crate::csv_io::CsvText;
use crate::long_work::duration_words;
use crate::output;
use crate::source;
use crate::volume_text::{format_bound, format_length, format_volume, format_volume_error};

/// Run the command.
pub(crate) fn run(args: &WorkspaceArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let inputs = source::inputs(&args.scenario, &scenario);
    let plot_out = match &args.plot {
        Some(path) => {
            let d = output::Destination::new(path, &inputs)?;
            d.require_file()?;
            crate::export::vector::check_extension(path)?;
            Some(d)
        }
        None => None,
    };
    if args.certified {
        return certified(args, &scenario, plot_out.as_ref());
    }
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let surface_out = match &args.surface {
        Some(path) => {
            let d = output::Destination::new(path, &inputs)?;
            d.require_file()?;
            if !path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("ply"))
            {
                bail!("{}: the surface file must end in .ply", path.display());
            }
            Some(d)
        }
        None => None,
    };
    let g = &scenario.geometry;
    let orientation = args.orientation.map(Angle::from_degrees);
    let ws = compute(
        g,
        &scenario.limits,
        orientation,
        usize::from(args.resolution),
        args.no_budget,
    )?;
    let [r, p, y] = args.orientation;
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "Workspace of `{}` at roll {r}°, pitch {p}°, yaw {y}°:",
        scenario.name
    );
    volume_lines(&mut s, &scenario, &ws);
    let position = args.position.unwrap_or([0.0, 0.0, g.home_height()]);
    orientation_lines(&mut s, &scenario, orientation, position);
    if let Some(plot) = &plot_out {
        let path = plot.shown();
        let lang = crate::i18n::for_command(args.lang, "workspace");
        let bytes = crate::export::workspace_plot::figure_file(
            &scenario,
            &ws,
            orientation,
            position,
            lang,
            path,
        )?;
        plot.write_bytes(&bytes)?;
        let _ = writeln!(s, "Wrote the slices to {}.", path.display());
    }
    if let Some(file) = &surface_out {
        write_surface(&mut s, file, &scenario, &ws, args.orientation)?;
    }
    if let Some(out) = &out {
        let path = out.shown();
        let text = points_file(path, &ws)?;
        out.write_bytes(text.as_bytes())?;
        let _ = writeln!(
            s,
            "Wrote {} boundary points to {}.",
            2 * ws.spans.len(),
            path.display()
        );
    }
    output::stdout(s.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// The volume with its bound and method, and the extent (or why there is none).
fn volume_lines(s: &mut String, scenario: &Scenario, ws: &ConstantOrientationWorkspace) {
    let n = ws.resolution;
    let method = ws.method_words(&scenario.geometry, &scenario.limits);
    let _ = writeln!(
        s,
        "  volume {} m³ ± {} m³ ({n} × {n} columns of {:.2} mm; {method}; the bound is twice the spread of the 16 interleaved grids 4× coarser)",
        format_volume(ws.volume),
        format_volume_error(ws.volume_error),
        ws.cell * 1e3
    );
    let _ = match ws.extent {
        Some([ex, ey, ez]) => writeln!(
            s,
            "  extent x {:.4} … {:.4} m, y {:.4} … {:.4} m, z {:.4} … {:.4} m",
            ex[0], ex[1], ey[0], ey[1], ez[0], ez[1]
        ),
        None if ws.cell > 0.0 => writeln!(
            s,
            "  no column centre is reachable at this orientation; a region thinner than {:.2} mm could lie between them: a higher --resolution looks closer",
            ws.cell * 1e3
        ),
        None => writeln!(
            s,
            "  no position is reachable at this orientation: the legs' reaches do not overlap"
        ),
    };
}

/// The range of each angle alone at `position`, from `orientation`.
fn orientation_lines(
    s: &mut String,
    scenario: &Scenario,
    orientation: [Angle; 3],
    position: [f64; 3],
) {
    let pose = Pose::new(
        Vector3::from(position),
        orientation[0],
        orientation[1],
        orientation[2],
    );
    let _ = writeln!(
        s,
        "Orientation range at ({}, {}, {}) m, each angle alone from the orientation above:",
        position[0], position[1], position[2]
    );
    let step = Angle::from_degrees(0.5);
    for (axis, name, span) in [
        (Axis::Roll, "roll", 90.0),
        (Axis::Pitch, "pitch", 90.0),
        (Axis::Yaw, "yaw", 180.0),
    ] {
        let line = match workspace::orientation_range(
            &scenario.geometry,
            &scenario.limits,
            &pose,
            axis,
            Angle::from_degrees(span),
            step,
        ) {
            Some([lo, hi]) => format!("{:.3}° … {:.3}°", lo.degrees(), hi.degrees()),
            None => "the position is not reachable at this orientation".to_owned(),
        };
        let _ = writeln!(s, "  {name:<5} {line}");
    }
}

/// Write the workspace's closed surface as PLY to `file`, and say so in `s`.
fn write_surface(
    s: &mut String,
    file: &output::Destination,
    scenario: &Scenario,
    ws: &ConstantOrientationWorkspace,
    orientation_deg: [f64; 3],
) -> Result<()> {
    let path = file.shown();
    let Some(_) = ws.extent else {
        bail!("no position is reachable at this orientation: there is no surface to write");
    };
    let surface = workspace::WorkspaceSurface::from_workspace(ws);
    let bytes = crate::export::ply::ply(
        &surface,
        &crate::export::ply::PlyHeader {
            name: &scenario.name,
            orientation_deg,
            volume: [ws.volume, ws.volume_error],
            resolution: ws.resolution,
        },
    );
    file.write_bytes(&bytes)?;
    let _ = writeln!(
        s,
        "Wrote the surface ({} triangles, enclosing {} m³) to {}.",
        surface.triangles.len(),
        format_volume(surface.enclosed_volume()),
        path.display()
    );
    Ok(())
}

/// Estimate the request's cost from a coarse probe, refuse it above the budget, and run
/// it with a progress bar and Ctrl-C when it is long.
fn compute(
    g: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    resolution: usize,
    no_budget: bool,
) -> Result<ConstantOrientationWorkspace> {
    let started = Instant::now();
    let cost = workspace::workspace_cost(g, limits, orientation, resolution)?;
    let estimate = cost.estimate(started.elapsed().as_secs_f64(), resolution);
    let seconds = estimate.seconds;
    let cost_words = format!(
        "about {}, {:.2e} limit evaluations and {:.0} MB",
        duration_words(seconds),
        cost.evaluations,
        cost.bytes / 1e6
    );
    if estimate.over_budget && !no_budget {
        let suggestion = estimate.within_budget.min(resolution - 1).max(2);
        bail!(
            "a {resolution} × {resolution} workspace would take {cost_words}; the budget is {} and {:.0} GB: use --resolution {suggestion} or lower, or --no-budget to run it anyway (Ctrl-C stops it)",
            duration_words(BUDGET_SECONDS),
            BUDGET_BYTES / 1e9
        );
    }
    let control = WorkspaceControl::default();
    let stop = crate::interrupt::flag();
    let long = seconds > 2.0;
    if long {
        let _ = writeln!(
            std::io::stderr(),
            "Computing a {resolution} × {resolution} workspace: {cost_words} (Ctrl-C stops it)."
        );
    }
    let progress = if long {
        let bar = ProgressBar::new(resolution as u64);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} rows  {eta} left")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    } else {
        ProgressBar::hidden()
    };
    let result = std::thread::scope(|scope| {
        let worker = scope.spawn(|| {
            workspace::constant_orientation_workspace_with(
                g,
                limits,
                orientation,
                resolution,
                &control,
            )
        });
        while !worker.is_finished() {
            if stop.load(Ordering::Relaxed) {
                control.cancel.store(true, Ordering::Relaxed);
            }
            progress.set_position(control.rows_done.load(Ordering::Relaxed) as u64);
            std::thread::sleep(Duration::from_millis(50));
        }
        worker.join()
    });
    progress.finish_and_clear();
    match result {
        Ok(Ok(ws)) => Ok(ws),
        Ok(Err(WorkspaceError::Cancelled)) => bail!("interrupted: nothing was written"),
        Ok(Err(e)) => Err(e.into()),
        Err(_) => bail!("internal error: the workspace computation panicked"),
    }
}

/// The boundary points (bottom and top of every reachable span) as CSV or PLY.
fn points_file(path: &std::path::Path, ws: &ConstantOrientationWorkspace) -> Result<String> {
    let points = ws
        .spans
        .iter()
        .flat_map(|s| [[s[0], s[1], s[2]], [s[0], s[1], s[3]]]);
    match output::extension(path).as_deref() {
        Some("csv") => {
            let mut csv = CsvText::with_header(&["x", "y", "z"]);
            for p in points {
                csv.row(p);
            }
            Ok(csv.into_string())
        }
        Some("ply") => {
            let mut s = format!(
                "ply\nformat ascii 1.0\ncomment Stewart platform workspace boundary, metres\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\nend_header\n",
                2 * ws.spans.len()
            );
            for [x, y, z] in points {
                // Writing to a String cannot fail.
                let _ = writeln!(s, "{x} {y} {z}");
            }
            Ok(s)
        }
        _ => Err(anyhow!(
            "`{}`: the points file must end in .csv or .ply",
            path.display()
        )),
    }
}

/// The JSON document of `--certified`.
#[derive(serde::Serialize)]
struct CertifiedJson<'a> {
    scenario: &'a str,
    orientation_deg: [f64; 3],
    inner_m3: f64,
    boundary_m3: f64,
    boundary_width_m: f64,
    boxes: usize,
    cut_short: bool,
}

/// `--certified`: the volume bracket proven by interval arithmetic (and, with `--plot`, the
/// certified boxes two planes cut).
fn certified(
    args: &WorkspaceArgs,
    scenario: &Scenario,
    plot: Option<&output::Destination>,
) -> Result<ExitCode> {
    use stewart_kinematics::analysis::certified::workspace::{
        WorkspaceRequest, certified_workspace,
    };
    let g = &scenario.geometry;
    let [roll, pitch, yaw] = args.orientation.map(Angle::from_degrees);
    let orientation = Pose::new(g.home_pose().position, roll, pitch, yaw);
    let width = args
        .boundary_width
        .unwrap_or(0.005 * g.characteristic_length());
    crate::interrupt::flag();
    // The stop is asked once a box: counting the asks counts the boxes, for the spinner.
    let asked = AtomicUsize::new(0);
    let stop = || {
        asked.fetch_add(1, Ordering::Relaxed);
        crate::interrupt::requested()
    };
    let request = WorkspaceRequest {
        orientation: &orientation,
        boundary_width: width,
        budget: usize::try_from(args.budget).unwrap_or(usize::MAX),
        stop: &stop,
    };
    let started = Instant::now();
    // On a terminal, the time spent and the boxes classified while it runs.
    let result = crate::long_work::with_spinner(
        || {
            format!(
                "{} boxes classified (Ctrl-C ends it with what is decided)",
                asked.load(Ordering::Relaxed)
            )
        },
        || certified_workspace(g, &scenario.limits, &request),
    );
    let w = result.ok_or_else(|| {
        anyhow::anyhow!(
            "scenario `{}`: the certified workspace needs both stroke limits (`leg_min` and `leg_max` in [geometry])",
            scenario.name
        )
    })?;
    let text = match args.format {
        crate::cli::ReportFormat::Json => {
            serde_json::to_string_pretty(&CertifiedJson {
                scenario: &scenario.name,
                orientation_deg: args.orientation,
                inner_m3: w.inner_m3,
                boundary_m3: w.boundary_m3,
                boundary_width_m: width,
                boxes: w.tested,
                cut_short: w.cut_short,
            })? + "\n"
        }
        crate::cli::ReportFormat::Text => {
            let mut t = format!(
                "Certified workspace of `{}` at roll {}°, pitch {}°, yaw {}°:\n  \
                 {} m³ ≤ volume ≤ {} m³ (inner {} m³, boundary {} m³, {})\n  \
                 {} boxes classified by interval arithmetic, none narrower than {} m, in {:.1} s.\n",
                scenario.name,
                args.orientation[0],
                args.orientation[1],
                args.orientation[2],
                format_bound(w.inner_m3, false),
                format_bound(w.inner_m3 + w.boundary_m3, true),
                format_bound(w.inner_m3, false),
                format_bound(w.boundary_m3, true),
                if w.inner_m3 > 0.0 {
                    format!("{:.1} % of inner", 100.0 * w.boundary_m3 / w.inner_m3)
                } else {
                    "no box proven inner".to_owned()
                },
                w.tested,
                format_length(width),
                started.elapsed().as_secs_f64()
            );
            if w.cut_short {
                t.push_str("  The box budget (--budget) or Ctrl-C ended it: the undecided boxes count as boundary.\n");
            }
            t
        }
    };
    let mut text = text;
    if let Some(plot) = plot {
        let orientation = args.orientation.map(Angle::from_degrees);
        // The sampled workspace gives the figure its extent and the boundary line.
        let ws = compute(
            g,
            &scenario.limits,
            orientation,
            usize::from(args.resolution),
            false,
        )?;
        let path = plot.shown();
        let bytes = crate::export::workspace_plot::certified_figure_file(
            scenario,
            &ws,
            &w.boxes,
            orientation,
            args.position.unwrap_or([0.0, 0.0, g.home_height()]),
            crate::i18n::for_command(args.lang, "workspace"),
            path,
        )?;
        plot.write_bytes(&bytes)?;
        if args.format == crate::cli::ReportFormat::Text {
            text.push_str(&format!("  Wrote the slices to {}.\n", path.display()));
        }
    }
    output::stdout(text.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}
