//! The workspace figure: a horizontal and a vertical slice through the constant-orientation
//! workspace side by side, each cell coloured by the normalised condition number (viridis,
//! logarithmic from 1 to the near-singular threshold; past it a marked colour), the
//! reachable boundary as a line, the platform centre as a cross, axes in metres and a
//! colour bar. Cells are merged into runs of one colour, so the SVG and PDF stay vectors.
//!
//! The certified figure (`workspace --certified --plot`) cuts the certified boxes with the
//! same two planes instead: proven reachable green, undecided amber, with the sampled
//! boundary's line over them (it must run inside the amber band).

use std::fmt::Write as _;

use anyhow::Result;
use stewart_kinematics::Angle;
use stewart_kinematics::analysis::certified::workspace::{BoxClass, ClassedBox};
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::analysis::workspace::{ConstantOrientationWorkspace, Plane, Slice};

use stewart_render::colormap;

use super::plot::nice_ticks;
use crate::i18n::Lang;

/// Page size in CSS pixels: 16 cm × 8 cm.
const WIDTH: f64 = 604.7;
const HEIGHT: f64 = 302.4;

/// Cells past the near-singular threshold (and singular ones), as an SVG colour.
fn past() -> String {
    hex(colormap::PAST)
}

/// `#RRGGBB`.
fn hex([r, g, b]: [u8; 3]) -> String {
    format!("#{r:02X}{g:02X}{b:02X}")
}

/// What the figure shows.
pub(crate) struct WorkspaceFigure<'a> {
    /// The title line.
    pub(crate) title: &'a str,
    /// The horizontal slice and the vertical one.
    pub(crate) slices: [&'a Slice; 2],
    /// The platform centre, metres.
    pub(crate) centre: [f64; 3],
    /// The near-singular threshold (`checks.condition_max`).
    pub(crate) condition_max: f64,
    /// The language of the words.
    pub(crate) lang: Lang,
    /// The certified boxes each slice's plane cuts, drawn instead of the condition
    /// number's cells (the certified figure).
    pub(crate) certified: Option<[Vec<Cut>; 2]>,
}

/// A certified box cut by a slice's plane: its rectangle in the slice's two axes
/// (`[[x0, x1], [y0, y1]]`, metres) and whether it is proven reachable (else undecided).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cut {
    /// Across and up, metres.
    pub(crate) rect: [[f64; 2]; 2],
    /// Proven reachable (else undecided).
    pub(crate) inner: bool,
}

/// The certified `boxes` the slice `sl`'s plane cuts.
pub(crate) fn cuts(boxes: &[ClassedBox], sl: &Slice) -> Vec<Cut> {
    let (normal, up) = match sl.plane {
        Plane::Horizontal => (2, 1),
        Plane::Vertical => (1, 2),
    };
    boxes
        .iter()
        .filter(|b| b.position[normal].contains(sl.at))
        .map(|b| Cut {
            rect: [
                [b.position[0].lo(), b.position[0].hi()],
                [b.position[up].lo(), b.position[up].hi()],
            ],
            inner: b.class == BoxClass::Inner,
        })
        .collect()
}

/// Colour of condition number `k`: viridis from 1 to `max` on a log scale
/// (`stewart_render::colormap`), quantised to 48 levels so that neighbouring cells merge
/// into runs.
fn colour(k: f64, max: f64) -> String {
    let Some(s) = colormap::condition_fraction(k, max) else {
        return past();
    };
    hex(colormap::viridis((s * 48.0).round() / 48.0))
}

/// Cells across the horizontal slice (the vertical one has the same cell size).
const SLICE_CELLS: usize = 200;

/// The two slices through the workspace `ws` at `position` (a horizontal one at its
/// height, a vertical one through its y) as a figure in the format `path` ends in.
pub(crate) fn figure_file(
    scenario: &stewart_kinematics::Scenario,
    ws: &ConstantOrientationWorkspace,
    orientation: [Angle; 3],
    position: [f64; 3],
    lang: Lang,
    path: &std::path::Path,
) -> Result<Vec<u8>> {
    let [horizontal, vertical] = slices(scenario, ws, orientation, position)?;
    let title = title(scenario, orientation, lang, "workspace.title");
    let svg = svg(&WorkspaceFigure {
        title: &title,
        slices: [&horizontal, &vertical],
        centre: position,
        condition_max: scenario.checks.condition_max,
        lang,
        certified: None,
    });
    super::vector::by_extension(svg, path)
}

/// The certified `boxes` cut by the same two planes as [`figure_file`]'s (their extent
/// and the sampled boundary from `ws`) as a figure in the format `path` ends in.
pub(crate) fn certified_figure_file(
    scenario: &stewart_kinematics::Scenario,
    ws: &ConstantOrientationWorkspace,
    boxes: &[ClassedBox],
    orientation: [Angle; 3],
    position: [f64; 3],
    lang: Lang,
    path: &std::path::Path,
) -> Result<Vec<u8>> {
    let [horizontal, vertical] = slices(scenario, ws, orientation, position)?;
    let title = title(scenario, orientation, lang, "workspace.certified_title");
    let certified = Some([cuts(boxes, &horizontal), cuts(boxes, &vertical)]);
    let svg = svg(&WorkspaceFigure {
        title: &title,
        slices: [&horizontal, &vertical],
        centre: position,
        condition_max: scenario.checks.condition_max,
        lang,
        certified,
    });
    super::vector::by_extension(svg, path)
}

/// The figure's title, from the catalogue's `key`.
fn title(
    scenario: &stewart_kinematics::Scenario,
    orientation: [Angle; 3],
    lang: Lang,
    key: &str,
) -> String {
    let [r, p, yaw] = orientation.map(|a| format!("{:.1}", a.degrees()));
    lang.fmt(
        key,
        &[
            ("name", &scenario.name),
            ("roll", &r),
            ("pitch", &p),
            ("yaw", &yaw),
        ],
    )
}

/// A horizontal slice at `position`'s height and a vertical one through its y, over the
/// workspace's extent with a margin.
fn slices(
    scenario: &stewart_kinematics::Scenario,
    ws: &ConstantOrientationWorkspace,
    orientation: [Angle; 3],
    position: [f64; 3],
) -> Result<[Slice; 2]> {
    let g = &scenario.geometry;
    let Some([ex, ey, ez]) = ws.extent else {
        anyhow::bail!("no position is reachable at this orientation: there is nothing to plot");
    };
    let pad = |[lo, hi]: [f64; 2]| {
        let m = (0.1 * (hi - lo)).max(0.02);
        [lo - m, hi + m]
    };
    let (x, y, z) = (pad(ex), pad(ey), pad(ez));
    let cell = (x[1] - x[0]) / SLICE_CELLS as f64;
    let count = |r: [f64; 2]| (((r[1] - r[0]) / cell).round() as usize).max(2);
    let horizontal = workspace::workspace_slice(
        g,
        &scenario.limits,
        orientation,
        Plane::Horizontal,
        position[2],
        [x, y],
        [count(x), count(y)],
    );
    let vertical = workspace::workspace_slice(
        g,
        &scenario.limits,
        orientation,
        Plane::Vertical,
        position[1],
        [x, z],
        [count(x), count(z)],
    );
    Ok([horizontal, vertical])
}

/// Where one slice is drawn: the box on the page and the metre-to-page scale.
struct SliceBox {
    left: f64,
    bottom: f64,
    scale: f64,
    range: [[f64; 2]; 2],
}

impl SliceBox {
    fn x(&self, v: f64) -> f64 {
        self.left + (v - self.range[0][0]) * self.scale
    }
    fn y(&self, v: f64) -> f64 {
        self.bottom - (v - self.range[1][0]) * self.scale
    }
}

/// The figure as an SVG document.
pub(crate) fn svg(fig: &WorkspaceFigure) -> String {
    let t = fig.lang;
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="160mm" height="80mm" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="{}" font-size="10">"#,
        super::plot::font_families()
    );
    let _ = writeln!(
        s,
        r#"<rect x="0" y="0" width="{WIDTH}" height="{HEIGHT}" fill="white"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="16" text-anchor="middle" font-size="12">{}</text>"#,
        WIDTH / 2.0,
        super::plot::escape(fig.title)
    );
    // Two panels with one metre-to-page scale, so both read alike.
    let (top, bottom, bar) = (32.0, HEIGHT - 36.0, 104.0);
    let gap = 58.0;
    let avail = [(WIDTH - bar - 3.0 * gap) / 2.0, bottom - top];
    let span = |sl: &Slice| {
        [
            sl.range[0][1] - sl.range[0][0],
            sl.range[1][1] - sl.range[1][0],
        ]
    };
    let scale = fig
        .slices
        .iter()
        .map(|sl| {
            let [w, h] = span(sl);
            (avail[0] / w.max(1e-9)).min(avail[1] / h.max(1e-9))
        })
        .fold(f64::INFINITY, f64::min);
    let mut left = gap;
    for (k, sl) in fig.slices.iter().enumerate() {
        let frame = SliceBox {
            left,
            bottom: bottom - 0.5 * (avail[1] - span(sl)[1] * scale),
            scale,
            range: sl.range,
        };
        match &fig.certified {
            Some(cuts) => certified_cells(&mut s, &cuts[k], &frame),
            None => cells(&mut s, fig, sl, &frame),
        }
        boundary(&mut s, sl, &frame);
        centre_mark(&mut s, fig, sl, &frame);
        panel_axes(&mut s, fig, sl, &frame);
        left += avail[0] + gap;
    }
    let (x, height) = (WIDTH - bar + 6.0, bottom - top - 40.0);
    match fig.certified {
        Some(_) => certified_key(&mut s, fig, x, top + 10.0),
        None => colour_bar(&mut s, fig, x, top + 10.0, height),
    }
    let _ = t;
    s.push_str("</svg>\n");
    s
}

/// The certified boxes a plane cuts: the proven ones green, then the undecided amber over
/// them, clipped to the panel.
fn certified_cells(s: &mut String, cuts: &[Cut], f: &SliceBox) {
    let [[x0, x1], [y0, y1]] = f.range;
    let _ = writeln!(s, r#"<g class="certified" shape-rendering="crispEdges">"#);
    for inner in [true, false] {
        let fill = hex(if inner {
            colormap::PROVEN
        } else {
            colormap::UNDECIDED
        });
        for c in cuts.iter().filter(|c| c.inner == inner) {
            let [[a0, a1], [b0, b1]] = c.rect;
            let (a0, a1, b0, b1) = (a0.max(x0), a1.min(x1), b0.max(y0), b1.min(y1));
            if a0 >= a1 || b0 >= b1 {
                continue;
            }
            let _ = writeln!(
                s,
                r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{fill}"/>"#,
                f.x(a0),
                f.y(b1),
                (a1 - a0) * f.scale + 0.3,
                (b1 - b0) * f.scale + 0.3
            );
        }
    }
    let _ = writeln!(s, "</g>");
}

/// A key's entry for the boundary line: a short black line and its `words`.
fn boundary_key(s: &mut String, x: f64, y: f64, words: &str) {
    let _ = writeln!(
        s,
        r#"<line x1="{x:.2}" y1="{:.2}" x2="{:.2}" y2="{:.2}" stroke="black" stroke-width="0.9"/><text x="{:.2}" y="{:.2}" font-size="8.5">{}</text>"#,
        y + 4.0,
        x + 12.0,
        y + 4.0,
        x + 15.0,
        y + 7.0,
        words
    );
}

/// The certified figure's key: proven, undecided, the sampled boundary.
fn certified_key(s: &mut String, fig: &WorkspaceFigure, x: f64, top: f64) {
    let t = fig.lang;
    for (k, (fill, key)) in [
        (colormap::PROVEN, "workspace.proven"),
        (colormap::UNDECIDED, "workspace.undecided"),
    ]
    .into_iter()
    .enumerate()
    {
        let y = top + 16.0 * k as f64;
        let _ = writeln!(
            s,
            r#"<rect x="{x:.2}" y="{y:.2}" width="12" height="8" fill="{}"/><text x="{:.2}" y="{:.2}" font-size="8.5">{}</text>"#,
            hex(fill),
            x + 15.0,
            y + 7.5,
            t.tr(key)
        );
    }
    let y = top + 32.0;
    boundary_key(s, x, y, t.tr("workspace.sampled_boundary"));
}

/// The reachable cells in their colours, a rectangle per run of one colour in a row.
fn cells(s: &mut String, fig: &WorkspaceFigure, sl: &Slice, f: &SliceBox) {
    let [nx, ny] = sl.cells;
    let cw = (sl.range[0][1] - sl.range[0][0]) / nx as f64;
    let ch = (sl.range[1][1] - sl.range[1][0]) / ny as f64;
    let _ = writeln!(s, r#"<g class="cells" shape-rendering="crispEdges">"#);
    for j in 0..ny {
        let mut i = 0;
        while i < nx {
            let Some(k) = sl.get(i, j) else {
                i += 1;
                continue;
            };
            let c = colour(k, fig.condition_max);
            let start = i;
            while i + 1 < nx
                && sl
                    .get(i + 1, j)
                    .is_some_and(|k| colour(k, fig.condition_max) == c)
            {
                i += 1;
            }
            let x0 = sl.range[0][0] + start as f64 * cw;
            let y1 = sl.range[1][0] + (j + 1) as f64 * ch;
            let _ = writeln!(
                s,
                r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{c}"/>"#,
                f.x(x0),
                f.y(y1),
                (i + 1 - start) as f64 * cw * f.scale + 0.3,
                ch * f.scale + 0.3
            );
            i += 1;
        }
    }
    let _ = writeln!(s, "</g>");
}

/// The boundary: every cell edge between a reachable cell and one out of reach.
fn boundary(s: &mut String, sl: &Slice, f: &SliceBox) {
    let [nx, ny] = sl.cells;
    let cw = (sl.range[0][1] - sl.range[0][0]) / nx as f64;
    let ch = (sl.range[1][1] - sl.range[1][0]) / ny as f64;
    let reach = |i: isize, j: isize| {
        i >= 0
            && j >= 0
            && (i as usize) < nx
            && (j as usize) < ny
            && sl.get(i as usize, j as usize).is_some()
    };
    let mut d = String::new();
    for j in 0..ny as isize {
        for i in 0..nx as isize {
            if !reach(i, j) {
                continue;
            }
            let (x0, x1) = (
                sl.range[0][0] + i as f64 * cw,
                sl.range[0][0] + (i + 1) as f64 * cw,
            );
            let (y0, y1) = (
                sl.range[1][0] + j as f64 * ch,
                sl.range[1][0] + (j + 1) as f64 * ch,
            );
            for (di, dj, a, b) in [
                (-1, 0, [x0, y0], [x0, y1]),
                (1, 0, [x1, y0], [x1, y1]),
                (0, -1, [x0, y0], [x1, y0]),
                (0, 1, [x0, y1], [x1, y1]),
            ] {
                if !reach(i + di, j + dj) {
                    let _ = write!(
                        d,
                        "M{:.2} {:.2}L{:.2} {:.2}",
                        f.x(a[0]),
                        f.y(a[1]),
                        f.x(b[0]),
                        f.y(b[1])
                    );
                }
            }
        }
    }
    let _ = writeln!(
        s,
        r#"<path class="boundary" d="{d}" stroke="black" stroke-width="0.9" fill="none"/>"#
    );
}

/// A cross at the platform centre.
fn centre_mark(s: &mut String, fig: &WorkspaceFigure, sl: &Slice, f: &SliceBox) {
    let (cx, cy) = match sl.plane {
        Plane::Horizontal => (fig.centre[0], fig.centre[1]),
        Plane::Vertical => (fig.centre[0], fig.centre[2]),
    };
    let (px, py) = (f.x(cx), f.y(cy));
    let _ = writeln!(
        s,
        r#"<path class="centre" d="M{:.2} {py:.2}H{:.2}M{px:.2} {:.2}V{:.2}" stroke="black" stroke-width="1.2"/>"#,
        px - 5.0,
        px + 5.0,
        py - 5.0,
        py + 5.0
    );
}

/// The panel's frame, ticks in metres, axis labels and title.
fn panel_axes(s: &mut String, fig: &WorkspaceFigure, sl: &Slice, f: &SliceBox) {
    let t = fig.lang;
    let (x0, x1) = (f.x(sl.range[0][0]), f.x(sl.range[0][1]));
    let (y0, y1) = (f.y(sl.range[1][0]), f.y(sl.range[1][1]));
    let _ = writeln!(
        s,
        r#"<rect x="{x0:.2}" y="{y1:.2}" width="{:.2}" height="{:.2}" fill="none" stroke="black" stroke-width="0.7"/>"#,
        x1 - x0,
        y0 - y1
    );
    for v in ticks(sl.range[0]) {
        let x = f.x(v);
        let _ = writeln!(
            s,
            r#"<line x1="{x:.2}" y1="{y0:.2}" x2="{x:.2}" y2="{:.2}" stroke="black" stroke-width="0.7"/><text x="{x:.2}" y="{:.2}" text-anchor="middle">{}</text>"#,
            y0 + 3.0,
            y0 + 13.0,
            tick(v)
        );
    }
    for v in ticks(sl.range[1]) {
        let y = f.y(v);
        let _ = writeln!(
            s,
            r#"<line x1="{:.2}" y1="{y:.2}" x2="{x0:.2}" y2="{y:.2}" stroke="black" stroke-width="0.7"/><text x="{:.2}" y="{:.2}" text-anchor="end">{}</text>"#,
            x0 - 3.0,
            x0 - 5.0,
            y + 3.5,
            tick(v)
        );
    }
    let (across, up, title) = match sl.plane {
        Plane::Horizontal => (
            "x (m)",
            "y (m)",
            t.fmt("workspace.horizontal", &[("at", &format!("{:.3}", sl.at))]),
        ),
        Plane::Vertical => (
            "x (m)",
            "z (m)",
            t.fmt("workspace.vertical", &[("at", &format!("{:.3}", sl.at))]),
        ),
    };
    let _ = writeln!(
        s,
        r#"<text x="{:.2}" y="{:.2}" text-anchor="middle">{across}</text>"#,
        0.5 * (x0 + x1),
        y0 + 26.0
    );
    let _ = writeln!(
        s,
        r#"<text x="{0:.2}" y="{1:.2}" text-anchor="middle" transform="rotate(-90 {0:.2} {1:.2})">{up}</text>"#,
        x0 - 36.0,
        0.5 * (y0 + y1)
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.2}" y="{:.2}" text-anchor="middle" font-size="10.5">{}</text>"#,
        0.5 * (x0 + x1),
        y1 - 6.0,
        super::plot::escape(&title)
    );
}

/// Nice ticks over `[lo, hi]`, at least three (a narrow range gets finer steps).
fn ticks([lo, hi]: [f64; 2]) -> Vec<f64> {
    [4, 6, 8, 12, 16]
        .into_iter()
        .map(|n| nice_ticks(lo, hi, n))
        .find(|t| t.len() >= 3)
        .unwrap_or_else(|| nice_ticks(lo, hi, 16))
}

/// A tick label: as many decimals as the value needs, up to three.
fn tick(v: f64) -> String {
    let text = format!("{v:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// The colour bar: condition number from 1 to the threshold (log scale), the colour past
/// it, and the boundary's key.
fn colour_bar(s: &mut String, fig: &WorkspaceFigure, x: f64, top: f64, height: f64) {
    let t = fig.lang;
    let max = fig.condition_max.max(1.5);
    let _ = writeln!(
        s,
        r#"<text x="{x:.2}" y="{:.2}" font-size="9">{}</text>"#,
        top - 6.0,
        t.tr("workspace.condition")
    );
    let steps = 48;
    for k in 0..steps {
        let f0 = k as f64 / steps as f64;
        let value = max.powf(f0 + 0.5 / steps as f64);
        let y = top + height * (1.0 - (k + 1) as f64 / steps as f64);
        let _ = writeln!(
            s,
            r#"<rect x="{x:.2}" y="{y:.2}" width="12" height="{:.2}" fill="{}"/>"#,
            height / steps as f64 + 0.3,
            colour(value, max)
        );
    }
    let _ = writeln!(
        s,
        r#"<rect x="{x:.2}" y="{top:.2}" width="12" height="{height:.2}" fill="none" stroke="black" stroke-width="0.6"/>"#
    );
    let mut marks = vec![1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0];
    marks.retain(|m| *m < max * 0.95);
    marks.push(max);
    for m in marks {
        let y = top + height * (1.0 - m.ln() / max.ln());
        let _ = writeln!(
            s,
            r#"<line x1="{:.2}" y1="{y:.2}" x2="{:.2}" y2="{y:.2}" stroke="black" stroke-width="0.6"/><text x="{:.2}" y="{:.2}" font-size="8.5">{}</text>"#,
            x + 12.0,
            x + 15.0,
            x + 17.0,
            y + 3.0,
            tick(m)
        );
    }
    let y = top + height + 12.0;
    let _ = writeln!(
        s,
        r#"<rect x="{x:.2}" y="{y:.2}" width="12" height="8" fill="{}"/><text x="{:.2}" y="{:.2}" font-size="8.5">{}</text>"#,
        past(),
        x + 15.0,
        y + 7.5,
        t.fmt("workspace.past", &[("max", &tick(max))])
    );
    let y = y + 14.0;
    boundary_key(s, x, y, t.tr("workspace.boundary"));
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::Scenario;
    use stewart_kinematics::analysis::certified::workspace::{
        WorkspaceRequest, certified_workspace,
    };
    use stewart_kinematics::analysis::workspace::{
        constant_orientation_workspace, pose_within_limits,
    };

    #[test]
    fn the_cut_boxes_hold_every_sampled_cell_and_the_proven_ones_are_reachable() {
        for name in ["paired", "servo-desk"] {
            let s = Scenario::preset(name).expect("preset");
            let g = &s.geometry;
            let level = [Angle::ZERO; 3];
            let ws = constant_orientation_workspace(g, &s.limits, level, 100).expect("grid");
            let home = g.home_pose();
            let never = || false;
            let request = WorkspaceRequest {
                orientation: &home,
                boundary_width: 0.02 * g.characteristic_length(),
                budget: 5_000_000,
                stop: &never,
            };
            let w = certified_workspace(g, &s.limits, &request).expect("certified");
            let centre = [0.0, 0.0, g.home_height()];
            let slices = slices(&s, &ws, level, centre).expect("slices");
            let (mut sampled, mut proven) = (0, 0);
            for sl in &slices {
                let cuts = cuts(&w.boxes, sl);
                let point = |[a, b]: [f64; 2]| match sl.plane {
                    Plane::Horizontal => home.with_position([a, b, sl.at].into()),
                    Plane::Vertical => home.with_position([a, sl.at, b].into()),
                };
                let inside = |c: &Cut, [a, b]: [f64; 2]| {
                    (c.rect[0][0]..=c.rect[0][1]).contains(&a)
                        && (c.rect[1][0]..=c.rect[1][1]).contains(&b)
                };
                // Every cell the grid finds reachable lies in a box kept (inner or not).
                for j in 0..sl.cells[1] {
                    for i in 0..sl.cells[0] {
                        let at = sl.centre(i, j);
                        if sl.get(i, j).is_some() && pose_within_limits(g, &s.limits, &point(at)) {
                            sampled += 1;
                            assert!(cuts.iter().any(|c| inside(c, at)), "{name}: {at:?}");
                        }
                    }
                }
                // The centre of every proven rectangle is reachable.
                for c in cuts.iter().filter(|c| c.inner) {
                    let at = [0, 1].map(|k| 0.5 * (c.rect[k][0] + c.rect[k][1]));
                    assert!(
                        pose_within_limits(g, &s.limits, &point(at)),
                        "{name}: {at:?}"
                    );
                    proven += 1;
                }
            }
            assert!(sampled > 1000 && proven > 50, "{name}: {sampled} {proven}");
        }
    }
}
