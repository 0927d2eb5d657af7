//! Forward kinematics speed: one warm-started solve (from the previous sample's pose, as
//! along a trajectory or in a control loop) and one cold solve from home.
//!
//! `cargo bench -p stewart_kinematics --bench forward`. Targets: a warm solve within 1 µs
//! for legs and for servo angles (the `servo-desk` preset), and every
//! assembly mode of Dietmaier's platform (40 real) well under a second.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::{Angle, Pose, Scenario, solve::forward::ForwardOptions};

fn bench(c: &mut Criterion) {
    let scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let g = scenario.geometry;
    let samples = scenario.motion.sample();
    let lengths: Vec<[f64; 6]> = samples.poses.iter().map(|p| g.leg_lengths(p)).collect();
    let options = ForwardOptions::default();
    let n = samples.poses.len();

    c.bench_function("forward_warm_start_per_solve", |b| {
        let mut k = 1;
        b.iter(|| {
            // Solve sample k from the exact pose of sample k − 1 (10 ms earlier).
            let start: &Pose = &samples.poses[k - 1];
            let s = g.forward(black_box(&lengths[k]), start, &options);
            k = if k + 1 < n { k + 1 } else { 1 };
            s
        })
    });
    c.bench_function("forward_cold_start_from_home", |b| {
        let home = g.home_pose();
        let mut k = 0;
        b.iter(|| {
            let s = g.forward(black_box(&lengths[k]), &home, &options);
            k = (k + 1) % n;
            s
        })
    });
}

/// Forward kinematics of a rotary platform from its servo angles, warm and cold.
fn servo_bench(c: &mut Criterion) {
    let scenario = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = scenario.geometry;
    let samples = scenario.motion.sample();
    let angles: Vec<[Angle; 6]> = samples
        .poses
        .iter()
        .map(|p| {
            g.servo_angles(p)
                .and_then(Result::ok)
                .unwrap_or_else(|| panic!("the preset's motion is reachable"))
        })
        .collect();
    let options = ForwardOptions::default();
    let n = samples.poses.len();
    c.bench_function("servo_forward_warm_start_per_solve", |b| {
        let mut k = 1;
        b.iter(|| {
            let start: &Pose = &samples.poses[k - 1];
            let s = g.forward_servos(black_box(&angles[k]), start, &options);
            k = if k + 1 < n { k + 1 } else { 1 };
            s
        })
    });
    c.bench_function("servo_forward_cold_start_from_home", |b| {
        let home = g.home_pose();
        let mut k = 0;
        b.iter(|| {
            let s = g.forward_servos(black_box(&angles[k]), &home, &options);
            k = (k + 1) % n;
            s
        })
    });
}

/// Every assembly mode at once, by homotopy: Dietmaier's platform at its home legs (40
/// real modes of 40), and the paired preset at home. The one-off solve of the generic
/// start system happens before the timing (the first call of a process pays it too).
fn all_modes_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("assembly_modes");
    group.sample_size(20);
    for name in ["dietmaier", "paired"] {
        let scenario = Scenario::preset(name).unwrap_or_else(|e| panic!("{e}"));
        let g = scenario.geometry;
        let legs = g.leg_lengths(&g.home_pose());
        let warm = g
            .all_assembly_modes(&legs)
            .unwrap_or_else(|e| panic!("{e}"));
        if name == "dietmaier" {
            assert_eq!(warm.modes.len(), 40);
        }
        group.bench_function(name, |b| b.iter(|| g.all_assembly_modes(black_box(&legs))));
    }
    group.finish();
}

criterion_group!(benches, bench, servo_bench, all_modes_bench);
criterion_main!(benches);
