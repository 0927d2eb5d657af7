//! Constant-orientation workspace at a million samples (1000 × 1000 columns, each
//! solved exactly in z), stroke limits only. The target: under 100 ms on the
//! 2-core reference machine. `cargo bench -p stewart_kinematics --bench workspace`.
//! Also a rotary platform's workspace, which is sampled rather than exact per column, and
//! the viewer's coarse and refined workspace surfaces.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::analysis::workspace::WorkspaceSurface;
use stewart_kinematics::{Angle, Scenario, model::limits::Limits};

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
                workspace::constant_orientation_workspace(
                    &g,
                    &Limits::default(),
                    black_box(orientation),
                    1000,
                )
            })
        });
    }
    group.finish();
}

/// A rotary platform's workspace (columns sampled in z and bisected at the edges),
/// 200 × 200 columns of the `servo-desk` preset, servo range only.
fn servo_bench(c: &mut Criterion) {
    let g = Scenario::preset("servo-desk")
        .unwrap_or_else(|e| panic!("{e}"))
        .geometry;
    let mut group = c.benchmark_group("workspace");
    group.sample_size(10);
    group.bench_function("servo_desk_200x200_columns", |b| {
        b.iter(|| {
            workspace::constant_orientation_workspace(
                &g,
                &Limits::default(),
                black_box([Angle::ZERO; 3]),
                200,
            )
        })
    });
    group.finish();
}

/// What the viewer computes while a slider is dragged: the workspace and its surface mesh,
/// first on a 128 × 128 column grid, then refined on 512 × 512. Targets: under 30 ms and
/// 300 ms on the 2-core reference machine.
fn viewer_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("workspace_surface");
    group.sample_size(20);
    for preset in ["seed", "paired"] {
        let g = Scenario::preset(preset)
            .unwrap_or_else(|e| panic!("{e}"))
            .geometry;
        let orientation = [5.0, -3.0, 10.0].map(Angle::from_degrees);
        for n in [128, 512] {
            group.bench_function(format!("{preset}_tilted_{n}x{n}"), |b| {
                b.iter(|| {
                    let ws = workspace::constant_orientation_workspace(
                        &g,
                        &Limits::default(),
                        orientation,
                        n,
                    )
                    .unwrap_or_else(|e| panic!("{e}"));
                    WorkspaceSurface::from_workspace(black_box(&ws))
                })
            });
        }
    }
    group.finish();
}

/// The same under each preset's own limits: the paired platform's joint cones and leg
/// clearance (cones exact per column, clearance by the certified scan), and the servo
/// desk's servo range and rod cones (exact per column) with and without its rod clearance
/// (sampled along each column, so 256 × 256 at most in the viewer).
fn limited_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("workspace_surface_limits");
    group.sample_size(10);
    let orientation = [5.0, -3.0, 10.0].map(Angle::from_degrees);
    for (preset, clearance, sizes) in [
        ("paired", true, [128, 512]),
        ("servo-desk", false, [128, 512]),
        ("servo-desk", true, [128, 512]),
    ] {
        let s = Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}"));
        let mut limits = s.limits;
        if !clearance {
            limits.leg_radius = None;
        }
        let label = if clearance { "" } else { "_no_clearance" };
        for n in sizes {
            group.bench_function(format!("{preset}{label}_tilted_{n}x{n}"), |b| {
                b.iter(|| {
                    let ws = workspace::constant_orientation_workspace(
                        &s.geometry,
                        &limits,
                        orientation,
                        n,
                    )
                    .unwrap_or_else(|e| panic!("{e}"));
                    WorkspaceSurface::from_workspace(black_box(&ws))
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench, servo_bench, viewer_bench, limited_bench);
criterion_main!(benches);
