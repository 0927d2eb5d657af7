//! Exported frames frame the platform's whole motion: the union of what the 3D view
//! shows over every frame is centred in its part of the frame, with a margin, and fills
//! it.

use std::path::Path;

use crate::{stderr, stewart, tempdir};

/// The bounding box (left, top, right, bottom; inclusive) of the platform, legs and
/// joints over every frame in `dir`, within the first `view_width` columns. Drawn
/// content is dark or saturated; the white background and the light grey ground grid
/// (and their blends) are neither.
fn content_box(dir: &Path, view_width: u32) -> (u32, u32, u32, u32) {
    let mut names: Vec<_> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).collect())
        .unwrap_or_default();
    names.sort();
    assert!(names.len() > 20, "{names:?}");
    let mut b = (u32::MAX, u32::MAX, 0, 0);
    for path in &names {
        let img = image::open(path)
            .map(|i| i.to_rgb8())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for (x, y, p) in img.enumerate_pixels() {
            let (lo, hi) = (p.0.iter().min().copied(), p.0.iter().max().copied());
            let (lo, hi) = (lo.unwrap_or(255), hi.unwrap_or(255));
            if x < view_width && (lo < 150 || hi - lo > 60) {
                b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
            }
        }
    }
    b
}

fn render_frames(dir: &Path, preset: &str, size: &str, composite: bool) -> std::path::PathBuf {
    let out = dir.join(format!("{preset}-{composite}"));
    let out_text = out.display().to_string();
    let mut args = vec![
        "render",
        "--preset",
        preset,
        "--out",
        &out_text,
        "--size",
        size,
        "--fps",
        "4",
        "--theme",
        "light",
        "--no-labels",
    ];
    if composite {
        args.push("--composite");
    }
    let o = stewart(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

/// The content box is centred in a view `w` × `h` within 3 % of its size, keeps a margin
/// of at least 4 % everywhere, and reaches within 15 % of an edge on one axis.
fn assert_framed(what: &str, (l, t, r, b): (u32, u32, u32, u32), w: u32, h: u32) {
    assert!(l < r && t < b, "{what}: nothing drawn");
    let (w, h) = (f64::from(w), f64::from(h));
    let cx = f64::from(l + r) / 2.0 / w;
    let cy = f64::from(t + b) / 2.0 / h;
    assert!(
        (cx - 0.5).abs() < 0.03,
        "{what}: centred at x {cx:.3} ({l}..{r} of {w})"
    );
    assert!(
        (cy - 0.5).abs() < 0.03,
        "{what}: centred at y {cy:.3} ({t}..{b} of {h})"
    );
    let margins = [
        f64::from(l) / w,
        f64::from(t) / h,
        1.0 - f64::from(r) / w,
        1.0 - f64::from(b) / h,
    ];
    assert!(
        margins.iter().all(|m| *m > 0.04),
        "{what}: margins {margins:?}"
    );
    let fill = (f64::from(r - l) / w).max(f64::from(b - t) / h);
    assert!(fill > 0.7, "{what}: fills only {fill:.2} of the view");
}

#[test]
fn a_composite_frames_the_whole_motion_centred_in_its_half() {
    let dir = tempdir();
    // 1920×1080 scaled down: the 3D view is the left 55 %.
    let (w, h) = (640, 360);
    let view = (f64::from(w) * 0.55).round() as u32;
    for preset in ["seed", "servo-desk"] {
        let out = render_frames(dir.path(), preset, "640x360", true);
        assert_framed(preset, content_box(&out, view), view, h);
    }
}

#[test]
fn a_full_frame_export_frames_the_whole_motion_too() {
    let dir = tempdir();
    let out = render_frames(dir.path(), "paired", "320x180", false);
    assert_framed("paired", content_box(&out, 320), 320, 180);
}
