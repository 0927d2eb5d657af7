//! Reference images. A missing or different reference fails; `UPDATE_SNAPSHOTS=1`
//! rewrites them. On failure the new image and a difference image are written next to
//! the reference as `*.new.png` and `*.diff.png` (ignored by git).
//!
//! Tolerance: a pixel differs when a channel differs by more than 24 of 255 (rasterisers
//! and drivers round edges and blends differently); at most 0.5 % of the pixels may
//! differ (a few anti-aliased edges), far less than any real change of the scene, which
//! moves thousands of pixels (see `the_image_changes_with_the_pose_and_only_then`).

use std::path::PathBuf;

use stewart_kinematics::{Pose, Scenario};
use stewart_render::{Frame, Theme};

use crate::{offscreen, render};

const CHANNEL_TOLERANCE: i32 = 24;
const MAX_DIFFERING: f64 = 0.005;

fn check(name: &str, frame: &Frame) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/snapshots");
    let path = dir.join(format!("{name}.png"));
    let new = image::RgbaImage::from_raw(frame.width, frame.height, frame.rgba.clone())
        .unwrap_or_else(|| panic!("bad frame"));
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        new.save(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        return;
    }
    let reference = match image::open(&path) {
        Ok(img) => img.to_rgba8(),
        Err(e) => {
            let _ = new.save(dir.join(format!("{name}.new.png")));
            panic!(
                "{}: no reference image ({e}); run with UPDATE_SNAPSHOTS=1 to create it",
                path.display()
            );
        }
    };
    assert_eq!(
        reference.dimensions(),
        new.dimensions(),
        "{name}: size differs"
    );
    let mut diff = image::RgbaImage::new(frame.width, frame.height);
    let mut differing = 0usize;
    for (x, y, p) in reference.enumerate_pixels() {
        let q = new.get_pixel(x, y);
        let d = (0..3)
            .map(|k| (p[k] as i32 - q[k] as i32).abs())
            .max()
            .unwrap_or(0);
        if d > CHANNEL_TOLERANCE {
            differing += 1;
            diff.put_pixel(x, y, image::Rgba([255, 0, 255, 255]));
        } else {
            diff.put_pixel(x, y, image::Rgba([p[0] / 3, p[1] / 3, p[2] / 3, 255]));
        }
    }
    let fraction = differing as f64 / (frame.width * frame.height) as f64;
    if fraction > MAX_DIFFERING {
        let _ = new.save(dir.join(format!("{name}.new.png")));
        let _ = diff.save(dir.join(format!("{name}.diff.png")));
        panic!(
            "{name}: {:.2} % of pixels differ from the reference (allowed {:.2} %)",
            100.0 * fraction,
            100.0 * MAX_DIFFERING
        );
    }
}

#[test]
fn seed_and_paired_match_their_references_in_both_themes() {
    let mut off = offscreen();
    let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let paired = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let tilted = Pose::from_xyz_rpy_deg([0.08, -0.05, 0.85], [6.0, -4.0, 12.0]);
    for (name, s, pose, theme) in [
        (
            "seed_home_dark",
            &seed,
            seed.geometry.home_pose(),
            Theme::DARK,
        ),
        (
            "seed_home_light",
            &seed,
            seed.geometry.home_pose(),
            Theme::LIGHT,
        ),
        ("paired_tilted_dark", &paired, tilted, Theme::DARK),
        ("paired_tilted_light", &paired, tilted, Theme::LIGHT),
    ] {
        let (frame, _) = render(&mut off, &s.geometry, &pose, &theme, 320, 240);
        check(name, &frame);
    }
}
