//! Resolving `--preset` / `--scenario` into a scenario.

use anyhow::Result;
use stewart_kinematics::Scenario;

use crate::cli::ScenarioArgs;

/// The scenario the arguments name; the `seed` preset when they name none.
pub fn load(args: &ScenarioArgs) -> Result<Scenario> {
    let scenario = match (&args.preset, &args.scenario) {
        (_, Some(path)) => Scenario::load(path)?,
        (Some(name), None) => Scenario::preset(name)?,
        (None, None) => Scenario::preset("seed")?,
    };
    Ok(scenario)
}
