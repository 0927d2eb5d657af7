//! Reading a scenario: a file, a preset or TOML text becomes a [`Scenario`] whose every
//! value lies in its accepted range. Above both the file format (`scenario`) and the
//! settings (whose ranges it applies), so neither depends on the other.

use std::path::Path;

use crate::io::scenario::build;
use crate::io::scenario::presets;
use crate::io::scenario::{Scenario, ScenarioError, ScenarioProblem};

impl Scenario {
    /// Parse a scenario from TOML text. `file` names it in errors; a pose table's
    /// relative path is resolved against `base_dir` (the current folder when `None`).
    pub fn from_toml_str(
        text: &str,
        file: &str,
        base_dir: Option<&Path>,
    ) -> Result<Self, ScenarioError> {
        Self::from_toml_str_checked(text, file, base_dir, &|_| None)
    }

    /// [`Scenario::from_toml_str`], then `check` (a rule of a layer above, such as the
    /// link's template grammar): its `(key, reason)` is refused at the key's line.
    pub fn from_toml_str_checked(
        text: &str,
        file: &str,
        base_dir: Option<&Path>,
        check: &dyn Fn(&Scenario) -> Option<(String, String)>,
    ) -> Result<Self, ScenarioError> {
        let scenario = build::parse(text, file, base_dir)?;
        // Values no constructor refused may still be absurd (a 1e300 m radius).
        if let Some((setting, reason)) = crate::io::settings::out_of_range(&scenario) {
            return Err(build::invalid_key(text, file, &setting.key, reason));
        }
        if let Some((key, reason)) = check(&scenario) {
            return Err(build::invalid_key(text, file, &key, reason));
        }
        Ok(scenario)
    }

    /// Load a scenario file.
    pub fn load(path: &Path) -> Result<Self, ScenarioError> {
        Self::load_checked(path, &|_| None)
    }

    /// [`Scenario::load`], then `check` as [`Scenario::from_toml_str_checked`] does.
    pub fn load_checked(
        path: &Path,
        check: &dyn Fn(&Scenario) -> Option<(String, String)>,
    ) -> Result<Self, ScenarioError> {
        let name = path.display().to_string();
        let unreadable = |message: String| ScenarioError {
            file: name.clone(),
            line: None,
            column: None,
            problem: Box::new(ScenarioProblem::Unreadable(message)),
        };
        let bytes = crate::io::file::read_file(path, crate::io::file::FileKind::Scenario)
            .map_err(|e| unreadable(gate_words(&e)))?;
        let text = crate::ground::text::decode(bytes).map_err(unreadable)?;
        Self::from_toml_str_checked(&text, &name, path.parent(), check)
    }

    /// A shipped preset by name.
    pub fn preset(name: &str) -> Result<Self, ScenarioError> {
        let text = presets::text(name).ok_or_else(|| ScenarioError {
            file: format!("preset `{name}`"),
            line: None,
            column: None,
            problem: Box::new(ScenarioProblem::UnknownPreset {
                name: name.to_owned(),
                known: presets::names().collect::<Vec<_>>().join(", "),
            }),
        })?;
        Self::from_toml_str(text, &format!("preset `{name}`"), None)
    }
}

/// A gate refusal in the words a scenario error puts after the file's name.
fn gate_words(e: &crate::io::file::FileError) -> String {
    use crate::io::file::FileError;
    match e {
        FileError::Io { cause, .. } => format!("cannot be read ({cause})"),
        FileError::NotRegular { what, .. } => format!("is {what}, not a file"),
        FileError::TooLarge { cap_mib, .. } => {
            format!("is larger than {cap_mib} MiB, the most this program reads from such a file")
        }
    }
}
