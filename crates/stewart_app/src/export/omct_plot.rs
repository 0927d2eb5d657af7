//! The OMCT's Bode figure: the six direct tests' gain (log scale) above their phase, one
//! colour a test, against frequency (log scale); with two algorithms, the washout's solid
//! and the planner's dashed. A distorted point is ringed. Vectors, for papers.

use std::fmt::Write as _;

use anyhow::Result;
use stewart_kinematics::Scenario;
use stewart_kinematics::analysis::cueing::omct::{OmctReport, OmctTest};
use stewart_kinematics::model::cueing_settings::CueingAlgorithm;

use super::plot::{escape, font_families, leg_colour_hex, nice_ticks};
use crate::i18n::Lang;

/// Page size in CSS pixels: 16 cm × 12 cm.
const WIDTH: f64 = 604.7;
const HEIGHT: f64 = 453.5;

/// The panels' left, right, and the legend's left edge.
const LEFT: f64 = 62.0;
const RIGHT: f64 = 470.0;

/// The figure of `reports` (one or two algorithms) for `scenario`, in the format `path`
/// ends in.
pub(crate) fn figure_file(
    scenario: &Scenario,
    reports: &[OmctReport],
    lang: Lang,
    path: &std::path::Path,
) -> Result<Vec<u8>> {
    super::vector::by_extension(svg(scenario, reports, lang), path)
}

/// Where a panel is drawn and what its axes span.
struct Panel {
    top: f64,
    bottom: f64,
    /// log10 of the frequency range.
    x: [f64; 2],
    /// The vertical range (log10 of the gain, or degrees).
    y: [f64; 2],
}

impl Panel {
    fn px(&self, log_w: f64) -> f64 {
        LEFT + (log_w - self.x[0]) / (self.x[1] - self.x[0]) * (RIGHT - LEFT)
    }
    fn py(&self, v: f64) -> f64 {
        self.bottom - (v - self.y[0]) / (self.y[1] - self.y[0]) * (self.bottom - self.top)
    }
}

/// The figure as an SVG document.
pub(crate) fn svg(scenario: &Scenario, reports: &[OmctReport], lang: Lang) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="160mm" height="120mm" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="{}" font-size="10">"#,
        font_families()
    );
    let _ = writeln!(
        s,
        r#"<rect x="0" y="0" width="{WIDTH}" height="{HEIGHT}" fill="white"/>"#
    );
    let title = lang.fmt("omct.title", &[("name", &scenario.name)]);
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="18" text-anchor="middle" font-size="12">{}</text>"#,
        WIDTH / 2.0,
        escape(&title)
    );
    let frequencies = reports.first().map_or(&[][..], |r| &r.frequencies[..]);
    let (lo, hi) = frequencies
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), w| {
            (a.min(*w), b.max(*w))
        });
    // A quarter of a decade's margin each side.
    let x = [lo.log10() - 0.1, hi.log10() + 0.1];
    // The gains of the direct tests: from the largest down four decades at most.
    let direct = |r: &OmctReport| {
        r.tests
            .iter()
            .filter(|t| t.test.direct())
            .cloned()
            .collect::<Vec<_>>()
    };
    let largest = reports
        .iter()
        .flat_map(direct)
        .flat_map(|t| t.gain)
        .filter(|g| g.is_finite())
        .fold(0.0f64, f64::max)
        .max(1e-6);
    let smallest = reports
        .iter()
        .flat_map(direct)
        .flat_map(|t| t.gain)
        .filter(|g| *g > 0.0 && g.is_finite())
        .fold(largest, f64::min)
        .max(largest * 1e-4);
    let gain = Panel {
        top: 36.0,
        bottom: 206.0,
        x,
        y: [
            smallest.log10().floor(),
            largest.log10().ceil().max(smallest.log10().floor() + 1.0),
        ],
    };
    let phases: Vec<f64> = reports
        .iter()
        .flat_map(direct)
        .flat_map(|t| t.continuous_phase_deg())
        .filter(|p| p.is_finite())
        .collect();
    let (plo, phi) = phases
        .iter()
        .fold((0.0f64, 0.0f64), |(a, b), p| (a.min(*p), b.max(*p)));
    let phase = Panel {
        top: 236.0,
        bottom: 406.0,
        x,
        y: [
            (plo / 45.0).floor() * 45.0,
            (phi / 45.0).ceil() * 45.0 + 1e-9,
        ],
    };
    axes(&mut s, &gain, true, lang);
    axes(&mut s, &phase, false, lang);
    for (a, r) in reports.iter().enumerate() {
        let dash = if a == 0 {
            ""
        } else {
            r#" stroke-dasharray="5 3""#
        };
        for (k, t) in r.tests.iter().filter(|t| t.test.direct()).enumerate() {
            let colour = leg_colour_hex(k);
            // A symmetric tuning gives surge and sway, and roll, pitch and yaw, the same
            // curve: drawn wide to narrow, each shows as a rim round the next.
            let width = [3.4, 1.4, 1.4, 4.0, 2.4, 1.0][k % 6];
            let floor = 10f64.powf(gain.y[0]);
            // No response (gain 0, no phase): no point.
            let points = |values: &[f64], panel: &Panel, log: bool| -> Vec<(f64, f64, bool)> {
                r.frequencies
                    .iter()
                    .zip(values)
                    .zip(&t.distorted)
                    .filter(|((_, v), _)| v.is_finite() && (!log || **v > 0.0))
                    .map(|((w, v), d)| {
                        let v = if log { v.max(floor).log10() } else { *v };
                        (panel.px(w.log10()), panel.py(v), *d)
                    })
                    .collect()
            };
            let continuous = t.continuous_phase_deg();
            for (values, panel, log) in [(&t.gain, &gain, true), (&continuous, &phase, false)] {
                let pts = points(values, panel, log);
                let d: Vec<String> = pts
                    .iter()
                    .map(|(x, y, _)| format!("{x:.2},{y:.2}"))
                    .collect();
                let _ = writeln!(
                    s,
                    r#"<polyline class="{}" points="{}" fill="none" stroke="{colour}" stroke-width="{width}"{dash}/>"#,
                    t.test.name(),
                    d.join(" ")
                );
                for (x, y, distorted) in &pts {
                    if *distorted {
                        let _ = writeln!(
                            s,
                            r#"<circle class="distorted" cx="{x:.2}" cy="{y:.2}" r="3.2" fill="none" stroke="{colour}" stroke-width="1"/>"#
                        );
                    } else {
                        let _ = writeln!(
                            s,
                            r#"<circle cx="{x:.2}" cy="{y:.2}" r="1.6" fill="{colour}"/>"#
                        );
                    }
                }
            }
        }
    }
    legend(&mut s, reports, lang);
    s.push_str("</svg>\n");
    s
}

/// A panel's frame, ticks and labels.
fn axes(s: &mut String, p: &Panel, log: bool, lang: Lang) {
    let _ = writeln!(
        s,
        r#"<rect x="{LEFT}" y="{:.2}" width="{:.2}" height="{:.2}" fill="none" stroke="black" stroke-width="0.7"/>"#,
        p.top,
        RIGHT - LEFT,
        p.bottom - p.top
    );
    // Decades along the frequency, with the 2 and 5 between.
    let mut decade = p.x[0].floor();
    while decade <= p.x[1] + 1e-9 {
        for m in [1.0f64, 2.0, 5.0] {
            let v = decade + m.log10();
            if v > p.x[1] + 1e-9 || v < p.x[0] - 1e-9 {
                continue;
            }
            let x = p.px(v);
            let grey = if m == 1.0 { "#BBBBBB" } else { "#E4E4E4" };
            let _ = writeln!(
                s,
                r#"<line x1="{x:.2}" y1="{:.2}" x2="{x:.2}" y2="{:.2}" stroke="{grey}" stroke-width="0.5"/>"#,
                p.top, p.bottom
            );
            if m == 1.0 && !log {
                let _ = writeln!(
                    s,
                    r#"<text x="{x:.2}" y="{:.2}" text-anchor="middle">{}</text>"#,
                    p.bottom + 13.0,
                    tick(10f64.powf(v))
                );
            }
        }
        decade += 1.0;
    }
    let ticks: Vec<f64> = if log {
        (p.y[0] as i32..=p.y[1] as i32).map(f64::from).collect()
    } else {
        nice_ticks(p.y[0], p.y[1], 6)
    };
    for v in ticks {
        let y = p.py(v);
        let label = if log { tick(10f64.powf(v)) } else { tick(v) };
        let _ = writeln!(
            s,
            r##"<line x1="{LEFT}" y1="{y:.2}" x2="{RIGHT}" y2="{y:.2}" stroke="#E4E4E4" stroke-width="0.5"/><text x="{:.2}" y="{:.2}" text-anchor="end">{label}</text>"##,
            LEFT - 4.0,
            y + 3.5
        );
    }
    let (label, middle) = if log {
        (lang.tr("omct.gain"), 0.5 * (p.top + p.bottom))
    } else {
        (lang.tr("omct.phase"), 0.5 * (p.top + p.bottom))
    };
    let _ = writeln!(
        s,
        r#"<text x="18" y="{middle:.2}" text-anchor="middle" transform="rotate(-90 18 {middle:.2})">{}</text>"#,
        escape(label)
    );
    if !log {
        let _ = writeln!(
            s,
            r#"<text x="{:.2}" y="{:.2}" text-anchor="middle">{}</text>"#,
            0.5 * (LEFT + RIGHT),
            p.bottom + 28.0,
            escape(lang.tr("omct.frequency"))
        );
    }
}

/// The key: a colour a test, a line style an algorithm, the ring of a distorted point.
fn legend(s: &mut String, reports: &[OmctReport], lang: Lang) {
    let x = RIGHT + 16.0;
    let mut y = 46.0;
    if let Some(r) = reports.first() {
        for (k, t) in r.tests.iter().filter(|t| t.test.direct()).enumerate() {
            let _ = writeln!(
                s,
                r#"<line x1="{x:.2}" y1="{y:.2}" x2="{:.2}" y2="{y:.2}" stroke="{}" stroke-width="2"/><text x="{:.2}" y="{:.2}" font-size="9">{}</text>"#,
                x + 16.0,
                leg_colour_hex(k),
                x + 20.0,
                y + 3.0,
                escape(test_words(t.test, lang))
            );
            y += 15.0;
        }
    }
    y += 8.0;
    for (a, r) in reports.iter().enumerate() {
        let dash = if a == 0 {
            ""
        } else {
            r#" stroke-dasharray="5 3""#
        };
        let word = match r.algorithm {
            CueingAlgorithm::Washout => lang.tr("omct.washout"),
            CueingAlgorithm::Mpc => lang.tr("omct.mpc"),
        };
        let _ = writeln!(
            s,
            r#"<line x1="{x:.2}" y1="{y:.2}" x2="{:.2}" y2="{y:.2}" stroke="black" stroke-width="1.4"{dash}/><text x="{:.2}" y="{:.2}" font-size="9">{}</text>"#,
            x + 16.0,
            x + 20.0,
            y + 3.0,
            escape(word)
        );
        y += 15.0;
    }
    let _ = writeln!(
        s,
        r#"<circle cx="{:.2}" cy="{y:.2}" r="3.2" fill="none" stroke="black" stroke-width="1"/><text x="{:.2}" y="{:.2}" font-size="9">{}</text>"#,
        x + 8.0,
        x + 20.0,
        y + 3.0,
        escape(lang.tr("omct.distorted"))
    );
    if let Some(r) = reports.first().filter(|r| r.latency_s > 0.0) {
        y += 15.0;
        let _ = writeln!(
            s,
            r#"<text x="{x:.2}" y="{:.2}" font-size="9">{}</text>"#,
            y + 3.0,
            escape(&lang.fmt(
                "omct.latency",
                &[("ms", &format!("{}", r.latency_s * 1000.0))]
            ))
        );
    }
}

/// A direct test's name in `lang`.
fn test_words(test: OmctTest, lang: Lang) -> &'static str {
    lang.tr(match test {
        OmctTest::Surge => "omct.surge",
        OmctTest::Sway => "omct.sway",
        OmctTest::Heave => "omct.heave",
        OmctTest::Roll => "omct.roll",
        OmctTest::Pitch => "omct.pitch",
        _ => "omct.yaw",
    })
}

/// A tick label: as few digits as the value needs, powers of ten below a thousandth.
fn tick(v: f64) -> String {
    if v != 0.0 && v.abs() < 1e-3 {
        return format!("{v:.0e}");
    }
    let text = format!("{v:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}
