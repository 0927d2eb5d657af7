//! Resolving `--preset` / `--scenario` and `--set` into a scenario.

use anyhow::Result;
use stewart_kinematics::{Scenario, io::settings};

use crate::cli::ScenarioArgs;

/// The scenario the arguments name (the `seed` preset when they name none), with the
/// `--set` assignments applied in order. A template that is no template is refused where
/// it is written: at its line in the file, or as the `--set` that wrote it.
pub(crate) fn load(args: &ScenarioArgs) -> Result<Scenario> {
    let mut scenario = match (&args.preset, &args.scenario) {
        (_, Some(path)) => Scenario::load_checked(path, &crate::link_plan::template_problem)?,
        (Some(name), None) => Scenario::preset(name)?,
        (None, None) => Scenario::preset("seed")?,
    };
    for text in &args.set {
        settings::apply_all(&mut scenario, [text.as_str()])
            .map_err(|e| anyhow::anyhow!("--set: {e}"))?;
        if let Some((key, reason)) = crate::link_plan::template_problem(&scenario) {
            anyhow::bail!("--set `{text}`: `{key}` refused: {reason}");
        }
    }
    Ok(scenario)
}

/// Whether the scenario the arguments name gives the table `[name]` itself: in its file's
/// text (a preset's included), or by a `--set name.…` (a command that reports on a table's
/// settings refuses to report the defaults as the user's).
pub(crate) fn gives_table(args: &ScenarioArgs, name: &str) -> bool {
    let prefix = format!("{name}.");
    if args.set.iter().any(|s| s.trim_start().starts_with(&prefix)) {
        return true;
    }
    let text = match (&args.preset, &args.scenario) {
        (_, Some(path)) => std::fs::read_to_string(path).ok(),
        (Some(preset), None) => {
            stewart_kinematics::io::scenario::presets::text(preset).map(str::to_owned)
        }
        (None, None) => stewart_kinematics::io::scenario::presets::text("seed").map(str::to_owned),
    };
    text.and_then(|t| t.parse::<toml::Table>().ok())
        .is_some_and(|t| t.contains_key(name))
}

/// A scenario file, its template checked as [`load`] checks it (the viewer's Open and a
/// session's scenario).
pub(crate) fn load_file(
    path: &std::path::Path,
) -> Result<Scenario, stewart_kinematics::io::scenario::ScenarioError> {
    Scenario::load_checked(path, &crate::link_plan::template_problem)
}

/// The files a command reads through these arguments, with the words that name them (an
/// output may never be one of them): the scenario file, and every file the scenario itself
/// read or draws — its pose table, its CAD parts (named from its folder).
pub(crate) fn inputs(
    args: &ScenarioArgs,
    scenario: &Scenario,
) -> Vec<(&'static str, std::path::PathBuf)> {
    let mut out: Vec<(&'static str, std::path::PathBuf)> = (args.scenario.iter())
        .map(|p| ("the scenario file", p.clone()))
        .collect();
    out.extend((scenario.files_read.iter()).map(|p| ("the scenario's pose table", p.clone())));
    let folder = crate::appearance::folder_of(args);
    for part in stewart_kinematics::model::appearance::Part::ALL {
        if let Some(look) = scenario.appearance.part(part) {
            out.push(("one of the scenario's CAD parts", folder.join(&look.file)));
        }
    }
    out
}

/// [`inputs`], with the files the scenario's CAD parts were read from beside them (an
/// OBJ's material files, a glTF's buffers).
pub(crate) fn inputs_with_parts(
    args: &ScenarioArgs,
    scenario: &Scenario,
    parts: &stewart_render::appearance::parts::PartSet,
) -> Vec<(&'static str, std::path::PathBuf)> {
    let mut out = inputs(args, scenario);
    out.extend(
        parts
            .files()
            .into_iter()
            .map(|p| ("a file of the scenario's CAD parts", p)),
    );
    out
}

/// The scenario the arguments name, in words for messages: its file as given, or
/// `preset NAME`.
pub(crate) fn describe(args: &ScenarioArgs) -> String {
    match (&args.scenario, &args.preset) {
        (Some(path), _) => path.display().to_string(),
        (None, Some(name)) => format!("preset `{name}`"),
        (None, None) => "preset `seed`".to_owned(),
    }
}
