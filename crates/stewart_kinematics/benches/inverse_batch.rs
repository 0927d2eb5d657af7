//! Batch inverse kinematics throughput (poses per second).
//!
//! `cargo bench -p stewart_kinematics --bench inverse_batch`. The target is at
//! least 30 million poses per second on the 2-core reference machine; criterion prints
//! the throughput as `Melem/s`.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::{BatchSolver, Geometry, Pose};

/// A deterministic spread of poses about the seed's home pose.
fn poses(n: usize) -> Vec<Pose> {
    (0..n)
        .map(|k| {
            let t = k as f64 * 1e-3;
            Pose::from_xyz_rpy_deg(
                [
                    0.15 * (1.3 * t).sin(),
                    0.15 * (0.7 * t).cos(),
                    0.8 + 0.08 * (0.5 * t).sin(),
                ],
                [
                    6.0 * (0.9 * t).sin(),
                    4.0 * (1.1 * t).cos(),
                    8.0 * (0.3 * t).sin(),
                ],
            )
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let geometry = Geometry::seed();
    let solver = BatchSolver::new(&geometry);
    let n = 1_000_000;
    let input = poses(n);
    let mut out = vec![[0.0; 6]; n];

    let mut group = c.benchmark_group("inverse_kinematics");
    group.throughput(Throughput::Elements(n as u64));
    group.sample_size(30);
    group.bench_function("batch_parallel_1M", |b| {
        b.iter(|| solver.solve_parallel(black_box(&input), black_box(&mut out)))
    });
    group.bench_function("batch_serial_1M", |b| {
        b.iter(|| solver.solve_serial(black_box(&input), black_box(&mut out)))
    });
    group.bench_function("single_pose_loop_1M", |b| {
        b.iter_batched(
            || (),
            |()| {
                for (p, o) in input.iter().zip(out.iter_mut()) {
                    *o = geometry.leg_lengths(black_box(p));
                }
            },
            BatchSize::SmallInput,
        )
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
