//! Screenshots from the viewer: F12 saves the 3D view at the chosen size, on the theme's
//! background or transparent, while playback goes on.

use std::time::{Duration, Instant};

use crate::viewer::state::ViewerState;
use crate::viewer::view3d::shots::{ShotKind, ShotScale};
use egui_kittest::Harness;

use super::harness;

/// Press F12 and wait for the shot; the PNG written.
fn shoot(h: &mut Harness<'static, ViewerState>) -> image::RgbaImage {
    h.state_mut().shots.status = None;
    h.key_press(egui::Key::F12);
    let started = Instant::now();
    while h.state().shots.status.is_none() {
        h.run();
        assert!(started.elapsed() < Duration::from_secs(60), "no screenshot");
        std::thread::sleep(Duration::from_millis(20));
    }
    let status = (h.state().shots.status.clone())
        .map(|s| s.map_err(|e| e.to_string()))
        .unwrap_or_else(|| Err("none".into()));
    let words = status.unwrap_or_else(|e| panic!("{e}"));
    let path = words
        .split(" to ")
        .nth(1)
        .map(|p| p.trim_end_matches('.'))
        .unwrap_or_else(|| panic!("{words}"));
    image::open(path)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .to_rgba8()
}

#[test]
fn f12_saves_the_3d_view_at_the_chosen_size_and_transparent_when_asked() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut h = harness("seed");
    h.state_mut().shots.folder = dir.path().to_path_buf();
    h.state_mut().look.view_px = [320, 200];
    h.state_mut().playback.playing = true;
    let img = shoot(&mut h);
    assert_eq!(img.dimensions(), (320, 200));
    // The theme's background in the corner, opaque; the platform (violet) in the middle.
    assert_eq!(img.get_pixel(0, 0)[3], 255);
    let red = img
        .pixels()
        .filter(|p| platform_violet(p[0], p[1], p[2]))
        .count();
    assert!(red > 200, "{red} platform pixels");
    assert!(h.state().playback.playing, "playback went on");
    h.state_mut().shots.scale = ShotScale::Two;
    h.state_mut().shots.transparent = true;
    let img = shoot(&mut h);
    assert_eq!(img.dimensions(), (640, 400));
    assert_eq!(img.get_pixel(0, 0)[3], 0, "the background is transparent");
    let opaque = img.pixels().filter(|p| p[3] == 255).count();
    assert!(opaque > 5000, "{opaque} opaque pixels");
    // Two shots, two files, none overwritten.
    assert_eq!(
        std::fs::read_dir(dir.path())
            .map(Iterator::count)
            .unwrap_or(0),
        2
    );
    assert_eq!(h.state().shots.kind, ShotKind::View);
}

/// The platform's violet (blue above red above green), through its translucency.
fn platform_violet(r: u8, g: u8, b: u8) -> bool {
    let [r, g, b] = [r, g, b].map(i32::from);
    b > r + 10 && r > g + 10
}
