//! Finite differences of a sampled series on a (possibly uneven) time grid: what leg
//! speeds, accelerations and jerks (`checks::rates`) and the payload's velocities and
//! accelerations (`forces`) are made of.
//!
//! Interior samples use central differences; at the two end samples the first
//! difference is one-sided (the first and last interval) and the second difference
//! takes its neighbour's value (the three-point formula needs a sample on each side).

use std::ops::{Mul, Sub};

/// First derivative at sample `k`: `(v[k+1] − v[k−1]) / (t[k+1] − t[k−1])`, one-sided at
/// the ends. `None` with fewer than two samples.
pub fn first_difference<T>(times: &[f64], values: &[T], k: usize) -> Option<T>
where
    T: Copy + Sub<Output = T> + Mul<f64, Output = T>,
{
    let n = values.len();
    if n < 2 {
        return None;
    }
    let (a, b) = (k.saturating_sub(1), (k + 1).min(n - 1));
    Some((values[b] - values[a]) * (1.0 / (times[b] - times[a])))
}

/// Second derivative at sample `k` by the three-point formula on an uneven grid (exact
/// for quadratics); the end samples take their neighbour's value. `None` with fewer than
/// three samples.
pub fn second_difference<T>(times: &[f64], values: &[T], k: usize) -> Option<T>
where
    T: Copy + Sub<Output = T> + Mul<f64, Output = T>,
{
    let n = values.len();
    if n < 3 {
        return None;
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
        // The ends are one-sided: the first interval's slope.
        let d0 = first_difference(&even, &v, 0).unwrap_or(f64::NAN);
        assert!((d0 - (v[1] - v[0]) / 0.1).abs() < 1e-15);
        assert_eq!(first_difference(&[0.0], &[1.0], 0), None);
        assert_eq!(second_difference(&[0.0, 1.0], &[1.0, 2.0], 0), None);
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
