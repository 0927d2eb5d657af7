//! The actuator range a motion envelope needs: over every pose of a 6-D box (x, y, z in
//! metres; roll, pitch, yaw in degrees), the smallest and largest value of each leg length
//! (or servo angle), the pose where each occurs, and the worst conditioning in the box.
//!
//! Method: every value is evaluated at a seed set — the box's 64 corners, its centre, the
//! 12 face centres and 512 points of a Halton sequence — and each extreme is then refined
//! from the four best seeds by a bounded pattern search (steps along each free
//! coordinate, halved down to 1e-10 of the box side). Leg lengths are smooth, so the
//! search converges to a local extreme; the seeds make it the global one for sensible
//! boxes, which tests check against dense brute force. Every reported value is attained
//! at the reported pose.

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// The coordinates' names, in pose order.
pub const NAMES: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];

/// A box of poses: per coordinate an interval, metres for x, y, z and degrees for roll,
/// pitch, yaw (a coordinate left out stays at home).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Envelope {
    /// Lower ends.
    pub lo: [f64; 6],
    /// Upper ends (equal to `lo` for a fixed coordinate).
    pub hi: [f64; 6],
}

impl Envelope {
    /// Parse `x=±0.1,y=-0.1..0.1,z=0.7..0.9,roll=±10,yaw=5`: each named coordinate at
    /// most once, as `±A` (or `+-A`) about home, `A..B` (absolute), or one value;
    /// the others stay at `home`.
    pub fn parse(text: &str, home: &Pose) -> Result<Envelope, EnvelopeError> {
        let h = home.to_coordinates();
        let home_units: [f64; 6] =
            std::array::from_fn(|k| if k < 3 { h[k] } else { h[k].to_degrees() });
        let mut env = Envelope {
            lo: home_units,
            hi: home_units,
        };
        let mut seen = [false; 6];
        if text.trim().is_empty() {
            return Err(EnvelopeError::Empty);
        }
        for part in text.split(',') {
            let part = part.trim();
            let (name, spec) = part
                .split_once('=')
                .ok_or_else(|| EnvelopeError::NotAssignment(part.to_owned()))?;
            let name = name.trim().to_ascii_lowercase();
            let k = NAMES
                .iter()
                .position(|n| *n == name)
                .ok_or_else(|| EnvelopeError::UnknownCoordinate(name.clone()))?;
            if seen[k] {
                return Err(EnvelopeError::Twice(name));
            }
            seen[k] = true;
            let spec = spec.trim();
            let (lo, hi) =
                interval(spec, home_units[k]).map_err(|problem| EnvelopeError::Range {
                    name: name.clone(),
                    spec: spec.to_owned(),
                    problem,
                })?;
            let limit = if k < 3 { 100.0 } else { 180.0 };
            if lo < -limit || hi > limit {
                return Err(EnvelopeError::TooFar {
                    name,
                    spec: spec.to_owned(),
                    limit,
                    unit: if k < 3 { "m" } else { "°" },
                });
            }
            env.lo[k] = lo;
            env.hi[k] = hi;
        }
        Ok(env)
    }

    /// The pose at `u` ∈ [0, 1]⁶ (0: lower end, 1: upper end).
    pub fn pose_at(&self, u: &[f64; 6]) -> Pose {
        let c = self.coordinates_at(u);
        Pose::from_xyz_rpy_deg([c[0], c[1], c[2]], [c[3], c[4], c[5]])
    }

    /// The coordinates (m, °) at `u` ∈ [0, 1]⁶.
    pub fn coordinates_at(&self, u: &[f64; 6]) -> [f64; 6] {
        std::array::from_fn(|k| self.lo[k] + u[k].clamp(0.0, 1.0) * (self.hi[k] - self.lo[k]))
    }

    /// The coordinates that vary.
    fn free(&self) -> Vec<usize> {
        (0..6).filter(|&k| self.hi[k] > self.lo[k]).collect()
    }
}

/// Why an envelope was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum EnvelopeError {
    /// Nothing given.
    #[error("the envelope is empty: name at least one coordinate, such as x=±0.1,roll=±10")]
    Empty,
    /// A part without `=`.
    #[error("`{0}` is not NAME=RANGE (such as z=0.7..0.9)")]
    NotAssignment(String),
    /// A name that is not x, y, z, roll, pitch or yaw.
    #[error("`{0}` is not a coordinate: x, y, z (m), roll, pitch, yaw (°)")]
    UnknownCoordinate(String),
    /// A coordinate named twice.
    #[error("`{0}` is given twice")]
    Twice(String),
    /// A range that does not read.
    #[error("`{name}={spec}`: {problem}")]
    Range {
        /// The coordinate.
        name: String,
        /// What was written after `=`.
        spec: String,
        /// What is wrong with it.
        problem: RangeProblem,
    },
    /// A range beyond ±100 m or ±180°.
    #[error("`{name}={spec}` reaches beyond ±{limit} {unit}")]
    TooFar {
        /// The coordinate.
        name: String,
        /// What was written after `=`.
        spec: String,
        /// The bound, m or °.
        limit: f64,
        /// `m` or `°`.
        unit: &'static str,
    },
}

/// What is wrong with one coordinate's range.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum RangeProblem {
    /// Nothing after `=`.
    #[error("no range given")]
    Missing,
    /// Not a number.
    #[error("`{0}` is not a number")]
    NotANumber(String),
    /// NaN or infinite.
    #[error("`{0}` is not a finite number")]
    NotFinite(String),
    /// `±A` with A < 0.
    #[error("a ± half-width cannot be negative")]
    NegativeHalfWidth,
    /// `A..B` with A > B.
    #[error("the range is inverted ({0} > {1})")]
    Inverted(f64, f64),
}

/// `±A`, `+-A` (about `home`), `A..B` or `A`.
fn interval(spec: &str, home: f64) -> Result<(f64, f64), RangeProblem> {
    let number = |t: &str| -> Result<f64, RangeProblem> {
        let t = t.trim();
        let v: f64 = t
            .parse()
            .map_err(|_| RangeProblem::NotANumber(t.to_owned()))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(RangeProblem::NotFinite(t.to_owned()))
        }
    };
    if spec.is_empty() {
        return Err(RangeProblem::Missing);
    }
    if let Some(a) = spec.strip_prefix('±').or_else(|| spec.strip_prefix("+-")) {
        let a = number(a)?;
        if a < 0.0 {
            return Err(RangeProblem::NegativeHalfWidth);
        }
        return Ok((home - a, home + a));
    }
    if let Some((a, b)) = spec.split_once("..") {
        let (a, b) = (number(a)?, number(b)?);
        if a > b {
            return Err(RangeProblem::Inverted(a, b));
        }
        return Ok((a, b));
    }
    let v = number(spec)?;
    Ok((v, v))
}

/// One extreme: the value and the pose (m, °) where it occurs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Extreme {
    /// The value (m, °, or a condition number).
    pub value: f64,
    /// x, y, z (m), roll, pitch, yaw (°).
    pub pose: [f64; 6],
}

/// What an envelope needs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DesignReport {
    /// Per actuator, its smallest and largest value over the box.
    pub actuators: Vec<[Extreme; 2]>,
    /// The largest normalised condition number in the box (infinite at a singular
    /// pose), where it occurs; `None` when no pose of the box was reachable.
    pub worst_condition: Option<Extreme>,
    /// A pose of the box some servo cannot reach at all, when there is one.
    pub unreachable: Option<[f64; 6]>,
    /// Seed poses (before the search).
    pub seeds: usize,
    /// Poses evaluated.
    pub evaluations: usize,
}

impl DesignReport {
    /// Whether the needed range ([`DesignReport::overall`]) lies within `limits` (min,
    /// max; either may be absent); `None` when there is no limit or no reachable pose.
    pub fn fits(&self, [lo, hi]: [Option<f64>; 2]) -> Option<bool> {
        let [a, b] = self.overall()?;
        if lo.is_none() && hi.is_none() {
            return None;
        }
        Some(lo.is_none_or(|l| a.value >= l) && hi.is_none_or(|h| b.value <= h))
    }

    /// The smallest and largest value over all actuators: the stroke (or servo range) the
    /// envelope needs.
    pub fn overall(&self) -> Option<[Extreme; 2]> {
        let lo = self
            .actuators
            .iter()
            .map(|a| a[0])
            .min_by(|a, b| a.value.total_cmp(&b.value))?;
        let hi = self
            .actuators
            .iter()
            .map(|a| a[1])
            .max_by(|a, b| a.value.total_cmp(&b.value))?;
        Some([lo, hi])
    }
}

/// Seeds from the Halton sequence (bases 2, 3, 5, 7, 11, 13).
const HALTON: usize = 512;
/// Seeds refined per extreme.
const STARTS: usize = 4;
/// The search stops when its step is below this fraction of the box side.
const FINEST: f64 = 1e-10;

/// The values at `u`: six actuator values, or `None` where a servo cannot reach.
fn values(g: &Geometry, env: &Envelope, u: &[f64; 6]) -> Option<[f64; 6]> {
    g.actuator_values_at(&env.pose_at(u)).ok()
}

/// Normalised condition number at `u` (infinite when singular; `None` when unreachable).
fn condition(g: &Geometry, env: &Envelope, u: &[f64; 6]) -> Option<f64> {
    let c = g.actuated_conditioning(&env.pose_at(u))?;
    if c.singular_values[0] <= 0.0 {
        return None;
    }
    Some(c.condition_number.unwrap_or(f64::INFINITY))
}

/// The k-th point of the Halton sequence in [0, 1]⁶.
fn halton(k: usize) -> [f64; 6] {
    const BASES: [usize; 6] = [2, 3, 5, 7, 11, 13];
    BASES.map(|b| {
        let (mut f, mut r, mut i) = (1.0, 0.0, k + 1);
        while i > 0 {
            f /= b as f64;
            r += f * (i % b) as f64;
            i /= b;
        }
        r
    })
}

/// The seed points: corners, centre, face centres and Halton points of the free
/// coordinates (fixed ones at 0).
fn seeds(free: &[usize]) -> Vec<[f64; 6]> {
    let mut out = Vec::new();
    let place = |pick: &dyn Fn(usize) -> f64| {
        let mut u = [0.0; 6];
        for (j, &k) in free.iter().enumerate() {
            u[k] = pick(j);
        }
        u
    };
    for mask in 0..(1usize << free.len()) {
        out.push(place(&|j| ((mask >> j) & 1) as f64));
    }
    out.push(place(&|_| 0.5));
    for face in 0..free.len() {
        for end in [0.0, 1.0] {
            out.push(place(&|j| if j == face { end } else { 0.5 }));
        }
    }
    for k in 0..HALTON {
        let h = halton(k);
        out.push(place(&|j| h[j]));
    }
    out
}

/// Maximise `f` over the free coordinates from `start` by a bounded pattern search.
fn climb(
    f: &mut dyn FnMut(&[f64; 6]) -> Option<f64>,
    free: &[usize],
    start: [f64; 6],
    value: f64,
) -> ([f64; 6], f64) {
    let (mut u, mut best) = (start, value);
    let mut step = 0.25;
    while step > FINEST {
        let mut moved = false;
        for &k in free {
            for sign in [1.0, -1.0] {
                let mut v = u;
                v[k] = (u[k] + sign * step).clamp(0.0, 1.0);
                if v[k] == u[k] {
                    continue;
                }
                if let Some(y) = f(&v)
                    && y > best
                {
                    (u, best) = (v, y);
                    moved = true;
                }
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    (u, best)
}

/// The extremes `sense` · f reaches (the largest for +1), searched from the best seeds.
fn extreme(
    f: &mut dyn FnMut(&[f64; 6]) -> Option<f64>,
    free: &[usize],
    seeded: &[([f64; 6], f64)],
    sense: f64,
) -> Option<([f64; 6], f64)> {
    let mut order: Vec<&([f64; 6], f64)> = seeded.iter().filter(|(_, v)| !v.is_nan()).collect();
    order.sort_by(|a, b| (sense * b.1).total_cmp(&(sense * a.1)));
    let mut g = |u: &[f64; 6]| f(u).map(|v| sense * v);
    order
        .into_iter()
        .take(STARTS)
        .map(|(u, v)| climb(&mut g, free, *u, sense * v))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(u, v)| (u, sense * v))
}

/// What `env` needs of `g`'s actuators (see the module docs).
pub fn envelope_needs(g: &Geometry, env: &Envelope) -> DesignReport {
    let free = env.free();
    let mut evaluations = 0usize;
    let mut unreachable = None;
    let points = seeds(&free);
    let seeded: Vec<([f64; 6], Option<[f64; 6]>)> =
        points.iter().map(|u| (*u, values(g, env, u))).collect();
    evaluations += seeded.len();
    if let Some((u, _)) = seeded.iter().find(|(_, v)| v.is_none()) {
        unreachable = Some(env.coordinates_at(u));
    }
    let mut actuators = Vec::with_capacity(6);
    for i in 0..6 {
        let column: Vec<([f64; 6], f64)> = seeded
            .iter()
            .map(|(u, v)| (*u, v.map_or(f64::NAN, |v| v[i])))
            .collect();
        let mut f = |u: &[f64; 6]| {
            evaluations += 1;
            values(g, env, u).map(|v| v[i])
        };
        let found = [-1.0, 1.0].map(|sense| extreme(&mut f, &free, &column, sense));
        if let [Some(lo), Some(hi)] = found {
            actuators.push([lo, hi].map(|(u, value)| Extreme {
                value,
                pose: env.coordinates_at(&u),
            }));
        }
    }
    let conditioned: Vec<([f64; 6], f64)> = points
        .iter()
        .map(|u| (*u, condition(g, env, u).unwrap_or(f64::NAN)))
        .collect();
    evaluations += conditioned.len();
    let mut f = |u: &[f64; 6]| {
        evaluations += 1;
        condition(g, env, u)
    };
    let worst_condition = extreme(&mut f, &free, &conditioned, 1.0).map(|(u, value)| Extreme {
        value,
        pose: env.coordinates_at(&u),
    });
    DesignReport {
        actuators,
        worst_condition,
        unreachable,
        seeds: points.len(),
        evaluations,
    }
}

#[cfg(test)]
mod tests;
