//! The batch kernels alone, for a profiler: `cargo run --release -p stewart_kinematics
//! --example batch_profile -- <legs|servos|rows> [poses] [repeats]` solves the same poses
//! `repeats` times and prints nanoseconds per pose (one thread for `legs` and `servos`;
//! `rows`, the table path of `solve --poses`, runs on rayon's threads: set
//! `RAYON_NUM_THREADS=1` for one). Under
//! `valgrind --tool=callgrind --toggle-collect='*vectorize*'` the instructions counted are
//! the kernel's alone (`scripts/batch-profile.sh` divides them by the poses).

use std::hint::black_box;
use std::time::Instant;
use stewart_kinematics::solve::batch::ServoBatch;
use stewart_kinematics::{BatchSolver, Geometry, Pose, Scenario};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kind = args.first().map_or("legs", String::as_str);
    if kind == "table" {
        return read_table(args.get(1).map_or("table.csv", String::as_str));
    }
    let number = |k: usize, default: usize| {
        args.get(k)
            .map_or(Ok(default), |s| s.parse::<usize>())
            .unwrap_or_else(|e| panic!("argument {k}: {e}"))
    };
    let (n, repeats) = (number(1, 1_000_000), number(2, 20));
    let geometry = match kind {
        "servos" => {
            Scenario::preset("servo-desk")
                .unwrap_or_else(|e| panic!("{e}"))
                .geometry
        }
        _ => Geometry::seed(),
    };
    let home = geometry.home_pose().to_row();
    // Small motions about home, spread by a fixed irrational stride.
    let rows: Vec<[f64; 6]> = (0..n)
        .map(|k| {
            let s = (k as f64 * 0.618_033_988_749_895).fract() - 0.5;
            let scale = [0.01, 0.01, 0.005, 4.0, 4.0, 8.0];
            std::array::from_fn(|c| home[c] + scale[c] * s * if c % 2 == 0 { 1.0 } else { -1.0 })
        })
        .collect();
    let poses: Vec<Pose> = rows.iter().map(Pose::from_row).collect();
    let mut out = vec![[0.0; 6]; n];
    let legs = BatchSolver::new(&geometry);
    let servos = ServoBatch::new(&geometry);
    let start = Instant::now();
    for _ in 0..repeats {
        match (kind, &servos) {
            ("legs", _) => legs.solve_serial(black_box(&poses), &mut out),
            ("servos", Some(s)) => s
                .solve_serial(black_box(&poses), &mut out)
                .unwrap_or_else(|e| panic!("unreachable {e:?}")),
            ("rows", _) => geometry
                .actuator_values_rows(black_box(&rows), &mut out)
                .unwrap_or_else(|e| panic!("{e:?}")),
            _ => panic!("kind: legs, servos or rows"),
        }
    }
    let seconds = start.elapsed().as_secs_f64();
    // FNV-1a over every bit of the results: equal digests, equal results.
    let digest = out
        .as_flattened()
        .iter()
        .fold(0xcbf2_9ce4_8422_2325_u64, |h, v| {
            (h ^ v.to_bits()).wrapping_mul(0x0100_0000_01b3)
        });
    println!(
        "{kind}: {:.2} ns per pose ({n} poses × {repeats}); digest {digest:016x}",
        seconds * 1e9 / (n * repeats) as f64,
    );
}

/// `table FILE`: the file read as `solve --poses` reads a pose table, then parsed, each
/// timed (the bytes read once, as the command does).
fn read_table(path: &str) {
    use stewart_kinematics::io::file::FileKind;
    use stewart_kinematics::model::trajectory::PoseTable;
    let start = Instant::now();
    let bytes = stewart_kinematics::io::file::read_file(path.as_ref(), FileKind::Table)
        .unwrap_or_else(|e| panic!("{e}"));
    let read = start.elapsed();
    let table = PoseTable::read_bytes(bytes, path).unwrap_or_else(|e| panic!("{e}"));
    println!(
        "table: {} poses; read {:.0} ms, parsed {:.0} ms",
        table.poses.len(),
        read.as_secs_f64() * 1e3,
        (start.elapsed() - read).as_secs_f64() * 1e3
    );
}
