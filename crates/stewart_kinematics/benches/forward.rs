//! Forward kinematics speed: one warm-started solve (from the previous sample's pose, as
//! along a trajectory or in a control loop) and one cold solve from home.
//!
//! `cargo bench -p stewart_kinematics --bench forward`. The target: a warm solve
//! under 2 µs.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::{ForwardOptions, Pose, Scenario};

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

criterion_group!(benches, bench);
criterion_main!(benches);
