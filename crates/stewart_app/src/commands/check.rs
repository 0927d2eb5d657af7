//! `stewart check`: the trajectory checks, as text or JSON.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::Result;
use serde::Serialize;
use stewart_kinematics::{CheckReport, Scenario, check_motion};

use crate::cli::{CheckArgs, Format};
use crate::output;
use crate::source;

/// The JSON document: the scenario's name and limits, then the report.
#[derive(Serialize)]
struct JsonReport<'a> {
    scenario: &'a str,
    clean: bool,
    leg_min_m: Option<f64>,
    leg_max_m: Option<f64>,
    #[serde(flatten)]
    report: &'a CheckReport,
}

/// Run the command.
pub fn run(args: &CheckArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let report = check_motion(
        &scenario.geometry,
        &scenario.motion.sample(),
        &scenario.checks,
    );
    let text = match args.format {
        Format::Text => text_report(&scenario, &report),
        Format::Json => {
            let stroke = scenario.geometry.stroke();
            let doc = JsonReport {
                scenario: &scenario.name,
                clean: report.is_clean(),
                leg_min_m: stroke.min,
                leg_max_m: stroke.max,
                report: &report,
            };
            serde_json::to_string_pretty(&doc)? + "\n"
        }
    };
    output::emit(None, text.as_bytes())?;
    Ok(if report.is_clean() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn text_report(scenario: &Scenario, report: &CheckReport) -> String {
    let mut s = String::new();
    let [t0, t1] = report.time_span;
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "Scenario `{}`: {} samples from t = {t0} s to t = {t1} s.",
        scenario.name, report.samples
    );
    let stroke = scenario.geometry.stroke();
    let fmt_limit = |v: Option<f64>| v.map_or_else(|| "none".to_owned(), |v| format!("{v} m"));
    let _ = writeln!(
        s,
        "Stroke limits: min {}, max {}.",
        fmt_limit(stroke.min),
        fmt_limit(stroke.max)
    );
    for (i, [lo, hi]) in report.leg_ranges.iter().enumerate() {
        let _ = writeln!(s, "  L{}: {lo:.4} m … {hi:.4} m", i + 1);
    }
    let _ = writeln!(
        s,
        "Rigid body: largest change of a platform-joint distance {:.1e} m (tolerance {:.1e} m).",
        report.rigid_worst_deviation, scenario.checks.rigid_tolerance
    );
    if report.is_clean() {
        let _ = writeln!(
            s,
            "No problem found: every leg stays within its stroke, no jumps, the platform moves rigidly."
        );
    } else {
        let _ = writeln!(s, "{} problem(s) found:", report.findings.len());
        for f in &report.findings {
            let _ = writeln!(s, "  - {f}");
        }
    }
    s
}
