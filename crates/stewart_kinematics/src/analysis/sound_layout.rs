//! The way out of an architecture singularity: the paired layout nearest a geometry's
//! joint angles whose legs do determine the pose, and condition it well.
//!
//! Any two regular hexagons related by a rotation and a scale are singular everywhere
//! (see [`crate::analysis::architecture`]); the usual remedy is to group each plate's joints in
//! three pairs. Among paired layouts (separations from 5° to 115° on each plate, in 5°
//! steps) this picks the one whose twelve joint angles move least from the present ones
//! (the largest single move, in degrees), of those that are not architecturally singular
//! and whose normalised Jacobian at home is at least [`MIN_INVERSE_CONDITION`].

use crate::analysis::architecture;
use crate::model::geometry::{Geometry, GeometryParams, Plate, PlateJoints};
use crate::model::layout::Layout;

/// The smallest inverse condition number at home a proposed layout must have (the
/// paired preset's is about 0.3; below 0.1 the legs barely hold some twist).
pub const MIN_INVERSE_CONDITION: f64 = 0.1;

/// A layout that removes the singularity, and what it changes.
#[derive(Clone, Debug)]
pub struct SoundLayout {
    /// The layout.
    pub layout: Layout,
    /// The geometry with that layout (radii, heights and actuators unchanged).
    pub geometry: Geometry,
    /// The largest move of one joint's angle, degrees.
    pub moved_deg: f64,
    /// Inverse condition number at home.
    pub inverse_condition: f64,
}

/// The difference of two angles in degrees, wrapped to [0°, 180°].
fn angle_between(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

/// This geometry's parameters with its joints on circles at `layout`'s angles (the
/// plates' radii kept; a plate given as coordinates goes back to a circle of its size).
pub fn params_with_layout(geometry: &Geometry, layout: Layout) -> GeometryParams {
    let mut params = geometry.params().clone();
    let (base, platform) = layout.angles();
    params.base = PlateJoints::Circle {
        radius: geometry.plate_radius(Plate::Base),
        angles: base,
    };
    params.platform = PlateJoints::Circle {
        radius: geometry.plate_radius(Plate::Platform),
        angles: platform,
    };
    params
}

/// This geometry with `layout` (see [`params_with_layout`]), or `None` when
/// that geometry is refused.
pub fn with_layout(geometry: &Geometry, layout: Layout) -> Option<Geometry> {
    Geometry::new(params_with_layout(geometry, layout)).ok()
}

/// The nearest paired layout that is not architecturally singular (see the module's
/// documentation), or `None` when no candidate qualifies.
pub fn nearest_sound_layout(geometry: &Geometry) -> Option<SoundLayout> {
    let angles = |g: &Geometry, plate: Plate| -> [f64; 6] {
        g.joints(plate).map(|j| j.y.atan2(j.x).to_degrees())
    };
    let (base, platform) = (
        angles(geometry, Plate::Base),
        angles(geometry, Plate::Platform),
    );
    let mut best: Option<SoundLayout> = None;
    let separations = (1..=23).map(|k| 5.0 * f64::from(k));
    for b in separations.clone() {
        for p in separations.clone() {
            let layout = Layout::Paired {
                base_separation_deg: b,
                platform_separation_deg: p,
            };
            let (lb, lp) = layout.angles_deg();
            let moved_deg = (0..6)
                .map(|i| angle_between(lb[i], base[i]).max(angle_between(lp[i], platform[i])))
                .fold(0.0, f64::max);
            if best
                .as_ref()
                .is_some_and(|s| s.moved_deg < moved_deg - 1e-9)
            {
                continue;
            }
            let Some(geometry) = with_layout(geometry, layout) else {
                continue;
            };
            let report = architecture::architecture(&geometry);
            let inverse_condition = report.home.inverse_condition();
            let conditioned =
                inverse_condition.is_finite() && inverse_condition >= MIN_INVERSE_CONDITION;
            if report.singular || !conditioned {
                continue;
            }
            let better = best.as_ref().is_none_or(|s| {
                moved_deg < s.moved_deg - 1e-9
                    || (moved_deg < s.moved_deg + 1e-9 && inverse_condition > s.inverse_condition)
            });
            if better {
                best = Some(SoundLayout {
                    layout,
                    geometry,
                    moved_deg,
                    inverse_condition,
                });
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_seed_has_a_nearby_paired_layout_that_is_not_singular() {
        let seed = Geometry::seed();
        assert!(architecture::architecture(&seed).singular);
        let found = nearest_sound_layout(&seed).unwrap_or_else(|| panic!("no layout"));
        // Base joints on the regular hexagon turned 30°, platform joints in three close
        // pairs (a 6-3-like platform): every joint moves at most 30°.
        assert_eq!(
            found.layout,
            Layout::Paired {
                base_separation_deg: 60.0,
                platform_separation_deg: 115.0
            }
        );
        assert!((found.moved_deg - 30.0).abs() < 1e-9, "{}", found.moved_deg);
        let report = architecture::architecture(&found.geometry);
        assert!(!report.singular);
        assert!(report.home.inverse_condition() >= MIN_INVERSE_CONDITION);
    }
}

#[cfg(test)]
mod more_tests {
    use super::*;

    #[test]
    fn moves_are_measured_around_the_circle() {
        assert!((angle_between(350.0, 10.0) - 20.0).abs() < 1e-12);
        assert!((angle_between(-170.0, 170.0) - 20.0).abs() < 1e-12);
        assert_eq!(angle_between(90.0, 90.0), 0.0);
    }

    #[test]
    fn a_sound_paired_geometry_is_its_own_nearest() {
        let g = crate::io::scenario::Scenario::preset("paired")
            .unwrap_or_else(|e| panic!("{e}"))
            .geometry;
        let found = nearest_sound_layout(&g).unwrap_or_else(|| panic!("no layout"));
        assert!(found.moved_deg < 1e-9, "{found:?}");
        assert_eq!(g.params().base, found.geometry.params().base);
    }
}
