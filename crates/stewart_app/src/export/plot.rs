//! The actuator plot as SVG — leg lengths L1…L6 (m) or servo angles θ1…θ6 (°): axes
//! with units, ticks, a legend, the stroke or servo range as dashed lines, white background, sized for a paper (16 cm × 9 cm). Text is SVG text and
//! every curve a `<polyline>`, so the vector outputs are real vectors.

use std::fmt::Write as _;

use stewart_kinematics::analysis::dynamics;
use stewart_kinematics::model::actuator::Quantity;

use crate::i18n::Lang;
use crate::i18n::words::{effort_name, quantity_name};

/// Actuator `k`'s colour as `#RRGGBB`: the renderer's series colours (Okabe–Ito), so a
/// curve has the colour of its leg in the 3D view.
pub(crate) fn leg_colour_hex(k: usize) -> String {
    let [r, g, b] = stewart_render::theme::SERIES_RGB[k % 6];
    format!("#{r:02X}{g:02X}{b:02X}")
}

/// What to plot.
pub(crate) struct PlotData<'a> {
    /// Title above the axes.
    pub(crate) title: &'a str,
    /// Sample times, seconds.
    pub(crate) times: &'a [f64],
    /// Six values per sample in the quantity's unit (NaN: no value, a gap in the curve).
    pub(crate) values: &'a [[f64; 6]],
    /// What the values are: leg lengths or servo angles.
    pub(crate) quantity: Quantity,
    /// The quantity's limits (stroke or servo range), each end optional.
    pub(crate) limits: [Option<f64>; 2],
    /// A vertical marker at this time (the current frame of a video), seconds.
    pub(crate) marker: Option<f64>,
    /// The language of the axis labels and the limits' names.
    pub(crate) lang: Lang,
    /// The values are the actuators' efforts (forces in N or torques in N·m), not the
    /// quantity itself.
    pub(crate) efforts: bool,
}

impl PlotData<'_> {
    /// What the curves show: name, symbol and unit (`leg length`, `L`, `m`; `leg
    /// force`, `F`, `N`).
    fn series(&self) -> (&'static str, &'static str, &'static str) {
        let q = &self.quantity;
        if self.efforts {
            (effort_name(self.lang, q), q.effort.0, q.effort.1)
        } else {
            (quantity_name(self.lang, q), q.symbol, q.unit)
        }
    }
}

/// The plot of `scenario`'s trajectory in `lang`: its sample times and the SVG.
pub(crate) fn scenario_svg(
    scenario: &stewart_kinematics::Scenario,
    lang: Lang,
) -> (Vec<f64>, String) {
    scenario_svg_on(scenario, lang, &PAPER)
}

/// [`scenario_svg`] on `page`.
pub(crate) fn scenario_svg_on(
    scenario: &stewart_kinematics::Scenario,
    lang: Lang,
    page: &Page,
) -> (Vec<f64>, String) {
    let samples = scenario.motion.sample();
    let g = &scenario.geometry;
    let values = g.actuator_values(&samples.poses);
    let quantity = g.quantity();
    let text = svg_on(
        &PlotData {
            title: &lang.fmt(
                if quantity.unit == "m" {
                    "plot.title_legs"
                } else {
                    "plot.title_servos"
                },
                &[("name", &scenario.name)],
            ),
            times: &samples.times,
            values: &values,
            quantity,
            limits: g.quantity_limits(),
            marker: None,
            lang,
            efforts: false,
        },
        page,
    );
    (samples.times, text)
}

/// The fonts SVG text asks for: a Latin sans-serif first, then the Chinese families (the
/// one this system has first) for characters the Latin font lacks. A PDF embeds the
/// glyphs it uses; an SVG names the families for the reader's system.
pub(crate) fn font_families() -> String {
    let mut families: Vec<&str> = vec!["DejaVu Sans", "Arial", "Helvetica"];
    if let Some(found) = crate::i18n::fonts::cjk() {
        families.push(&found.family);
    }
    for name in stewart_render::text::CJK {
        if !families.contains(&name) {
            families.push(name);
        }
    }
    let mut list: Vec<String> = families.iter().map(|f| format!("'{f}'")).collect();
    list.push("sans-serif".to_owned());
    list.join(", ")
}

/// `text` with its first letter in upper case.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
}

/// Page size in CSS pixels (96 per inch): 16 cm × 9 cm.
pub(crate) const WIDTH: f64 = 604.7;
/// See [`WIDTH`].
pub(crate) const HEIGHT: f64 = 340.2;

/// Plot area margins: left, right, top, bottom.
const MARGIN: [f64; 4] = [62.0, 78.0, 30.0, 44.0];

/// The colours of a page: background, text and ticks, grid, the axes' frame, the limits'
/// lines and words, the time marker (SVG colours).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Ink {
    /// The page.
    pub(crate) background: &'static str,
    /// Text and tick labels (`None`: SVG's own black, the paper's).
    pub(crate) text: Option<&'static str>,
    /// Tick labels.
    pub(crate) ticks: &'static str,
    /// Grid lines.
    pub(crate) grid: &'static str,
    /// The axes' frame.
    pub(crate) frame: &'static str,
    /// The limits' dashed lines and words.
    pub(crate) limit: &'static str,
    /// The time marker.
    pub(crate) marker: &'static str,
}

/// Black on white, for papers and slides.
pub(crate) const PAPER_INK: Ink = Ink {
    background: "white",
    text: None,
    ticks: "black",
    grid: "#e0e0e0",
    frame: "black",
    limit: "#444",
    marker: "black",
};

/// Light on the dark 3D view's background, for frames of the dark theme.
pub(crate) const DARK_INK: Ink = Ink {
    background: "#1C1F24",
    text: Some("#DDDDDD"),
    ticks: "#DDDDDD",
    grid: "#3A3F47",
    frame: "#9A9FA8",
    limit: "#B0B0B0",
    marker: "white",
};

/// A page the plot is laid out on: its size in CSS pixels, the text's scale (margins and
/// text offsets scale with it) and its colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Page {
    /// Width, CSS pixels.
    pub(crate) width: f64,
    /// Height, CSS pixels.
    pub(crate) height: f64,
    /// Text size against the paper's (11 px body).
    pub(crate) text: f64,
    /// Colours.
    pub(crate) ink: Ink,
}

/// The paper page: 16 cm × 9 cm, black on white.
pub(crate) const PAPER: Page = Page {
    width: WIDTH,
    height: HEIGHT,
    text: 1.0,
    ink: PAPER_INK,
};

impl Page {
    /// A page of the paper's width with `aspect` (width / height), text `text` times the
    /// paper's, in `ink`: the plot half of a composite frame fills its half.
    pub(crate) fn fitting(aspect: f64, text: f64, ink: Ink) -> Self {
        Self {
            width: WIDTH,
            height: WIDTH / aspect.clamp(0.2, 5.0),
            text,
            ink,
        }
    }

    /// The plot area's margins (left, right, top, bottom) in CSS pixels of the page.
    pub(crate) fn margins(&self) -> (f64, f64, f64, f64) {
        let k = self.text;
        (MARGIN[0] * k, MARGIN[1] * k, MARGIN[2] * k, MARGIN[3] * k)
    }
}

/// About `count` "nice" ticks (1, 2, 5 × 10ⁿ apart) covering `[lo, hi]`.
pub(crate) fn nice_ticks(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    let span = (hi - lo).abs().max(1e-12);
    let step = stewart_render::ticks::nice_step(span / count.max(1) as f64);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

fn label(v: f64, step: f64) -> String {
    let decimals = if step >= 1.0 {
        0
    } else {
        (-step.log10()).ceil() as usize
    };
    format!("{v:.decimals$}")
}

/// Where the axes sit in the document and what they span.
struct Axes {
    /// Time span shown, seconds.
    t: (f64, f64),
    /// Value span shown (padded).
    v: (f64, f64),
    /// Left and right edge of the axes box, document units.
    x: (f64, f64),
    /// Bottom and top edge.
    y: (f64, f64),
}

impl Axes {
    /// The axes for `data` on `page`: its times, and its values and limits with 5 % to
    /// spare.
    fn of(data: &PlotData, page: &Page) -> Self {
        let t0 = data.times.first().copied().unwrap_or(0.0);
        let t1 = data.times.last().copied().unwrap_or(1.0).max(t0 + 1e-9);
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for l in data.values.iter().flatten().filter(|v| !v.is_nan()) {
            lo = lo.min(*l);
            hi = hi.max(*l);
        }
        for limit in data.limits.into_iter().flatten() {
            lo = lo.min(limit);
            hi = hi.max(limit);
        }
        if !lo.is_finite() {
            (lo, hi) = (0.0, 1.0);
        }
        let pad = 0.05 * (hi - lo).max(1e-6);
        let (ml, mr, mt, mb) = page.margins();
        Self {
            t: (t0, t1),
            v: (lo - pad, hi + pad),
            x: (ml, page.width - mr),
            y: (page.height - mb, mt),
        }
    }

    /// A time's document x.
    fn sx(&self, t: f64) -> f64 {
        self.x.0 + (t - self.t.0) / (self.t.1 - self.t.0) * (self.x.1 - self.x.0)
    }

    /// A value's document y.
    fn sy(&self, l: f64) -> f64 {
        self.y.0 + (l - self.v.0) / (self.v.1 - self.v.0) * (self.y.1 - self.y.0)
    }
}

/// The plot as an SVG document on the paper page.
pub(crate) fn svg(data: &PlotData) -> String {
    svg_on(data, &PAPER)
}

/// The plot as an SVG document on `page`.
pub(crate) fn svg_on(data: &PlotData, page: &Page) -> String {
    let axes = Axes::of(data, page);
    let (x0, x1) = axes.x;
    let k = page.text;
    let ink = &page.ink;
    let mut s = String::new();
    // Writing to a String cannot fail.
    let fill = ink
        .text
        .map(|c| format!(r#" fill="{c}""#))
        .unwrap_or_default();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{:.0}mm" height="{:.0}mm" viewBox="0 0 {} {}" font-family="{}" font-size="{}"{fill}>"#,
        page.width / 96.0 * 25.4,
        page.height / 96.0 * 25.4,
        page.width,
        page.height,
        font_families(),
        11.0 * k
    );
    let _ = writeln!(
        s,
        r#"<rect x="0" y="0" width="{}" height="{}" fill="{}"/>"#,
        page.width, page.height, ink.background
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="{}" text-anchor="middle" font-size="{}">{}</text>"#,
        0.5 * (x0 + x1),
        18.0 * k,
        13.0 * k,
        escape(data.title)
    );
    grid_and_ticks(&mut s, &axes, page);
    axis_titles(&mut s, &axes, data, page);
    limit_lines(&mut s, &axes, data, page);
    curves(&mut s, &axes, data);
    if let Some(t) = data.marker {
        let x = axes.sx(t.clamp(axes.t.0, axes.t.1));
        let (y0, y1) = axes.y;
        let _ = writeln!(
            s,
            r#"<line class="marker" x1="{x:.2}" y1="{y0:.2}" x2="{x:.2}" y2="{y1:.2}" stroke="{}" stroke-width="1.2"/>"#,
            ink.marker
        );
    }
    legend(&mut s, &axes, data.series().1, k);
    s.push_str("</svg>\n");
    s
}

/// The grid lines and the tick labels of both axes.
fn grid_and_ticks(s: &mut String, axes: &Axes, page: &Page) {
    let k = page.text;
    let ((x0, x1), (y0, y1)) = (axes.x, axes.y);
    let x_ticks = nice_ticks(axes.t.0, axes.t.1, 8);
    let y_ticks = nice_ticks(axes.v.0, axes.v.1, 6);
    let step = |ticks: &[f64], otherwise| {
        ticks
            .windows(2)
            .map(|w| w[1] - w[0])
            .next()
            .unwrap_or(otherwise)
    };
    let (x_step, y_step) = (step(&x_ticks, 1.0), step(&y_ticks, 0.1));
    let _ = writeln!(
        s,
        r#"<g class="grid" stroke="{}" stroke-width="0.6">"#,
        page.ink.grid
    );
    for &t in &x_ticks {
        let _ = writeln!(
            s,
            r#"<line x1="{0:.2}" y1="{y0:.2}" x2="{0:.2}" y2="{y1:.2}"/>"#,
            axes.sx(t)
        );
    }
    for &l in &y_ticks {
        let _ = writeln!(
            s,
            r#"<line x1="{x0:.2}" y1="{0:.2}" x2="{x1:.2}" y2="{0:.2}"/>"#,
            axes.sy(l)
        );
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(s, r#"<g class="ticks" fill="{}">"#, page.ink.ticks);
    for &t in &x_ticks {
        let _ = writeln!(
            s,
            r#"<text x="{:.2}" y="{:.2}" text-anchor="middle">{}</text>"#,
            axes.sx(t),
            y0 + 15.0 * k,
            label(t, x_step)
        );
    }
    for &l in &y_ticks {
        let _ = writeln!(
            s,
            r#"<text x="{:.2}" y="{:.2}" text-anchor="end">{}</text>"#,
            x0 - 6.0 * k,
            axes.sy(l) + 4.0 * k,
            label(l, y_step)
        );
    }
    let _ = writeln!(s, "</g>");
}

/// The axes' box and titles.
fn axis_titles(s: &mut String, axes: &Axes, data: &PlotData, page: &Page) {
    let ((x0, x1), (y0, y1)) = (axes.x, axes.y);
    let k = page.text;
    let (name, symbol, unit) = data.series();
    let _ = writeln!(
        s,
        r#"<rect x="{x0:.2}" y="{y1:.2}" width="{:.2}" height="{:.2}" fill="none" stroke="{}" stroke-width="0.8"/>"#,
        x1 - x0,
        y0 - y1,
        page.ink.frame
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
        0.5 * (x0 + x1),
        page.height - 8.0 * k,
        data.lang.tr("plot.time_axis")
    );
    let _ = writeln!(
        s,
        r#"<text x="{4}" y="{0:.1}" text-anchor="middle" transform="rotate(-90 {4} {0:.1})">{1} {2} ({3})</text>"#,
        0.5 * (y0 + y1),
        capitalised(name),
        symbol,
        unit,
        16.0 * k
    );
}

/// The stroke's or servo range's ends, dashed and labelled.
fn limit_lines(s: &mut String, axes: &Axes, data: &PlotData, page: &Page) {
    let (x0, x1) = axes.x;
    let (k, ink) = (page.text, page.ink.limit);
    let q = data.quantity;
    let unit_suffix = if q.unit == "°" {
        "°".to_owned()
    } else {
        format!(" {}", q.unit)
    };
    let [min, max] = data.limits;
    for (name, limit) in [("min", min), ("max", max)] {
        if let Some(l) = limit {
            let y = axes.sy(l);
            let _ = writeln!(
                s,
                r#"<line class="stroke-{name}" x1="{x0:.2}" y1="{y:.2}" x2="{x1:.2}" y2="{y:.2}" stroke="{ink}" stroke-width="1" stroke-dasharray="5 3"/>"#
            );
            let _ = writeln!(
                s,
                r#"<text x="{:.2}" y="{:.2}" fill="{ink}" font-size="{}" text-anchor="end">{}{} = {l}{}</text>"#,
                x1 - 4.0 * k,
                y - 3.0 * k,
                9.0 * k,
                q.symbol,
                data.lang.tr(&format!("plot.{name}")),
                unit_suffix
            );
        }
    }
}

/// One polyline per actuator and run of values (a servo out of reach breaks its curve).
fn curves(s: &mut String, axes: &Axes, data: &PlotData) {
    let q = data.quantity;
    for leg in 0..6 {
        let mut points = String::with_capacity(data.values.len() * 16);
        let flush = |points: &mut String, s: &mut String| {
            if !points.is_empty() {
                let _ = writeln!(
                    s,
                    r#"<polyline class="leg {}{}" fill="none" stroke="{}" stroke-width="1.4" stroke-linejoin="round" points="{}"/>"#,
                    q.letter,
                    leg + 1,
                    leg_colour_hex(leg),
                    points.trim_end()
                );
                points.clear();
            }
        };
        for (t, l) in data.times.iter().zip(data.values) {
            if l[leg].is_nan() {
                flush(&mut points, s);
            } else {
                let _ = write!(points, "{:.2},{:.2} ", axes.sx(*t), axes.sy(l[leg]));
            }
        }
        flush(&mut points, s);
    }
}

/// The legend, right of the axes.
fn legend(s: &mut String, axes: &Axes, symbol: &str, k: f64) {
    let x1 = axes.x.1;
    let _ = writeln!(s, r#"<g class="legend">"#);
    for (leg, colour) in (0..6).map(|k| (k, leg_colour_hex(k))) {
        let y = axes.y.1 + 14.0 * k + 16.0 * k * leg as f64;
        let _ = writeln!(
            s,
            r#"<line x1="{:.2}" y1="{y:.2}" x2="{:.2}" y2="{y:.2}" stroke="{}" stroke-width="2"/><text x="{:.2}" y="{:.2}">{}{}</text>"#,
            x1 + 8.0 * k,
            x1 + 26.0 * k,
            colour,
            x1 + 31.0 * k,
            y + 4.0 * k,
            symbol,
            leg + 1
        );
    }
    let _ = writeln!(s, "</g>");
}

pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The plot of the actuator efforts (leg forces or servo torques, with the legs' parts
/// and friction of `[dynamics]`) along `scenario`'s trajectory for its `[payload]`.
pub(crate) fn efforts_svg(
    scenario: &stewart_kinematics::Scenario,
    lang: Lang,
) -> anyhow::Result<String> {
    let payload = scenario.payload.ok_or_else(|| {
        anyhow::anyhow!(
            "scenario `{}` has no [payload] table: the forces need the moving mass",
            scenario.name
        )
    })?;
    let samples = scenario.motion.sample();
    let g = &scenario.geometry;
    let series = dynamics::efforts_along(g, &samples, &payload, &scenario.dynamics)?;
    let quantity = g.quantity();
    Ok(svg(&PlotData {
        title: &lang.fmt_kind(
            "plot.title_efforts",
            quantity.actuator,
            &[("name", &scenario.name)],
        ),
        times: &series.times,
        values: &series.dynamics,
        quantity,
        limits: [None, None],
        marker: None,
        lang,
        efforts: true,
    }))
}

/// The scenario's leg-length plot (with `efforts`, its actuator forces) in the format
/// `path` ends in: `.svg` (text stays text), `.pdf` (vector) or `.png` (300 dpi).
pub(crate) fn plot_file(
    scenario: &stewart_kinematics::Scenario,
    path: &std::path::Path,
    lang: Lang,
    efforts: bool,
) -> anyhow::Result<Vec<u8>> {
    let text = if efforts {
        efforts_svg(scenario, lang)?
    } else {
        scenario_svg(scenario, lang).1
    };
    super::vector::by_extension(text, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_nice_and_cover_the_range() {
        assert_eq!(
            nice_ticks(0.0, 10.0, 8),
            vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]
        );
        let t = nice_ticks(0.82, 1.21, 6);
        assert!(t.iter().all(|v| (0.82..=1.21).contains(v)));
        assert!((t[1] - t[0] - 0.1).abs() < 1e-12, "{t:?}"); // 0.39 / 6 = 0.065 rounds up to 0.1
    }

    #[test]
    fn the_svg_holds_six_curves_limits_and_labels() {
        let times: Vec<f64> = (0..11).map(|k| k as f64).collect();
        let lengths: Vec<[f64; 6]> = times.iter().map(|t| [1.0 + 0.01 * t; 6]).collect();
        let text = svg(&PlotData {
            title: "a < b",
            times: &times,
            values: &lengths,
            quantity: stewart_kinematics::model::actuator::LEG_LENGTH,
            limits: [Some(0.9), Some(1.2)],
            marker: Some(5.0),
            lang: Lang::En,
            efforts: false,
        });
        assert_eq!(text.matches("<polyline").count(), 6);
        assert!(text.contains("Time t (s)") && text.contains("Leg length L (m)"));
        assert!(text.contains("stroke-dasharray") && text.contains("Lmax = 1.2 m"));
        assert!(text.contains("a &lt; b"));
        assert!(text.contains(r#"class="marker""#));
    }

    #[test]
    fn servo_angles_plot_in_degrees_with_gaps_where_out_of_reach() {
        let times: Vec<f64> = (0..11).map(|k| k as f64).collect();
        let mut angles: Vec<[f64; 6]> = times.iter().map(|t| [2.0 * t - 10.0; 6]).collect();
        // Servo 3 cannot reach at t = 4 and 5: its curve breaks in two.
        angles[4][2] = f64::NAN;
        angles[5][2] = f64::NAN;
        let text = svg(&PlotData {
            title: "servos",
            times: &times,
            values: &angles,
            quantity: stewart_kinematics::model::actuator::SERVO_ANGLE,
            limits: [Some(-80.0), Some(80.0)],
            marker: None,
            lang: Lang::En,
            efforts: false,
        });
        assert_eq!(text.matches("<polyline").count(), 7);
        assert_eq!(text.matches(r#"class="leg S3""#).count(), 2);
        assert!(text.contains("Servo angle θ (°)"), "{text}");
        assert!(text.contains("θmax = 80°") && text.contains(">θ6</text>"));
        assert!(!text.contains("NaN"));
    }
}
