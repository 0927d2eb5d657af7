//! The certified constant-orientation workspace: boxes of positions classed, by interval
//! arithmetic, *inner* (every position of the box is reachable: the stroke, the joint
//! cones and the legs' clearance hold, above the base plane), *outer* (none is) or
//! *boundary* (undecided at the finest width asked), by branch and bound. The volume then
//! lies in `[inner, inner + boundary]` — a bracket, not an estimate.
//!
//! The clearance of two legs is bounded by its value at the box's centre and how far the
//! legs can move inside the box: with the orientation held, every point of a leg moves at
//! most as far as its platform joint, at most the box's half-diagonal, so two legs' distance
//! changes by at most twice that (a margin covers the centre's own rounding).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use nalgebra::Vector3;
use rayon::prelude::*;

use crate::ground::interval::Interval;
use crate::model::geometry::Geometry;
use crate::model::limits::{LEG_PAIRS, Limits, segment_distance};
use crate::model::pose::Pose;

use super::pose_box::{BoxLegs, IVec3, PoseBox};
use super::servos::{BoxServos, Reach};
use crate::analysis::checks::servos::rod_distances;
use crate::model::rotary::RotaryActuators;
use crate::solve::servo_closure;

/// What a box of positions is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BoxClass {
    /// Every position reachable.
    Inner,
    /// No position reachable.
    Outer,
    /// Undecided at the finest width.
    Boundary,
}

/// One classified box: its position intervals (x, y, z) and its class.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClassedBox {
    /// x, y, z, metres.
    pub position: [Interval; 3],
    /// Its class.
    pub class: BoxClass,
}

/// The certified workspace.
#[derive(Clone, Debug, PartialEq)]
pub struct CertifiedWorkspace {
    /// Volume of the inner boxes, m³: at most the workspace's volume.
    pub inner_m3: f64,
    /// Volume of the boundary boxes, m³: the workspace's volume is at most `inner_m3 +
    /// boundary_m3`.
    pub boundary_m3: f64,
    /// The inner and boundary boxes (outer ones are dropped), for slices and pictures.
    pub boxes: Vec<ClassedBox>,
    /// Boxes classified.
    pub tested: usize,
    /// Whether the box budget or a stop request ended it: the boxes not yet split count
    /// as boundary, so the bracket still holds.
    pub cut_short: bool,
}

/// What is asked.
#[derive(Clone, Copy)]
pub struct WorkspaceRequest<'a> {
    /// The orientation held (its position is ignored).
    pub orientation: &'a Pose,
    /// Boxes narrower than this (metres, on their widest side) are not split further.
    pub boundary_width: f64,
    /// The most boxes to classify.
    pub budget: usize,
    /// Asked now and then: `true` ends it with what is decided (the rest as boundary).
    pub stop: &'a (dyn Fn() -> bool + Sync),
}

/// The certified workspace of `geometry` under its stroke and `limits` at the request's
/// orientation. Needs both stroke limits (without them it is unbounded).
pub fn certified_workspace(
    geometry: &Geometry,
    limits: &Limits,
    request: &WorkspaceRequest,
) -> Option<CertifiedWorkspace> {
    let stroke = geometry.stroke();
    let (min, max) = match geometry.rotary() {
        // A joint within horn and rod of its shaft: the farthest any can be.
        Some(servos) => (0.0, servos.horn_length() + servos.rod_length()),
        None => (stroke.min?, stroke.max?),
    };
    let judge = Judge::new(
        geometry,
        limits,
        request.orientation,
        Interval::new(min, max).unwrap_or(Interval::ENTIRE),
    );
    // Breadth first, a level at a time on all cores: a run stopped early has classed the
    // whole region coarsely, so its bracket is already useful.
    let tested = AtomicUsize::new(0);
    let stopped = AtomicBool::new(false);
    let mut boxes: Vec<ClassedBox> = Vec::new();
    let mut frontier = vec![judge.start(max)];
    while !frontier.is_empty() {
        let level: Vec<Step> = frontier
            .par_iter()
            .map(|b| judge.step(b, request, &tested, &stopped))
            .collect();
        frontier = Vec::new();
        for step in level {
            match step {
                Step::Done(b) => boxes.push(b),
                Step::Split(halves) => frontier.extend(halves),
                Step::Dropped => {}
            }
        }
    }
    // Inner rounded down and boundary up, so that the bracket holds to the last bit.
    let volume = |class: BoxClass, round: fn(Interval) -> f64| {
        let mut sum = Interval::point(0.0);
        for b in boxes.iter().filter(|b| b.class == class) {
            let mut v = Interval::point(1.0);
            for side in &b.position {
                v = v * Interval::new(side.width_below(), side.width()).unwrap_or(Interval::ENTIRE);
            }
            sum = sum + v;
        }
        round(sum)
    };
    Some(CertifiedWorkspace {
        inner_m3: volume(BoxClass::Inner, |v| v.lo().max(0.0)),
        boundary_m3: volume(BoxClass::Boundary, |v| v.hi()),
        tested: tested.load(Ordering::Relaxed),
        cut_short: stopped.load(Ordering::Relaxed),
        boxes,
    })
}

/// A step above `x`, so that a bound computed in floating point stays a bound.
fn up(x: f64) -> f64 {
    x.next_up()
}

/// Half the diagonal of a position box: the farthest a point of it is from its centre.
fn half_diagonal(position: &[Interval; 3]) -> f64 {
    0.5 * (position[0].width().powi(2) + position[1].width().powi(2) + position[2].width().powi(2))
        .sqrt()
}

/// The widest side of a position box.
fn widest(b: &[Interval; 3]) -> usize {
    (0..3)
        .max_by(|&i, &j| b[i].width().total_cmp(&b[j].width()))
        .unwrap_or(0)
}

/// The two halves of a position box across side `k`.
fn split(b: &[Interval; 3], k: usize) -> [[Interval; 3]; 2] {
    let [lo, hi] = b[k].split();
    let mut a = *b;
    let mut c = *b;
    a[k] = lo;
    c[k] = hi;
    [a, c]
}

/// What became of one box of a level.
enum Step {
    /// Classed for good.
    Done(ClassedBox),
    /// Split for the next level.
    Split([[Interval; 3]; 2]),
    /// Outer: no position of it is reachable.
    Dropped,
}

/// The limits, ready to judge boxes.
struct Judge<'a> {
    geometry: &'a Geometry,
    stroke: Interval,
    /// The cosines of the base and platform cone limits, enclosed.
    cones: [Option<Interval>; 2],
    /// The least distance between two legs' axes.
    clearance: Option<f64>,
    orientation: Pose,
    /// Added to the clearance bound for the centre distance's rounding, metres.
    margin: f64,
}

/// The least distance between two legs (for servos: two rods, or a rod and another servo's
/// horn) over a box of positions at `orientation`'s, bounded below and above: the bound the
/// clearance limit is judged by.
#[cfg(test)]
pub(super) fn least_distance_bounds(
    geometry: &Geometry,
    orientation: &Pose,
    position: &[Interval; 3],
) -> Option<(f64, f64)> {
    let judge = Judge::new(geometry, &Limits::default(), orientation, Interval::ENTIRE);
    match geometry.rotary() {
        None => judge.clearance_bounds(position),
        Some(servos) => {
            let mut b = PoseBox::at(orientation);
            b.coordinates[..3].copy_from_slice(position);
            let legs = BoxLegs::of(geometry, &b);
            let over = BoxServos::of(servos, geometry.base_joints(), &legs);
            judge.rod_clearance_bounds(servos, position, &over)
        }
    }
}

impl<'a> Judge<'a> {
    /// The limits of `geometry` at `orientation`'s orientation, `stroke` the legs' (for
    /// servos, the joints' distance from their shafts that the search starts within).
    fn new(geometry: &'a Geometry, limits: &Limits, orientation: &Pose, stroke: Interval) -> Self {
        Judge {
            geometry,
            stroke,
            cones: [limits.base_cone, limits.platform_cone]
                .map(|a| a.map(|a| Interval::point(a.radians()).cos())),
            clearance: limits.leg_radius.map(|r| 2.0 * r),
            orientation: *orientation,
            margin: 1e-9 * geometry.characteristic_length(),
        }
    }

    /// A box holding every reachable position: within the longest leg of every base
    /// joint's shifted centre, above the base plane.
    fn start(&self, longest: f64) -> [Interval; 3] {
        let at = PoseBox::at(&self.orientation.with_position(Vector3::zeros()));
        let legs = BoxLegs::of(self.geometry, &at);
        // At position p leg i is p + legs_i(0): within `longest` of −legs_i(0).
        let mut lo = [f64::NEG_INFINITY; 3];
        let mut hi = [f64::INFINITY; 3];
        for l in &legs.legs {
            for k in 0..3 {
                let reach = -l[k] + Interval::new(-longest, longest).unwrap_or(Interval::ENTIRE);
                lo[k] = lo[k].max(reach.lo());
                hi[k] = hi[k].min(reach.hi());
            }
        }
        lo[2] = lo[2].max(0.0);
        std::array::from_fn(|k| Interval::new(lo[k], hi[k].max(lo[k])).unwrap_or(Interval::ENTIRE))
    }

    /// One box of a level: classed (kept when inner, or boundary at the finest width),
    /// dropped (outer), or split in two for the next level. Once the budget is spent or a
    /// stop was asked, every box left stays undecided: boundary, so the bracket holds.
    fn step(
        &self,
        b: &[Interval; 3],
        request: &WorkspaceRequest,
        tested: &AtomicUsize,
        stopped: &AtomicBool,
    ) -> Step {
        let boundary = ClassedBox {
            position: *b,
            class: BoxClass::Boundary,
        };
        if stopped.load(Ordering::Relaxed) {
            return Step::Done(boundary);
        }
        let spent = tested.fetch_add(1, Ordering::Relaxed) >= request.budget;
        if spent || (request.stop)() {
            stopped.store(true, Ordering::Relaxed);
            return Step::Done(boundary);
        }
        match self.class(b) {
            BoxClass::Outer => Step::Dropped,
            BoxClass::Boundary if b[widest(b)].width() > request.boundary_width => {
                Step::Split(split(b, widest(b)))
            }
            class => Step::Done(ClassedBox {
                position: *b,
                class,
            }),
        }
    }

    /// The class of a box of positions.
    fn class(&self, position: &[Interval; 3]) -> BoxClass {
        if position[2].hi() <= 0.0 {
            return BoxClass::Outer;
        }
        let mut b = PoseBox::at(&self.orientation);
        b.coordinates[..3].copy_from_slice(position);
        let legs = BoxLegs::of(self.geometry, &b);
        let verdict = match self.geometry.rotary() {
            None => self.legs_class(position, &b, &legs),
            Some(servos) => self.servos_class(servos, position, &b, &legs),
        };
        match verdict {
            Some(true) if position[2].lo() > 0.0 => BoxClass::Inner,
            Some(_) => BoxClass::Boundary,
            None => BoxClass::Outer,
        }
    }

    /// Linear legs over a box: `None` when no position of it is reachable, else whether
    /// every one is (the stroke, the cones, the clearance).
    fn legs_class(&self, position: &[Interval; 3], b: &PoseBox, legs: &BoxLegs) -> Option<bool> {
        let mut all = true;
        let lengths = legs.lengths();
        for length in lengths {
            if length.lo() > self.stroke.hi() || length.hi() < self.stroke.lo() {
                return None;
            }
            all &= length.within(&self.stroke);
        }
        let rods: [Option<(IVec3, Interval)>; 6] =
            std::array::from_fn(|i| Some((legs.legs[i], lengths[i])));
        all &= self.cones_hold(b, &rods)?;
        all &= self.clearance_holds(|| self.clearance_bounds(position))?;
        Some(all)
    }

    /// Rotary servos over a box: `None` when no position of it is reachable, else whether
    /// every one is (every servo closes its rod within its range; the rods' cones and
    /// clearance).
    fn servos_class(
        &self,
        servos: &RotaryActuators,
        position: &[Interval; 3],
        b: &PoseBox,
        legs: &BoxLegs,
    ) -> Option<bool> {
        let over = BoxServos::of(servos, self.geometry.base_joints(), legs);
        let mut all = true;
        // A servo's bounds hold at the poses of the box that reach it: the rest are out
        // anyway, so a bound broken everywhere it holds still rules the whole box out.
        for (reach, servo) in over.reach.iter().zip(&over.servos) {
            all &= *reach == Reach::Every;
            match (reach, servo) {
                (Reach::None, _) => return None,
                (_, Some(servo)) => {
                    if let Some((min, max)) = servos.range() {
                        let range =
                            Interval::new(min.radians(), max.radians()).unwrap_or(Interval::ENTIRE);
                        if servo.angle.hi() < range.lo() || servo.angle.lo() > range.hi() {
                            return None;
                        }
                        all &= servo.angle.within(&range);
                    }
                }
                (_, None) => all = false,
            }
        }
        // A rod is exactly its length wherever it closes.
        let s = Interval::point(servos.rod_length());
        let rods = over.servos.map(|servo| servo.map(|v| (v.rod, s)));
        all &= self.cones_hold(b, &rods)?;
        all &= self.clearance_holds(|| self.rod_clearance_bounds(servos, position, &over))?;
        Some(all)
    }

    /// The clearance limit against the least distance's `bounds` over a box (asked only
    /// when the limit is set): `None` when every position of the box collides, else
    /// whether none does.
    fn clearance_holds(&self, bounds: impl FnOnce() -> Option<(f64, f64)>) -> Option<bool> {
        let Some(clearance) = self.clearance else {
            return Some(true);
        };
        match bounds() {
            Some((lo, _)) if lo >= clearance => Some(true),
            Some((_, hi)) if hi < clearance => None,
            _ => Some(false),
        }
    }

    /// The cone limits on `rods` (each a vector from the base side to the platform joint
    /// and its length; `None`: not bounded): `None` when every position of the box breaks
    /// one, else whether every position keeps them all.
    fn cones_hold(&self, b: &PoseBox, rods: &[Option<(IVec3, Interval)>; 6]) -> Option<bool> {
        let rotation = b.rotation();
        let normals: [IVec3; 2] = [
            [
                Interval::point(0.0),
                Interval::point(0.0),
                Interval::point(1.0),
            ],
            [rotation[0][2], rotation[1][2], rotation[2][2]],
        ];
        let mut all = true;
        for (cone, n) in self.cones.iter().zip(&normals) {
            let Some(cos_max) = cone else { continue };
            for rod in rods {
                let Some((l, length)) = rod else {
                    all = false;
                    continue;
                };
                let along = l[0] * n[0] + l[1] * n[1] + l[2] * n[2];
                match along.div(length) {
                    Some(cos) if cos.hi() < cos_max.lo() => return None,
                    Some(cos) => all &= cos.lo() >= cos_max.hi(),
                    None => all = false,
                }
            }
        }
        Some(all)
    }

    /// The least distance between two rods, or a rod and another servo's horn, over the
    /// box: from the box's centre, less and more twice the farthest an end moves inside it
    /// (a platform joint at most the half-diagonal, a horn tip at most the horn times its
    /// angle's range), and the margin. `None` unless every servo's angle is bounded and
    /// the centre reached.
    fn rod_clearance_bounds(
        &self,
        servos: &RotaryActuators,
        position: &[Interval; 3],
        over: &BoxServos,
    ) -> Option<(f64, f64)> {
        // A horn tip moves at most the horn times its angle's change: at most the angle's
        // range, and, where every pose reaches with the transmission away from 0, at most
        // `s / min |d · h'|` per metre the joint moves (the angle's rate is
        // `d · δq / (d · h')` with `|d| = s`), the joint moving at most the half-diagonal.
        let (a, s) = (servos.horn_length(), servos.rod_length());
        let half = half_diagonal(position);
        let mut swing: f64 = 0.0;
        for (servo, reach) in over.servos.iter().zip(&over.reach) {
            let servo = (*servo)?;
            let mut turn = servo.angle.width();
            let least = servo.transmission.mig();
            if *reach == Reach::Every && least > 0.0 {
                turn = turn.min(up(s * half / least));
            }
            swing = swing.max(up(a * turn));
        }
        let centre = self.orientation.with_position(Vector3::new(
            position[0].mid(),
            position[1].mid(),
            position[2].mid(),
        ));
        let joints = self.geometry.inverse(&centre).platform_joints;
        let bases = self.geometry.base_joints();
        let angles = servo_closure::servo_angles(servos, bases, &joints).ok()?;
        let tips: [Vector3<f64>; 6] =
            std::array::from_fn(|i| servos.horn_tip(i, &bases[i], angles[i]));
        let (rods, horns) = rod_distances(bases, &joints, &tips);
        let least = rods
            .iter()
            .chain(&horns)
            .copied()
            .fold(f64::INFINITY, f64::min);
        let moves = half.max(swing);
        // The centre's angles are the library's arcsine: near the edge of reach its error
        // grows to about √ε rad, covered by a millionth of a radian of horn.
        let margin = self.margin + 1e-6 * a;
        least.is_finite().then(|| {
            let reach = 2.0 * moves + margin;
            (least - reach, least + reach)
        })
    }

    /// The least distance between two legs over the box: from the box's centre, less and
    /// more twice the half-diagonal (and the margin).
    fn clearance_bounds(&self, position: &[Interval; 3]) -> Option<(f64, f64)> {
        let centre = self.orientation.with_position(Vector3::new(
            position[0].mid(),
            position[1].mid(),
            position[2].mid(),
        ));
        let joints = self.geometry.inverse(&centre).platform_joints;
        let bases = self.geometry.base_joints();
        let half_diagonal = half_diagonal(position);
        let least = LEG_PAIRS
            .iter()
            .map(|&(i, j)| segment_distance(bases[i], joints[i], bases[j], joints[j]))
            .fold(f64::INFINITY, f64::min);
        least.is_finite().then(|| {
            let reach = 2.0 * half_diagonal + self.margin;
            (least - reach, least + reach)
        })
    }
}
