//! `stewart cue --omct`: the Objective Motion Cueing Test of the scenario's cueing (or, with
//! `--compare`, of both algorithms) on its rig — gain and phase of the ten tests at the
//! test frequencies, as a table, as JSON, and as a Bode figure.

use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};

use anyhow::{Result, anyhow, bail};
use serde::Serialize;
use stewart_kinematics::Scenario;
use stewart_kinematics::analysis::cueing::omct::{
    DISTORTION_SHARE, OmctError, OmctOptions, OmctReport, frequencies, omct,
};
use stewart_kinematics::model::cueing_settings::{CueingAlgorithm, CueingSettings};

use crate::cli::{CueArgs, ReportFormat};
use crate::{output, source};

/// Run `cue --omct`.
pub(crate) fn run(args: &CueArgs, scenario: &Scenario) -> Result<ExitCode> {
    if !source::gives_table(&args.scenario, "cueing") {
        bail!(
            "{}: no [cueing] table: the test reports a cueing tuning, and this scenario states none (add a [cueing] table, or --set cueing.algorithm=washout to test the defaults)",
            source::describe(&args.scenario)
        );
    }
    let inputs = source::inputs(&args.scenario, scenario);
    let out = output::destination(args.out.as_deref(), &inputs)?;
    if let Some(out) = &out {
        out.check_writable()?;
    }
    let plot = match &args.plot {
        Some(path) => {
            let d = output::Destination::new(path, &inputs)?;
            crate::export::vector::check_extension(path)?;
            d.check_writable()?;
            if let Some(out) = &out {
                out.refuse_same(&d, "--out (the report) and --plot (the figure)")?;
            }
            Some(d)
        }
        None => None,
    };
    let options = OmctOptions {
        frequencies: args
            .frequencies
            .clone()
            .unwrap_or_else(|| frequencies().to_vec()),
        amplitude_scale: args.amplitude_scale.unwrap_or(1.0),
        latency_s: args.latency_ms.unwrap_or(0.0) / 1000.0,
    };
    let algorithms = if args.compare {
        vec![CueingAlgorithm::Washout, CueingAlgorithm::Mpc]
    } else {
        vec![scenario.cueing.algorithm]
    };
    let mut reports = Vec::new();
    for algorithm in algorithms {
        let settings = CueingSettings {
            algorithm,
            ..scenario.cueing.clone()
        };
        reports.push(run_one(scenario, &settings, &options).map_err(|e| match e {
            OmctError::Cueing(e) => anyhow!("{}: {e}", source::describe(&args.scenario)),
            other => anyhow!("{other}"),
        })?);
    }
    let text = match args.format {
        ReportFormat::Text => table(scenario, &reports),
        ReportFormat::Json => json(scenario, &reports)?,
    };
    if let Some(plot) = &plot {
        let lang = crate::i18n::for_command(args.lang, "cue");
        let bytes = crate::export::omct_plot::figure_file(scenario, &reports, lang, plot.shown())?;
        plot.write_bytes(&bytes)?;
    }
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    if let Some(plot) = &plot {
        eprintln!("cue: wrote the Bode figure to {}", plot.shown().display());
    }
    Ok(ExitCode::SUCCESS)
}

/// One algorithm's test, with a spinner on a terminal and Ctrl-C ending it.
fn run_one(
    scenario: &Scenario,
    settings: &CueingSettings,
    options: &OmctOptions,
) -> Result<OmctReport, OmctError> {
    crate::interrupt::flag();
    let asked = AtomicUsize::new(0);
    let stop = || {
        asked.fetch_add(1, Ordering::Relaxed);
        crate::interrupt::requested()
    };
    let word = algorithm_word(settings.algorithm);
    crate::long_work::with_spinner(
        || {
            format!(
                "OMCT of the {word}: {} periods run (Ctrl-C stops it)",
                asked.load(Ordering::Relaxed)
            )
        },
        || {
            omct(
                &scenario.geometry,
                &scenario.limits,
                settings,
                options,
                &stop,
            )
        },
    )
}

/// `washout` or `mpc`, as `[cueing]` spells them.
fn algorithm_word(a: CueingAlgorithm) -> &'static str {
    match a {
        CueingAlgorithm::Washout => "washout",
        CueingAlgorithm::Mpc => "mpc",
    }
}

/// The report as tables: per algorithm, per test, a line per frequency.
fn table(scenario: &Scenario, reports: &[OmctReport]) -> String {
    let mut s = String::new();
    for r in reports {
        s.push_str(&format!(
            "OMCT of `{}`, {} cueing{}: gain and phase (negative: a lag) of what is felt against the vehicle's motion\n",
            scenario.name,
            algorithm_word(r.algorithm),
            if r.latency_s > 0.0 {
                format!(", with a transport delay of {} ms", r.latency_s * 1000.0)
            } else {
                String::new()
            }
        ));
        for t in &r.tests {
            s.push_str(&format!(
                "\n  {}: {} over the vehicle's {}, input amplitude {} {}{}\n  {:>10}  {:>11}  {:>10}  {}\n",
                t.test.name(),
                t.test.output().felt_words(),
                t.test.input().words(),
                t.amplitude,
                t.test.input().unit(),
                if t.test.direct() {
                    String::new()
                } else {
                    format!(", gain in {}", t.test.unit())
                },
                "ω (rad/s)",
                "gain",
                "phase (°)",
                "harmonics"
            ));
            for (k, w) in r.frequencies.iter().enumerate() {
                let phase = if t.phase_deg[k].is_finite() {
                    // Rounded to nothing, a phase has no sign.
                    let p = format!("{:.2}", t.phase_deg[k]);
                    if p == "-0.00" { "0.00".to_owned() } else { p }
                } else {
                    "—".to_owned()
                };
                s.push_str(&format!(
                    "  {:>10.4}  {:>11.5}  {:>10}  {:>5.1} %{}\n",
                    w,
                    t.gain[k],
                    phase,
                    100.0 * t.distortion[k],
                    if t.distorted[k] {
                        if t.limited[k] {
                            "  distorted: a limit acted"
                        } else {
                            "  distorted"
                        }
                    } else {
                        ""
                    }
                ));
            }
        }
        let distorted: Vec<String> = r
            .tests
            .iter()
            .flat_map(|t| {
                t.distorted
                    .iter()
                    .zip(&r.frequencies)
                    .filter(|(d, _)| **d)
                    .map(move |(_, w)| format!("{} at {w:.3} rad/s", t.test.name()))
            })
            .collect();
        if distorted.is_empty() {
            s.push_str(&format!(
                "\n  No test distorted (harmonics under {:.0} % of the fundamental, no limit acting).\n\n",
                100.0 * DISTORTION_SHARE
            ));
        } else {
            s.push_str(&format!(
                "\n  Distorted (harmonics over {:.0} % of the fundamental, or a limit acting): {}. Their gain and phase describe the fundamental only; try a smaller --amplitude-scale.\n\n",
                100.0 * DISTORTION_SHARE,
                distorted.join(", ")
            ));
        }
    }
    s
}

#[derive(Serialize)]
struct TestJson<'a> {
    name: &'a str,
    input: String,
    output: String,
    unit: String,
    amplitude: f64,
    amplitude_unit: &'a str,
    gain: &'a [f64],
    /// `null` where there is no response (gain 0).
    phase_deg: Vec<Option<f64>>,
    harmonic_distortion: &'a [f64],
    distorted: &'a [bool],
}

#[derive(Serialize)]
struct ReportJson<'a> {
    scenario: &'a str,
    algorithm: &'a str,
    latency_ms: f64,
    frequencies_rad_s: &'a [f64],
    distortion_threshold: f64,
    tests: Vec<TestJson<'a>>,
}

/// One JSON object (a list of two with `--compare`).
fn json(scenario: &Scenario, reports: &[OmctReport]) -> Result<String> {
    let objects: Vec<ReportJson> = reports
        .iter()
        .map(|r| ReportJson {
            scenario: &scenario.name,
            algorithm: algorithm_word(r.algorithm),
            latency_ms: r.latency_s * 1000.0,
            frequencies_rad_s: &r.frequencies,
            distortion_threshold: DISTORTION_SHARE,
            tests: r
                .tests
                .iter()
                .map(|t| TestJson {
                    name: t.test.name(),
                    input: format!("vehicle {}", t.test.input().words()),
                    output: t.test.output().felt_words(),
                    unit: t.test.unit(),
                    amplitude: t.amplitude,
                    amplitude_unit: t.test.input().unit(),
                    gain: &t.gain,
                    phase_deg: t
                        .phase_deg
                        .iter()
                        .map(|p| p.is_finite().then_some(*p))
                        .collect(),
                    harmonic_distortion: &t.distortion,
                    distorted: &t.distorted,
                })
                .collect(),
        })
        .collect();
    let text = match objects.as_slice() {
        [one] => serde_json::to_string_pretty(one)?,
        all => serde_json::to_string_pretty(all)?,
    };
    Ok(text + "\n")
}
