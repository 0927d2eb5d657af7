//! The conditioning colour map shared by the 3D view and the figures: viridis
//! (perceptually uniform, colour-blind safe) on a logarithmic scale from a condition
//! number of 1 to the near-singular threshold, and one marked colour past it.

/// Viridis at nine stops, sRGB.
const VIRIDIS: [[u8; 3]; 9] = [
    [68, 1, 84],
    [71, 44, 122],
    [59, 81, 139],
    [44, 113, 142],
    [33, 144, 141],
    [39, 173, 129],
    [92, 200, 99],
    [170, 220, 50],
    [253, 231, 37],
];

/// Poses past the near-singular threshold (and singular ones), sRGB magenta.
pub const PAST: [u8; 3] = [0xD0, 0x1C, 0x8B];

/// A certified region whose every position is proven reachable, sRGB green.
pub const PROVEN: [u8; 3] = [0x3C, 0xA0, 0x5A];

/// A certified region left undecided (the boundary's band), sRGB amber.
pub const UNDECIDED: [u8; 3] = [0xF2, 0xA9, 0x00];

/// Viridis at `s` in 0 ..= 1 (clamped), sRGB.
pub fn viridis(s: f64) -> [u8; 3] {
    let x = s.clamp(0.0, 1.0) * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - i as f64;
    std::array::from_fn(|k| {
        let (a, b) = (f64::from(VIRIDIS[i][k]), f64::from(VIRIDIS[i + 1][k]));
        (a + f * (b - a)).round() as u8
    })
}

/// Where condition number `k` falls on the scale: 0 at 1, 1 at `max` (logarithmic);
/// `None` past `max` or when singular (infinite or not a number).
pub fn condition_fraction(k: f64, max: f64) -> Option<f64> {
    if !k.is_finite() || k > max {
        return None;
    }
    Some((k.max(1.0).ln() / max.max(1.0 + 1e-9).ln()).clamp(0.0, 1.0))
}

/// The colour of condition number `k` with threshold `max`, sRGB.
pub fn condition_colour(k: f64, max: f64) -> [u8; 3] {
    condition_fraction(k, max).map_or(PAST, viridis)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ends_of_the_scale_are_viridis_ends_and_past_is_magenta() {
        assert_eq!(condition_colour(1.0, 100.0), [68, 1, 84]);
        assert_eq!(condition_colour(0.5, 100.0), [68, 1, 84]);
        assert_eq!(condition_colour(100.0, 100.0), [253, 231, 37]);
        assert_eq!(condition_colour(100.5, 100.0), PAST);
        assert_eq!(condition_colour(f64::INFINITY, 100.0), PAST);
        assert_eq!(condition_colour(f64::NAN, 100.0), PAST);
        // 10 is half way on a log scale to 100: the middle stop.
        assert_eq!(condition_colour(10.0, 100.0), [33, 144, 141]);
    }

    #[test]
    fn the_map_brightens_monotonically() {
        let luma = |c: [u8; 3]| 0.2126 * c[0] as f64 + 0.7152 * c[1] as f64 + 0.0722 * c[2] as f64;
        let mut last = -1.0;
        for k in 0..=100 {
            let l = luma(viridis(k as f64 / 100.0));
            assert!(l > last, "{k}");
            last = l;
        }
    }
}
