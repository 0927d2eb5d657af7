use super::*;
use crate::io::scenario::Scenario;

fn seed() -> Geometry {
    Geometry::seed()
}

fn env(text: &str, g: &Geometry) -> Envelope {
    Envelope::parse(text, &g.home_pose()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn envelopes_read_as_written() {
    let g = seed();
    let e = env("x=±0.1, y=+-0.05, z=0.7..0.9, roll=±10, yaw=15", &g);
    assert_eq!(e.lo, [-0.1, -0.05, 0.7, -10.0, 0.0, 15.0]);
    assert_eq!(e.hi, [0.1, 0.05, 0.9, 10.0, 0.0, 15.0]);
    // Left out: home (z = 0.8 for the seed).
    let e = env("pitch=-5..5", &g);
    assert_eq!((e.lo[2], e.hi[2]), (0.8, 0.8));
    assert_eq!((e.lo[4], e.hi[4]), (-5.0, 5.0));
}

#[test]
fn bad_envelopes_are_refused_by_name() {
    let home = seed().home_pose();
    for (text, words) in [
        ("", "empty"),
        ("  ", "empty"),
        ("x", "NAME=RANGE"),
        ("w=1", "`w` is not a coordinate"),
        ("x=1,x=2", "given twice"),
        ("z=0.9..0.7", "inverted"),
        ("x=NaN", "not a finite number"),
        ("x=inf", "not a finite number"),
        ("x=±-1", "cannot be negative"),
        ("x=", "no range given"),
        ("x=0.1..abc", "`abc` is not a number"),
        ("roll=±400", "beyond ±180 °"),
        ("z=0..1e9", "beyond ±100 m"),
    ] {
        let e = Envelope::parse(text, &home)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.contains(words), "{text:?}: {e}");
    }
}

/// Every actuator value over a grid of `n` points per free coordinate.
fn brute(g: &Geometry, e: &Envelope, n: usize) -> Vec<[f64; 2]> {
    let free = e.free();
    let mut out = vec![[f64::INFINITY, f64::NEG_INFINITY]; 6];
    let total = n.pow(free.len() as u32);
    for k in 0..total {
        let mut u = [0.0; 6];
        let mut rest = k;
        for &c in &free {
            u[c] = (rest % n) as f64 / (n - 1) as f64;
            rest /= n;
        }
        if let Ok(v) = g.actuator_values_at(&e.pose_at(&u)) {
            for i in 0..6 {
                out[i][0] = out[i][0].min(v[i]);
                out[i][1] = out[i][1].max(v[i]);
            }
        }
    }
    out
}

/// The search finds at least the brute-force extremes, and each value is the actuator's
/// value at the pose it names.
fn agrees_with_brute_force(g: &Geometry, e: &Envelope, n: usize, slack: f64) {
    let report = envelope_needs(g, e);
    let grid = brute(g, e, n);
    assert_eq!(report.actuators.len(), 6);
    for (i, [lo, hi]) in report.actuators.iter().enumerate() {
        assert!(
            lo.value <= grid[i][0] + 1e-12,
            "leg {i}: min {} vs grid {}",
            lo.value,
            grid[i][0]
        );
        assert!(
            hi.value >= grid[i][1] - 1e-12,
            "leg {i}: max {} vs grid {}",
            hi.value,
            grid[i][1]
        );
        // Not beyond what a finer look allows either (the grid misses at most `slack`).
        assert!(
            grid[i][0] - lo.value <= slack,
            "leg {i}: min {} far below {}",
            lo.value,
            grid[i][0]
        );
        assert!(
            hi.value - grid[i][1] <= slack,
            "leg {i}: max {} far above {}",
            hi.value,
            grid[i][1]
        );
        for x in [lo, hi] {
            let p = x.pose;
            let pose = Pose::from_xyz_rpy_deg([p[0], p[1], p[2]], [p[3], p[4], p[5]]);
            let v = g
                .actuator_values_at(&pose)
                .unwrap_or_else(|e| panic!("{e}"));
            assert!((v[i] - x.value).abs() < 1e-12);
            for (k, c) in p.iter().enumerate() {
                assert!(
                    *c >= e.lo[k] - 1e-12 && *c <= e.hi[k] + 1e-12,
                    "outside the box"
                );
            }
        }
    }
}

#[test]
fn the_seed_envelope_matches_dense_brute_force() {
    let g = seed();
    let e = env("x=±0.1,y=±0.1,z=0.7..0.9,roll=±10,pitch=±10,yaw=±15", &g);
    agrees_with_brute_force(&g, &e, 7, 2e-3);
}

#[test]
fn an_extreme_inside_the_range_is_found_exactly() {
    // Leg length over a wide yaw swing peaks strictly inside the range: no corner has it.
    let g = seed();
    let e = env("yaw=-70..70", &g);
    let report = envelope_needs(&g, &e);
    let grid = brute(&g, &e, 140_001);
    for (i, [lo, hi]) in report.actuators.iter().enumerate() {
        assert!(
            (hi.value - grid[i][1]).abs() < 1e-9,
            "leg {i}: {} vs {}",
            hi.value,
            grid[i][1]
        );
        assert!(
            (lo.value - grid[i][0]).abs() < 1e-9,
            "leg {i}: {} vs {}",
            lo.value,
            grid[i][0]
        );
    }
    let interior = report
        .actuators
        .iter()
        .flatten()
        .filter(|x| x.pose[5].abs() < 69.9)
        .count();
    assert!(interior > 0, "this test needs an interior extreme");
}

#[test]
fn a_servo_platform_matches_brute_force() {
    let s = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let e = env("x=±0.01,y=±0.01,roll=±5,pitch=±5,yaw=±8", g);
    agrees_with_brute_force(g, &e, 7, 0.5);
}

#[test]
fn the_worst_conditioning_is_at_least_the_grids() {
    let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let e = env("x=±0.1,y=±0.1,roll=±10,pitch=±10,yaw=±20", g);
    let report = envelope_needs(g, &e);
    let worst = report.worst_condition.unwrap_or_else(|| panic!("none"));
    let mut grid: f64 = 0.0;
    for k in 0..4usize.pow(5) {
        let mut u = [0.0; 6];
        let mut rest = k;
        for c in [0, 1, 3, 4, 5] {
            u[c] = (rest % 4) as f64 / 3.0;
            rest /= 4;
        }
        let c = g
            .actuated_conditioning(&e.pose_at(&u))
            .unwrap_or_else(|| panic!("unreachable"));
        grid = grid.max(c.condition_number.unwrap_or(f64::INFINITY));
    }
    assert!(worst.value >= grid - 1e-9, "{} < {grid}", worst.value);
    assert!(worst.value.is_finite() && worst.value > 1.0);
}

#[test]
fn a_fixed_pose_is_its_own_envelope() {
    let g = seed();
    let e = env("z=0.8", &g);
    let report = envelope_needs(&g, &e);
    let home = g.leg_lengths(&g.home_pose());
    for (i, [lo, hi]) in report.actuators.iter().enumerate() {
        assert!((lo.value - home[i]).abs() < 1e-15 && (hi.value - home[i]).abs() < 1e-15);
    }
}
