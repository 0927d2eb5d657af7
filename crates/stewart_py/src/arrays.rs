//! Checking the arrays handed in: an `(n, k)` float64 array (or a list a numpy array can be
//! made of) with finite values, read in place when it is C-contiguous (zero-copy), copied
//! once otherwise. Every refusal names the argument, and a bad value its row and column.

use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The rows of a checked table: borrowed from the array, or a copy of it in row order.
pub enum Rows<'py> {
    /// The caller's C-contiguous array, read in place.
    Borrowed(PyReadonlyArray2<'py, f64>),
    /// A contiguous copy of a strided array.
    Copied(Vec<f64>),
}

impl Rows<'_> {
    /// The values, row after row.
    pub fn values(&self) -> &[f64] {
        match self {
            Rows::Borrowed(a) => a.as_slice().unwrap_or(&[]),
            Rows::Copied(v) => v,
        }
    }
}

/// `obj` as an `(n, columns.len())` float64 table named `name` in messages (its values
/// not yet checked: see [`finite_table`]). A list or tuple is made an array first; another
/// dtype is refused.
pub fn table<'py>(obj: &Bound<'py, PyAny>, name: &str, columns: &[&str]) -> PyResult<Rows<'py>> {
    let py = obj.py();
    let numpy = py.import("numpy")?;
    let is_array = obj.is_instance(&numpy.getattr("ndarray")?)?;
    let array = if is_array {
        obj.clone()
    } else {
        numpy
            .getattr("asarray")?
            .call1((obj, "float64"))
            .map_err(|e| PyTypeError::new_err(format!("{name}: not an array of numbers ({e})")))?
    };
    let dtype: String = array.getattr("dtype")?.str()?.extract()?;
    let shape: Vec<usize> = array.getattr("shape")?.extract()?;
    let k = columns.len();
    if shape.len() != 2 || shape[1] != k {
        return Err(PyValueError::new_err(format!(
            "{name} must be an (n, {k}) array with columns {}; got shape {shape:?}",
            columns.join(", ")
        )));
    }
    if dtype != "float64" {
        return Err(PyTypeError::new_err(format!(
            "{name} must be float64, got {dtype} (convert with .astype(numpy.float64))"
        )));
    }
    let typed = array
        .cast::<PyArray2<f64>>()
        .map_err(|e| PyTypeError::new_err(format!("{name}: {e}")))?;
    let readonly = typed.readonly();
    // Only a C-contiguous array holds its values row after row: a Fortran-ordered one is
    // contiguous too (`as_slice` takes it) but column after column, so it is copied in
    // row order like any other strided array.
    let rows = if typed.is_c_contiguous() {
        Rows::Borrowed(readonly)
    } else {
        // `iter` walks the array in its logical (row-major) order, whatever its strides.
        Rows::Copied(readonly.as_array().iter().copied().collect())
    };
    Ok(rows)
}

/// [`table`] with every value checked finite (on all cores, the GIL released).
pub fn finite_table<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
    columns: &[&str],
) -> PyResult<Rows<'py>> {
    let rows = table(obj, name, columns)?;
    let values = rows.values();
    if let Some(at) = obj.py().detach(|| first_non_finite(values)) {
        let k = columns.len();
        return Err(not_finite(name, at / k, columns[at % k], values[at]));
    }
    Ok(rows)
}

/// The refusal of `value` at `row`, `column` of the table `name`.
pub fn not_finite(name: &str, row: usize, column: &str, value: f64) -> PyErr {
    PyValueError::new_err(format!(
        "{name}, row {row} (from 0), column {column}: {value} is not a finite number"
    ))
}

/// The refusal of `row` of the pose table `name`, whose value `column` is outside the
/// accepted range of poses (the words `solve --poses` uses for a pose table).
pub fn pose_outside(name: &str, row: usize, values: &[f64; 6], column: usize) -> PyErr {
    use stewart_kinematics::ground::bounds::{POSE_ROW, POSE_ROW_UNITS, check, symmetric};
    let why = check(
        values[column],
        &symmetric(POSE_ROW[column]),
        POSE_ROW_UNITS[column],
    )
    .err()
    .map_or_else(
        || "is outside its accepted range".to_owned(),
        |e| e.to_string(),
    );
    PyValueError::new_err(format!(
        "{name}, row {row} (from 0), column {}: {why}",
        POSE_COLUMNS[column]
    ))
}

/// The pose columns' names in messages.
pub const POSE_COLUMNS: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];

/// Six finite numbers (a pose or one row of actuator values) named `name`.
pub fn six(obj: &Bound<'_, PyAny>, name: &str, columns: &[&str; 6]) -> PyResult<[f64; 6]> {
    let values: Vec<f64> = obj.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be six numbers: {}",
            columns.join(", ")
        ))
    })?;
    let row: [f64; 6] = values.as_slice().try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "{name} must be six numbers ({}), got {}",
            columns.join(", "),
            values.len()
        ))
    })?;
    if let Some(i) = row.iter().position(|v| !v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{name}, {}: {} is not a finite number",
            columns[i], row[i]
        )));
    }
    Ok(row)
}

/// A pose `[x, y, z, roll, pitch, yaw]` (metres, degrees) named `name`: six finite
/// numbers within the accepted range of poses, as a pose table's rows are checked.
pub fn pose(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<stewart_kinematics::Pose> {
    let row = six(obj, name, &POSE_COLUMNS)?;
    if let Err((column, why)) = stewart_kinematics::ground::bounds::check_pose_row(&row) {
        return Err(PyValueError::new_err(format!(
            "{name}, {}: {why}",
            POSE_COLUMNS[column]
        )));
    }
    Ok(stewart_kinematics::Pose::from_row(&row))
}

/// Whether `out` can take `n` rows of six values: `(n, 6)`, C-contiguous and writeable.
pub fn check_out(out: &Bound<'_, PyArray2<f64>>, n: usize) -> PyResult<()> {
    if out.shape() != [n, 6] {
        return Err(PyValueError::new_err(format!(
            "out must have shape ({n}, 6), got {:?}",
            out.shape()
        )));
    }
    if !out.is_c_contiguous() {
        return Err(PyValueError::new_err("out must be C-contiguous"));
    }
    out.try_readwrite()
        .map(drop)
        .map_err(|e| PyValueError::new_err(format!("out cannot be written: {e}")))
}

/// The index of the first value that is not finite, searched on all cores.
fn first_non_finite(values: &[f64]) -> Option<usize> {
    use rayon::prelude::*;
    const PIECE: usize = 1 << 15;
    let piece = values
        .par_chunks(PIECE)
        .position_first(|c| c.iter().any(|v| !v.is_finite()))?;
    let start = piece * PIECE;
    values[start..]
        .iter()
        .position(|v| !v.is_finite())
        .map(|k| start + k)
}
