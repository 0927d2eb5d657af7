//! `stewart.Platform`: a scenario (geometry, motion, limits, payload) with its kinematics
//! on numpy arrays, and `stewart.calibrate`.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use stewart_kinematics::analysis::architecture;
use stewart_kinematics::analysis::calibration::{
    Held, Measurement, calibrate as fit, calibrated_scenario,
};
use stewart_kinematics::analysis::checks::document::CheckDocument;
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::model::angle::Angle;
use stewart_kinematics::model::link_settings::TEMPLATE_KEY;
use stewart_kinematics::solve::batch::RowError;
use stewart_kinematics::solve::forward::ForwardSolution;
use stewart_kinematics::solve::forward::assembly::canonical;
use stewart_kinematics::{
    Pose, Scenario, analysis::checks::check_motion, io::settings, solve::forward::ForwardOptions,
};

use crate::arrays::{self, Rows};
use crate::errors::{raise, scenario as scenario_error};
use crate::waiting;

/// Poses found for rows, or the row (from 0) that has none and why.
type RowPoses = Result<Vec<[f64; 6]>, (usize, String)>;

/// The pose columns.
const POSE: [&str; 6] = arrays::POSE_COLUMNS;

/// A Gough–Stewart platform and its motion (a scenario of the studio): made from a preset
/// or a scenario file, changed by setting keys, and solved on numpy arrays.
#[pyclass(module = "stewart")]
pub struct Platform {
    scenario: Scenario,
}

impl Platform {
    /// The scenario behind it.
    pub(crate) fn scenario(&self) -> &Scenario {
        &self.scenario
    }
}

/// A pose as a row `[x, y, z, roll, pitch, yaw]` (metres, degrees), its angles in the
/// forward solver's canonical range (as `stewart fk` writes them).
fn row_of(s: &ForwardSolution) -> [f64; 6] {
    canonical(&s.pose).to_row()
}

/// A link template that the link's grammar refuses, as (key, reason): held to it where it is
/// written, as the command line holds it.
fn template_problem(scenario: &Scenario) -> Option<(String, String)> {
    let text = scenario.link.template.as_deref()?;
    let refused = stewart_link::template::Template::parse(text).err()?;
    Some((TEMPLATE_KEY.to_owned(), refused.to_string()))
}

/// A new `(n, 6)` array of `rows`.
fn array<'py>(py: Python<'py>, rows: &[[f64; 6]]) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    let a = PyArray1::from_vec(py, flat);
    a.reshape([rows.len(), 6])
        .unwrap_or_else(|_| unreachable!("n × 6 values reshape to (n, 6)"))
}

impl Platform {
    fn columns(&self) -> [&'static str; 6] {
        self.scenario.geometry.quantity().columns
    }
}

#[pymethods]
impl Platform {
    /// A shipped preset: `seed`, `paired`, `circle`, `figure8`, `helix`, `sway`,
    /// `keyframes`, `servo-desk`, `crank-rig` or `dietmaier` (see `stewart.presets()`).
    #[staticmethod]
    fn preset(py: Python<'_>, name: &str) -> PyResult<Self> {
        Scenario::preset(name)
            .map(|scenario| Self { scenario })
            .map_err(|e| scenario_error(py, e))
    }

    /// A scenario file (TOML); errors name the file, line and key. Read with the GIL
    /// released, Ctrl-C ending the wait (a FIFO no one writes to blocks nothing else).
    #[staticmethod]
    fn from_file(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Self> {
        waiting::interruptible(py, None, move || {
            Scenario::load_checked(&path, &template_problem)
        })?
        .map(|scenario| Self { scenario })
        .map_err(|e| scenario_error(py, e))
    }

    /// Change one setting by its key, as `stewart settings` lists them and `--set` takes
    /// them: a number (`p.set("geometry.base_radius", 1.2)`), `None` to switch an optional
    /// one off, `True`/`False` for switches, or words for `link.*` keys and
    /// `cueing.algorithm` (`"washout"`, `"mpc"`). A refused value
    /// leaves the platform unchanged.
    fn set(&mut self, py: Python<'_>, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let text = if value.is_none() {
            "off".to_owned()
        } else if let Ok(b) = value.extract::<bool>() {
            b.to_string()
        } else if let Ok(v) = value.extract::<f64>() {
            format!("{v}")
        } else if let Ok(words) = value.extract::<String>() {
            words
        } else {
            // Bytes, a list…: its repr (`b'…'`, `bytearray(…)`) would be taken as the words.
            return Err(scenario_error(
                py,
                format!(
                    "`{key}`: give a number, True or False, None or text (a str), not {}",
                    value.get_type().name()?
                ),
            ));
        };
        let mut edited = self.scenario.clone();
        settings::apply_all(&mut edited, [format!("{key}={text}").as_str()])
            .map_err(|e| scenario_error(py, e))?;
        if let Some((key, reason)) = template_problem(&edited) {
            return Err(scenario_error(py, format!("`{key}` refused: {reason}")));
        }
        self.scenario = edited;
        Ok(())
    }

    /// The value of a setting: a number (`None` when it is off or does not apply), or for
    /// `link.*` keys, which `set` takes as words, their word (a number where it is one);
    /// `cueing.algorithm` gives `"washout"` or `"mpc"`.
    fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        if key.trim().starts_with("link.") {
            let entries = self.scenario.link.entries();
            let Some((_, word)) = entries.iter().find(|(k, _)| k == key.trim()) else {
                let known: Vec<&str> = entries.iter().map(|(k, _)| k.as_str()).collect();
                return Err(scenario_error(
                    py,
                    format!(
                        "unknown setting `{key}`; the link's are {}",
                        known.join(", ")
                    ),
                ));
            };
            return Ok(match (word.as_str(), word.parse::<f64>()) {
                (_, Ok(v)) => v.into_pyobject(py)?.into_any(),
                ("off", _) => py.None().into_bound(py),
                ("true", _) => true.into_pyobject(py)?.to_owned().into_any(),
                ("false", _) => false.into_pyobject(py)?.to_owned().into_any(),
                (_, Err(_)) => word.into_pyobject(py)?.into_any(),
            });
        }
        if key.trim() == "cueing.algorithm" {
            let word = self.scenario.cueing.algorithm.word();
            return Ok(word.into_pyobject(py)?.into_any());
        }
        let setting = settings::find(key).map_err(|e| scenario_error(py, e))?;
        Ok(setting.get(&self.scenario).into_pyobject(py)?.into_any())
    }

    /// The scenario's name.
    #[getter]
    fn name(&self) -> String {
        self.scenario.name.clone()
    }

    /// `"linear"` legs or `"rotary"` servos.
    #[getter]
    fn actuator(&self) -> &'static str {
        self.scenario.geometry.actuator().kind_name()
    }

    /// The actuator values' names: `L1…L6` (metres) or `theta1…theta6` (degrees).
    #[getter]
    fn columns_names(&self) -> Vec<&'static str> {
        self.columns().to_vec()
    }

    /// The home pose `[x, y, z, roll, pitch, yaw]`.
    #[getter]
    fn home(&self) -> [f64; 6] {
        self.scenario.geometry.home_pose().to_row()
    }

    /// The scenario as TOML text (what `from_file` reads back).
    fn to_toml(&self) -> String {
        self.scenario.to_toml()
    }

    /// Inverse kinematics of `poses`, an `(n, 6)` float64 array of x, y, z (metres) and
    /// roll, pitch, yaw (degrees): the `(n, 6)` leg lengths (metres) or servo angles
    /// (degrees), on all cores with the GIL released. A C-contiguous input is read in
    /// place and the result written straight into the array returned (no copy either
    /// way). `out`, an `(n, 6)` C-contiguous float64 array, takes the result instead of a
    /// new one (no allocation: for loops over many batches). A pose a servo cannot reach
    /// raises `UnreachableError` with its row and servo.
    #[pyo3(signature = (poses, out = None))]
    fn ik<'py>(
        slf: PyRef<'py, Self>,
        poses: &Bound<'py, PyAny>,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let py = slf.py();
        // Not a float64 array: said as such (numpy's own cast error names no dtype).
        let out = out
            .map(|o| match o.cast_into::<PyArray2<f64>>() {
                Ok(array) => Ok(array),
                Err(e) => {
                    let o = e.into_inner();
                    let dtype = o.getattr("dtype").map_or_else(
                        |_| {
                            o.get_type()
                                .name()
                                .map_or_else(|_| "?".to_owned(), |n| n.to_string())
                        },
                        |d| d.to_string(),
                    );
                    Err(pyo3::exceptions::PyTypeError::new_err(format!(
                        "out must be a two-dimensional float64 array of shape (n, 6), got {dtype}"
                    )))
                }
            })
            .transpose()?;
        // The platform as it is now; `set` from another thread meanwhile waits for nothing.
        let g = slf.scenario.geometry.clone();
        drop(slf);
        let rows = arrays::table(poses, "poses", &POSE)?;
        let n = rows.values().len() / 6;
        let out = match out {
            Some(out) => {
                arrays::check_out(&out, n)?;
                out
            }
            None => PyArray2::<f64>::zeros(py, [n, 6], false),
        };
        {
            let mut writer = out.readwrite();
            let slice = writer
                .as_slice_mut()
                .unwrap_or_else(|_| unreachable!("a new array is contiguous"));
            let target: &mut [[f64; 6]] = bytemuck::cast_slice_mut(slice);
            let input: &[[f64; 6]] = bytemuck::cast_slice(rows.values());
            let g = &g;
            let solved = py.detach(|| g.actuator_values_rows(input, target));
            match solved {
                Ok(()) => {}
                Err(RowError::NotFinite { row, column }) => {
                    let value = input[row][column];
                    return Err(arrays::not_finite("poses", row, POSE[column], value));
                }
                Err(RowError::Outside { row, column }) => {
                    return Err(arrays::pose_outside("poses", row, &input[row], column));
                }
                Err(RowError::Unreachable { row, servo }) => {
                    // In the closed form's words, as `stewart solve` says it.
                    let why = g
                        .actuator_values_at(&Pose::from_row(&input[row]))
                        .err()
                        .map_or_else(
                            || format!("servo {} cannot reach its platform joint", servo + 1),
                            |e| e.to_string(),
                        );
                    let message = format!("poses, row {row} (from 0): {why}");
                    return Err(raise(py, "UnreachableError", (message, row, servo + 1)));
                }
            }
        }
        drop(rows);
        Ok(out)
    }

    /// Forward kinematics of `values`, an `(n, 6)` array of leg lengths (metres) or servo
    /// angles (degrees): the `(n, 6)` poses, each row started from the previous row's
    /// pose (from home for the first), as `stewart fk` does. With `assembly_modes=True`,
    /// a list with every assembly mode of each row instead (an `(k, 6)` array per row).
    #[pyo3(signature = (values, assembly_modes = false))]
    fn fk<'py>(
        slf: PyRef<'py, Self>,
        values: &Bound<'py, PyAny>,
        assembly_modes: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let columns = slf.columns();
        let (g, name) = (slf.scenario.geometry.clone(), slf.scenario.name.clone());
        drop(slf);
        let rows: Rows<'_> = arrays::finite_table(values, "values", &columns)?;
        let input: Vec<[f64; 6]> = bytemuck::cast_slice(rows.values()).to_vec();
        drop(rows);
        if g.rotary().is_none() && architecture::architecture(&g).singular {
            return Err(raise(
                py,
                "ForwardError",
                (
                    format!(
                        "scenario `{}`: the pose is not determined by the leg lengths, so forward kinematics has no answer",
                        name
                    ),
                    0usize,
                ),
            ));
        }
        let forward_error = |row: usize, e: &dyn std::fmt::Display| {
            raise(
                py,
                "ForwardError",
                (format!("values, row {row} (from 0): {e}"), row),
            )
        };
        if assembly_modes {
            let found: Vec<RowPoses> = waiting::interruptible(py, None, move || {
                input
                    .iter()
                    .enumerate()
                    .map(|(k, row)| {
                        let modes = if g.rotary().is_some() {
                            g.servo_assembly_modes(&row.map(Angle::from_degrees))
                        } else {
                            g.assembly_modes(row)
                        };
                        modes
                            .map(|m| m.iter().map(row_of).collect())
                            .map_err(|e| (k, e.to_string()))
                    })
                    .collect()
            })?;
            let list = PyList::empty(py);
            for modes in found {
                let modes = modes.map_err(|(k, e)| forward_error(k, &e))?;
                list.append(array(py, &modes))?;
            }
            return Ok(list.into_any());
        }
        let options = ForwardOptions::default();
        let solved: RowPoses = waiting::interruptible(py, None, move || {
            if g.rotary().is_some() {
                let mut start = g.home_pose();
                let mut out = Vec::with_capacity(input.len());
                for (k, row) in input.iter().enumerate() {
                    let s = g
                        .forward_servos(&row.map(Angle::from_degrees), &start, &options)
                        .map_err(|e| (k, e.to_string()))?;
                    start = s.pose;
                    out.push(row_of(&s));
                }
                Ok(out)
            } else {
                g.forward_sequence(&input, false, &options)
                    .map(|s| s.solutions.iter().map(row_of).collect())
                    .map_err(|e| (e.index, e.error.to_string()))
            }
        })?;
        let poses = solved.map_err(|(k, e)| forward_error(k, &e))?;
        Ok(array(py, &poses).into_any())
    }

    /// The 6×6 Jacobian of the actuators at `pose` (`[x, y, z, roll, pitch, yaw]`):
    /// actuator rates per twist `(v, ω)` about the pivot point — rows `[u, r × u]` for
    /// legs, the servo Jacobian for servos.
    fn jacobian<'py>(
        &self,
        py: Python<'py>,
        pose: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let p = arrays::pose(pose, "pose")?;
        let g = &self.scenario.geometry;
        if let Some(leg) = g.leg_without_direction(&p).filter(|_| g.rotary().is_none()) {
            return Err(raise(
                py,
                "SingularError",
                (
                    format!(
                        "pose: leg {} has zero length (its joints meet), so it has no direction and the Jacobian is undefined",
                        leg + 1
                    ),
                    leg + 1,
                ),
            ));
        }
        let j = g.actuator_jacobian(&p).map_err(|e| {
            raise(
                py,
                "UnreachableError",
                (format!("pose: {e}"), 0usize, e.servo),
            )
        })?;
        let rows: Vec<[f64; 6]> = (0..6).map(|i| std::array::from_fn(|k| j[(i, k)])).collect();
        Ok(array(py, &rows))
    }

    /// The normalised condition number of the actuators' Jacobian at `pose` (infinite at
    /// a singular pose), as the checks and the viewer report it.
    fn condition(&self, py: Python<'_>, pose: &Bound<'_, PyAny>) -> PyResult<f64> {
        let p = arrays::pose(pose, "pose")?;
        let c = self
            .scenario
            .geometry
            .actuated_conditioning(&p)
            .ok_or_else(|| {
                raise(
                    py,
                    "UnreachableError",
                    (
                        "pose: a servo cannot reach its platform joint".to_owned(),
                        0usize,
                        0usize,
                    ),
                )
            })?;
        Ok(c.condition_number.unwrap_or(f64::INFINITY))
    }

    /// The pre-flight check of the motion as a dict: what `stewart check --format json`
    /// prints. Ctrl-C stops the wait.
    fn check<'py>(slf: PyRef<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let s = slf.scenario.clone();
        drop(slf);
        let (report, s) = waiting::interruptible(py, None, move || {
            let report = check_motion(
                &s.geometry,
                &s.limits,
                &s.motion.samples_judged(s.link.rate_hz),
                &s.checks,
            );
            (report, s)
        })?;
        let doc = CheckDocument::new(&s.name, &s.geometry, &report);
        let text = serde_json::to_string(&doc).map_err(|e| PyValueError::new_err(e.to_string()))?;
        py.import("json")?.getattr("loads")?.call1((text,))
    }

    /// The reachable workspace at a fixed `orientation` (roll, pitch, yaw in degrees) on a
    /// grid of `resolution` columns a side: a dict with `volume` and `volume_error` (m³)
    /// and `extent` (`[[x_min, x_max], [y_min, y_max], [z_min, z_max]]`, `None` when
    /// nothing is reachable), as `stewart workspace` reports them. A request estimated
    /// over the budget (two minutes, 2 GB), as `stewart workspace` estimates it, is refused
    /// with the largest resolution that fits unless `budget=False`; Ctrl-C stops it.
    #[pyo3(signature = (orientation = (0.0, 0.0, 0.0), resolution = 400, budget = true))]
    fn workspace<'py>(
        slf: PyRef<'py, Self>,
        orientation: (f64, f64, f64),
        resolution: usize,
        budget: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        use stewart_kinematics::analysis::workspace::{BUDGET_SECONDS, WorkspaceControl};
        let py = slf.py();
        let angles = [orientation.0, orientation.1, orientation.2];
        if let Some(a) = angles.iter().find(|a| !a.is_finite() || a.abs() > 3600.0) {
            return Err(PyValueError::new_err(format!(
                "orientation: {a} is not an angle within ±3600°"
            )));
        }
        if !(2..=4096).contains(&resolution) {
            return Err(PyValueError::new_err(format!(
                "resolution must be from 2 to 4096 columns a side, got {resolution}"
            )));
        }
        let (g, limits) = (slf.scenario.geometry.clone(), slf.scenario.limits);
        drop(slf);
        let orientation = angles.map(Angle::from_degrees);
        let cancel = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let stop = std::sync::Arc::clone(&cancel);
        let ws = waiting::interruptible(py, Some(cancel), move || {
            if budget {
                let started = std::time::Instant::now();
                let cost = workspace::workspace_cost(&g, &limits, orientation, resolution)
                    .map_err(|e| e.to_string())?;
                let estimate = cost.estimate(started.elapsed().as_secs_f64(), resolution);
                if estimate.over_budget {
                    return Err(format!(
                        "a {resolution} × {resolution} workspace would take about {:.0} s and {:.0} MB, over the budget of {BUDGET_SECONDS:.0} s and 2 GB: use resolution={} or lower, or budget=False to run it anyway (Ctrl-C stops it)",
                        estimate.seconds,
                        cost.bytes / 1e6,
                        estimate.within_budget.min(resolution - 1).max(2)
                    ));
                }
            }
            let control = WorkspaceControl::stopped_by(stop);
            workspace::constant_orientation_workspace_with(&g, &limits, orientation, resolution, &control)
                .map_err(|e| e.to_string())
        })?
        .map_err(PyValueError::new_err)?;
        let d = PyDict::new(py);
        d.set_item("volume", ws.volume)?;
        d.set_item("volume_error", ws.volume_error)?;
        d.set_item("extent", ws.extent.map(|e| e.map(|r| r.to_vec()).to_vec()))?;
        d.set_item("resolution", ws.resolution)?;
        Ok(d)
    }

    /// The motion, sampled: `(times, poses)`, an `(n,)` array of seconds and an `(n, 6)`
    /// array of x, y, z (metres), roll, pitch, yaw (degrees).
    fn trajectory<'py>(
        &self,
        py: Python<'py>,
    ) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray2<f64>>) {
        let samples = self.scenario.motion.sample();
        let rows: Vec<[f64; 6]> = samples.poses.iter().map(Pose::to_row).collect();
        (PyArray1::from_vec(py, samples.times), array(py, &rows))
    }

    fn __repr__(&self) -> String {
        format!(
            "Platform('{}', {} actuators)",
            self.scenario.name,
            self.actuator()
        )
    }
}

/// The names of the shipped presets.
#[pyfunction]
pub fn presets() -> Vec<&'static str> {
    stewart_kinematics::io::scenario::presets::names().collect()
}

/// Calibrate a built platform from `measured`, an `(n, 12)` array per measurement of the
/// measured pose (x, y, z in metres, roll, pitch, yaw in degrees) and the six values
/// commanded for it (leg lengths in metres, or model servo angles in degrees as `ik`
/// gives them); `hold` names parameter groups kept as designed (`"base"`, `"platform"`,
/// `"offsets"`). Returns `(calibrated, report)`: a `Platform` with its joints as
/// coordinates and the offsets folded in (as `stewart calibrate --out` writes it) and a
/// dict with the offsets and the residuals before and after.
#[pyfunction]
#[pyo3(signature = (platform, measured, hold = Vec::new()))]
pub fn calibrate<'py>(
    py: Python<'py>,
    platform: PyRef<'py, Platform>,
    measured: &Bound<'py, PyAny>,
    hold: Vec<String>,
) -> PyResult<(Platform, Bound<'py, PyDict>)> {
    // The platform as it is now; `set` from another thread meanwhile waits for nothing.
    let scenario = platform.scenario.clone();
    drop(platform);
    let quantity = scenario.geometry.quantity();
    let mut columns: Vec<&str> = POSE.to_vec();
    columns.extend(quantity.columns);
    let rows = arrays::finite_table(measured, "measured", &columns)?;
    for (k, row) in rows.values().chunks_exact(12).enumerate() {
        let pose: [f64; 6] = std::array::from_fn(|i| row[i]);
        // Finite already (`finite_table`): only a pose outside the accepted ranges is left.
        if let Err((column, _)) = stewart_kinematics::ground::bounds::check_pose_row(&pose) {
            return Err(arrays::pose_outside("measured", k, &pose, column));
        }
    }
    let measurements: Vec<Measurement> = rows
        .values()
        .chunks_exact(12)
        .map(|r| Measurement {
            pose: Pose::from_row(&[r[0], r[1], r[2], r[3], r[4], r[5]]),
            commanded: std::array::from_fn(|i| r[6 + i] * quantity.si_per_unit),
        })
        .collect();
    drop(rows);
    for h in &hold {
        if !["base", "platform", "offsets"].contains(&h.as_str()) {
            return Err(PyValueError::new_err(format!(
                "hold: `{h}` is not one of base, platform, offsets"
            )));
        }
    }
    let held = Held {
        base: hold.iter().any(|h| h == "base"),
        platform: hold.iter().any(|h| h == "platform"),
        offsets: hold.iter().any(|h| h == "offsets"),
    };
    let g = &scenario.geometry;
    let c = py
        .detach(|| fit(g, &measurements, held))
        .map_err(|e| raise(py, "CalibrationError", (format!("measured: {e}"),)))?;
    let calibrated = calibrated_scenario(&scenario, &c, measurements.len());
    let report = PyDict::new(py);
    let per_unit = 1.0 / quantity.si_per_unit;
    report.set_item("offsets", c.offsets.map(|o| o * per_unit).to_vec())?;
    report.set_item("rms_before", c.before.rms)?;
    report.set_item("rms_after", c.after.rms)?;
    report.set_item("max_before", c.before.max)?;
    report.set_item("max_after", c.after.max)?;
    report.set_item("row_residuals", c.row_residuals.clone())?;
    Ok((
        Platform {
            scenario: calibrated,
        },
        report,
    ))
}
