//! Errors of scenario files: one sentence naming the file, the line and the value at fault.

use std::fmt;

use thiserror::Error;

use crate::io::table::TableError;
use crate::model::geometry::GeometryError;
use crate::model::trajectory::{KeyframeError, SamplingError};

/// What is wrong with a scenario.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ScenarioProblem {
    /// The file could not be read.
    #[error("{0}")]
    Unreadable(String),
    /// TOML syntax, a wrong type, a missing or unknown key (the TOML parser's words).
    #[error("{0}")]
    Syntax(String),
    /// The geometry was refused.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// The rotary actuators were refused.
    #[error(transparent)]
    Actuator(#[from] crate::model::rotary::RotaryError),
    /// The sampling was refused.
    #[error(transparent)]
    Sampling(#[from] SamplingError),
    /// The keyframes were refused.
    #[error(transparent)]
    Keyframes(#[from] KeyframeError),
    /// The pose table named by the scenario was refused (its error names its own file and line).
    #[error("in the pose table: {0}")]
    Table(#[from] TableError),
    /// A value that parsed but makes no sense.
    #[error("`{field}` {reason}")]
    Invalid {
        /// The key at fault, with its table (`trajectory.radius_m`).
        field: String,
        /// Why, as the end of a sentence.
        reason: String,
    },
    /// No preset of that name.
    #[error("no preset is called `{name}` (presets: {known})")]
    UnknownPreset {
        /// The name asked for.
        name: String,
        /// The names that exist.
        known: String,
    },
}

/// A scenario that could not be loaded, with where the problem is.
#[derive(Debug, Clone, PartialEq, Error)]
pub struct ScenarioError {
    /// The file (or preset) name.
    pub file: String,
    /// Line from 1, when known.
    pub line: Option<usize>,
    /// Column from 1, when known.
    pub column: Option<usize>,
    /// What is wrong (boxed: it can be large, and errors travel by value).
    pub problem: Box<ScenarioProblem>,
}

impl ScenarioError {
    /// An error at a byte range of the source text `src`.
    pub(crate) fn at(
        file: &str,
        src: &str,
        span: Option<std::ops::Range<usize>>,
        problem: impl Into<ScenarioProblem>,
    ) -> Self {
        let (line, column) = match span {
            Some(span) => {
                let start = span.start.min(src.len());
                let before = &src[..start];
                let line = before.matches('\n').count() + 1;
                let line_start = before.rfind('\n').map_or(0, |i| i + 1);
                (Some(line), Some(src[line_start..start].chars().count() + 1))
            }
            None => (None, None),
        };
        Self {
            file: file.to_owned(),
            line,
            column,
            problem: Box::new(problem.into()),
        }
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => {
                write!(f, "{}, line {l}, column {c}: {}", self.file, self.problem)
            }
            (Some(l), None) => write!(f, "{}, line {l}: {}", self.file, self.problem),
            _ => write!(f, "{}: {}", self.file, self.problem),
        }
    }
}
