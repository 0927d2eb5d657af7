//! Constant-orientation workspace at a million samples (1000 × 1000 columns, each
//! solved exactly in z), stroke limits only. The target: under 100 ms on the
//! 2-core reference machine. `cargo bench -p stewart_kinematics --bench workspace`.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::{Angle, Limits, Scenario};

fn bench(c: &mut Criterion) {
    let g = Scenario::preset("paired")
        .unwrap_or_else(|e| panic!("{e}"))
        .geometry;
    let mut group = c.benchmark_group("workspace");
    group.sample_size(20);
    for (name, rpy) in [
        ("level_1M_columns", [0.0, 0.0, 0.0]),
        ("tilted_1M_columns", [5.0, -3.0, 10.0]),
    ] {
        let orientation = rpy.map(Angle::from_degrees);
        group.bench_function(name, |b| {
            b.iter(|| {
                g.constant_orientation_workspace(&Limits::default(), black_box(orientation), 1000)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
