//! Narrowing one column's reachable `z` intervals by one more constraint at a time, three
//! ways, from exact to sampled:
//!
//! - [`keep_between_cuts`]: the constraint can change only at known points (roots of its
//!   boundary polynomial), so deciding each piece between them at its midpoint is exact;
//! - [`keep_where_margin`]: the constraint is `margin(z) ≥ 0` for a margin that changes by
//!   at most `|Δz|` (1-Lipschitz, as the distance between two legs is when the platform
//!   moves at a fixed orientation), so a sample with margin `g` decides `±|g|` around it;
//!   the column is split at such certified pieces until they are shorter than the sample
//!   spacing (then sampled at both ends and the middle), and each change of sign between
//!   consecutive samples is found by bisection;
//! - [`keep_sampled`]: anything else, sampled at a spacing and bisected at every change.
//!
//! Intervals are sorted and disjoint. Each function reads `spans`, writes the narrowed
//! intervals into `out` (cleared first) and returns the constraint evaluations it made.

/// One column's reachable `z` intervals, sorted and disjoint.
pub(super) type Spans = Vec<(f64, f64)>;

/// Bisection stops when the bracket is this narrow, metres.
const EDGE_TOLERANCE: f64 = 1e-12;

/// Append `(a, b)` to `out`, joining it to the last interval when they touch.
pub(super) fn push_joined(out: &mut Spans, a: f64, b: f64) {
    match out.last_mut() {
        Some(last) if last.1 >= a => last.1 = last.1.max(b),
        _ => out.push((a, b)),
    }
}

/// A change of the constraint at `edge` while walking up a column: an interval opened at
/// `start` closes there, or one opens.
fn cross(start: &mut Option<f64>, edge: f64, out: &mut Spans) {
    match start.take() {
        Some(s) => push_joined(out, s, edge),
        None => *start = Some(edge),
    }
}

/// The parts of `spans` where `allowed` holds, for a constraint that can change only at
/// `cuts` (in any order; those outside every span are ignored).
pub(super) fn keep_between_cuts(
    spans: &[(f64, f64)],
    cuts: &mut [f64],
    mut allowed: impl FnMut(f64) -> bool,
    out: &mut Spans,
) -> usize {
    out.clear();
    cuts.sort_unstable_by(f64::total_cmp);
    let mut evaluations = 0;
    let mut next_cut = 0;
    for &(a, b) in spans {
        while next_cut < cuts.len() && cuts[next_cut] <= a {
            next_cut += 1;
        }
        let mut start = a;
        loop {
            let end = match cuts.get(next_cut) {
                Some(&c) if c < b => {
                    next_cut += 1;
                    c
                }
                _ => b,
            };
            if end > start {
                evaluations += 1;
                if allowed(0.5 * (start + end)) {
                    push_joined(out, start, end);
                }
            }
            if end >= b {
                break;
            }
            start = end;
        }
    }
    evaluations
}

/// One decided piece of a column, in order along it: the whole piece has the sign of the
/// sample `margin(at) = value`.
#[derive(Clone, Copy)]
struct Piece {
    at: f64,
    value: f64,
}

/// The parts of `spans` where a 1-Lipschitz `margin` is at least zero (see the module
/// docs); pieces shorter than `dz` are decided by three samples.
pub(super) fn keep_where_margin(
    spans: &[(f64, f64)],
    dz: f64,
    mut margin: impl FnMut(f64) -> f64,
    out: &mut Spans,
) -> usize {
    out.clear();
    let mut evaluations = 0;
    let mut pieces: Vec<Piece> = Vec::new();
    for &(a, b) in spans {
        pieces.clear();
        split(a, b, dz, &mut margin, &mut pieces, &mut evaluations);
        // Walk the pieces in order; at each change of sign the edge lies between the two
        // samples (outside both certified pieces), found by bisection on the margin.
        let mut start = (pieces[0].value >= 0.0).then_some(a);
        for w in pieces.windows(2) {
            let (p, q) = (w[0], w[1]);
            if (p.value >= 0.0) == (q.value >= 0.0) {
                continue;
            }
            let edge = bisect(p.at, q.at, p.value >= 0.0, &mut |z| margin(z) >= 0.0);
            evaluations += edge.1;
            cross(&mut start, edge.0, out);
        }
        if let Some(s) = start {
            push_joined(out, s, b);
        }
    }
    evaluations
}

/// Split `[a, b]` into pieces of known sign: the sample at the midpoint decides `±|g|`
/// around it, and what it leaves on either side is split the same way.
fn split(
    a: f64,
    b: f64,
    dz: f64,
    margin: &mut impl FnMut(f64) -> f64,
    pieces: &mut Vec<Piece>,
    evaluations: &mut usize,
) {
    let m = 0.5 * (a + b);
    let value = margin(m);
    *evaluations += 1;
    let reach = value.abs();
    if reach >= 0.5 * (b - a) || !reach.is_finite() {
        pieces.push(Piece { at: m, value });
        return;
    }
    if b - a <= dz {
        // Too short to split further: decided by samples at both ends and the middle, so
        // that a change within it is still bracketed (and a span's own end is sampled).
        for at in [a, m, b] {
            let value = if at == m { value } else { margin(at) };
            *evaluations += usize::from(at != m);
            pieces.push(Piece { at, value });
        }
        return;
    }
    split(a, m - reach, dz, margin, pieces, evaluations);
    pieces.push(Piece { at: m, value });
    split(m + reach, b, dz, margin, pieces, evaluations);
}

/// The parts of `spans` where `allowed` holds, sampled every `dz` (or closer, so that each
/// span has a whole number of steps) and bisected at every change; what is thinner than
/// `dz` may be missed.
pub(super) fn keep_sampled(
    spans: &[(f64, f64)],
    dz: f64,
    mut allowed: impl FnMut(f64) -> bool,
    out: &mut Spans,
) -> usize {
    out.clear();
    let mut evaluations = 0;
    for &(a, b) in spans {
        let count = ((b - a) / dz).ceil().max(1.0) as usize;
        let step = (b - a) / count as f64;
        let mut previous = allowed(a);
        evaluations += count + 1;
        let mut start = previous.then_some(a);
        for k in 1..=count {
            let z = if k == count { b } else { a + k as f64 * step };
            let now = allowed(z);
            if now != previous {
                let (edge, n) = bisect(z - step, z, previous, &mut allowed);
                evaluations += n;
                cross(&mut start, edge, out);
            }
            previous = now;
        }
        if let Some(s) = start {
            push_joined(out, s, b);
        }
    }
    evaluations
}

/// The edge between `lo` (where `allowed` is `lo_inside`) and `hi` (where it is not), to
/// [`EDGE_TOLERANCE`]; also the evaluations made.
fn bisect(
    lo: f64,
    hi: f64,
    lo_inside: bool,
    allowed: &mut impl FnMut(f64) -> bool,
) -> (f64, usize) {
    let (mut a, mut b) = (lo, hi);
    let mut n = 0;
    while b - a > EDGE_TOLERANCE {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        n += 1;
        if allowed(mid) == lo_inside {
            a = mid;
        } else {
            b = mid;
        }
    }
    (0.5 * (a + b), n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn cuts_decide_each_piece_by_its_midpoint() {
        // Allowed where sin z > 0 on [0, 10]: changes at π, 2π, 3π.
        let pi = std::f64::consts::PI;
        let mut cuts = vec![3.0 * pi, pi, 2.0 * pi, 20.0];
        let mut out = Vec::new();
        let n = keep_between_cuts(&[(0.0, 10.0)], &mut cuts, |z| z.sin() > 0.0, &mut out);
        assert_eq!(out, vec![(0.0, pi), (2.0 * pi, 3.0 * pi)]);
        assert_eq!(n, 4);
        // Two spans, a cut on a span's end, adjacent allowed pieces joined.
        let mut cuts = vec![1.0, 2.0, 5.0];
        keep_between_cuts(&[(0.0, 2.0), (4.0, 6.0)], &mut cuts, |z| z < 5.0, &mut out);
        assert_eq!(out, vec![(0.0, 2.0), (4.0, 5.0)]);
    }

    proptest! {
        /// A 1-Lipschitz margin (distance to the nearest of some points, minus a radius):
        /// the kept intervals are exactly where it is ≥ 0, ends to 1e-11, with far fewer
        /// evaluations than samples at the spacing.
        #[test]
        fn lipschitz_scan_finds_the_exact_edges(
            centres in prop::collection::vec(0.0f64..1.0, 1..5),
            radius in 0.001f64..0.05,
        ) {
            let margin = |z: f64| {
                centres.iter().map(|c| (z - c).abs()).fold(f64::INFINITY, f64::min) - radius
            };
            let mut out = Vec::new();
            let n = keep_where_margin(&[(0.0, 1.0)], 1e-3, margin, &mut out);
            // The true answer: [0, 1] minus the union of (c − r, c + r).
            let mut holes: Vec<(f64, f64)> = centres.iter().map(|c| (c - radius, c + radius)).collect();
            holes.sort_by(|p, q| p.0.total_cmp(&q.0));
            let mut want: Spans = Vec::new();
            let mut from = 0.0;
            for (a, b) in holes {
                if a > from { push_joined(&mut want, from, a.min(1.0)); }
                from = from.max(b);
            }
            if from < 1.0 { push_joined(&mut want, from, 1.0); }
            want.retain(|(a, b)| b > a);
            prop_assert_eq!(out.len(), want.len(), "{:?} vs {:?}", out, want);
            for (g, w) in out.iter().zip(&want) {
                prop_assert!((g.0 - w.0).abs() < 1e-11 && (g.1 - w.1).abs() < 1e-11, "{:?} vs {:?}", out, want);
            }
            prop_assert!(n < 1000, "{} evaluations", n);
        }

        /// Sampling finds intervals at least as wide as the spacing, edges to 1e-11.
        #[test]
        fn sampling_finds_wide_intervals(a in 0.05f64..0.45, w in 0.01f64..0.5) {
            let b = a + w;
            let mut out = Vec::new();
            keep_sampled(&[(0.0, 1.0)], 0.005, |z| z > a && z < b, &mut out);
            let want = (a, b.min(1.0));
            prop_assert_eq!(out.len(), 1);
            prop_assert!((out[0].0 - want.0).abs() < 1e-11 && (out[0].1 - want.1).abs() < 1e-11, "{:?}", out);
        }
    }
}
