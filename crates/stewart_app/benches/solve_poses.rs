//! Where `stewart solve --poses` spends its time on a 1 M-row table: reading the CSV
//! (parse, checks, poses), solving the legs on all cores, and writing the result CSV —
//! each stage alone, in memory, by the same functions the command calls.
//! `cargo bench -p stewart_app --bench solve_poses`; `scripts/bench-inputs.sh` times the
//! whole command with its files (and `scripts/profile.sh solve` shows the rest: start-up,
//! file reads and writes, the kernel).

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use stewart_app::export::tables::{solve_table, trajectory_table, write_solved_csv};
use stewart_kinematics::Scenario;
use stewart_kinematics::model::trajectory::{PoseTable, Sampling};

const ROWS: usize = 1_000_000;

fn bench(c: &mut Criterion) {
    // The table scripts/bench-inputs.sh uses: the paired preset's motion at 1 M samples,
    // as `solve` writes it (time, pose and leg columns).
    let mut scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let sampling = &scenario.motion.sampling;
    scenario.motion.sampling =
        Sampling::with_start(sampling.start(), sampling.duration(), ROWS as u64)
            .unwrap_or_else(|e| panic!("{e}"));
    let table = trajectory_table(&scenario);
    let solved = solve_table(&scenario.geometry, &table, |k| format!("row {k}"))
        .unwrap_or_else(|e| panic!("{e}"));
    let mut csv = Vec::new();
    write_solved_csv(&mut csv, &table, &solved).unwrap_or_else(|e| panic!("{e}"));
    let read = || PoseTable::read(black_box(csv.as_slice()), "table.csv");

    let mut group = c.benchmark_group("solve_poses_1M");
    group.sample_size(10);
    group.throughput(Throughput::Elements(ROWS as u64));
    group.bench_function("read_csv", |b| b.iter(read));
    group.bench_function("solve", |b| {
        b.iter(|| {
            solve_table(&scenario.geometry, black_box(&table), |k| {
                format!("row {k}")
            })
        })
    });
    let mut out = Vec::with_capacity(csv.len());
    group.bench_function("write_csv", |b| {
        b.iter(|| {
            out.clear();
            write_solved_csv(&mut out, black_box(&table), &solved)
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
