//! `stewart settings`: every key `--set` accepts, as a table.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::io::settings::{Setting, Target, Unit};
use stewart_kinematics::{Scenario, io::bounds, io::settings};

use crate::cli::SettingsArgs;
use crate::{output, source};

/// Run the command.
pub fn run(args: &SettingsArgs) -> Result<ExitCode> {
    if args.as_coordinates {
        let out = output::destination(args.out.as_deref(), &source::inputs(&args.scenario))?;
        let scenario = source::load(&args.scenario)?;
        let text = scenario.as_coordinates().to_toml();
        output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
        return Ok(ExitCode::SUCCESS);
    }
    let scenario = source::load(&args.scenario)?;
    output::stdout(table(&scenario).as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// The table: key, current value, unit, slider range, accepted range, default.
pub fn table(scenario: &Scenario) -> String {
    // Ten decimals hide the last-bit noise of angles stored in radians.
    let number = |v: Option<f64>| {
        v.map_or_else(
            || "off".to_owned(),
            |v| {
                if v != 0.0 && v.abs() < 1e-3 {
                    return format!("{v:e}");
                }
                let text = format!("{v:.10}");
                let text = text.trim_end_matches('0').trim_end_matches('.');
                if text == "-0" {
                    "0".to_owned()
                } else {
                    text.to_owned()
                }
            },
        )
    };
    // A switch reads `true` or `false`.
    let value_of = |s: &Setting, v: Option<f64>| match (s.unit, v) {
        (Unit::Switch, Some(v)) => (v != 0.0).to_string(),
        _ => number(v),
    };
    let rows: Vec<[String; 6]> = settings::all()
        .iter()
        .map(|s| {
            let value = if s.applies(scenario) {
                value_of(s, s.get(scenario))
            } else if let Target::Geometry(key) = s.target
                && key.circle_plate().is_some()
            {
                "(joints as coordinates)".to_owned()
            } else {
                "(other kinds)".to_owned()
            };
            [
                s.key.clone(),
                value,
                s.unit.symbol().to_owned(),
                format!(
                    "{} .. {}",
                    number(Some(*s.range.start())),
                    number(Some(*s.range.end()))
                ),
                format!(
                    "{}{} .. {}{}",
                    if s.min_excluded { "> " } else { "" },
                    bounds::short(*s.accepted.start()),
                    if s.max_excluded { "< " } else { "" },
                    bounds::short(*s.accepted.end())
                ),
                value_of(s, s.default_for(scenario)),
            ]
        })
        .collect();
    let header = [
        "key",
        "value",
        "unit",
        "slider range",
        "accepted",
        "default",
    ]
    .map(str::to_owned);
    let mut widths = [0; 6];
    for row in std::iter::once(&header).chain(&rows) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = format!(
        "Settings of `{}` (trajectory kind `{}`); change one with --set KEY=VALUE.\n",
        scenario.name,
        scenario.motion.trajectory.kind_name()
    );
    for row in std::iter::once(&header).chain(&rows) {
        let mut line = String::new();
        for (w, cell) in widths.iter().zip(row) {
            let pad = w - cell.chars().count();
            let _ = write!(line, "{cell}{}  ", " ".repeat(pad));
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    let _ = writeln!(
        out,
        "\nThe link to hardware ([link]; words or numbers, --set link.KEY=VALUE, K = channel 1..6):"
    );
    let entries = scenario.link.entries();
    let width = entries.iter().map(|(k, _)| k.len()).max().unwrap_or(0);
    for (key, value) in entries {
        let _ = writeln!(out, "{key:width$}  {value}");
    }
    if scenario.geometry.actuator().kind().has_level_home() {
        let _ = match scenario.geometry.servo_home_height() {
            Some(h) => writeln!(
                out,
                "Automatic home height (servos level with the platform centred and level): {h:.6} m; use it with --set geometry.home_height={h:.6}"
            ),
            None => writeln!(
                out,
                "No home height levels the servos with the platform centred and level."
            ),
        };
    }
    out
}
