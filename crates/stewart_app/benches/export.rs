//! Export throughput: the seed trajectory rendered at 1280×720 and encoded to PNG files
//! or a GIF by the same pipeline as `stewart render` (GPU render and read-back on one
//! thread, PNG encoding or GIF quantising on worker threads). Each iteration exports 60 frames; criterion reports
//! frames per second. `cargo bench -p stewart_app --bench export`.

use std::sync::atomic::AtomicBool;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use indicatif::ProgressBar;
use stewart_app::export::encode::{FrameSink, export};
use stewart_app::export::frames::{FrameJob, FrameSource, default_camera};
use stewart_kinematics::Scenario;
use stewart_render::{Overlays, Theme};

const FRAMES: usize = 60;

fn bench(c: &mut Criterion) {
    let scenario = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let job = FrameJob {
        first_index: 0,
        times: scenario.motion.sampling.times().collect(),
        width: 1280,
        height: 720,
        theme: Theme::DARK,
        camera: Some(default_camera(&scenario)),
        composite: false,
        overlays: Overlays::default(),
        readout: None,
        lang: stewart_app::i18n::Lang::En,
        parts: stewart_render::appearance::parts::PartSet::none(),
    };
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut group = c.benchmark_group("export_1280x720");
    group.sample_size(10);
    group.throughput(Throughput::Elements(FRAMES as u64));
    let mut run = 0;
    // One frame per 100 Hz sample for PNG files, the GIF's default 25 frames/s.
    for (name, extension, fps) in [("png_frames", "", 100.0), ("gif", ".gif", 25.0)] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut source =
                    FrameSource::new(&scenario, &job).unwrap_or_else(|e| panic!("{e}"));
                run += 1;
                let out = dir.path().join(format!("run{run}{extension}"));
                export(
                    &mut source,
                    0..FRAMES,
                    fps,
                    &FrameSink::from_path(&out),
                    &ProgressBar::hidden(),
                    &AtomicBool::new(false),
                )
                .unwrap_or_else(|e| panic!("{e}"));
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
