//! "Nice" steps for grids and axes: 1, 2 or 5 × 10ⁿ.

/// The nice mantissas, largest first.
const MANTISSAS: [f64; 3] = [5.0, 2.0, 1.0];

/// The smallest nice step (1, 2, 5 × 10ⁿ) at least `raw` (`raw` itself when it is not a
/// positive finite number). A hair of tolerance keeps `raw` = 0.2 from becoming 0.5.
pub fn nice_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return raw;
    }
    let magnitude = 10f64.powf(raw.log10().floor());
    // Smallest first: 1, 2, 5, 10 × 10ⁿ.
    MANTISSAS
        .iter()
        .rev()
        .chain(std::iter::once(&10.0))
        .map(|m| m * magnitude)
        .find(|s| *s >= raw * 0.999)
        .unwrap_or(raw)
}

/// The largest nice step with at least `at_least` multiples in `lo..=hi` (`None` for an
/// empty or non-finite range): the labelled step of an axis that must show that many
/// labels.
pub fn largest_step_with(lo: f64, hi: f64, at_least: usize) -> Option<f64> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0 && at_least > 0) {
        return None;
    }
    let count = |step: f64| ((hi / step).floor() - (lo / step).ceil()) as i64 + 1;
    // A step of span / at_least is the largest that can fit them; walk down from there.
    let mut decade = 10f64.powf((span / at_least as f64).log10().floor() + 1.0);
    for _ in 0..8 {
        for factor in MANTISSAS {
            let step = factor * decade / 10.0;
            if count(step) >= at_least as i64 {
                return Some(step);
            }
        }
        decade /= 10.0;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_one_two_or_five_times_a_power_of_ten() {
        assert_eq!(nice_step(0.13), 0.2);
        assert_eq!(nice_step(0.2), 0.2);
        assert_eq!(nice_step(3.0), 5.0);
        assert_eq!(nice_step(7.0), 10.0);
        assert!((nice_step(0.0031) - 0.005).abs() < 1e-15);
        assert_eq!(nice_step(0.0), 0.0);
    }

    #[test]
    fn the_largest_step_leaves_enough_labels() {
        assert_eq!(largest_step_with(0.5, 1.5, 3), Some(0.5));
        assert_eq!(largest_step_with(0.0, 10.0, 3), Some(5.0));
        assert_eq!(largest_step_with(1.0, 1.0, 3), None);
    }
}
