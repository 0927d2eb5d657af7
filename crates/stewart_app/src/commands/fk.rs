//! `stewart fk`: poses from leg lengths.

use std::io::Write as _;
use std::process::ExitCode;
use stewart_kinematics::analysis::architecture;

use anyhow::{Result, anyhow};
use stewart_kinematics::ground::bounds;
use stewart_kinematics::io::table::NumericTable;
use stewart_kinematics::model::actuator::Actuator;
use stewart_kinematics::model::trajectory::POSE_COLUMNS;
use stewart_kinematics::solve::forward::assembly::canonical;
use stewart_kinematics::{
    Angle, Geometry, solve::forward::ForwardOptions, solve::forward::ForwardSolution,
};

use crate::cli::FkArgs;
use crate::csv_io::{CsvText, read_input};
use crate::i18n::{Lang, words};
use crate::output;
use crate::source;

/// Each solution's columns after the pose's: the solver's iterations and its residual.
const SOLVER_OUT: [&str; 2] = ["iterations", "residual"];

/// Run the command.
pub(crate) fn run(args: &FkArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let mut inputs = source::inputs(&args.scenario, &scenario);
    inputs.push(("the table", args.legs.clone()));
    let out = output::destination(args.out.as_deref(), &inputs)?;
    // Each kind has its own forward solver.
    match scenario.geometry.actuator() {
        Actuator::Rotary(_) => return servos(args, &scenario, out.as_ref()),
        Actuator::Linear => {}
    }
    let geometry = &scenario.geometry;
    // Read the table first, so that a bad file is reported whatever the geometry.
    let (table, file) = actuator_table(args, geometry)?;
    let t_index = table.index("t");
    let lengths: Vec<[f64; 6]> = table
        .rows()
        .map(|r| [r[0], r[1], r[2], r[3], r[4], r[5]])
        .collect();

    let architecture = architecture::architecture(geometry);
    if architecture.singular {
        return Err(anyhow!(
            "scenario `{}`: the pose is not determined by the leg lengths, so forward kinematics has no answer. {}",
            scenario.name,
            words::architecture(Lang::En, &architecture)
        ));
    }

    let mut csv = pose_table(t_index.is_some(), args.assembly_modes);
    let time = |k: usize| t_index.map(|i| table.row(k)[i]);

    if args.assembly_modes {
        for (k, row) in lengths.iter().enumerate() {
            let modes = geometry
                .assembly_modes(row)
                .map_err(|e| anyhow!("{file}, line {}: {e}", table.line(k)))?;
            mode_rows(&mut csv, time(k), k, &modes);
        }
    } else {
        let sequence = geometry
            .forward_sequence(&lengths, args.cold, &ForwardOptions::default())
            .map_err(|e| anyhow!("{file}, line {}: {}", table.line(e.index), e.error))?;
        for change in &sequence.branch_changes {
            let _ = writeln!(
                std::io::stderr(),
                "warning: {file}, line {}: the solution moved to another assembly branch (det J changed sign from {:.3e} to {:.3e})",
                table.line(change.index),
                change.det_before,
                change.det_after
            );
        }
        for (k, s) in sequence.solutions.iter().enumerate() {
            csv.row(time(k).into_iter().chain(pose_values(s)));
        }
    }
    let text = csv.into_string();
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    Ok(ExitCode::SUCCESS)
}

/// The table of actuator values (`L1…L6` in metres or `theta1…theta6` in degrees, as the
/// geometry's actuators take them, and an optional `t`), each value in its sane range.
fn actuator_table(args: &FkArgs, geometry: &Geometry) -> Result<(NumericTable, String)> {
    let quantity = geometry.quantity();
    let (table, file) = read_input(&args.legs, |r, name| {
        Ok((
            NumericTable::read(r, name, &quantity.columns, &["t"])?,
            name.to_owned(),
        ))
    })?;
    let (lo, hi) = quantity.widest;
    for name in quantity.columns {
        table.check_range(name, &(lo..=hi), quantity.unit)?;
    }
    table.check_range("t", &bounds::symmetric(bounds::TIME_S), "s")?;
    Ok((table, file))
}

/// `fk` for a rotary platform: poses from servo angles `theta1..theta6` (degrees), each
/// row warm-started from the previous one (or from home with `--cold`).
fn servos(
    args: &FkArgs,
    scenario: &stewart_kinematics::Scenario,
    out: Option<&output::Destination>,
) -> Result<ExitCode> {
    let geometry = &scenario.geometry;
    let (table, file) = actuator_table(args, geometry)?;
    let t_index = table.index("t");
    let mut csv = pose_table(t_index.is_some(), args.assembly_modes);
    let options = ForwardOptions::default();
    let mut start = geometry.home_pose();
    for (k, row) in table.rows().enumerate() {
        let angles = [row[0], row[1], row[2], row[3], row[4], row[5]].map(Angle::from_degrees);
        if args.assembly_modes {
            let modes = geometry
                .servo_assembly_modes(&angles)
                .map_err(|e| anyhow!("{file}, line {}: {e}", table.line(k)))?;
            mode_rows(&mut csv, t_index.map(|i| row[i]), k, &modes);
            continue;
        }
        let from = if args.cold {
            geometry.home_pose()
        } else {
            start
        };
        let s = geometry
            .forward_servos(&angles, &from, &options)
            .map_err(|e| anyhow!("{file}, line {}: {e}", table.line(k)))?;
        start = s.pose;
        csv.row(t_index.map(|i| row[i]).into_iter().chain(pose_values(&s)));
    }
    let text = csv.into_string();
    output::emit_with(out, |w| w.write_all(text.as_bytes()))?;
    Ok(ExitCode::SUCCESS)
}

/// The output table: `t` when the input has times, `row` (the input row, from 1) and
/// `mode` when assembly modes are listed, then the pose columns.
fn pose_table(times: bool, modes: bool) -> CsvText {
    let mut header: Vec<&str> = Vec::new();
    if times {
        header.push("t");
    }
    if modes {
        header.extend(["row", "mode"]);
    }
    header.extend(POSE_COLUMNS);
    header.extend(SOLVER_OUT);
    CsvText::with_header(&header)
}

/// One row per assembly mode of input row `k` (counted from 0, written from 1), the modes
/// numbered from 1.
fn mode_rows(csv: &mut CsvText, time: Option<f64>, k: usize, modes: &[ForwardSolution]) {
    for (m, s) in modes.iter().enumerate() {
        csv.row(
            time.into_iter()
                .chain([(k + 1) as f64, (m + 1) as f64])
                .chain(pose_values(s)),
        );
    }
}

/// `x, y, z, roll_deg, pitch_deg, yaw_deg, iterations, residual` of a solution, angles in
/// their principal ranges.
fn pose_values(s: &ForwardSolution) -> [f64; 8] {
    let [x, y, z, roll, pitch, yaw] = canonical(&s.pose).to_row();
    [x, y, z, roll, pitch, yaw, s.iterations as f64, s.residual]
}
