//! Motion cueing from Python: `cue` makes vehicle motion into platform poses by the
//! platform's `[cueing]` table (classical washout or model-predictive), as `stewart cue`
//! does; `cue_compare` runs both algorithms and returns their measures, as
//! `stewart cue --compare --format json` does.

use numpy::PyArray2;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use stewart_kinematics::Pose;
use stewart_kinematics::analysis::cueing::compare::{CueMeasures, compare};
use stewart_kinematics::analysis::cueing::{CueError, VehicleMotion, cue_recording};

use crate::arrays;
use crate::platform::Platform;

/// The vehicle table's columns.
const VEHICLE: [&str; 7] = ["t", "ax", "ay", "az", "wx", "wy", "wz"];

/// `vehicle` as samples, every value within the ranges `stewart cue` accepts.
fn samples(vehicle: &Bound<'_, PyAny>) -> PyResult<Vec<(f64, VehicleMotion)>> {
    use stewart_kinematics::ground::bounds::{check, symmetric};
    // The one range rule of vehicle motion, as `stewart cue` and the games' datagrams.
    use stewart_link::vehicle::COLUMN_BOUNDS;
    let rows = arrays::finite_table(vehicle, "vehicle", &VEHICLE)?;
    for (k, row) in rows.values().chunks_exact(7).enumerate() {
        for (i, v) in row.iter().enumerate() {
            let (_, range, unit) = COLUMN_BOUNDS[i];
            if let Err(why) = check(*v, &symmetric(range), unit) {
                return Err(PyValueError::new_err(format!(
                    "vehicle, row {k} (from 0), column {}: {why}",
                    VEHICLE[i]
                )));
            }
        }
    }
    Ok(rows
        .values()
        .chunks_exact(7)
        .map(|r| {
            (
                r[0],
                VehicleMotion {
                    accel: [r[1], r[2], r[3]],
                    rates_deg_s: [r[4], r[5], r[6]],
                },
            )
        })
        .collect())
}

/// A cueing error in the words `stewart cue` uses, naming the vehicle row where there is
/// one.
fn refused(e: CueError) -> PyErr {
    match e {
        CueError::Time { index, .. } | CueError::PoseOutside { index, .. } => {
            PyValueError::new_err(format!("vehicle, row {index} (from 0): {e}"))
        }
        other => PyValueError::new_err(format!("cueing: {other}")),
    }
}

/// Platform poses from vehicle motion: `vehicle` an `(n, 7)` array of t (s), ax, ay, az
/// (the vehicle's specific force in its own frame, gravity excluded, m/s²) and wx, wy, wz
/// (°/s); returns the `(n, 6)` poses (x, y, z in metres, roll, pitch, yaw in degrees) by the
/// platform's `[cueing]` table — `p.set("cueing.algorithm", "mpc")` for model-predictive
/// cueing — as `stewart cue` writes them. Runs with the GIL released.
#[pyfunction]
pub fn cue<'py>(
    py: Python<'py>,
    platform: PyRef<'py, Platform>,
    vehicle: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let scenario = platform.scenario().clone();
    drop(platform);
    let samples = samples(vehicle)?;
    if samples.is_empty() {
        // As `stewart cue` refuses a table of no rows.
        return Err(PyValueError::new_err(
            "vehicle holds no rows: a recording needs at least one sample",
        ));
    }
    let s = &scenario;
    let cued = py
        .detach(|| cue_recording(&s.geometry, &s.limits, &s.checks, &s.cueing, &samples))
        .map_err(refused)?;
    let rows: Vec<[f64; 6]> = cued.poses.iter().map(Pose::to_row).collect();
    Ok(PyArray2::from_vec2(
        py,
        &rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>(),
    )?)
}

/// One algorithm's measures as a dict (the keys of `stewart cue --compare --format json`).
fn measures<'py>(py: Python<'py>, m: &CueMeasures) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("algorithm", m.algorithm.word())?;
    d.set_item("force_rmse_xy_m_s2", m.force_rmse_xy)?;
    d.set_item("force_rmse_m_s2", m.force_rmse.to_vec())?;
    d.set_item("force_correlation", m.force_correlation.to_vec())?;
    d.set_item("rate_rmse_deg_s", m.rate_rmse_deg_s.to_vec())?;
    d.set_item("false_tilt_rate_deg_s", m.false_tilt_rate_deg_s)?;
    d.set_item("stroke_used", m.stroke_used)?;
    d.set_item("limiter_s", m.limiter_s)?;
    d.set_item("failed_solves", m.failed_solves)?;
    d.set_item("stops", m.stops)?;
    Ok(d)
}

/// Both algorithms on `vehicle` (as for [`cue`]) with the platform's scales, rig and
/// limits — the washout with its workspace limiter on — and how each reproduces what is
/// felt: `{"washout": {...}, "mpc": {...}}`, each with the felt specific-force error
/// (RMSE, surge and sway together and per axis), shape correlation, rotation-rate error,
/// the false rotation of tilt, the largest stroke used, the limiter's time, and the
/// planner's failed solves and stops.
#[pyfunction]
pub fn cue_compare<'py>(
    py: Python<'py>,
    platform: PyRef<'py, Platform>,
    vehicle: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let scenario = platform.scenario().clone();
    drop(platform);
    let samples = samples(vehicle)?;
    let s = &scenario;
    let both = py
        .detach(|| compare(&s.geometry, &s.limits, &s.checks, &s.cueing, &samples))
        .map_err(refused)?;
    let out = PyDict::new(py);
    out.set_item("washout", measures(py, &both[0].0)?)?;
    out.set_item("mpc", measures(py, &both[1].0)?)?;
    Ok(out)
}
