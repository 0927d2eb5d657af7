//! `stewart calibrate`: joint coordinates and actuator offsets from measured poses.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::{Result, anyhow};
use stewart_kinematics::analysis::calibration::{
    Calibration, Held, Measurement, Parameter, ParameterUnit, calibrate, calibrated_scenario,
    offsets_folded_into,
};
use stewart_kinematics::io::table::NumericTable;
use stewart_kinematics::model::trajectory::{POSE_COLUMNS, check_pose_ranges};
use stewart_kinematics::{Pose, Scenario};

use crate::cli::{CalibrateArgs, HoldGroup};
use crate::csv_io::read_input;
use crate::output;
use crate::source;

/// A measurement whose largest residual after calibration exceeds this many times the RMS
/// is named as a likely outlier.
const OUTLIER_FACTOR: f64 = 5.0;
/// A joint moved by more than this fraction of the platform's size is worth a warning.
const LARGE_CHANGE: f64 = 0.1;

/// Run the command.
pub(crate) fn run(args: &CalibrateArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let mut inputs = source::inputs(&args.scenario, &scenario);
    inputs.push(("the measurements", args.measurements.clone()));
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let quantity = scenario.geometry.quantity();
    let commanded_columns = quantity.columns;
    let required: Vec<&str> = POSE_COLUMNS
        .iter()
        .chain(&commanded_columns)
        .copied()
        .collect();
    let (table, file) = read_input(&args.measurements, |r, name| {
        Ok((
            NumericTable::read(r, name, &required, &[])?,
            name.to_owned(),
        ))
    })?;
    check_pose_ranges(&table)?;
    let (lo, hi) = quantity.widest;
    for name in commanded_columns {
        table.check_range(name, &(lo..=hi), quantity.unit)?;
    }
    let measurements: Vec<Measurement> = table
        .rows()
        .map(|r| Measurement {
            pose: Pose::from_xyz_rpy_deg([r[0], r[1], r[2]], [r[3], r[4], r[5]]),
            commanded: std::array::from_fn(|i| r[6 + i] * quantity.si_per_unit),
        })
        .collect();
    let held = Held {
        base: args.hold.contains(&HoldGroup::Base),
        platform: args.hold.contains(&HoldGroup::Platform),
        offsets: args.hold.contains(&HoldGroup::Offsets),
    };
    let calibration =
        calibrate(&scenario.geometry, &measurements, held).map_err(|e| anyhow!("{file}: {e}"))?;
    let line = |k: usize| table.line(k);
    let mut text = report(&scenario, &calibration, &file, &line);
    if let Some(out) = &out {
        let calibrated = calibrated_scenario(&scenario, &calibration, measurements.len());
        let toml = calibrated.to_toml();
        out.write_with(|w| w.write_all(toml.as_bytes()))?;
        let _ = writeln!(
            text,
            "\nwritten: {} (joints as coordinates; {})",
            out.shown().display(),
            offsets_folded_into(quantity.actuator)
        );
    } else {
        text.push_str("\nnothing written: give --out FILE to write the calibrated scenario\n");
    }
    output::stdout(text.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// Millimetres from metres, for the report.
fn mm(v: f64) -> f64 {
    v * 1e3
}

/// The report in words and tables.
fn report(scenario: &Scenario, c: &Calibration, file: &str, line: &dyn Fn(usize) -> u64) -> String {
    let mut t = String::new();
    let kind = scenario.geometry.quantity().kind;
    let _ = writeln!(
        t,
        "calibration of `{}` ({kind}) from {} measured poses in {file}",
        scenario.name,
        c.row_residuals.len()
    );
    let _ = writeln!(
        t,
        "closure residual (per leg and pose): before RMS {:.4} mm, max {:.4} mm (line {}, leg {}); after RMS {:.4} mm, max {:.4} mm (line {}, leg {})",
        mm(c.before.rms),
        mm(c.before.max),
        line(c.before.worst_measurement),
        c.before.worst_leg + 1,
        mm(c.after.rms),
        mm(c.after.max),
        line(c.after.worst_measurement),
        c.after.worst_leg + 1,
    );
    let size = scenario.geometry.characteristic_length();
    let mut large = Vec::new();
    for (leg, fit) in c.legs.iter().enumerate() {
        leg_fit(&mut t, leg, fit, size, &mut large);
    }
    let outliers: Vec<String> = c
        .row_residuals
        .iter()
        .enumerate()
        .filter(|(_, r)| **r > OUTLIER_FACTOR * c.after.rms && **r > 1e-9)
        .map(|(k, r)| format!("line {} ({:.4} mm)", line(k), mm(*r)))
        .collect();
    if !outliers.is_empty() {
        let _ = writeln!(
            t,
            "\nwarning: {} measurement(s) misclose by more than {OUTLIER_FACTOR} times the RMS after calibration (likely outliers: remove them and run again): {}",
            outliers.len(),
            outliers
                .iter()
                .take(10)
                .cloned()
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if !large.is_empty() {
        let _ = writeln!(
            t,
            "\nwarning: {} moved by more than {:.0} % of the platform's size ({:.1} mm): check that the measured poses are in the scenario's frames and the commanded values in its leg order",
            large.join(", "),
            LARGE_CHANGE * 100.0,
            mm(LARGE_CHANGE * size)
        );
    }
    t
}

/// One leg's fit: its residuals, how well its parameters are determined, and each
/// parameter's change (the names of those that moved more than `LARGE_CHANGE` of `size`
/// pushed to `large`).
fn leg_fit(
    t: &mut String,
    leg: usize,
    fit: &stewart_kinematics::analysis::calibration::LegCalibration,
    size: f64,
    large: &mut Vec<String>,
) {
    let _ = writeln!(
        t,
        "\nleg {}: RMS {:.4} mm before, {:.4} mm after ({} steps)",
        leg + 1,
        mm(fit.rms_before),
        mm(fit.rms_after),
        fit.iterations
    );
    let values: Vec<String> = fit
        .singular_values
        .iter()
        .map(|s| format!("{s:.3e}"))
        .collect();
    let _ = writeln!(
        t,
        "  singular values of the identification Jacobian (RMS residual per unit change): {}",
        values.join(" ")
    );
    let weakest: Vec<String> = fit
        .weakest_direction
        .iter()
        .map(|(name, v)| format!("{v:+.2} {name}"))
        .collect();
    let _ = writeln!(t, "  least determined combination: {}", weakest.join(" "));
    let _ = writeln!(
        t,
        "  {:<12} {:>13} {:>13} {:>12} {:>12}",
        "parameter", "nominal", "calibrated", "change", "± (1σ)"
    );
    for p in &fit.parameters {
        let _ = writeln!(t, "  {}", parameter_row(p));
        if p.unit == ParameterUnit::Metre && (p.value - p.nominal).abs() > LARGE_CHANGE * size {
            large.push(p.name.clone());
        }
    }
}

/// One parameter's row: name, nominal, calibrated, change, uncertainty (mm or degrees).
fn parameter_row(p: &Parameter) -> String {
    let uncertainty = |scale: f64, unit: &str| match (p.held, p.uncertainty) {
        (true, _) => "held".to_owned(),
        (false, Some(u)) => format!("{:.4} {unit}", u * scale),
        (false, None) => "—".to_owned(),
    };
    match p.unit {
        ParameterUnit::Metre if p.name.starts_with("offset") => format!(
            "{:<12} {:>10.4} mm {:>10.4} mm {:>+9.4} mm {:>12}",
            p.name,
            mm(p.nominal),
            mm(p.value),
            mm(p.value - p.nominal),
            uncertainty(1e3, "mm")
        ),
        ParameterUnit::Metre => format!(
            "{:<12} {:>11.6} m {:>11.6} m {:>+9.4} mm {:>12}",
            p.name,
            p.nominal,
            p.value,
            mm(p.value - p.nominal),
            uncertainty(1e3, "mm")
        ),
        ParameterUnit::Radian => format!(
            "{:<12} {:>11.4} ° {:>11.4} ° {:>+10.4} ° {:>12}",
            p.name,
            p.nominal.to_degrees(),
            p.value.to_degrees(),
            (p.value - p.nominal).to_degrees(),
            uncertainty(180.0 / std::f64::consts::PI, "°")
        ),
    }
}
