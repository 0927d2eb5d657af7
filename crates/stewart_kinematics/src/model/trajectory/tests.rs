use super::*;

#[test]
fn seed_sampling_is_linspace_0_10_1001() {
    let s = Sampling::SEED;
    let t: Vec<f64> = s.times().collect();
    assert_eq!(t.len(), 1001);
    assert_eq!(t[0], 0.0);
    assert_eq!(t[1], 0.01);
    assert_eq!(t[500], 5.0);
    assert_eq!(t[1000], 10.0);
    // Every time is the double nearest to k/100.
    for (k, &tk) in t.iter().enumerate() {
        assert_eq!(tk, k as f64 / 100.0);
    }
}

#[test]
fn sampling_refuses_nonsense() {
    assert_eq!(Sampling::new(0.0, 10), Err(SamplingError::Duration(0.0)));
    assert!(Sampling::new(f64::NAN, 10).is_err());
    assert_eq!(Sampling::new(1.0, 1), Err(SamplingError::TooFewSamples(1)));
    assert!(Sampling::with_start(f64::INFINITY, 1.0, 10).is_err());
    let s = Sampling::with_start(2.0, 4.0, 5).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.times().collect::<Vec<_>>(), vec![2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(s.step(), 1.0);
}

/// A table joined by a spline is judged between its rows at the link's rate, and a table
/// too long for that rate is judged as finely as the sample cap allows, never at its rows
/// alone (it once fell back to the rows past 1e7 instants).
#[test]
fn a_spline_table_is_judged_between_its_rows_however_long() {
    let keys = |span: f64| {
        let frames = (0..25)
            .map(|k| Keyframe {
                t: span * f64::from(k) / 24.0,
                pose: Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8 + 0.1 * f64::from(k % 3)], [0.0; 3]),
            })
            .collect();
        Keyframes::new(frames, Interpolation::Cubic).unwrap_or_else(|e| panic!("{e}"))
    };
    for (span, rate) in [(240.0, 100.0), (20_000.0, 1000.0)] {
        let keyframes = keys(span);
        let motion = Motion {
            sampling: Sampling::at_keys(&keyframes).unwrap_or_else(|e| panic!("{e}")),
            trajectory: Trajectory::Keyframes(keyframes),
        };
        let judged = motion.samples_judged(rate);
        assert!(
            judged.len() > 1000 && judged.len() <= MAX_SAMPLES,
            "{span}: {}",
            judged.len()
        );
        assert!(
            judged.times.windows(2).all(|w| w[1] > w[0]),
            "{span}: times increase"
        );
        // Every row among them.
        for k in 0..25 {
            let t = span * f64::from(k) / 24.0;
            assert!(judged.times.contains(&t), "{span}: row {k}");
        }
    }
}
