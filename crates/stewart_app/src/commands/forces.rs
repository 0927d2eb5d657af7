//! `stewart forces`: leg forces (N) — or a rotary platform's servo torques (N·m) — for a
//! payload along the trajectory.

use std::process::ExitCode;
use stewart_kinematics::analysis::architecture;
use stewart_kinematics::analysis::dynamics;

use anyhow::{Result, anyhow};
use nalgebra::{Matrix3, Vector3};
use stewart_kinematics::analysis::forces::Payload;

use crate::cli::ForcesArgs;
use crate::csv_io::CsvText;
use crate::output;
use crate::source;

/// Run the command.
pub(crate) fn run(args: &ForcesArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let out = output::destination(
        args.out.as_deref(),
        &source::inputs(&args.scenario, &scenario),
    )?;
    let g = &scenario.geometry;
    let base = scenario.payload;
    let mass = args.mass.or(base.map(|p| p.mass)).ok_or_else(|| {
        anyhow!(
            "scenario `{}` has no [payload] table: give the moving mass with --mass KG",
            scenario.name
        )
    })?;
    let com = args
        .com
        .map(Vector3::from)
        .or(base.map(|p| p.centre_of_mass))
        .unwrap_or_else(Vector3::zeros);
    let inertia = args
        .inertia
        .and_then(|i| stewart_kinematics::analysis::forces::inertia_tensor(&i))
        .or(base.map(|p| p.inertia))
        .unwrap_or_else(Matrix3::zeros);
    let payload = Payload::new(mass, com, inertia)?;
    if architecture::architecture(g).singular {
        return Err(anyhow!(
            "scenario `{}` is architecturally singular, so the actuator forces are not determined at any pose (use a paired layout)",
            scenario.name
        ));
    }
    let series =
        dynamics::efforts_along(g, &scenario.motion.sample(), &payload, &scenario.dynamics)?;
    // Leg forces F (N) or servo torques T (N·m).
    let letter = g.quantity().effort.0;
    let mut header = vec!["t".to_owned()];
    header.extend((1..=6).map(|i| format!("{letter}{i}_static")));
    header.extend((1..=6).map(|i| format!("{letter}{i}")));
    let mut csv = CsvText::with_header(&header);
    for k in 0..series.times.len() {
        csv.row(
            [series.times[k]]
                .into_iter()
                .chain(series.statics[k])
                .chain(series.dynamics[k]),
        );
    }
    let text = csv.into_string();
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    Ok(ExitCode::SUCCESS)
}
