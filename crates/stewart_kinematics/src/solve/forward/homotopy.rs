//! Every assembly mode by polynomial homotopy continuation.
//!
//! The forward problem in Study coordinates ([`super::study`]) is seven quadrics in
//! `P⁷`; a general platform has 40 isolated complex solutions (Ronga–Vust, Lazard,
//! Mourrain, Raghavan), and its real solutions are its assembly modes. They are all
//! found in two stages, each a standard probability-one method:
//!
//! 1. **Once per process, a generic start platform**: a platform with random complex
//!    joints and lengths is solved by a total-degree homotopy
//!    `H = (1 − s)·γ·G + s·F` from `G_k = z_k² − z_7²` (2⁷ = 128 known solutions) with a
//!    random complex `γ`. Every isolated solution of `F` is the end of one of the 128
//!    paths (the "gamma trick": for all but finitely many `γ` on the unit circle no path
//!    meets a singularity before `s = 1`). The start platform must give exactly 40
//!    distinct finite nonsingular solutions, or another random platform is drawn.
//! 2. **Per query, a parameter homotopy**: the joints and lengths move in a straight
//!    line from the start platform to the real one, and the 40 solutions are tracked
//!    along. Since the start platform is a generic complex point of the (irreducible)
//!    parameter space, every isolated solution of the real platform is the end of one
//!    of the 40 paths (coefficient-parameter continuation, Morgan and Sommese 1989).
//!
//! Paths are tracked with a fourth-order Runge–Kutta predictor on `dz/ds = −H_z⁻¹ H_s`
//! and a Newton corrector with an adaptive step; all points satisfy a fixed random
//! linear patch `c·z = 1`, so no path runs to infinity in coordinates. A path whose
//! end is singular (a degenerate platform's solutions at infinity or on the spurious
//! set `e = 0`) stops early and is dropped; real ends are polished by the real Newton
//! solver to the leg-length tolerance.

use nalgebra::SVector;
use rayon::prelude::*;
use std::sync::OnceLock;

use super::study::{C, Coords, LegParams, Square, leg_quadric, leg_quadric_rate, study_condition};

/// A homotopy: its value, its derivative in `z` and its derivative in `s` at `(z, s)`.
trait Homotopy: Sync {
    fn eval(&self, z: &Coords, s: f64) -> (Coords, Square, Coords);
}

/// Rows 6 and 7 of every system here: Study's quadric and the patch `c·z = 1`.
fn study_and_patch(z: &Coords, patch: &Coords, h: &mut Coords, j: &mut Square) {
    let (value, gradient) = study_condition(z);
    h[6] = value;
    j.set_row(6, &gradient.transpose());
    h[7] = patch.dot(z) - C::from(1.0);
    j.set_row(7, &patch.transpose());
}

/// `zᵀ M z` and its gradient `2 M z` (M symmetric).
fn quadric_value(m: &Square, z: &Coords) -> (C, Coords) {
    let mz = m * z;
    (z.dot(&mz), mz * C::from(2.0))
}

/// The total-degree homotopy from `z_k² − z_7²` to a platform's leg quadrics.
struct TotalDegree {
    quadrics: [Square; 6],
    gamma: C,
    patch: Coords,
}

impl Homotopy for TotalDegree {
    fn eval(&self, z: &Coords, s: f64) -> (Coords, Square, Coords) {
        let mut h = Coords::zeros();
        let mut j = Square::zeros();
        let mut hs = Coords::zeros();
        let (study, study_gradient) = study_condition(z);
        for k in 0..7 {
            // Start equation z_k² − z_7² and target equation k (legs, then Study).
            let g = z[k] * z[k] - z[7] * z[7];
            let (f, df) = if k < 6 {
                quadric_value(&self.quadrics[k], z)
            } else {
                (study, study_gradient)
            };
            let w = self.gamma * (1.0 - s);
            h[k] = w * g + f * s;
            hs[k] = f - self.gamma * g;
            let mut row = df * C::from(s);
            row[k] += w * z[k] * 2.0;
            row[7] -= w * z[7] * 2.0;
            j.set_row(k, &row.transpose());
        }
        h[7] = self.patch.dot(z) - C::from(1.0);
        j.set_row(7, &self.patch.transpose());
        (h, j, hs)
    }
}

/// The parameter homotopy: each leg's parameters move linearly from `from` to `to`.
struct ParameterPath {
    from: [LegParams; 6],
    rate: [LegParams; 6],
    to: [LegParams; 6],
    patch: Coords,
}

impl Homotopy for ParameterPath {
    fn eval(&self, z: &Coords, s: f64) -> (Coords, Square, Coords) {
        let mut h = Coords::zeros();
        let mut j = Square::zeros();
        let mut hs = Coords::zeros();
        for i in 0..6 {
            let p = self.from[i].lerp(&self.to[i], s);
            let (value, gradient) = quadric_value(&leg_quadric(&p), z);
            h[i] = value;
            j.set_row(i, &gradient.transpose());
            hs[i] = quadric_value(&leg_quadric_rate(&p, &self.rate[i]), z).0;
        }
        study_and_patch(z, &self.patch, &mut h, &mut j);
        (h, j, hs)
    }
}

/// How a path ended.
#[derive(Clone, Copy, Debug)]
struct PathEnd {
    z: Coords,
    /// Whether the tracker reached `s = 1` with a nonsingular end.
    finished: bool,
}

const MAX_STEPS: usize = 4000;
const MIN_STEP: f64 = 1e-13;
/// Newton's correction must shrink below this (relative) for a step to count.
const CORRECTOR_TOLERANCE: f64 = 1e-10;

fn solve(j: &Square, rhs: &Coords) -> Option<Coords> {
    let x = j.lu().solve(rhs)?;
    x.iter()
        .all(|c| c.re.is_finite() && c.im.is_finite())
        .then_some(x)
}

/// `dz/ds` on the path through `(z, s)`.
fn tangent<H: Homotopy>(h: &H, z: &Coords, s: f64) -> Option<Coords> {
    let (_, j, hs) = h.eval(z, s);
    solve(&j, &(-hs))
}

/// A fourth-order Runge–Kutta step of length `ds` along the path.
fn predict<H: Homotopy>(h: &H, z: &Coords, s: f64, ds: f64) -> Option<Coords> {
    let k1 = tangent(h, z, s)?;
    let k2 = tangent(h, &(z + k1 * C::from(ds / 2.0)), s + ds / 2.0)?;
    let k3 = tangent(h, &(z + k2 * C::from(ds / 2.0)), s + ds / 2.0)?;
    let k4 = tangent(h, &(z + k3 * C::from(ds)), s + ds)?;
    Some(z + (k1 + (k2 + k3) * C::from(2.0) + k4) * C::from(ds / 6.0))
}

/// Newton's method at fixed `s`: the corrected point once a correction is below the
/// tolerance, within `iterations`, each correction at most half the one before.
fn correct<H: Homotopy>(h: &H, z: &Coords, s: f64, iterations: usize) -> Option<Coords> {
    let mut z = *z;
    let mut last = f64::INFINITY;
    for _ in 0..iterations {
        let (value, j, _) = h.eval(&z, s);
        let dz = solve(&j, &(-value))?;
        z += dz;
        let size = dz.norm() / (1.0 + z.norm());
        if size < CORRECTOR_TOLERANCE {
            return Some(z);
        }
        if size > 0.5 * last {
            return None;
        }
        last = size;
    }
    None
}

/// Follow the path from `start` at `s = 0` to `s = 1`, in steps of at most `max_step`.
fn track<H: Homotopy>(h: &H, start: &Coords, max_step: f64) -> PathEnd {
    let mut z = *start;
    let mut s = 0.0;
    let mut ds: f64 = 0.02_f64.min(max_step);
    let mut good = 0;
    for _ in 0..MAX_STEPS {
        if s >= 1.0 {
            break;
        }
        ds = ds.min(1.0 - s);
        let next = predict(h, &z, s, ds).and_then(|p| correct(h, &p, s + ds, 3));
        match next {
            Some(n) => {
                z = n;
                s = if ds >= 1.0 - s { 1.0 } else { s + ds };
                good += 1;
                if good >= 2 {
                    ds = (ds * 2.0).min(max_step);
                    good = 0;
                }
            }
            None => {
                ds *= 0.5;
                good = 0;
                if ds < MIN_STEP {
                    return PathEnd { z, finished: false };
                }
            }
        }
    }
    if s < 1.0 {
        return PathEnd { z, finished: false };
    }
    // Polish at s = 1; a singular end does not converge quadratically and is dropped.
    match correct(h, &z, 1.0, 8) {
        Some(z) => PathEnd { z, finished: true },
        None => PathEnd { z, finished: false },
    }
}

/// Follow every path; where two end at the same nonsingular solution, one of them
/// jumped to another path on the way: follow those again with smaller steps.
fn track_all<H: Homotopy>(h: &H, starts: &[Coords]) -> Vec<PathEnd> {
    let mut ends: Vec<PathEnd> = starts.par_iter().map(|s| track(h, s, 1.0)).collect();
    for max_step in [0.02, 0.002] {
        let again = crowded(&ends);
        if again.is_empty() {
            break;
        }
        let retracked: Vec<(usize, PathEnd)> = again
            .par_iter()
            .map(|&i| (i, track(h, &starts[i], max_step)))
            .collect();
        for (i, end) in retracked {
            ends[i] = end;
        }
    }
    ends
}

/// The paths whose proper end another path shares.
fn crowded(ends: &[PathEnd]) -> Vec<usize> {
    let proper = |e: &PathEnd| e.finished && is_proper(&e.z);
    (0..ends.len())
        .filter(|&i| {
            proper(&ends[i])
                && ends.iter().enumerate().any(|(j, other)| {
                    j != i
                        && proper(other)
                        && (other.z - ends[i].z).norm() < SAME_SOLUTION * (1.0 + ends[i].z.norm())
                })
        })
        .collect()
}

/// A small deterministic random generator (SplitMix64): the start platform and `γ` are
/// fixed by a seed, so every run tracks the same paths.
pub(crate) struct SplitMix(pub(crate) u64);

impl SplitMix {
    /// The next number, uniform in [−1, 1).
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut x = self.0;
        x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        x ^= x >> 31;
        // 53 random bits in [0, 1), then to [−1, 1).
        (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    fn complex(&mut self) -> C {
        C::new(self.next(), self.next())
    }
}

/// A generic complex platform with all its solutions.
struct StartSystem {
    legs: [LegParams; 6],
    patch: Coords,
    solutions: Vec<Coords>,
}

/// The number of complex assembly modes of a general platform.
pub const GENERIC_SOLUTIONS: usize = 40;

/// Two solutions closer than this (relative, in patch coordinates) are one.
const SAME_SOLUTION: f64 = 1e-7;

/// Whether `z` is a usable solution: not on the spurious set `e = 0`.
fn is_proper(z: &Coords) -> bool {
    let e: f64 = (0..4).map(|i| z[i].norm_sqr()).sum::<f64>().sqrt();
    e > 1e-8 * z.norm()
}

/// The distinct proper ends of finished paths.
fn distinct_ends(ends: &[PathEnd]) -> Vec<Coords> {
    let mut out: Vec<Coords> = Vec::new();
    for end in ends.iter().filter(|e| e.finished && is_proper(&e.z)) {
        let scale = 1.0 + end.z.norm();
        if !out
            .iter()
            .any(|o| (o - end.z).norm() < SAME_SOLUTION * scale)
        {
            out.push(end.z);
        }
    }
    out
}

/// Solve a random complex platform from `seed` by the total-degree homotopy; `None`
/// unless it has exactly [`GENERIC_SOLUTIONS`] distinct solutions.
fn generic_start(seed: u64) -> Option<StartSystem> {
    let mut rng = SplitMix(seed);
    let legs: [LegParams; 6] = std::array::from_fn(|_| LegParams {
        a: std::array::from_fn(|_| rng.complex()),
        b: std::array::from_fn(|_| rng.complex()),
        k: rng.complex(),
    });
    let patch = Coords::from_fn(|_, _| rng.complex());
    let angle = std::f64::consts::TAU * rng.next();
    let homotopy = TotalDegree {
        quadrics: legs.map(|l| leg_quadric(&l)),
        gamma: C::from_polar(1.0, angle),
        patch,
    };
    let starts: Vec<Coords> = (0..128u32)
        .map(|bits| {
            let v = Coords::from_fn(|k, _| {
                let sign = if k < 7 && bits & (1 << k) != 0 {
                    -1.0
                } else {
                    1.0
                };
                C::from(sign)
            });
            v / patch.dot(&v)
        })
        .collect();
    let ends = track_all(&homotopy, &starts);
    let solutions = distinct_ends(&ends);
    (solutions.len() == GENERIC_SOLUTIONS).then_some(StartSystem {
        legs,
        patch,
        solutions,
    })
}

/// The start system, computed on first use (a few random platforms are tried; the first
/// is generic with probability one).
fn start_system() -> Option<&'static StartSystem> {
    static START: OnceLock<Option<StartSystem>> = OnceLock::new();
    START
        .get_or_init(|| (1..=8u64).find_map(|k| generic_start(0x5EED_0000 + k)))
        .as_ref()
}

/// Every isolated complex solution of the platform with legs `legs`, in Study
/// coordinates on the solver's patch: at most [`GENERIC_SOLUTIONS`]. `None` if the
/// start system could not be built (not seen in practice).
pub fn all_solutions(legs: &[LegParams; 6]) -> Option<Vec<Coords>> {
    let start = start_system()?;
    let homotopy = ParameterPath {
        from: start.legs,
        rate: std::array::from_fn(|i| start.legs[i].towards(&legs[i])),
        to: *legs,
        patch: start.patch,
    };
    let ends = track_all(&homotopy, &start.solutions);
    Some(distinct_ends(&ends))
}

/// The real solutions among `solutions`, as real Study coordinates (scaled so that the
/// largest entry is real), with imaginary parts at most `tolerance` relative.
pub fn real_solutions(solutions: &[Coords], tolerance: f64) -> Vec<SVector<f64, 8>> {
    solutions
        .iter()
        .filter_map(|z| {
            let big = z
                .iter()
                .max_by(|a, b| a.norm_sqr().total_cmp(&b.norm_sqr()))?;
            let w = z / *big;
            let imaginary = w.iter().map(|c| c.im.abs()).fold(0.0, f64::max);
            (imaginary <= tolerance).then(|| w.map(|c| c.re))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::forward::study::placement_of;
    use nalgebra::Vector3;

    /// P. Dietmaier's platform (1998) whose 40 assembly modes are all real: base joints,
    /// platform joints and leg lengths as published (the CLI tests' files).
    pub(crate) fn dietmaier() -> ([Vector3<f64>; 6], [Vector3<f64>; 6], [f64; 6]) {
        let text = include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/fixtures/dietmaier.toml"
        ));
        let s = crate::io::scenario::Scenario::from_toml_str(text, "dietmaier.toml", None)
            .unwrap_or_else(|e| panic!("{e}"));
        let legs = include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/fixtures/dietmaier_legs.csv"
        ));
        let row: Vec<f64> = legs
            .lines()
            .nth(1)
            .unwrap_or_default()
            .split(',')
            .map(|v| v.parse().unwrap_or(f64::NAN))
            .collect();
        let lengths = std::array::from_fn(|i| row.get(i).copied().unwrap_or(f64::NAN));
        (
            *s.geometry.base_joints(),
            *s.geometry.platform_joints(),
            lengths,
        )
    }

    #[test]
    fn dietmaiers_platform_has_forty_real_solutions() {
        let (base, platform, lengths) = dietmaier();
        let legs = std::array::from_fn(|i| LegParams::real(&platform[i], &base[i], lengths[i]));
        let all = all_solutions(&legs).unwrap_or_else(|| panic!("no start system"));
        assert_eq!(all.len(), GENERIC_SOLUTIONS);
        let real = real_solutions(&all, 1e-8);
        assert_eq!(real.len(), GENERIC_SOLUTIONS);
        for z in &real {
            let (r, t) = placement_of(z);
            for i in 0..6 {
                let l = (r * platform[i] + t - base[i]).norm();
                assert!(
                    (l - lengths[i]).abs() < 1e-9,
                    "leg {i}: {l} vs {}",
                    lengths[i]
                );
            }
        }
    }

    #[test]
    fn paths_that_share_an_end_are_found_for_retracking() {
        let at = |v: f64| Coords::from_element(C::new(v, 0.5));
        let end = |z: Coords, finished: bool| PathEnd { z, finished };
        let ends = [
            end(at(1.0), true),
            end(at(2.0), true),
            end(at(1.0 + 1e-12), true),
            end(at(2.0), false),
            end(Coords::zeros(), true),
            end(Coords::zeros(), true),
        ];
        // 0 and 2 end together; 1 shares its end only with an unfinished path; the last
        // two are on the spurious set e = 0, where many paths end.
        assert_eq!(crowded(&ends), vec![0, 2]);
    }

    #[test]
    fn a_random_complex_platform_has_forty_solutions() {
        let mut rng = SplitMix(42);
        let legs: [LegParams; 6] = std::array::from_fn(|_| LegParams {
            a: std::array::from_fn(|_| rng.complex()),
            b: std::array::from_fn(|_| rng.complex()),
            k: rng.complex(),
        });
        let all = all_solutions(&legs).unwrap_or_else(|| panic!("no start system"));
        assert_eq!(all.len(), GENERIC_SOLUTIONS);
        // Each is a solution: every equation vanishes.
        for z in &all {
            for l in &legs {
                assert!(quadric_value(&leg_quadric(l), z).0.norm() < 1e-9);
            }
            assert!(study_condition(z).0.norm() < 1e-9);
        }
    }
}
