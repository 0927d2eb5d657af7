//! Raising the package's own exceptions (defined in `stewart/_errors.py`) with the core's
//! located messages.

use pyo3::prelude::*;

/// The exception `class` of `stewart._errors` made with `args`.
pub fn raise<'py>(py: Python<'py>, class: &str, args: impl pyo3::call::PyCallArgs<'py>) -> PyErr {
    let made = py
        .import("stewart._errors")
        .and_then(|m| m.getattr(class))
        .and_then(|c| c.call1(args));
    match made {
        Ok(error) => PyErr::from_value(error),
        Err(e) => e,
    }
}

/// A `ScenarioError` saying `message`.
pub fn scenario(py: Python<'_>, message: impl std::fmt::Display) -> PyErr {
    raise(py, "ScenarioError", (message.to_string(),))
}
