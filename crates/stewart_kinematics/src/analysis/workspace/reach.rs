//! Reach at one pose: how far each pose coordinate can move alone before a limit is hit,
//! and which roll–pitch pairs are reachable at the pose's position and yaw (a reach map).

use crate::analysis::workspace;
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// Which roll–pitch pairs are reachable, on a square grid centred on level.
#[derive(Clone, Debug, PartialEq)]
pub struct ReachMap {
    /// Half the side: roll and pitch run from −span to +span.
    pub span: Angle,
    /// Cells a side.
    pub cells: usize,
    /// Reachable or not, row by row from the lowest pitch; within a row by roll.
    pub reachable: Vec<bool>,
}

impl ReachMap {
    /// Roll and pitch at the centre of cell (`i` across, `j` up).
    pub fn angles(&self, i: usize, j: usize) -> [Angle; 2] {
        let at = |k: usize| {
            let s = self.span.radians();
            Angle::from_radians(-s + (k as f64 + 0.5) * 2.0 * s / self.cells as f64)
        };
        [at(i), at(j)]
    }

    /// Whether cell (`i`, `j`) is reachable.
    pub fn get(&self, i: usize, j: usize) -> bool {
        self.reachable[j * self.cells + i]
    }
}

/// The most cells a side of a reach map.
pub const MAX_REACH_CELLS: usize = 512;

/// The interval of pose coordinate `k` (`Pose::to_coordinates` order: x, y, z in
/// metres, roll, pitch, yaw in radians) around the pose's own value, within `bounds`,
/// over which the pose changed in that coordinate alone stays within the stroke and
/// `limits`: searched outward in `steps` steps across `bounds` and each edge refined by
/// bisection to 1e-9 of the bounds' width. `None` when the pose itself is out of reach
/// or the question is malformed (a coordinate index past 5, bounds not finite or empty,
/// a value outside them, no steps).
pub fn coordinate_range(
    geometry: &Geometry,
    limits: &Limits,
    pose: &Pose,
    k: usize,
    bounds: [f64; 2],
    steps: usize,
) -> Option<[f64; 2]> {
    let start = pose.to_coordinates();
    let centre = *start.get(k)?;
    let [lo, hi] = bounds;
    let sound = lo.is_finite() && hi.is_finite() && lo < hi && steps > 0;
    if !sound || !(lo..=hi).contains(&centre) {
        return None;
    }
    let within = |v: f64| {
        let mut c = start;
        c[k] = v;
        workspace::pose_within_limits(geometry, limits, &Pose::from_coordinates(c))
    };
    if !within(centre) {
        return None;
    }
    let step = (hi - lo) / steps as f64;
    let tolerance = 1e-9 * (hi - lo);
    let edge = |end: f64| {
        let direction = (end - centre).signum();
        let mut inside = centre;
        loop {
            let next = inside + direction * step;
            if (next - end) * direction >= 0.0 {
                // The last step reaches the bound.
                if within(end) {
                    return end;
                }
                return bisect(&within, inside, end, tolerance);
            }
            if !within(next) {
                return bisect(&within, inside, next, tolerance);
            }
            inside = next;
        }
    };
    Some([edge(lo), edge(hi)])
}

/// Which roll–pitch pairs on a `cells × cells` grid over ±`span` keep the pose's
/// position and yaw within the stroke and `limits` (cells clamped to
/// 2 ..= [`MAX_REACH_CELLS`]).
pub fn roll_pitch_map(
    geometry: &Geometry,
    limits: &Limits,
    pose: &Pose,
    span: Angle,
    cells: usize,
) -> ReachMap {
    let cells = cells.clamp(2, MAX_REACH_CELLS);
    let mut map = ReachMap {
        span,
        cells,
        reachable: Vec::with_capacity(cells * cells),
    };
    for j in 0..cells {
        for i in 0..cells {
            let [roll, pitch] = map.angles(i, j);
            let p = Pose::new(pose.position, roll, pitch, pose.yaw);
            map.reachable
                .push(workspace::pose_within_limits(geometry, limits, &p));
        }
    }
    map
}

/// The last value still inside between `inside` (reachable) and `outside` (not), to
/// `tolerance`.
fn bisect(within: &impl Fn(f64) -> bool, mut inside: f64, mut outside: f64, tolerance: f64) -> f64 {
    while (outside - inside).abs() > tolerance {
        let mid = 0.5 * (inside + outside);
        if within(mid) {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::workspace::Axis;
    use crate::io::scenario::Scenario;

    fn paired() -> Scenario {
        Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn angle_ranges_agree_with_the_orientation_search() {
        let s = paired();
        let pose = Pose::from_xyz_rpy_deg([0.05, -0.03, 0.85], [3.0, -2.0, 10.0]);
        for (k, axis) in [(3, Axis::Roll), (4, Axis::Pitch), (5, Axis::Yaw)] {
            let wide = std::f64::consts::FRAC_PI_2;
            let ours = coordinate_range(&s.geometry, &s.limits, &pose, k, [-wide, wide], 180)
                .unwrap_or_else(|| panic!("{axis:?} out of reach"));
            let theirs = workspace::orientation_range(
                &s.geometry,
                &s.limits,
                &pose,
                axis,
                Angle::from_degrees(200.0),
                Angle::from_degrees(0.5),
            )
            .unwrap_or_else(|| panic!("{axis:?}"));
            for e in 0..2 {
                let t = theirs[e].radians();
                if t.abs() < wide - 1e-6 {
                    assert!(
                        (ours[e] - t).abs() < 1e-6,
                        "{axis:?}: {ours:?} vs {theirs:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_height_range_ends_where_a_leg_reaches_its_stroke() {
        // Level at the centre, legs are equal: z rises until every leg is at its maximum.
        let s = paired();
        let g = &s.geometry;
        let pose = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0; 3]);
        // The stroke alone (the preset's joint-cone limits stop it lower down sooner).
        let [lo, hi] = coordinate_range(g, &Limits::default(), &pose, 2, [0.0, 2.0], 200)
            .unwrap_or_else(|| panic!("home out of reach"));
        let stroke = g.stroke();
        let (min, max) = (stroke.min.unwrap_or(0.0), stroke.max.unwrap_or(0.0));
        let at = |z: f64| {
            g.inverse(&Pose::from_xyz_rpy_deg([0.0, 0.0, z], [0.0; 3]))
                .lengths
        };
        let shortest = at(lo).iter().copied().fold(f64::INFINITY, f64::min);
        let longest = at(hi).iter().copied().fold(f64::NEG_INFINITY, f64::max);
        // Down to the base plane the legs stay longer than their minimum (the plates'
        // radii differ by 0.4 m): the range runs to the bound.
        assert_eq!(lo, 0.0);
        assert!(shortest > min, "{shortest} at z {lo}");
        assert!((longest - max).abs() < 1e-6, "{longest} at z {hi}");
    }

    #[test]
    fn a_range_stops_at_its_bounds_and_refuses_bad_questions() {
        let s = paired();
        let g = &s.geometry;
        let pose = g.home_pose();
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 0, [-0.01, 0.01], 10),
            Some([-0.01, 0.01])
        );
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 6, [-1.0, 1.0], 10),
            None
        );
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 0, [1.0, -1.0], 10),
            None
        );
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 0, [f64::NAN, 1.0], 10),
            None
        );
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 0, [-1.0, 1.0], 0),
            None
        );
        assert_eq!(
            coordinate_range(g, &s.limits, &pose, 0, [0.5, 1.0], 10),
            None
        );
        let away = Pose::from_xyz_rpy_deg([0.0, 0.0, 3.0], [0.0; 3]);
        assert_eq!(
            coordinate_range(g, &s.limits, &away, 2, [0.0, 4.0], 10),
            None
        );
    }

    #[test]
    fn the_roll_pitch_map_agrees_with_the_single_angle_ranges() {
        let s = paired();
        let g = &s.geometry;
        let pose = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.9], [0.0, 0.0, 0.0]);
        // An even count puts no cell on zero pitch: use the row just above and compare with
        // the roll range at that pitch.
        let map = roll_pitch_map(g, &s.limits, &pose, Angle::from_degrees(45.0), 60);
        let j = 30;
        let [_, pitch] = map.angles(0, j);
        let at = Pose::new(pose.position, Angle::ZERO, pitch, pose.yaw);
        let half = std::f64::consts::FRAC_PI_2;
        let [lo, hi] = coordinate_range(g, &s.limits, &at, 3, [-half, half], 180)
            .unwrap_or_else(|| panic!("out of reach"));
        for i in 0..map.cells {
            let roll = map.angles(i, j)[0].radians();
            if (roll - lo).abs() > 1e-9 && (roll - hi).abs() > 1e-9 {
                assert_eq!(map.get(i, j), roll > lo && roll < hi, "roll {roll}");
            }
        }
        let count = map.reachable.iter().filter(|&&r| r).count();
        assert!(count > 100 && count < map.cells * map.cells, "{count}");
    }
}
