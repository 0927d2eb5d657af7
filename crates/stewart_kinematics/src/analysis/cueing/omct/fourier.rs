//! A sampled signal's component at one frequency over whole periods, and how much of the
//! signal is something else (harmonics, clipping, noise).

use std::f64::consts::TAU;

/// The complex amplitude `c` of the component `Re(c e^{iωt})` of the samples `y` at
/// times `t` (evenly spaced, covering whole periods of `ω`): `(2/N) Σ y_k e^{−iωt_k}`, as
/// `(re, im)`. Over whole periods of evenly spaced samples it is exact for a sine of `ω`
/// plus any of its harmonics below the Nyquist frequency and any constant.
pub fn component(times: &[f64], y: &[f64], omega: f64) -> (f64, f64) {
    let n = y.len().max(1) as f64;
    let (mut re, mut im) = (0.0, 0.0);
    for (t, v) in times.iter().zip(y) {
        let (s, c) = (omega * t).sin_cos();
        re += v * c;
        im -= v * s;
    }
    (2.0 * re / n, 2.0 * im / n)
}

/// The harmonics the samples `y` hold against their fundamental (total harmonic
/// distortion): `√(Σ |c_k|²) / |c_1|` over harmonics 2 to 10 (those below half the
/// sampling rate), each exact over whole periods. A constant offset and whatever is no
/// harmonic of `ω` (a planner's step ripple) do not count; 0 for a pure sine and for an
/// output no larger than `nothing` (rounding's noise on no response at all), about 0.45
/// for a square wave.
pub fn harmonic_distortion(
    times: &[f64],
    y: &[f64],
    omega: f64,
    per_period: usize,
    nothing: f64,
) -> f64 {
    let size = |(re, im): (f64, f64)| re.hypot(im);
    let fundamental = size(component(times, y, omega));
    let harmonics = (2..=10)
        .filter(|k| 2 * k < per_period)
        .map(|k| size(component(times, y, k as f64 * omega)).powi(2))
        .sum::<f64>()
        .sqrt();
    let largest = y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if largest <= nothing || harmonics <= 1e-12 * largest || harmonics == 0.0 {
        0.0
    } else {
        harmonics / fundamental
    }
}

/// Samples per period for a step no longer than `longest`: whole, so that the samples of
/// whole periods are evenly spaced and the component exact.
pub fn steps_per_period(omega: f64, longest: f64) -> usize {
    ((TAU / omega) / longest).ceil().max(8.0) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sine_with_harmonics_and_an_offset_gives_its_fundamental_exactly() {
        let omega = 1.7;
        let n = steps_per_period(omega, 0.01);
        let h = TAU / omega / n as f64;
        let times: Vec<f64> = (0..3 * n).map(|k| k as f64 * h).collect();
        // 2 sin(ωt + 0.3) + 0.5 sin(3ωt) + 4.
        let y: Vec<f64> = times
            .iter()
            .map(|t| 2.0 * (omega * t + 0.3).sin() + 0.5 * (3.0 * omega * t).sin() + 4.0)
            .collect();
        let (re, im) = component(&times, &y, omega);
        // sin(x + 0.3) = Re(e^{i(x + 0.3 − π/2)}).
        let phase = 0.3 - std::f64::consts::FRAC_PI_2;
        assert!((re - 2.0 * phase.cos()).abs() < 1e-12, "{re}");
        assert!((im - 2.0 * phase.sin()).abs() < 1e-12, "{im}");
        // The third harmonic over the fundamental: 0.5 / 2.
        let share = harmonic_distortion(&times, &y, omega, n, 0.0);
        assert!((share - 0.25).abs() < 1e-12, "{share}");
        // Nothing at all: no distortion.
        assert_eq!(
            harmonic_distortion(&times, &vec![1e-13; y.len()], omega, n, 1e-9),
            0.0
        );
    }

    #[test]
    fn a_square_wave_is_mostly_harmonics() {
        let omega = 1.0;
        let n = steps_per_period(omega, 1e-3);
        let h = TAU / omega / n as f64;
        let times: Vec<f64> = (0..n).map(|k| (k as f64 + 0.5) * h).collect();
        let y: Vec<f64> = times.iter().map(|t| (omega * t).sin().signum()).collect();
        let c = component(&times, &y, omega);
        // Its fundamental is 4/π; the rest √(1 − 8/π²) of the fundamental's RMS √8/π.
        assert!((c.0.hypot(c.1) - 4.0 / std::f64::consts::PI).abs() < 1e-5);
        // Its odd harmonics are 1/k of the fundamental: 3, 5, 7 and 9 within the ten.
        let share = harmonic_distortion(&times, &y, omega, n, 0.0);
        let exact = (1.0f64 / 9.0 + 1.0 / 25.0 + 1.0 / 49.0 + 1.0 / 81.0).sqrt();
        assert!((share - exact).abs() < 1e-4, "{share} {exact}");
    }
}
