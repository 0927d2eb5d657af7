//! The `stewart._stewart` extension module: the kinematics core behind the `stewart`
//! Python package (`python/stewart`). Arrays in and out are numpy float64, one pose or one
//! set of six actuator values per row; batches run on all cores with the GIL released.

mod arrays;
mod cueing;
mod errors;
mod platform;
mod waiting;

use pyo3::prelude::*;

/// The module: `Platform`, `calibrate`, `cue`, `cue_compare` and `presets`.
#[pymodule]
fn _stewart(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<platform::Platform>()?;
    m.add_function(wrap_pyfunction!(platform::calibrate, m)?)?;
    m.add_function(wrap_pyfunction!(platform::presets, m)?)?;
    m.add_function(wrap_pyfunction!(cueing::cue, m)?)?;
    m.add_function(wrap_pyfunction!(cueing::cue_compare, m)?)?;
    Ok(())
}
