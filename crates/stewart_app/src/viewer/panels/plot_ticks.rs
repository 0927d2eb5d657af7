//! The live plot's value axis: ticks at 1, 2 or 5 times a power of ten, as coarse as still
//! gives at least three labelled ticks in view, each labelled with as many decimals as
//! its step needs. (egui_plot's own spacer steps by powers of ten only, so a range of
//! 0.5–1.5 m showed a single label, "1".)

use egui_plot::{GridInput, GridMark};

/// At least this many labelled ticks in view.
pub(crate) const MIN_LABELLED: usize = 3;

/// The labelled step for values `lo..hi`: the largest 1-2-5 step with at least
/// [`MIN_LABELLED`] multiples in the range (`None` for an empty or non-finite range); the
/// rule is the renderer's ([`stewart_render::ticks`]).
pub(crate) fn major_step(lo: f64, hi: f64) -> Option<f64> {
    stewart_render::ticks::largest_step_with(lo, hi, MIN_LABELLED)
}

/// At least this many labelled ticks on a time axis (egui_plot's own spacer gave a narrow
/// plot's 10 s only "0" and "10").
pub(crate) const MIN_TIME_LABELS: usize = 5;

/// Time labels are drawn once this far apart, faded in over the range, points (egui_plot's
/// 60 to 80 suits long numbers; times are short).
pub(crate) const TIME_LABEL_SPACING: std::ops::RangeInclusive<f32> = 24.0..=32.0;

/// The marks for egui_plot: the labelled ticks, and unlabelled grid lines between them
/// (a fifth of the step, or a half when the step is 2 × 10ᵏ).
pub(crate) fn marks(input: GridInput) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    marks_with(input, major_step(lo, hi))
}

/// The marks of a time axis: as [`marks`], with at least [`MIN_TIME_LABELS`] labelled.
pub(crate) fn time_marks(input: GridInput) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    marks_with(
        input,
        stewart_render::ticks::largest_step_with(lo, hi, MIN_TIME_LABELS),
    )
}

/// A time axis below a plot, named `name`: its labels as [`label`] writes them, drawn at
/// [`TIME_LABEL_SPACING`] (with [`time_marks`] as the plot's x spacer).
pub(crate) fn time_axis<'a>(name: impl Into<egui::WidgetText>) -> egui_plot::AxisHints<'a> {
    egui_plot::AxisHints::new_x()
        .label(name)
        .formatter(|mark, _| label(mark))
        .label_spacing(TIME_LABEL_SPACING)
}

/// The marks labelled every `major` (none without one).
fn marks_with(input: GridInput, major: Option<f64>) -> Vec<GridMark> {
    let (lo, hi) = input.bounds;
    let Some(major) = major else {
        return Vec::new();
    };
    let leading = major / 10f64.powf(major.log10().floor());
    let parts: i64 = if (leading - 2.0).abs() < 1e-9 { 2 } else { 5 };
    let minor = major / parts as f64;
    let (first, last) = ((lo / major).ceil() as i64, (hi / major).floor() as i64);
    let mut out = Vec::new();
    // Bounded: at most seven labelled ticks and the lines around them.
    for j in first - 1..=last {
        if j >= first {
            out.push(GridMark {
                value: j as f64 * major,
                step_size: major,
            });
        }
        for k in 1..parts {
            let value = j as f64 * major + k as f64 * minor;
            if (lo..=hi).contains(&value) {
                out.push(GridMark {
                    value,
                    step_size: minor,
                });
            }
        }
    }
    out
}

/// A tick's label: as many decimals as its step needs (0.5 → one, 0.02 → two).
pub(crate) fn label(mark: GridMark) -> String {
    let decimals = (-mark.step_size.log10().floor()).max(0.0) as usize;
    let text = format!("{:.*}", decimals, mark.value);
    // No "-0.0".
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        text.trim_start_matches('-').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labelled(lo: f64, hi: f64) -> Vec<String> {
        let input = GridInput {
            bounds: (lo, hi),
            base_step_size: (hi - lo) / 100.0,
        };
        let major = major_step(lo, hi).unwrap_or_else(|| panic!("{lo}..{hi}"));
        marks(input)
            .into_iter()
            .filter(|m| m.step_size == major)
            .map(label)
            .collect()
    }

    #[test]
    fn the_issue_s_range_gets_several_labels() {
        // The seed at 0.5 m of x amplitude: legs from about 0.5 to 1.5 m.
        assert_eq!(labelled(0.48, 1.52), ["0.5", "1.0", "1.5"]);
        assert_eq!(labelled(0.0, 1.0), ["0.0", "0.5", "1.0"]);
        assert_eq!(labelled(-70.0, 70.0), ["-50", "0", "50"]);
        assert_eq!(
            labelled(1.1, 1.19),
            ["1.10", "1.12", "1.14", "1.16", "1.18"]
        );
    }

    #[test]
    fn every_range_and_zoom_has_three_to_seven_distinct_labels() {
        let mut lo: f64 = -3.7;
        for k in 0..4000 {
            // Spans from 1e-6 to 1e4, anywhere.
            let span = 10f64.powf(-6.0 + 10.0 * (k as f64 / 4000.0));
            lo = (lo * 1.618 + 0.37).rem_euclid(50.0) - 25.0;
            let labels = labelled(lo, lo + span);
            assert!(
                (MIN_LABELLED..=7).contains(&labels.len()),
                "{lo}..{}: {labels:?}",
                lo + span
            );
            let mut unique = labels.clone();
            unique.dedup();
            assert_eq!(unique.len(), labels.len(), "{labels:?}");
        }
    }

    #[test]
    fn a_time_axis_gets_five_labels_or_more() {
        for (lo, hi) in [
            (0.0, 10.0),
            (-10.0, 0.0),
            (0.0, 5.0),
            (0.0, 12.0),
            (0.0, 60.0),
        ] {
            let input = GridInput {
                bounds: (lo, hi),
                base_step_size: (hi - lo) / 100.0,
            };
            let all = time_marks(input);
            let major = all.iter().map(|m| m.step_size).fold(0.0, f64::max);
            let labelled: Vec<String> = (all.into_iter())
                .filter(|m| m.step_size == major)
                .map(label)
                .collect();
            assert!(
                labelled.len() >= MIN_TIME_LABELS,
                "{lo}..{hi}: {labelled:?}"
            );
        }
    }

    #[test]
    fn minor_lines_fall_between_the_labelled_ones() {
        let input = GridInput {
            bounds: (0.48, 1.52),
            base_step_size: 0.01,
        };
        let all = marks(input);
        let major = all.iter().filter(|m| m.step_size == 0.5).count();
        assert_eq!(major, 3);
        assert!(all.len() > 3 * major, "{}", all.len());
        assert!(all.iter().all(|m| (0.48..=1.52).contains(&m.value)));
        assert!(major_step(1.0, 1.0).is_none() && major_step(0.0, f64::NAN).is_none());
    }
}
