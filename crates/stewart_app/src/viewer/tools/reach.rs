//! Reach at the pose shown, for the Orientation reach panel and the manual-pose sliders:
//! each pose coordinate's reachable interval alone, and the roll–pitch reach map. Cached
//! by what they depend on, so a still pose costs nothing and a moving one a few thousand
//! inverse solutions a frame.

use stewart_kinematics::analysis::certified::free::{Search, free_range};
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::analysis::workspace::ReachMap;
use stewart_kinematics::{Angle, Geometry, Pose, model::limits::Limits};

/// Roll, pitch and yaw are searched over ± this many degrees.
pub(crate) const ANGLE_SPAN_DEG: f64 = 90.0;
/// The roll–pitch map covers ± this many degrees.
pub(crate) const MAP_SPAN_DEG: f64 = 45.0;
/// Cells a side of the roll–pitch map (odd: one cell sits on level).
pub(crate) const MAP_CELLS: usize = 41;
/// Steps of the outward search across a coordinate's bounds.
const STEPS: usize = 120;
/// Boxes the proof of a slider's singularity-free range may test.
const FREE_BOXES: usize = 600;

/// Reach around the pose at its position: roll, pitch and yaw alone (radians), and the
/// roll–pitch map at its yaw.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct OrientationReach {
    /// Roll, pitch, yaw intervals; `None` when the pose is out of reach.
    pub(crate) angles: [Option<[f64; 2]>; 3],
    /// The map.
    pub(crate) map: ReachMap,
}

/// What a reach was computed for.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    geometry: Geometry,
    limits: Limits,
    pose: Pose,
    bounds: [[f64; 2]; 6],
}

/// The cached answers.
#[derive(Clone, Debug, Default)]
pub(crate) struct ReachCache {
    sliders: Option<(Key, [Option<[f64; 2]>; 6])>,
    free: Option<(Key, [Option<[f64; 2]>; 6])>,
    orientation: Option<(Key, OrientationReach)>,
}

impl ReachCache {
    /// Each coordinate's reachable interval within its slider's `bounds` (pose
    /// coordinates: metres and radians).
    pub(crate) fn sliders(
        &mut self,
        geometry: &Geometry,
        limits: &Limits,
        pose: &Pose,
        bounds: [[f64; 2]; 6],
    ) -> [Option<[f64; 2]>; 6] {
        let key = Key {
            geometry: geometry.clone(),
            limits: *limits,
            pose: *pose,
            bounds,
        };
        if let Some((k, ranges)) = &self.sliders
            && *k == key
        {
            return *ranges;
        }
        let ranges = std::array::from_fn(|k| {
            workspace::coordinate_range(geometry, limits, pose, k, bounds[k], STEPS)
        });
        self.sliders = Some((key, ranges));
        ranges
    }

    /// Each coordinate's range about the pose proven free of singularity (the others
    /// held), within its slider's `bounds`: `None` where not even the pose is proven
    /// regular (servos: also every servo away from the edge of its reach). A few hundred
    /// boxes a coordinate, a
    /// millisecond or so, when the pose or the scenario changes.
    pub(crate) fn certified(
        &mut self,
        geometry: &Geometry,
        pose: &Pose,
        bounds: [[f64; 2]; 6],
    ) -> [Option<[f64; 2]>; 6] {
        let key = Key {
            geometry: geometry.clone(),
            limits: Limits::default(),
            pose: *pose,
            bounds,
        };
        if let Some((k, ranges)) = &self.free
            && *k == key
        {
            return *ranges;
        }
        let c = pose.to_coordinates();
        let never = || false;
        let ranges = std::array::from_fn(|k| {
            let reach = (c[k] - bounds[k][0]).abs().max((bounds[k][1] - c[k]).abs());
            let search = Search {
                budget: FREE_BOXES,
                stop: &never,
            };
            let range = free_range(geometry, pose, k, reach, search);
            range
                .interval
                .map(|[lo, hi]| [lo.max(bounds[k][0]), hi.min(bounds[k][1])])
        });
        self.free = Some((key, ranges));
        ranges
    }

    /// Roll, pitch and yaw alone over ±[`ANGLE_SPAN_DEG`] and the roll–pitch map.
    pub(crate) fn orientation(
        &mut self,
        geometry: &Geometry,
        limits: &Limits,
        pose: &Pose,
    ) -> &OrientationReach {
        let span = ANGLE_SPAN_DEG.to_radians();
        let key = Key {
            geometry: geometry.clone(),
            limits: *limits,
            pose: *pose,
            bounds: [[-span, span]; 6],
        };
        if self.orientation.as_ref().is_some_and(|(k, _)| *k != key) {
            self.orientation = None;
        }
        &self
            .orientation
            .get_or_insert_with(|| {
                let reach = OrientationReach {
                    angles: std::array::from_fn(|a| {
                        let c = pose.to_coordinates()[3 + a];
                        // Around the pose's own angle, as far as the span either side.
                        workspace::coordinate_range(
                            geometry,
                            limits,
                            pose,
                            3 + a,
                            [c - span, c + span],
                            STEPS,
                        )
                    }),
                    map: workspace::roll_pitch_map(
                        geometry,
                        limits,
                        pose,
                        Angle::from_degrees(MAP_SPAN_DEG),
                        MAP_CELLS,
                    ),
                };
                (key, reach)
            })
            .1
    }
}

#[cfg(test)]
mod certified_tests {
    use super::ReachCache;
    use stewart_kinematics::Scenario;

    #[test]
    fn the_yaw_slider_shows_the_range_proven_free_up_to_fichters_ninety_degrees() {
        let s = Scenario::preset("paired").expect("preset");
        let g = &s.geometry;
        let home = g.home_pose();
        let c = home.to_coordinates();
        let wide = 2.0_f64;
        let bounds = std::array::from_fn(|k| [c[k] - wide, c[k] + wide]);
        let mut cache = ReachCache::default();
        let free = cache.certified(g, &home, bounds);
        let [lo, hi] = free[5].expect("home is regular").map(f64::to_degrees);
        assert!(
            (-90.0..-89.0).contains(&lo) && (89.0..90.0).contains(&hi),
            "{lo} {hi}"
        );
        // Asked again for the same pose: the cached answer.
        assert_eq!(cache.certified(g, &home, bounds), free);
        // The seed: nothing.
        let s = Scenario::preset("seed").expect("preset");
        let home = s.geometry.home_pose();
        assert!(
            cache
                .certified(&s.geometry, &home, bounds)
                .iter()
                .all(Option::is_none)
        );
        // A servo desk: its yaw to where its servo Jacobian fails (±56.02°).
        let s = Scenario::preset("servo-desk").expect("preset");
        let home = s.geometry.home_pose();
        let free = cache.certified(&s.geometry, &home, bounds);
        let [lo, hi] = free[5].expect("home is regular").map(f64::to_degrees);
        assert!(
            (lo + 56.018).abs() < 1e-3 && (hi - 56.018).abs() < 1e-3,
            "{lo} {hi}"
        );
    }
}
