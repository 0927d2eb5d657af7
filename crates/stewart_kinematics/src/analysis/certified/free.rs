//! Certified singularity-free ranges about a pose: the widest interval of one coordinate
//! (the others held), or the widest ball of positions (the orientation held), over which
//! the inverse Jacobian is proven regular box by box.

use crate::ground::interval::Interval;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

use super::pose_box::{BoxLegs, PoseBox};
use super::regular::proven_regular;
use super::servos::BoxServos;

/// What a certification found and what it cost.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeRange {
    /// The certified range of the coordinate (metres or radians), `None` when not even the
    /// pose itself is proven regular.
    pub interval: Option<[f64; 2]>,
    /// Boxes tested.
    pub boxes: usize,
    /// Whether the box budget or a stop request ended the search before its tolerance.
    pub cut_short: bool,
}

/// A certified ball of positions.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeBall {
    /// Its radius, metres (`None`: not even the pose itself is proven regular).
    pub radius: Option<f64>,
    /// Boxes tested.
    pub boxes: usize,
    /// Whether the box budget or a stop request ended the search early.
    pub cut_short: bool,
}

/// How far and how finely to search, and when to stop.
#[derive(Clone, Copy)]
pub struct Search<'a> {
    /// The most boxes to test.
    pub budget: usize,
    /// Asked between boxes: `true` ends the search with what is certified so far.
    pub stop: &'a (dyn Fn() -> bool + Sync),
}

/// Whether every pose of `b` is proven away from singularity — for a rotary platform, also
/// every servo away from the edge of its reach (horn and rod in line), where its angle's
/// rate runs away.
pub fn proven_free(geometry: &Geometry, b: &PoseBox) -> bool {
    let legs = BoxLegs::of(geometry, b);
    let length = geometry.characteristic_length();
    match geometry.rotary() {
        None => proven_regular(&legs.jacobian(length)),
        Some(servos) => BoxServos::of(servos, geometry.base_joints(), &legs)
            .jacobian(&legs, length)
            .is_some_and(|j| proven_regular(&j)),
    }
}

/// The widest range of coordinate `k` (0…5: x, y, z in metres, roll, pitch, yaw in
/// radians) about `pose`'s, within `reach` of it on each side, over which every pose is
/// proven regular; the two sides are searched on two threads.
pub fn free_range(
    geometry: &Geometry,
    pose: &Pose,
    k: usize,
    reach: f64,
    search: Search,
) -> FreeRange {
    // A reach that is no finite distance searches nothing beyond the pose.
    let reach = if reach.is_finite() { reach.abs() } else { 0.0 };
    let at = PoseBox::at(pose);
    if !proven_free(geometry, &at) {
        return FreeRange {
            interval: None,
            boxes: 1,
            cut_short: false,
        };
    }
    let v = at.coordinates[k].mid();
    let tolerance = if k < 3 {
        1e-7 * geometry.characteristic_length()
    } else {
        1e-7
    };
    let half = Search {
        budget: search.budget / 2,
        stop: search.stop,
    };
    let side = |direction: f64| march(geometry, &at, k, v, v + direction * reach, tolerance, half);
    let ((lo, a, cut_a), (hi, b, cut_b)) = rayon::join(|| side(-1.0), || side(1.0));
    FreeRange {
        interval: Some([lo, hi]),
        boxes: 1 + a + b,
        cut_short: cut_a || cut_b,
    }
}

/// From `from` towards `to` along coordinate `k`, steps proven one after another, each
/// doubled after a proof and halved after a failure until below `tolerance`: how far the
/// proofs reach, the boxes tested, and whether the budget or a stop cut it short.
fn march(
    geometry: &Geometry,
    at: &PoseBox,
    k: usize,
    from: f64,
    to: f64,
    tolerance: f64,
    search: Search,
) -> (f64, usize, bool) {
    let direction = (to - from).signum();
    let mut reached = from;
    let mut step = (to - from).abs() / 16.0;
    let mut boxes = 0;
    while (to - reached) * direction > 0.0 {
        if boxes >= search.budget || (search.stop)() {
            return (reached, boxes, true);
        }
        let next = if direction > 0.0 {
            (reached + step).min(to)
        } else {
            (reached - step).max(to)
        };
        let range = Interval::new(reached.min(next), reached.max(next)).unwrap_or(Interval::ENTIRE);
        boxes += 1;
        if proven_free(geometry, &at.with(k, range)) {
            reached = next;
            step *= 2.0;
        } else {
            step /= 2.0;
            if step < tolerance {
                break;
            }
        }
    }
    (reached, boxes, false)
}

/// The widest ball of positions about `pose`'s (its orientation held), of radius at most
/// `reach`, proven regular: the cube about it is proven box by box, its half-side found by
/// doubling, then by bisection to a thousandth.
pub fn free_ball(geometry: &Geometry, pose: &Pose, reach: f64, search: Search) -> FreeBall {
    // A reach that is no finite distance searches nothing beyond the pose.
    let reach = if reach.is_finite() { reach.abs() } else { 0.0 };
    let at = PoseBox::at(pose);
    let mut boxes = 1;
    if !proven_free(geometry, &at) {
        return FreeBall {
            radius: None,
            boxes,
            cut_short: false,
        };
    }
    let mut good = 0.0;
    let mut bad = None;
    let mut r = reach / 64.0;
    let mut cut_short = false;
    for _ in 0..40 {
        if let Some(b) = bad
            && b - good < 1e-3 * b
        {
            break;
        }
        match proven_cube(geometry, &at, r, search, &mut boxes) {
            Some(true) => good = r,
            Some(false) => bad = Some(r),
            None => {
                cut_short = true;
                break;
            }
        }
        r = match bad {
            None if good >= reach => break,
            None => (2.0 * r).min(reach),
            Some(b) => 0.5 * (good + b),
        };
    }
    FreeBall {
        radius: Some(good),
        boxes,
        cut_short,
    }
}

/// Whether the cube of half-side `r` about `at`'s position is proven regular, splitting
/// boxes down to a 64th of `r`; `None` when the budget or a stop ends it first.
fn proven_cube(
    geometry: &Geometry,
    at: &PoseBox,
    r: f64,
    search: Search,
    boxes: &mut usize,
) -> Option<bool> {
    let mut cube = *at;
    for k in 0..3 {
        cube.coordinates[k] = Interval::around(at.coordinates[k].mid(), r);
    }
    let smallest = r / 64.0;
    let mut queue = vec![cube];
    while let Some(b) = queue.pop() {
        if *boxes >= search.budget || (search.stop)() {
            return None;
        }
        *boxes += 1;
        if proven_free(geometry, &b) {
            continue;
        }
        let k = b.widest(1.0);
        if b.coordinates[k].width() < smallest {
            return Some(false);
        }
        queue.extend(b.split(k));
    }
    Some(true)
}
