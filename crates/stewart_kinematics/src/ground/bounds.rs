//! The sane range of every kind of input number.
//!
//! A number can be finite and still absurd: a duration of 1e308 s makes every sample
//! time infinite, a base radius of 1e300 m makes every leg length infinite, and an
//! iterative solver fed such values never settles. Every number that enters the model
//! (scenario files, `--set`, command-line options, CSV tables) is therefore checked
//! against the range of its kind below, generous enough for any laboratory platform or
//! motion simulator and small enough that nothing derived from in-range inputs can
//! overflow. The settings declare their ranges from these (`stewart settings` prints
//! them) and docs/guide/bad-input.md lists them.

use std::ops::RangeInclusive;

use thiserror::Error;

/// Largest length, position or offset, metres (|value|).
pub const LENGTH_M: f64 = 1e3;
/// Largest angle, degrees (|value|): ten turns.
pub const ANGLE_DEG: f64 = 3600.0;
/// Largest time, seconds (|value|): about 11.6 days.
pub const TIME_S: f64 = 1e6;
/// Largest frequency, hertz.
pub const FREQUENCY_HZ: f64 = 1e3;
/// Largest speed limit, metres per second.
pub const SPEED_M_S: f64 = 1e4;
/// Largest acceleration limit, metres per second squared.
pub const ACCEL_M_S2: f64 = 1e7;
/// Largest angular speed limit, degrees per second.
pub const ANGULAR_SPEED_DEG_S: f64 = 1e6;
/// Largest angular acceleration limit, degrees per second squared.
pub const ANGULAR_ACCEL_DEG_S2: f64 = 1e9;
/// Largest jerk limit, metres per second cubed.
pub const JERK_M_S3: f64 = 1e10;
/// Largest angular jerk limit, degrees per second cubed.
pub const ANGULAR_JERK_DEG_S3: f64 = 1e12;
/// Largest pure number (ratios, condition-number thresholds).
pub const RATIO: f64 = 1e12;
/// Largest mass, kilograms.
pub const MASS_KG: f64 = 1e6;
/// Largest moment of inertia, kg·m².
pub const INERTIA_KG_M2: f64 = 1e6;
/// Largest camera distance, metres.
pub const CAMERA_DISTANCE_M: f64 = 1e4;

/// The largest |value| of each entry of a pose row `[x, y, z, roll, pitch, yaw]` (metres,
/// degrees): what every pose read from a table, a file or an array keeps to, and what
/// every pose the studio writes keeps to (so that it is accepted back).
pub const POSE_ROW: [f64; 6] = [
    LENGTH_M, LENGTH_M, LENGTH_M, ANGLE_DEG, ANGLE_DEG, ANGLE_DEG,
];

/// The units of a pose row's entries ([`POSE_ROW`]).
pub const POSE_ROW_UNITS: [&str; 6] = ["m", "m", "m", "°", "°", "°"];

/// The first entry (0 to 5) of a pose row `[x, y, z, roll, pitch, yaw]` outside its
/// accepted range ([`POSE_ROW`]), and why.
pub fn check_pose_row(row: &[f64; 6]) -> Result<(), (usize, OutOfBounds)> {
    for (k, v) in row.iter().enumerate() {
        check(*v, &symmetric(POSE_ROW[k]), POSE_ROW_UNITS[k]).map_err(|e| (k, e))?;
    }
    Ok(())
}

/// `-limit ..= limit`.
pub const fn symmetric(limit: f64) -> RangeInclusive<f64> {
    -limit..=limit
}

/// Why a number was refused; its words end a sentence that starts with the value's name.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum OutOfBounds {
    /// NaN or infinite.
    #[error("must be a finite number, got {0}")]
    NotFinite(f64),
    /// Finite, outside the accepted range.
    #[error("{} is outside {}", short(*.value), describe(&(*.min..=*.max), .unit))]
    Outside {
        /// The value given.
        value: f64,
        /// The accepted range's lower end.
        min: f64,
        /// Its upper end.
        max: f64,
        /// The unit's symbol (may be empty).
        unit: String,
    },
}

impl From<OutOfBounds> for String {
    fn from(e: OutOfBounds) -> String {
        e.to_string()
    }
}

/// `value` if it is finite and within `range`, else why not.
pub fn check(value: f64, range: &RangeInclusive<f64>, unit: &str) -> Result<f64, OutOfBounds> {
    if !value.is_finite() {
        return Err(OutOfBounds::NotFinite(value));
    }
    if range.contains(&value) {
        return Ok(value);
    }
    Err(OutOfBounds::Outside {
        value,
        min: *range.start(),
        max: *range.end(),
        unit: unit.to_owned(),
    })
}

/// A range in words: `-1000 … 1000 m`.
pub fn range_words(range: &RangeInclusive<f64>, unit: &str) -> String {
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    format!("{} … {}{unit}", short(*range.start()), short(*range.end()))
}

/// The rule a value broke, in words: `the accepted range -1000 … 1000 m`.
pub fn describe(range: &RangeInclusive<f64>, unit: &str) -> String {
    format!("the accepted range {}", range_words(range, unit))
}

/// A number as people write it: `1000`, `1e6`, `0.001`.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_read_as_sentences() {
        let far = check(1e308, &symmetric(TIME_S), "s").unwrap_err();
        assert_eq!(
            far.to_string(),
            "1e308 is outside the accepted range -1e6 … 1e6 s"
        );
        assert!(matches!(far, OutOfBounds::Outside { max: TIME_S, .. }));
        let nan = check(f64::NAN, &symmetric(1.0), "").unwrap_err();
        assert_eq!(nan.to_string(), "must be a finite number, got NaN");
        assert!(matches!(nan, OutOfBounds::NotFinite(v) if v.is_nan()));
        assert_eq!(check(-2.5, &symmetric(LENGTH_M), "m"), Ok(-2.5));
        assert_eq!(short(0.5), "0.5");
        assert_eq!(short(1e-7), "1e-7");
    }

    #[test]
    fn a_pose_row_is_checked_entry_by_entry() {
        assert_eq!(
            check_pose_row(&[1000.0, -1000.0, 0.0, 3600.0, -3600.0, 0.0]),
            Ok(())
        );
        let (k, why) = check_pose_row(&[0.0, 0.0, 1000.5, 0.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(k, 2);
        assert_eq!(
            why.to_string(),
            "1000.5 is outside the accepted range -1000 … 1000 m"
        );
        let (k, why) = check_pose_row(&[0.0, 0.0, 0.0, 0.0, 0.0, -3600.1]).unwrap_err();
        assert_eq!((k, why.to_string().ends_with("°")), (5, true));
        let (k, why) = check_pose_row(&[0.0, f64::NAN, 1e200, 0.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(k, 1);
        assert!(matches!(why, OutOfBounds::NotFinite(v) if v.is_nan()));
    }
}
