//! A rotary platform's servos over a box of poses: for each, whether every pose, none or
//! only some lets its horn close the rod, the horn's angle over the box, its horn tip, its
//! rod and the inverse Jacobian's rows — each holding its value at every pose of the box.
//!
//! Servo `i` closes its rod when `N cos θ + M sin θ = L`, with `l = q_i − B_i`,
//! `L = |l|² − (s² − a²)`, `M = 2a l_z`, `N = 2a (h_i · l)` (`solve::servo_closure`):
//! every pose of the box reaches when `L / √(M² + N²)` lies within [−1, 1] over it, none
//! when it lies wholly outside. Where `M > 0` over the box (the joint above the shaft, as on
//! every working rig) the studio's branch `θ = asin(L / √(M² + N²)) − atan(N / M)` is
//! continuous, and the angle's interval follows from the arcsine's (of the ratio's part
//! within [−1, 1]) and arctangent's: it holds the angle of every pose of the box that
//! reaches, so a box that straddles the edge of reach can still be shown out of the
//! servo's range wherever it reaches.
//!
//! The Jacobian's row `i` is `[d_i, r_i × d_i] / (d_i · h'_i)` (`d_i` the rod, `h'_i` the
//! horn tip's velocity per radian): it is regular when every `d_i · h'_i` is away from 0
//! (no servo at the edge of its reach, horn and rod in line) and the rods' matrix
//! `[d_i, r_i × d_i]` is regular.

use crate::ground::interval::Interval;
use crate::model::rotary::RotaryActuators;

use super::pose_box::{BoxLegs, IVec3, cross};

/// Whether a servo's horn closes its rod over a box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reach {
    /// At every pose of the box.
    Every,
    /// At no pose of the box.
    None,
    /// Not decided: at some poses perhaps.
    Undecided,
}

/// One servo over a box: its angle, tip and rod at every pose of the box that reaches.
#[derive(Clone, Copy, Debug)]
pub struct BoxServo {
    /// The horn's angle, radians (the studio's model angle, before trims).
    pub angle: Interval,
    /// The horn tip, base frame.
    pub tip: IVec3,
    /// The rod, horn tip to platform joint.
    pub rod: IVec3,
    /// The horn tip's velocity per radian of the servo.
    pub tip_rate: IVec3,
    /// The transmission `d · h'`: the servo's angle turns by `d · δq / (d · h')` as its
    /// platform joint moves by `δq`, so it is away from 0 except at the edge of reach.
    pub transmission: Interval,
}

/// The six servos over a box: for each its reach, and what it is at the poses that reach,
/// where its angle is bounded.
#[derive(Clone, Copy, Debug)]
pub struct BoxServos {
    /// Whether each servo reaches.
    pub reach: [Reach; 6],
    /// Each servo at the poses of the box that reach it, where its angle is bounded (`M > 0`
    /// over the box, and some pose may reach).
    pub servos: [Option<BoxServo>; 6],
}

impl BoxServos {
    /// The servos `servos` over the box whose legs (base joint to platform joint) are
    /// `legs`, with shaft centres `bases`.
    pub fn of(
        servos: &RotaryActuators,
        bases: &[nalgebra::Vector3<f64>; 6],
        legs: &BoxLegs,
    ) -> Self {
        let a = Interval::point(servos.horn_length());
        let s = Interval::point(servos.rod_length());
        let mut reach = [Reach::Undecided; 6];
        let mut out = [None; 6];
        for i in 0..6 {
            let l = &legs.legs[i];
            let h = servos.horn_direction(i);
            let big_l = l[0].sqr() + l[1].sqr() + l[2].sqr() - (s.sqr() - a.sqr());
            let m = Interval::point(2.0) * a * l[2];
            let n = Interval::point(2.0) * a * (l[0] * h.x + l[1] * h.y);
            let Some(ratio) = (m.sqr() + n.sqr()).sqrt().and_then(|r| big_l.div(&r)) else {
                continue;
            };
            let whole = Interval::point(-1.0).hull(&Interval::point(1.0));
            reach[i] = if ratio.lo() > 1.0 || ratio.hi() < -1.0 {
                Reach::None
            } else if ratio.within(&whole) {
                Reach::Every
            } else {
                Reach::Undecided
            };
            if reach[i] == Reach::None || m.lo() <= 0.0 {
                continue;
            }
            let (Some(asin), Some(tan)) = (ratio.asin(), n.div(&m)) else {
                continue;
            };
            let angle = asin - tan.atan();
            let (sin, cos) = (angle.sin(), angle.cos());
            let base = bases[i].map(Interval::point);
            let tip: IVec3 = [
                base[0] + a * cos * h.x,
                base[1] + a * cos * h.y,
                base[2] + a * sin,
            ];
            // The platform joint is the base joint plus the leg.
            let rod: IVec3 = std::array::from_fn(|k| base[k] + l[k] - tip[k]);
            let tip_rate: IVec3 = [-(a * sin * h.x), -(a * sin * h.y), a * cos];
            let transmission = rod[0] * tip_rate[0] + rod[1] * tip_rate[1] + rod[2] * tip_rate[2];
            out[i] = Some(BoxServo {
                angle,
                tip,
                rod,
                tip_rate,
                transmission,
            });
        }
        Self { reach, servos: out }
    }

    /// The rods' matrix `[d_iᵀ, (r_i × d_i)ᵀ]`, rotation columns divided by `length`, and
    /// whether every servo's transmission `d_i · h'_i` is away from 0 — `None` unless every
    /// servo reaches at every pose of the box with its angle bounded. (Rows scaled by a
    /// number away from 0 keep a matrix regular or singular.)
    pub fn jacobian(&self, legs: &BoxLegs, length: f64) -> Option<[[Interval; 6]; 6]> {
        let mut rows = [[Interval::point(0.0); 6]; 6];
        for (i, row) in rows.iter_mut().enumerate() {
            if self.reach[i] != Reach::Every {
                return None;
            }
            let servo = self.servos[i]?;
            let d = &servo.rod;
            if servo.transmission.contains(0.0) {
                return None;
            }
            let moment = cross(&legs.arms[i], d);
            let inv = 1.0 / length;
            *row = [
                d[0],
                d[1],
                d[2],
                moment[0] * inv,
                moment[1] * inv,
                moment[2] * inv,
            ];
        }
        Some(rows)
    }
}
