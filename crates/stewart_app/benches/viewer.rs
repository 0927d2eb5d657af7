//! The viewer's CPU work per frame — UI layout of every panel, kinematics, the scene's
//! draw list and egui's tessellation — for the seed playing at 1280×720, without a
//! window or GPU (the same work `stewart view --frame-stats` reports as the CPU part);
//! and with the workspace surface recomputed off the UI thread as the pose plays.
//! `cargo bench -p stewart_app --bench viewer`.

use criterion::{Criterion, criterion_group, criterion_main};
use stewart_app::viewer::ViewerState;
use stewart_app::viewer::panels::viewer_ui;
use stewart_kinematics::Scenario;

fn frame(ctx: &egui::Context, state: &mut ViewerState) -> usize {
    state.advance(1.0 / 60.0);
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(1280.0, 720.0),
        )),
        ..Default::default()
    };
    let output = ctx.run_ui(input, |ui| viewer_ui(ui, state));
    ctx.tessellate(output.shapes, output.pixels_per_point).len()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("viewer_frame_1280x720");
    for (name, expand) in [
        ("seed_playing", false),
        ("seed_playing_all_panels_open", true),
    ] {
        let scenario = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let mut state = ViewerState::new(scenario);
        state.look.expand_panels = expand;
        let ctx = egui::Context::default();
        // Warm up: fonts, first layout.
        for _ in 0..5 {
            frame(&ctx, &mut state);
        }
        group.bench_function(name, |b| b.iter(|| frame(&ctx, &mut state)));
    }
    // The workspace shown at the playing pose's orientation: every frame asks for a new
    // surface (the worker computes on its own thread; the frame only swaps results in).
    let scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let mut state = ViewerState::new(scenario);
    state.tools.workspace.show = true;
    let ctx = egui::Context::default();
    for _ in 0..5 {
        frame(&ctx, &mut state);
    }
    group.bench_function("paired_playing_workspace_following", |b| {
        b.iter(|| frame(&ctx, &mut state))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
