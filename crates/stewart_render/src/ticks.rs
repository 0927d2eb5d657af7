//! "Nice" steps for grids and axes: 1, 2 or 5 × 10ⁿ.

/// The smallest nice step (1, 2, 5 × 10ⁿ) at least `raw` (`raw` itself when it is not a
/// positive finite number). A hair of tolerance keeps `raw` = 0.2 from becoming 0.5.
pub fn nice_step(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return raw;
    }
    let magnitude = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * magnitude)
        .find(|s| *s >= raw * 0.999)
        .unwrap_or(raw)
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
}
