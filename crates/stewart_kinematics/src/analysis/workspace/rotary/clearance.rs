//! Clearance of a rotary platform's rods and horns along one column, by branch and bound.
//!
//! Over a piece `[a, b]` of the column every joint moves by at most half the piece from
//! its place at the midpoint, and every horn tip by at most the chord of the largest
//! change of its servo's angle from the midpoint's, which is known exactly: the angle's
//! extremes over the piece are at its ends or where it turns (`dθ/dz = 0`, the roots of
//! a quartic computed once per column, see `Columns::turning_points`). So every point of
//! a rod or horn moves by at most the larger of the two, and at the midpoint a pair of
//! parts whose distance exceeds the least allowed by more than both movements is clear
//! over the whole piece, one short of it by more is in collision over the whole piece.
//! Pairs not settled are carried into the two halves; pieces shorter than the column
//! spacing are sampled at their ends and middle for the pairs still open, and each
//! change is bisected to 1e-12 m.

use nalgebra::Vector3;

use super::super::column::{Spans, keep_sampled, push_joined};
use super::Columns;
use crate::analysis::checks::servos::ROD_HORN_PAIRS;
use crate::model::angle::Angle;
use crate::model::limits::{LEG_PAIRS, segment_distance};

/// Two parts that must keep apart.
#[derive(Clone, Copy)]
enum Pair {
    /// Rods `i` and `j`.
    Rods(usize, usize),
    /// Rod `i` and servo `j`'s horn.
    RodHorn(usize, usize),
}

/// The 45 pairs.
const PAIRS: usize = 45;

/// The clearance limit at one orientation.
pub(super) struct Clearance<'a> {
    /// The orientation's servos, joints and horn directions.
    pub(super) columns: &'a Columns<'a>,
    /// The least distance allowed (twice the leg radius), metres.
    pub(super) least: f64,
}

/// One column: where it is, its turning points, and scratch space.
pub(super) struct Column<'a> {
    pub(super) x: f64,
    pub(super) y: f64,
    /// The finest piece split, metres.
    pub(super) dz: f64,
    /// Heights at which each servo's angle turns, ascending.
    pub(super) turning: &'a [Vec<f64>; 6],
}

/// Horn tips and platform joints of the six servos.
type Rods = [(Vector3<f64>, Vector3<f64>); 6];

/// A piece `[a, b]` of a column and the servo angles at its ends (NaN out of reach).
#[derive(Clone, Copy)]
struct Piece {
    a: f64,
    b: f64,
    ends: [[f64; 6]; 2],
}

impl Clearance<'_> {
    /// Servo `i`'s shaft centre.
    fn base(&self, i: usize) -> &Vector3<f64> {
        &self.columns.geometry.base_joints()[i]
    }

    /// Servo `i`'s angle (radians) at platform position `p`, `None` out of reach.
    fn angle(&self, i: usize, p: &Vector3<f64>) -> Option<f64> {
        let joint = p + self.columns.offsets[i];
        let theta = self.columns.angle(i, self.base(i), &joint)?;
        Some(theta.radians())
    }

    /// The six servos' angles at `p` (NaN for one out of reach).
    fn angles(&self, p: &Vector3<f64>) -> [f64; 6] {
        std::array::from_fn(|i| self.angle(i, p).unwrap_or(f64::NAN))
    }

    /// Horn tips and platform joints of the six servos at `p` with angles `angles`, `None`
    /// when one is out of reach.
    fn rods(&self, p: &Vector3<f64>, angles: &[f64; 6]) -> Option<Rods> {
        let mut rods = [(Vector3::zeros(), Vector3::zeros()); 6];
        for i in 0..6 {
            if angles[i].is_nan() {
                return None;
            }
            let theta = Angle::from_radians(angles[i]);
            let tip = self
                .columns
                .servos
                .tip_along(&self.columns.horns[i], self.base(i), theta);
            rods[i] = (tip, p + self.columns.offsets[i]);
        }
        Some(rods)
    }

    /// The pair's distance with the rods `rods`.
    fn distance(&self, pair: Pair, rods: &Rods) -> f64 {
        match pair {
            Pair::Rods(i, j) => segment_distance(rods[i].0, rods[i].1, rods[j].0, rods[j].1),
            Pair::RodHorn(i, j) => segment_distance(rods[i].0, rods[i].1, *self.base(j), rods[j].0),
        }
    }

    /// Narrow the column's `spans` to where every pair keeps its distance; returns the
    /// evaluations made.
    pub(super) fn narrow(&self, column: &Column, spans: &mut Spans, spare: &mut Spans) -> usize {
        let mut all = [Pair::Rods(0, 0); PAIRS];
        for (slot, pair) in all.iter_mut().zip(
            LEG_PAIRS
                .iter()
                .map(|&(i, j)| Pair::Rods(i, j))
                .chain(ROD_HORN_PAIRS.iter().map(|&(i, j)| Pair::RodHorn(i, j))),
        ) {
            *slot = pair;
        }
        spare.clear();
        let mut sampled = Spans::new();
        let mut evaluations = 0;
        for &(a, b) in spans.iter() {
            let ends = [a, b].map(|z| self.angles(&Vector3::new(column.x, column.y, z)));
            evaluations += 2;
            let piece = Piece { a, b, ends };
            self.settle(column, &piece, &all, spare, &mut sampled, &mut evaluations);
        }
        std::mem::swap(spans, spare);
        evaluations
    }

    /// Settle `[a, b]` for the pairs `open` (see the module docs), appending what is clear
    /// to `out`.
    fn settle(
        &self,
        column: &Column,
        piece: &Piece,
        open: &[Pair],
        out: &mut Spans,
        sampled: &mut Spans,
        evaluations: &mut usize,
    ) {
        let at = |z: f64| Vector3::new(column.x, column.y, z);
        let Piece { a, b, ends } = *piece;
        let m = 0.5 * (a + b);
        let half = 0.5 * (b - a);
        *evaluations += 1;
        let angles = self.angles(&at(m));
        let mut still = [Pair::Rods(0, 0); PAIRS];
        let mut count = 0;
        if let Some(rods) = self.rods(&at(m), &angles) {
            // How far each horn tip (and any point of each rod) can be from its place at m.
            let mut tip = [0.0; 6];
            let mut moved = [0.0; 6];
            for i in 0..6 {
                let turns = column.turning[i]
                    .iter()
                    .copied()
                    .filter(|&z| a < z && z < b);
                let turned = turns.map(|z| {
                    *evaluations += 1;
                    self.angle(i, &at(z)).unwrap_or(f64::NAN)
                });
                let mut spread: f64 = 0.0;
                for t in [ends[0][i], ends[1][i]].into_iter().chain(turned) {
                    // NaN (out of reach) counts as the largest possible turn.
                    let change = (t - angles[i]).abs();
                    spread = if change.is_nan() {
                        std::f64::consts::PI
                    } else {
                        spread.max(change)
                    };
                }
                tip[i] = 2.0
                    * self.columns.servos.horn_length()
                    * (0.5 * spread.min(std::f64::consts::PI)).sin();
                moved[i] = half.max(tip[i]);
            }
            for &pair in open {
                let slack = self.distance(pair, &rods) - self.least;
                let bound = match pair {
                    Pair::Rods(i, j) => moved[i] + moved[j],
                    Pair::RodHorn(i, j) => moved[i] + tip[j],
                };
                if slack < -bound {
                    return;
                }
                if slack <= bound {
                    still[count] = pair;
                    count += 1;
                }
            }
        } else {
            still[..open.len()].copy_from_slice(open);
            count = open.len();
        }
        let still = &still[..count];
        if still.is_empty() {
            push_joined(out, a, b);
        } else if b - a <= column.dz {
            let clear = |z: f64| {
                self.rods(&at(z), &self.angles(&at(z))).is_some_and(|rods| {
                    still
                        .iter()
                        .all(|&pair| self.distance(pair, &rods) >= self.least)
                })
            };
            *evaluations += keep_sampled(&[(a, b)], column.dz, clear, sampled);
            for &(s0, s1) in sampled.iter() {
                push_joined(out, s0, s1);
            }
        } else {
            let lower = Piece {
                a,
                b: m,
                ends: [ends[0], angles],
            };
            let upper = Piece {
                a: m,
                b,
                ends: [angles, ends[1]],
            };
            self.settle(column, &lower, still, out, sampled, evaluations);
            self.settle(column, &upper, still, out, sampled, evaluations);
        }
    }
}
