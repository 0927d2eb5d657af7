//! Finite differences of a sampled series on a (possibly uneven) time grid: what leg
//! speeds, accelerations and jerks (`checks::rates`) and the payload's velocities and
//! accelerations (`forces`) are made of.
//!
//! Interior samples use central differences; at the two end samples the differences are
//! one-sided and of the same (second) order: the derivatives there of the parabola through
//! the three end samples (first derivative) and of the cubic through the four (second).
//! With fewer samples the ends fall back to what there is (the one interval's slope; the
//! three samples' one parabola).

use std::ops::{Mul, Sub};

/// First derivative at sample `k`: `(v[k+1] − v[k−1]) / (t[k+1] − t[k−1])`; at the ends
/// the slope there of the parabola through the three end samples (exact for quadratics),
/// or of the one interval when there are only two samples. `None` with fewer than two.
pub fn first_difference<T>(times: &[f64], values: &[T], k: usize) -> Option<T>
where
    T: Copy + Sub<Output = T> + Mul<f64, Output = T>,
{
    let n = values.len();
    if n < 2 {
        return None;
    }
    let slope = |i: usize| (values[i + 1] - values[i]) * (1.0 / (times[i + 1] - times[i]));
    if n == 2 {
        return Some(slope(0));
    }
    if k == 0 {
        // p'(t0) = f[t0,t1] − (t1 − t0) f[t0,t1,t2]
        let curvature = (slope(1) - slope(0)) * (1.0 / (times[2] - times[0]));
        return Some(slope(0) - curvature * (times[1] - times[0]));
    }
    if k >= n - 1 {
        // p'(tₙ) = f[tₙ₋₁,tₙ] + (tₙ − tₙ₋₁) f[tₙ₋₂,tₙ₋₁,tₙ]
        let (a, b) = (n - 3, n - 2);
        let curvature = (slope(b) - slope(a)) * (1.0 / (times[n - 1] - times[a]));
        return Some(slope(b) - curvature * (times[b] - times[n - 1]));
    }
    let (a, b) = (k - 1, k + 1);
    Some((values[b] - values[a]) * (1.0 / (times[b] - times[a])))
}

/// Second derivative at sample `k` by the three-point formula on an uneven grid (exact
/// for quadratics); at the ends that of the cubic through the four end samples (exact for
/// cubics), or, with three samples only, the middle's. `None` with fewer than three.
pub fn second_difference<T>(times: &[f64], values: &[T], k: usize) -> Option<T>
where
    T: Copy + Sub<Output = T> + Mul<f64, Output = T>,
{
    let n = values.len();
    if n < 3 {
        return None;
    }
    let slope = |i: usize| (values[i + 1] - values[i]) * (1.0 / (times[i + 1] - times[i]));
    // f[tᵢ, tᵢ₊₁, tᵢ₊₂]
    let curvature = |i: usize| (slope(i + 1) - slope(i)) * (1.0 / (times[i + 2] - times[i]));
    if n >= 4 && (k == 0 || k >= n - 1) {
        // p''(t) = 2 f[t₀,t₁,t₂] + 2 f[t₀,…,t₃] ((t − t₀) + (t − t₁) + (t − t₂)) for the
        // nodes t₀…t₃ in either order (divided differences are symmetric).
        let a = if k == 0 { 0 } else { n - 4 };
        let third = (curvature(a + 1) - curvature(a)) * (1.0 / (times[a + 3] - times[a]));
        let (near, t) = if k == 0 {
            (curvature(a), times[a])
        } else {
            (curvature(a + 1), times[a + 3])
        };
        let nodes: [usize; 3] = if k == 0 {
            [a, a + 1, a + 2]
        } else {
            [a + 3, a + 2, a + 1]
        };
        let spread: f64 = nodes.iter().map(|&i| t - times[i]).sum();
        return Some(near * 2.0 - third * (-2.0 * spread));
    }
    let k = k.clamp(1, n - 2);
    let (h0, h1) = (times[k] - times[k - 1], times[k + 1] - times[k]);
    let ahead = (values[k + 1] - values[k]) * (1.0 / h1);
    let back = (values[k] - values[k - 1]) * (1.0 / h0);
    Some((ahead - back) * (2.0 / (h0 + h1)))
}

/// Third derivative at sample `k` from the four samples around it (`k − 1 … k + 2`,
/// shifted inside at the ends): six times their third divided difference, exact for cubics
/// on an uneven grid. `None` with fewer than four samples.
pub fn third_difference<T>(times: &[f64], values: &[T], k: usize) -> Option<T>
where
    T: Copy + Sub<Output = T> + Mul<f64, Output = T>,
{
    let n = values.len();
    if n < 4 {
        return None;
    }
    let a = k.saturating_sub(1).min(n - 4);
    let (t, v) = (&times[a..a + 4], &values[a..a + 4]);
    let first = |i: usize| (v[i + 1] - v[i]) * (1.0 / (t[i + 1] - t[i]));
    let second = |i: usize| (first(i + 1) - first(i)) * (1.0 / (t[i + 2] - t[i]));
    Some((second(1) - second(0)) * (6.0 / (t[3] - t[0])))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_a_parabola_on_an_uneven_grid() {
        // v = 1 + 0.3 t + t²: v' = 0.3 + 2t, v'' = 2.
        let times = [0.0, 0.1, 0.25, 0.3, 0.5];
        let values: Vec<f64> = times.iter().map(|&t| 1.0 + 0.3 * t + t * t).collect();
        for k in 0..times.len() {
            let a = second_difference(&times, &values, k).unwrap_or(f64::NAN);
            assert!((a - 2.0).abs() < 1e-12, "{k}: {a}");
        }
        // Interior central differences on an even stretch are exact too.
        let even = [0.0, 0.1, 0.2];
        let v: Vec<f64> = even.iter().map(|&t| 1.0 + 0.3 * t + t * t).collect();
        let d = first_difference(&even, &v, 1).unwrap_or(f64::NAN);
        assert!((d - (0.3 + 2.0 * 0.1)).abs() < 1e-12);
        // The ends are one-sided and exact for the parabola too; with two samples the
        // one interval's slope.
        for (k, t) in [(0, 0.0), (2, 0.2)] {
            let d = first_difference(&even, &v, k).unwrap_or(f64::NAN);
            assert!((d - (0.3 + 2.0 * t)).abs() < 1e-12, "{k}: {d}");
        }
        let d = first_difference(&times, &values, 4).unwrap_or(f64::NAN);
        assert!((d - (0.3 + 2.0 * 0.5)).abs() < 1e-12, "{d}");
        let d = first_difference(&[0.0, 0.5], &[1.0, 2.0], 1).unwrap_or(f64::NAN);
        assert_eq!(d, 2.0);
        assert_eq!(first_difference(&[0.0], &[1.0], 0), None);
        assert_eq!(second_difference(&[0.0, 1.0], &[1.0, 2.0], 0), None);
    }

    #[test]
    fn the_ends_are_second_order_exact_for_a_cubics_second_derivative() {
        // v = 2 − t + 0.5 t² + 1.5 t³: v'' = 1 + 9 t, exact at both ends (four samples);
        // v' = −1 + t + 4.5 t², to O(h²) at the ends: halving the spacing quarters the error.
        let cubic = |t: f64| 2.0 - t + 0.5 * t * t + 1.5 * t * t * t;
        let times = [0.0, 0.07, 0.2, 0.26, 0.5, 0.55];
        let values: Vec<f64> = times.iter().map(|&t| cubic(t)).collect();
        for k in [0, 5] {
            let a = second_difference(&times, &values, k).unwrap_or(f64::NAN);
            assert!((a - (1.0 + 9.0 * times[k])).abs() < 1e-9, "{k}: {a}");
        }
        let error = |h: f64, at_end: bool| {
            let t: Vec<f64> = (0..6).map(|i| 1.0 + h * f64::from(i)).collect();
            let v: Vec<f64> = t.iter().map(|&t| cubic(t)).collect();
            let k = if at_end { 5 } else { 0 };
            let d = first_difference(&t, &v, k).unwrap_or(f64::NAN);
            (d - (-1.0 + t[k] + 4.5 * t[k] * t[k])).abs()
        };
        for at_end in [false, true] {
            let ratio = error(0.01, at_end) / error(0.005, at_end);
            assert!((ratio - 4.0).abs() < 0.05, "{at_end}: {ratio}");
        }
    }

    #[test]
    fn the_third_difference_is_exact_for_a_cubic_on_an_uneven_grid() {
        // v = 2 − t + 0.5 t² + 1.5 t³: its third derivative is 9 everywhere.
        let times = [0.0, 0.07, 0.2, 0.26, 0.5, 0.55];
        let values: Vec<f64> = times
            .iter()
            .map(|&t| 2.0 - t + 0.5 * t * t + 1.5 * t * t * t)
            .collect();
        for k in 0..times.len() {
            let j = third_difference(&times, &values, k).unwrap_or(f64::NAN);
            assert!((j - 9.0).abs() < 1e-9, "{k}: {j}");
        }
        // A parabola has none.
        let p: Vec<f64> = times.iter().map(|&t| 3.0 * t * t).collect();
        assert!(third_difference(&times, &p, 2).is_some_and(|j| j.abs() < 1e-9));
        assert_eq!(
            third_difference(&[0.0, 1.0, 2.0], &[1.0, 2.0, 3.0], 1),
            None
        );
    }
}
