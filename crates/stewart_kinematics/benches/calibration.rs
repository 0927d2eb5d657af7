//! Calibration: a built `paired` platform (joints a few millimetres off, length offsets)
//! identified from 60 and from 600 measured poses.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::Vector3;
use stewart_kinematics::analysis::calibration::{Held, Measurement, calibrate};
use stewart_kinematics::{
    Geometry, GeometryParams, Pose, model::geometry::PlateJoints, model::layout::Layout,
};

/// A deterministic spread in [−1, 1) from an index and a salt.
fn spread(k: usize, salt: usize) -> f64 {
    ((k * 7919 + salt * 104_729) as f64 * 0.618_033_988_75).fract() * 2.0 - 1.0
}

fn measurements(nominal: &Geometry, count: usize) -> Vec<Measurement> {
    let mut params: GeometryParams = nominal.params().clone();
    let moved = |p: &[Vector3<f64>; 6], salt: usize| {
        std::array::from_fn(|i| {
            p[i] + Vector3::new(spread(i, salt), spread(i, salt + 1), spread(i, salt + 2)) * 3e-3
        })
    };
    params.base = PlateJoints::Points(moved(nominal.base_joints(), 1));
    params.platform = PlateJoints::Points(moved(nominal.platform_joints(), 4));
    let truth = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    (0..count)
        .map(|k| {
            let pose = Pose::from_xyz_rpy_deg(
                [
                    0.1 * spread(k, 10),
                    0.1 * spread(k, 11),
                    0.8 + 0.15 * spread(k, 12),
                ],
                [
                    15.0 * spread(k, 13),
                    15.0 * spread(k, 14),
                    15.0 * spread(k, 15),
                ],
            );
            let legs = truth.leg_lengths(&pose);
            Measurement {
                pose,
                commanded: std::array::from_fn(|i| legs[i] - 0.002 * spread(i, 20)),
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let nominal = Geometry::new(GeometryParams::from_layout(
        1.0,
        0.6,
        0.8,
        Layout::paired(20.0),
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let mut group = c.benchmark_group("calibration");
    for count in [60, 600] {
        let m = measurements(&nominal, count);
        group.bench_function(format!("paired_{count}_poses"), |b| {
            b.iter(|| calibrate(black_box(&nominal), black_box(&m), Held::default()))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
