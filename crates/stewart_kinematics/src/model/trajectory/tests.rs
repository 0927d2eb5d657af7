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
