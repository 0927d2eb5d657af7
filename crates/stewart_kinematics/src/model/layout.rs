//! Named joint layouts: where the twelve joints sit on their circles.

use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;

/// A named arrangement of the six base joints and six platform joints.
///
/// Leg `i` runs from base joint `i` to platform joint `i`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Layout {
    /// The seed's layout: both plates carry regular hexagons (joints every 60°), the
    /// platform's turned by `offset` (30° in the seed). Note: any two regular hexagons
    /// related by a rotation and a scale are architecturally singular.
    Staggered {
        /// Rotation of the platform hexagon relative to the base hexagon, degrees.
        offset_deg: f64,
    },
    /// The layout most real platforms use: joints in three pairs on each plate. Base
    /// pairs are centred at 0°, 120°, 240°; platform pairs at 60°, 180°, 300°; each
    /// leg runs from one base pair to the neighbouring platform pair, so the legs form
    /// the familiar zig-zag.
    Paired {
        /// Angle between the two joints of a base pair, degrees.
        base_separation_deg: f64,
        /// Angle between the two joints of a platform pair, degrees.
        platform_separation_deg: f64,
    },
}

impl Layout {
    /// The seed's layout: base joints at 0°, 60°, …, 300°, platform joints at 30°, 90°, …, 330°.
    pub fn seed() -> Self {
        Layout::Staggered { offset_deg: 30.0 }
    }

    /// A paired layout with the same separation (degrees) on both plates.
    pub fn paired(separation_deg: f64) -> Self {
        Layout::Paired {
            base_separation_deg: separation_deg,
            platform_separation_deg: separation_deg,
        }
    }

    /// Base and platform joint angles in degrees, leg by leg (whole-degree layouts give
    /// exact values: 0, 60, 120, … rather than rounded radians).
    pub fn angles_deg(&self) -> ([f64; 6], [f64; 6]) {
        match *self {
            Layout::Staggered { offset_deg: off } => {
                let base = std::array::from_fn(|i| 60.0 * i as f64);
                let platform = std::array::from_fn(|i| off + 60.0 * i as f64);
                (base, platform)
            }
            Layout::Paired {
                base_separation_deg,
                platform_separation_deg,
            } => {
                let hb = base_separation_deg / 2.0;
                let hp = platform_separation_deg / 2.0;
                let mut base = [0.0; 6];
                let mut platform = [0.0; 6];
                for k in 0..3 {
                    let base_centre = 120.0 * k as f64;
                    let platform_centre = base_centre + 60.0;
                    // Leg 2k leaves base pair k on its counter-clockwise side and meets
                    // platform pair k on its clockwise side; leg 2k+1 the mirror image.
                    base[2 * k] = base_centre + hb;
                    platform[2 * k] = platform_centre - hp;
                    base[2 * k + 1] = base_centre + 120.0 - hb;
                    platform[2 * k + 1] = platform_centre + hp;
                }
                (base, platform)
            }
        }
    }

    /// The named layout these joint angles follow (to 1e-9°), if any.
    pub fn recognise(base: &[Angle; 6], platform: &[Angle; 6]) -> Option<Layout> {
        let (b0, p0) = (base[0].degrees(), platform[0].degrees());
        let candidates = [
            Layout::Staggered {
                offset_deg: p0 - b0,
            },
            Layout::Paired {
                base_separation_deg: 2.0 * b0,
                platform_separation_deg: 2.0 * (60.0 - p0),
            },
        ];
        let same = |a: &[f64; 6], b: &[Angle; 6]| {
            a.iter().zip(b).all(|(x, y)| (x - y.degrees()).abs() < 1e-9)
        };
        candidates.into_iter().find(|c| {
            let (cb, cp) = c.angles_deg();
            same(&cb, base) && same(&cp, platform)
        })
    }

    /// Base and platform joint angles as [`Angle`]s.
    pub fn angles(&self) -> ([Angle; 6], [Angle; 6]) {
        let (b, p) = self.angles_deg();
        (b.map(Angle::from_degrees), p.map(Angle::from_degrees))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_are_recognised_from_their_angles() {
        for layout in [
            Layout::seed(),
            Layout::paired(20.0),
            Layout::Paired {
                base_separation_deg: 12.0,
                platform_separation_deg: 30.0,
            },
        ] {
            let (b, p) = layout.angles();
            let found = Layout::recognise(&b, &p).unwrap_or_else(|| panic!("{layout:?}"));
            let (fb, fp) = found.angles_deg();
            let (lb, lp) = layout.angles_deg();
            for k in 0..6 {
                assert!((fb[k] - lb[k]).abs() < 1e-9 && (fp[k] - lp[k]).abs() < 1e-9);
            }
        }
        let (mut b, p) = Layout::seed().angles();
        b[3] = Angle::from_degrees(185.0);
        assert_eq!(Layout::recognise(&b, &p), None);
    }

    #[test]
    fn seed_layout_matches_the_article() {
        let (b, p) = Layout::seed().angles_deg();
        assert_eq!(b, [0.0, 60.0, 120.0, 180.0, 240.0, 300.0]);
        assert_eq!(p, [30.0, 90.0, 150.0, 210.0, 270.0, 330.0]);
    }

    #[test]
    fn paired_layout_forms_three_pairs_on_each_plate() {
        let (b, p) = Layout::paired(20.0).angles_deg();
        assert_eq!(b, [10.0, 110.0, 130.0, 230.0, 250.0, 350.0]);
        assert_eq!(p, [50.0, 70.0, 170.0, 190.0, 290.0, 310.0]);
        // Each leg spans 40°–60° around the circle, alternating direction (zig-zag).
        for i in 0..6 {
            let d = p[i] - b[i];
            let expected = if i % 2 == 0 { 40.0 } else { -40.0 };
            assert_eq!(d, expected, "leg {}", i + 1);
        }
    }
}
