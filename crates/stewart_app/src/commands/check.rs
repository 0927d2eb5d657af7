//! `stewart check`: the pre-flight report, as text or JSON.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::analysis::checks::LimitSummary;
use stewart_kinematics::analysis::checks::document::CheckDocument;
use stewart_kinematics::model::trajectory::Samples;
use stewart_kinematics::{
    CheckReport, Scenario, analysis::checks::FindingKind, analysis::checks::check_motion,
};

use crate::cli::{CheckArgs, ReportFormat};
use crate::i18n::Lang;
use crate::i18n::words::{self, finding};
use crate::long_work::{self, PROBE_SAMPLES};
use crate::output;
use crate::source;

/// Run the command.
pub(crate) fn run(args: &CheckArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let samples = scenario.motion.samples_judged(scenario.link.rate_hz);
    // A long motion (millions of samples) says what it will cost before it starts.
    let report = long_work::over_samples(
        &format!("check: {} samples", samples.len()),
        &samples,
        PROBE_SAMPLES,
        |samples: &Samples| {
            check_motion(
                &scenario.geometry,
                &scenario.limits,
                samples,
                &scenario.checks,
            )
        },
    );
    let text = match args.format {
        ReportFormat::Text => text_report(&scenario, &report),
        ReportFormat::Json => {
            let doc = CheckDocument::new(&scenario.name, &scenario.geometry, &report);
            serde_json::to_string_pretty(&doc)? + "\n"
        }
    };
    output::stdout(text.as_bytes())?;
    Ok(if report.is_clean() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// What a limit is called in the text report.
fn limit_name(kind: FindingKind) -> &'static str {
    match kind {
        FindingKind::StrokeMax => "leg length (max)",
        FindingKind::StrokeMin => "leg length (min)",
        FindingKind::LegSpeed => "leg speed",
        FindingKind::LegAccel => "leg acceleration",
        FindingKind::LegJerk => "leg jerk",
        FindingKind::BaseCone => "base joint cone",
        FindingKind::PlatformCone => "platform joint cone",
        FindingKind::LegCollision => "leg clearance",
        FindingKind::NearSingular => "condition number",
        FindingKind::ArchitectureSingular => "architecture",
        FindingKind::Jump => "jumps",
        FindingKind::RigidBody => "rigid body",
        FindingKind::Unreachable => "servo reach",
        FindingKind::ServoMax => "servo angle (max)",
        FindingKind::ServoMin => "servo angle (min)",
        FindingKind::ServoSpeed => "servo speed",
        FindingKind::ServoAccel => "servo acceleration",
        FindingKind::ServoJerk => "servo jerk",
        FindingKind::HornCone => "horn joint cone",
        FindingKind::RodPlatformCone => "platform joint cone",
        FindingKind::RodCollision => "rod clearance",
        FindingKind::RodHornCollision => "rod-horn clearance",
        FindingKind::ServoJump => "servo jumps",
    }
}

/// The letter numbering the things a limit is about: legs, servos, rods.
fn part_letters(kind: FindingKind) -> [char; 2] {
    match kind {
        FindingKind::Unreachable
        | FindingKind::ServoMax
        | FindingKind::ServoMin
        | FindingKind::ServoSpeed
        | FindingKind::ServoAccel
        | FindingKind::ServoJerk
        | FindingKind::ServoJump => ['S', 'S'],
        FindingKind::HornCone | FindingKind::RodPlatformCone | FindingKind::RodCollision => {
            ['R', 'R']
        }
        FindingKind::RodHornCollision => ['R', 'S'],
        _ => ['L', 'L'],
    }
}

fn summary_line(s: &LimitSummary) -> String {
    let letters = part_letters(s.kind);
    let legs: Vec<String> = s
        .legs
        .iter()
        .zip(letters.iter().chain(std::iter::repeat(&letters[1])))
        .map(|(l, c)| format!("{c}{l}"))
        .collect();
    let at = if legs.is_empty() {
        String::new()
    } else {
        format!(" ({})", legs.join(", "))
    };
    let unit = if s.unit.is_empty() {
        String::new()
    } else {
        format!(" {}", s.unit)
    };
    let verdict = if s.margin >= 0.0 { "ok" } else { "VIOLATED" };
    // A singular pose has an infinite condition number: say so in words.
    let (worst, margin) = if s.worst_value.is_finite() && s.margin.is_finite() {
        (
            format!("{:.4}{unit}", s.worst_value),
            format!("{:.4}{unit}", s.margin),
        )
    } else {
        ("singular".to_owned(), "none".to_owned())
    };
    format!(
        "  {:<20} worst {worst}{at} at t = {} s, limit {}{unit}, margin {margin}  {verdict}",
        limit_name(s.kind),
        words::time_text(s.worst_time),
        s.limit,
    )
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
    if let Some(ranges) = &report.servo_ranges_deg {
        let _ = writeln!(s, "Servo angles over the motion:");
        for (i, [lo, hi]) in ranges.iter().enumerate() {
            if lo.is_nan() {
                let _ = writeln!(s, "  S{}: never reaches its joint", i + 1);
            } else {
                let _ = writeln!(s, "  S{}: {lo:.2}° … {hi:.2}°", i + 1);
            }
        }
    } else {
        let _ = writeln!(s, "Leg lengths over the motion:");
        for (i, [lo, hi]) in report.leg_ranges.iter().enumerate() {
            let _ = writeln!(s, "  L{}: {lo:.4} m … {hi:.4} m", i + 1);
        }
    }
    let _ = writeln!(s, "Limits (worst over the motion, and the margin left):");
    for l in &report.limits {
        let _ = writeln!(s, "{}", summary_line(l));
    }
    let _ = writeln!(
        s,
        "Rigid body: largest change of a platform-joint distance {:.1e} m (tolerance {:.1e} m).",
        report.rigid_worst_deviation, scenario.checks.rigid_tolerance
    );
    let _ = writeln!(
        s,
        "Architecture: {}",
        words::architecture(Lang::En, &report.architecture)
    );
    if report.is_clean() {
        let _ = writeln!(s, "No problem found.");
    } else {
        let _ = writeln!(s, "{} problem(s) found:", report.findings.len());
        for f in &report.findings {
            let _ = writeln!(s, "  - {}", finding(Lang::En, f));
        }
    }
    s
}
