//! Volumes as people read them, for the command line and the viewer alike: four
//! significant digits (a desk platform's workspace is a fraction of a litre, a motion
//! simulator's a cubic metre), and uncertainties to two, in powers of ten when small.

/// A volume in m³ to four significant digits.
pub(crate) fn format_volume(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = volume_decimals(v);
    format!("{v:.decimals$}")
}

/// The decimals that give `v` four significant digits.
fn volume_decimals(v: f64) -> usize {
    (3 - v.abs().log10().floor() as i32).clamp(0, 12) as usize
}

/// A bound of a proven bracket in m³ to four significant digits, rounded away from the
/// inside: `up` for an upper bound, else down (the printed bracket still holds).
pub(crate) fn format_bound(v: f64, up: bool) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = volume_decimals(v);
    let scale = 10f64.powi(decimals as i32);
    let mut units = if up {
        (v * scale).ceil()
    } else {
        (v * scale).floor()
    };
    // The product's own rounding could land on the wrong side: step one unit out.
    let text = |u: f64| format!("{:.decimals$}", u / scale);
    let wrong = |u: f64| {
        let back: f64 = text(u).parse().unwrap_or(v);
        if up { back < v } else { back > v }
    };
    if wrong(units) {
        units += if up { 1.0 } else { -1.0 };
    }
    text(units)
}

/// An uncertainty of a volume, m³: two significant digits, in powers of ten when small
/// (`4.5e-6`, not `0.000004474`).
pub(crate) fn format_volume_error(e: f64) -> String {
    if e != 0.0 && e.is_finite() && e.abs() < 1e-2 {
        format!("{e:.1e}")
    } else {
        format_volume(e)
    }
}

/// A length in metres to three significant digits (`0.000325`, not
/// `0.00032500000000000004`).
pub(crate) fn format_length(m: f64) -> String {
    if m == 0.0 || !m.is_finite() {
        return format!("{m}");
    }
    let decimals = (2 - m.abs().log10().floor() as i32).clamp(0, 15) as usize;
    format!("{m:.decimals$}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn volumes_keep_four_significant_digits() {
        assert_eq!(format_volume(0.170_704), "0.1707");
        assert_eq!(format_volume(0.000_221_37), "0.0002214");
        assert_eq!(format_volume(1.234_56e-6), "0.000001235");
        assert_eq!(format_volume(12.345_67), "12.35");
        assert_eq!(format_volume(0.0), "0");
        assert_eq!(format_volume_error(0.000_004_474), "4.5e-6");
        assert_eq!(format_volume_error(0.0123), "0.01230");
        assert_eq!(format_bound(0.000_311_49, false), "0.0003114");
        assert_eq!(format_bound(0.000_311_41, true), "0.0003115");
        assert_eq!(format_bound(0.25, true), "0.2500");
        assert_eq!(format_bound(0.25, false), "0.2500");
        assert_eq!(format_length(0.000_325_000_000_000_000_04), "0.000325");
        assert_eq!(format_length(0.02), "0.0200");
        assert_eq!(format_length(1.5), "1.50");
    }
}
