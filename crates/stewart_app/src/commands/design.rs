//! `stewart design`: the stroke (or servo range) a motion envelope needs, as text or JSON.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::{Result, anyhow};
use serde::Serialize;
use stewart_kinematics::analysis::design::{
    DesignReport, Envelope, Extreme, NAMES, envelope_needs,
};
use stewart_kinematics::{Geometry, Scenario};

use crate::cli::{DesignArgs, ReportFormat};
use crate::output;
use crate::source;

/// The JSON document.
#[derive(Serialize)]
struct JsonReport<'a> {
    scenario: &'a str,
    actuator: &'static str,
    unit: &'static str,
    envelope: &'a Envelope,
    needed: Option<[Extreme; 2]>,
    limits: [Option<f64>; 2],
    fits: Option<bool>,
    #[serde(flatten)]
    report: &'a DesignReport,
}

/// Run the command.
pub(crate) fn run(args: &DesignArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let g = &scenario.geometry;
    let envelope =
        Envelope::parse(&args.envelope, &g.home_pose()).map_err(|e| anyhow!("--envelope: {e}"))?;
    let report = envelope_needs(g, &envelope);
    let text = match args.format {
        ReportFormat::Text => text(&scenario, &envelope, &report),
        ReportFormat::Json => {
            let q = g.quantity();
            let needed = report.overall();
            let limits = g.quantity_limits();
            let json = JsonReport {
                scenario: &scenario.name,
                actuator: q.part,
                unit: q.unit,
                envelope: &envelope,
                needed,
                limits,
                fits: report.fits(limits),
                report: &report,
            };
            serde_json::to_string_pretty(&json)? + "\n"
        }
    };
    output::stdout(text.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// A pose in words: `x +0.1000 y -0.1000 z 0.9000 m, roll +10.00° pitch …`.
pub(crate) fn pose_words(p: &[f64; 6]) -> String {
    format!(
        "x {:+.4} y {:+.4} z {:.4} m, roll {:+.2}° pitch {:+.2}° yaw {:+.2}°",
        p[0], p[1], p[2], p[3], p[4], p[5]
    )
}

/// The envelope in words.
fn envelope_words(e: &Envelope) -> String {
    (0..6)
        .map(|k| {
            let unit = if k < 3 { " m" } else { "°" };
            if e.lo[k] == e.hi[k] {
                format!("{} {}{unit}", NAMES[k], e.lo[k])
            } else {
                format!("{} {}..{}{unit}", NAMES[k], e.lo[k], e.hi[k])
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn text(scenario: &Scenario, envelope: &Envelope, report: &DesignReport) -> String {
    let g: &Geometry = &scenario.geometry;
    let q = g.quantity();
    let (decimals, unit) = if q.unit == "m" { (4, " m") } else { (2, "°") };
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "What the envelope {} needs of `{}`:",
        envelope_words(envelope),
        scenario.name
    );
    for (i, [lo, hi]) in report.actuators.iter().enumerate() {
        let _ = writeln!(
            s,
            "  {}{}  {:.*} .. {:.*}{unit}   min at {}\n               max at {}",
            q.letter,
            i + 1,
            decimals,
            lo.value,
            decimals,
            hi.value,
            pose_words(&lo.pose),
            pose_words(&hi.pose)
        );
    }
    needed_range(&mut s, g, report, decimals, unit);
    if let Some(p) = &report.unreachable {
        let _ = writeln!(
            s,
            "Some poses are out of reach (a servo cannot reach its platform joint), e.g. at {}.",
            pose_words(p)
        );
    }
    if let Some(w) = &report.worst_condition {
        let value = if w.value.is_finite() {
            format!("{:.2}", w.value)
        } else {
            "singular".to_owned()
        };
        let _ = writeln!(
            s,
            "Worst normalised condition number: {value} at {} (threshold {}).",
            pose_words(&w.pose),
            scenario.checks.condition_max
        );
    }
    let _ = writeln!(
        s,
        "Found by a bounded pattern search from the best of {} seed poses (corners, centre, face centres, Halton points); {} poses evaluated.",
        report.seeds, report.evaluations
    );
    s
}

/// The range the envelope needs of the actuators, and whether the scenario's limits hold
/// it.
fn needed_range(s: &mut String, g: &Geometry, report: &DesignReport, decimals: usize, unit: &str) {
    let q = g.quantity();
    match report.overall() {
        Some([lo, hi]) => {
            let _ = writeln!(
                s,
                "Needed {} range: {:.*} .. {:.*}{unit} ({:.*}{unit} of travel).",
                q.part,
                decimals,
                lo.value,
                decimals,
                hi.value,
                decimals,
                hi.value - lo.value
            );
            let limits = g.quantity_limits();
            let limit_words =
                |v: Option<f64>| v.map_or("none".to_owned(), |v| format!("{v}{unit}"));
            match report.fits(limits) {
                Some(true) => {
                    let _ = writeln!(
                        s,
                        "It fits the scenario's limits ({} .. {}).",
                        limit_words(limits[0]),
                        limit_words(limits[1])
                    );
                }
                Some(false) => {
                    let _ = writeln!(
                        s,
                        "It does not fit the scenario's limits ({} .. {}).",
                        limit_words(limits[0]),
                        limit_words(limits[1])
                    );
                }
                None => {
                    let _ = writeln!(s, "The scenario sets no limits to compare with.");
                }
            }
        }
        None => {
            let _ = writeln!(s, "No pose of the envelope is reachable.");
        }
    }
}
