//! An angle whose unit is carried by the type.
//!
//! The seed script's most common bug is a value in degrees passed where radians are
//! expected (its author once set `yaw = 8` meaning degrees and watched the platform
//! spin). [`Angle`] can only be built by naming the unit, and read back only by naming
//! it again, so that mistake cannot be written.

use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

use serde::{Deserialize, Serialize};

/// A plane angle. Stored in radians; constructed and read only through named units.
#[derive(Clone, Copy, Debug, Default, PartialEq, PartialOrd, Serialize, Deserialize)]
pub struct Angle {
    radians: f64,
}

impl Angle {
    /// The zero angle.
    pub const ZERO: Angle = Angle { radians: 0.0 };

    /// An angle of `radians` radians.
    #[inline]
    pub const fn from_radians(radians: f64) -> Self {
        Self { radians }
    }

    /// An angle of `degrees` degrees (converted as `degrees · π/180`, as MATLAB's `deg2rad`).
    #[inline]
    pub fn from_degrees(degrees: f64) -> Self {
        Self {
            radians: degrees.to_radians(),
        }
    }

    /// The angle in radians.
    #[inline]
    pub const fn radians(self) -> f64 {
        self.radians
    }

    /// The angle in degrees.
    #[inline]
    pub fn degrees(self) -> f64 {
        let raw = self.radians.to_degrees();
        // The shortest decimal (up to 12 places) that is the very same angle, so that 60°
        // reads back as 60 and not 59.99999999999999: same radians, to the last bit.
        let mut scale = 1.0;
        for _ in 0..=12 {
            let d = (raw * scale).round() / scale;
            if d.to_radians() == self.radians {
                return d;
            }
            scale *= 10.0;
        }
        if raw.to_radians() == self.radians {
            return raw;
        }
        // Else a neighbour of the plain conversion that reads back as the same radians
        // (degrees · π/180 rounds, so the plain one can miss by an ulp), when there is one.
        let mut below = raw;
        let mut above = raw;
        for _ in 0..8 {
            below = below.next_down();
            above = above.next_up();
            for d in [below, above] {
                if d.to_radians() == self.radians {
                    return d;
                }
            }
        }
        raw
    }

    /// The angle a table row in degrees holds after this angle is written there and read
    /// back: itself when some number of degrees converts to exactly these radians (most
    /// angles), else the nearest angle that does. Poses made in radians (the cue's
    /// limiter) take it, so that what a command checks is what the file it writes gives.
    pub fn as_written(self) -> Angle {
        Angle::from_degrees(self.degrees())
    }

    /// Sine and cosine of the angle.
    #[inline]
    pub fn sin_cos(self) -> (f64, f64) {
        self.radians.sin_cos()
    }

    /// Whether the angle is a finite number.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.radians.is_finite()
    }
}

impl Add for Angle {
    type Output = Angle;
    fn add(self, rhs: Angle) -> Angle {
        Angle::from_radians(self.radians + rhs.radians)
    }
}

impl Sub for Angle {
    type Output = Angle;
    fn sub(self, rhs: Angle) -> Angle {
        Angle::from_radians(self.radians - rhs.radians)
    }
}

impl Neg for Angle {
    type Output = Angle;
    fn neg(self) -> Angle {
        Angle::from_radians(-self.radians)
    }
}

impl Mul<f64> for Angle {
    type Output = Angle;
    fn mul(self, rhs: f64) -> Angle {
        Angle::from_radians(self.radians * rhs)
    }
}

impl fmt::Display for Angle {
    /// Angles are shown to people in degrees, with the unit.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match f.precision() {
            Some(p) => write!(f, "{:.*}°", p, self.degrees()),
            None => write!(f, "{}°", self.degrees()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn degrees_read_back_as_written() {
        for d in [60.0, 30.0, 120.0, 12.3, 0.1, -45.5, 359.999, 1e-7, 3600.0] {
            assert_eq!(Angle::from_degrees(d).degrees(), d);
        }
        // An angle that is no short decimal keeps every bit.
        let a = Angle::from_radians(1.0);
        assert_eq!(a.degrees().to_radians(), 1.0);
    }

    #[test]
    fn an_angle_as_written_reads_back_to_the_bit() {
        // Random radians (a xorshift): written in degrees and read back, `as_written`
        // is a fixed point, and the plain angle is kept whenever degrees can hold it.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut kept = 0;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let r = (x >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0;
            let a = Angle::from_radians(r);
            let w = a.as_written();
            assert_eq!(
                Angle::from_degrees(w.degrees()).radians().to_bits(),
                w.radians().to_bits()
            );
            assert!((w.radians() - r).abs() <= 4.0 * f64::EPSILON * r.abs().max(1e-300));
            if w == a {
                kept += 1;
            }
        }
        // Most angles are some number of degrees exactly.
        assert!(kept > 90_000, "{kept}");
    }

    #[test]
    fn degrees_and_radians_agree_on_known_values() {
        assert_eq!(Angle::from_degrees(180.0).radians(), PI);
        assert_eq!(Angle::from_degrees(90.0).radians(), PI / 2.0);
        // The seed's pitch phase is π/4; written as 45° in files it must be the same double.
        assert_eq!(Angle::from_degrees(45.0).radians(), PI / 4.0);
        assert_eq!(Angle::from_radians(PI).degrees(), 180.0);
    }

    #[test]
    fn arithmetic_keeps_units() {
        let a = Angle::from_degrees(30.0) + Angle::from_degrees(60.0);
        assert!((a.degrees() - 90.0).abs() < 1e-12);
        assert!(((-a).degrees() + 90.0).abs() < 1e-12);
        assert!(((a * 2.0).degrees() - 180.0).abs() < 1e-12);
        assert_eq!(format!("{:.1}", Angle::from_degrees(12.5)), "12.5°");
    }
}
