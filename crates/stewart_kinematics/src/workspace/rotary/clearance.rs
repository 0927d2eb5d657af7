//! Clearance of a rotary platform's rods and horns along one column.
//!
//! Each of the 45 pairs (rod–rod, rod–other servo's horn) is taken alone. A pair is first
//! checked once per interval at its midpoint: over the interval each joint moves by at
//! most half its length and each horn tip by at most the chord of its range, so every
//! point of a rod or horn moves by at most the larger of the two, and a pair whose
//! distance exceeds the least allowed by the sum of both movements is clear over the whole
//! interval. Only the pairs this does not settle are sampled at the column spacing and
//! bisected at every change.

use nalgebra::Vector3;

use super::super::column::{Spans, keep_sampled};
use crate::checks::servos::ROD_HORN_PAIRS;
use crate::limits::{LEG_PAIRS, segment_distance};
use crate::rotary::RotaryActuators;

/// Two parts that must keep apart.
#[derive(Clone, Copy)]
enum Pair {
    /// Rods `i` and `j`.
    Rods(usize, usize),
    /// Rod `i` and servo `j`'s horn.
    RodHorn(usize, usize),
}

/// The clearance limit at one orientation.
pub(super) struct Clearance<'a> {
    pub(super) servos: &'a RotaryActuators,
    pub(super) bases: &'a [Vector3<f64>; 6],
    /// `d_i`: platform joint `i` minus the platform position, base frame.
    pub(super) offsets: &'a [Vector3<f64>; 6],
    /// The least distance allowed (twice the leg radius), metres.
    pub(super) least: f64,
}

impl Clearance<'_> {
    /// Horn tips and platform joints of the six servos at platform position `p`, `None`
    /// when a servo cannot reach.
    fn rods(&self, p: &Vector3<f64>) -> Option<[(Vector3<f64>, Vector3<f64>); 6]> {
        let mut rods = [(Vector3::zeros(), Vector3::zeros()); 6];
        for (i, rod) in rods.iter_mut().enumerate() {
            let joint = p + self.offsets[i];
            let theta = self.servos.servo_angle(i, &self.bases[i], &joint).ok()?;
            *rod = (self.servos.horn_tip(i, &self.bases[i], theta), joint);
        }
        Some(rods)
    }

    /// The pair's distance with the rods `rods`.
    fn distance(&self, pair: Pair, rods: &[(Vector3<f64>, Vector3<f64>); 6]) -> f64 {
        match pair {
            Pair::Rods(i, j) => segment_distance(rods[i].0, rods[i].1, rods[j].0, rods[j].1),
            Pair::RodHorn(i, j) => segment_distance(rods[i].0, rods[i].1, self.bases[j], rods[j].0),
        }
    }

    /// The most a horn tip can move: the chord of the servo's range (its diameter when the
    /// range is a half turn or more, or unset).
    fn tip_chord(&self) -> f64 {
        let turn = self
            .servos
            .range()
            .map_or(std::f64::consts::PI, |(min, max)| {
                (max.radians() - min.radians()).min(std::f64::consts::PI)
            });
        2.0 * self.servos.horn_length() * (0.5 * turn).sin()
    }

    /// Narrow the column at `(x, y)`'s `spans` to where every pair keeps its distance;
    /// returns the evaluations made.
    pub(super) fn narrow(
        &self,
        x: f64,
        y: f64,
        dz: f64,
        spans: &mut Spans,
        spare: &mut Spans,
    ) -> usize {
        let chord = self.tip_chord();
        let at = |z: f64| Vector3::new(x, y, z);
        let pairs = LEG_PAIRS
            .iter()
            .map(|&(i, j)| Pair::Rods(i, j))
            .chain(ROD_HORN_PAIRS.iter().map(|&(i, j)| Pair::RodHorn(i, j)));
        let mut evaluations = 0;
        // Whether each pair is settled over every interval, from the rods at the midpoints.
        let mut settled = [true; 45];
        for &(a, b) in spans.iter() {
            evaluations += 1;
            let half = 0.5 * (b - a);
            let Some(rods) = self.rods(&at(a + half)) else {
                settled = [false; 45];
                break;
            };
            for (k, pair) in pairs.clone().enumerate() {
                let moved = match pair {
                    Pair::Rods(..) => 2.0 * half.max(chord),
                    Pair::RodHorn(..) => half.max(chord) + chord,
                };
                settled[k] &= self.distance(pair, &rods) - self.least > moved;
            }
        }
        let mut open = [Pair::Rods(0, 0); 45];
        let mut count = 0;
        for (pair, _) in pairs.zip(settled).filter(|(_, s)| !s) {
            open[count] = pair;
            count += 1;
        }
        if count > 0 {
            let clear = |z: f64| {
                self.rods(&at(z)).is_some_and(|rods| {
                    open[..count]
                        .iter()
                        .all(|&pair| self.distance(pair, &rods) >= self.least)
                })
            };
            evaluations += keep_sampled(spans, dz, clear, spare);
            std::mem::swap(spans, spare);
        }
        evaluations
    }
}
