//! The report of `stewart cue --compare`: the measures of both algorithms side by side,
//! as a table for people or one JSON object.

use stewart_kinematics::analysis::cueing::compare::CueMeasures;

/// One line of the table: its label, unit and each algorithm's value as text.
fn lines(m: &[CueMeasures; 2]) -> Vec<(String, &'static str, [String; 2])> {
    let fixed = |v: f64, digits: usize| format!("{v:.digits$}");
    let each = |f: &dyn Fn(&CueMeasures) -> String| [f(&m[0]), f(&m[1])];
    let mut out = Vec::new();
    out.push((
        "specific-force RMSE, surge and sway".to_owned(),
        "m/s²",
        each(&|c| fixed(c.force_rmse_xy, 3)),
    ));
    for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
        out.push((
            format!("specific-force RMSE {axis}"),
            "m/s²",
            each(&|c| fixed(c.force_rmse[i], 3)),
        ));
    }
    for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
        out.push((
            format!("shape correlation {axis}"),
            "",
            each(&|c| c.force_correlation[i].map_or("—".to_owned(), |r| fixed(r, 3))),
        ));
    }
    for (i, axis) in ["roll", "pitch", "yaw"].into_iter().enumerate() {
        out.push((
            format!("rotation-rate RMSE {axis}"),
            "°/s",
            each(&|c| fixed(c.rate_rmse_deg_s[i], 2)),
        ));
    }
    out.push((
        "false rotation of tilt, largest".to_owned(),
        "°/s",
        each(&|c| fixed(c.false_tilt_rate_deg_s, 2)),
    ));
    out.push((
        "stroke used, largest".to_owned(),
        "%",
        each(&|c| fixed(100.0 * c.stroke_used, 1)),
    ));
    out.push((
        "limiter engaged".to_owned(),
        "s",
        each(&|c| fixed(c.limiter_s, 2)),
    ));
    out.push((
        "planner: failed solves, stops".to_owned(),
        "",
        each(&|c| format!("{}, {}", c.failed_solves, c.stops)),
    ));
    out
}

/// The table, one measure a line, the washout's column then the planner's, and the
/// change of the headline error.
pub(super) fn table(m: &[CueMeasures; 2]) -> String {
    let rows = lines(m);
    let width = rows.iter().map(|r| r.0.chars().count()).max().unwrap_or(0);
    let mut s = format!(
        "{:width$}  {:6}  {:>12}  {:>12}\n",
        "measure", "unit", "washout", "mpc"
    );
    for (label, unit, [a, b]) in &rows {
        s.push_str(&format!("{label:width$}  {unit:6}  {a:>12}  {b:>12}\n"));
    }
    let (w, p) = (m[0].force_rmse_xy, m[1].force_rmse_xy);
    if w > 0.0 {
        s.push_str(&format!(
            "the planner's surge-and-sway force error is {:.1} % {} the washout's (its limiter on)\n",
            100.0 * (p - w).abs() / w,
            if p <= w { "below" } else { "above" }
        ));
    }
    s
}

/// One JSON object: the input's name and each algorithm's measures.
pub(super) fn json(m: &[CueMeasures; 2], input: &str) -> String {
    let one = |c: &CueMeasures| {
        serde_json::json!({
            "algorithm": c.algorithm.word(),
            "force_rmse_xy_m_s2": c.force_rmse_xy,
            "force_rmse_m_s2": c.force_rmse,
            "force_correlation": c.force_correlation,
            "rate_rmse_deg_s": c.rate_rmse_deg_s,
            "false_tilt_rate_deg_s": c.false_tilt_rate_deg_s,
            "stroke_used": c.stroke_used,
            "limiter_s": c.limiter_s,
            "failed_solves": c.failed_solves,
            "stops": c.stops,
        })
    };
    let value = serde_json::json!({
        "input": input,
        "washout": one(&m[0]),
        "mpc": one(&m[1]),
    });
    format!("{value:#}\n")
}
