//! Batch inverse kinematics throughput (poses per second).
//!
//! `cargo bench -p stewart_kinematics --bench inverse_batch`. The target is at
//! least 30 million poses per second on the 2-core reference machine; criterion prints
//! the throughput as `Melem/s`.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::model::actuator::Actuator;
use stewart_kinematics::model::rotary::RotaryActuators;
use stewart_kinematics::{
    Angle, BatchSolver, Geometry, GeometryParams, Pose, model::geometry::PlateJoints,
    model::layout::Layout, solve::batch::ServoBatch,
};

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
    // The same poses as rows of a table (x, y, z, roll, pitch, yaw in metres and degrees),
    // as `solve --poses` and the Python package hand them in.
    let rows: Vec<[f64; 6]> = input.iter().map(Pose::to_row).collect();
    group.bench_function("batch_rows_parallel_1M", |b| {
        b.iter(|| {
            geometry
                .actuator_values_rows(black_box(&rows), black_box(&mut out))
                .unwrap_or_else(|e| panic!("{e:?}"))
        })
    });
    // A fresh result each time, as a caller that keeps no buffer gets it (the Python
    // package's `p.ik(poses)` without `out=`): the 48 MB are new pages to fault in.
    group.bench_function("batch_parallel_1M_new_output", |b| {
        b.iter(|| geometry.leg_lengths_batch(black_box(&input)))
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

/// The desktop servo platform of `tests/fixtures/rotary.toml`, and small motions about its home.
fn servo_bench(c: &mut Criterion) {
    let mut p = GeometryParams::from_layout(0.08, 0.06, 0.117, Layout::seed());
    p.base = PlateJoints::Circle {
        radius: 0.08,
        angles: [350.0, 10.0, 110.0, 130.0, 230.0, 250.0].map(Angle::from_degrees),
    };
    p.platform = PlateJoints::Circle {
        radius: 0.06,
        angles: [345.0, 15.0, 105.0, 135.0, 225.0, 255.0].map(Angle::from_degrees),
    };
    p.actuator = Actuator::Rotary(
        RotaryActuators::new(0.025, 0.12, [255.0, 105.0, 15.0, 225.0, 135.0, 345.0], None)
            .unwrap_or_else(|e| panic!("{e}")),
    );
    let geometry = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
    let solver = ServoBatch::new(&geometry).unwrap_or_else(|| panic!("not rotary"));
    let n = 1_000_000;
    let input: Vec<Pose> = (0..n)
        .map(|k| {
            let t = k as f64 * 1e-3;
            Pose::from_xyz_rpy_deg(
                [
                    0.01 * (1.3 * t).sin(),
                    0.01 * (0.7 * t).cos(),
                    0.117 + 0.005 * (0.5 * t).sin(),
                ],
                [
                    4.0 * (0.9 * t).sin(),
                    4.0 * (1.1 * t).cos(),
                    8.0 * (0.3 * t).sin(),
                ],
            )
        })
        .collect();
    let mut out = vec![[0.0; 6]; n];
    let mut group = c.benchmark_group("servo_angles");
    group.throughput(Throughput::Elements(n as u64));
    group.sample_size(20);
    group.bench_function("batch_parallel_1M", |b| {
        b.iter(|| {
            solver
                .solve_parallel(black_box(&input), black_box(&mut out))
                .unwrap_or_else(|e| panic!("unreachable {e:?}"))
        })
    });
    group.finish();
}

/// The memory traffic of the batch without its arithmetic: each pose's six coordinates
/// read (48 bytes) and six values written (48 bytes), on both cores in the batch's chunks.
/// Its rate is the most poses per second the batch could reach if memory were the limit;
/// 1 M poses (96 MB in all) as in the batch benchmark, and 16 M (1.5 GB, far beyond any
/// cache) for main memory.
fn memory_bound_bench(c: &mut Criterion) {
    use rayon::prelude::*;
    use stewart_kinematics::solve::batch::CHUNK;
    let mut group = c.benchmark_group("memory_bound");
    group.sample_size(10);
    for (name, n) in [
        ("copy_1M_poses_parallel", 1_000_000),
        ("copy_16M_poses_parallel", 16_000_000),
    ] {
        let input = poses(n);
        let mut out = vec![[0.0; 6]; n];
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(name, |b| {
            b.iter(|| {
                black_box(&input)
                    .par_chunks(CHUNK)
                    .zip(black_box(&mut out).par_chunks_mut(CHUNK))
                    .for_each(|(p, o)| {
                        for (p, o) in p.iter().zip(o) {
                            *o = p.to_coordinates();
                        }
                    })
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench, servo_bench, memory_bound_bench);
criterion_main!(benches);
