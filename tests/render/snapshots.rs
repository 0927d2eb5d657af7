//! Reference images. A missing or different reference fails; `UPDATE_SNAPSHOTS=1`
//! rewrites them. On failure the new image and a difference image are written next to
//! the reference as `*.new.png` and `*.diff.png` (ignored by git).
//!
//! Tolerance: a pixel differs when a channel differs by more than 24 of 255 (rasterisers
//! and drivers round edges and blends differently); at most 40 of the 172 800 pixels of
//! a 480 × 360 image may differ (a few anti-aliased edge pixels). A colour change
//! confined to one leg moves a hundred pixels or more and fails
//! (`a_colour_change_of_one_leg_fails_the_comparison`); a new pose moves thousands (see
//! `the_image_changes_with_the_pose_and_only_then`).

use std::path::PathBuf;

use stewart_kinematics::{Pose, Scenario};
use stewart_render::{Image, Theme};

use crate::{offscreen, render};

const CHANNEL_TOLERANCE: i32 = 24;
/// Most pixels that may differ from a reference.
const MAX_DIFFERING: usize = 40;
/// Size of the reference images.
pub(crate) const SIZE: (u32, u32) = (480, 360);

/// Pixels of `new` that differ from `reference` by more than the channel tolerance, and
/// a picture of where (magenta).
fn compare(reference: &image::RgbaImage, new: &image::RgbaImage) -> (usize, image::RgbaImage) {
    let (w, h) = new.dimensions();
    let mut diff = image::RgbaImage::new(w, h);
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
    (differing, diff)
}

/// Compare `frame` with the reference image `name` (see the module docs).
pub(crate) fn check(name: &str, frame: &Image) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("snapshots");
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
    let (differing, diff) = compare(&reference, &new);
    if differing > MAX_DIFFERING {
        let _ = new.save(dir.join(format!("{name}.new.png")));
        let _ = diff.save(dir.join(format!("{name}.diff.png")));
        panic!("{name}: {differing} pixels differ from the reference (allowed {MAX_DIFFERING})");
    }
}

#[test]
fn presets_match_their_references() {
    let mut off = offscreen();
    let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let paired = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let tilted = Pose::from_xyz_rpy_deg([0.08, -0.05, 0.85], [6.0, -4.0, 12.0]);
    let servo = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let servo_pose = Pose::from_xyz_rpy_deg([0.01, -0.008, 0.118], [5.0, -4.0, 8.0]);
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
        ("servo_desk_tilted_dark", &servo, servo_pose, Theme::DARK),
    ] {
        let (frame, _) = render(&mut off, &s.geometry, &pose, &theme, SIZE.0, SIZE.1);
        check(name, &frame);
    }
}

#[test]
fn a_colour_change_of_one_leg_fails_the_comparison() {
    // Shift the colour of leg 1's actuator body only (a disc around its middle, where the
    // body is drawn) by 40 of 255: the comparison must see it.
    let mut off = offscreen();
    let paired = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let pose = paired.geometry.home_pose();
    let (frame, camera) = render(
        &mut off,
        &paired.geometry,
        &pose,
        &Theme::DARK,
        SIZE.0,
        SIZE.1,
    );
    let reference = image::RgbaImage::from_raw(frame.width, frame.height, frame.rgba.clone())
        .unwrap_or_else(|| panic!("bad frame"));
    let legs = paired.geometry.inverse(&pose);
    let base = paired.geometry.base_joints()[0];
    let middle = base + 0.3 * legs.legs[0];
    let (cx, cy) = crate::project(
        &camera,
        glam::Vec3::new(middle.x as f32, middle.y as f32, middle.z as f32),
        SIZE.0,
        SIZE.1,
    );
    let mut changed = reference.clone();
    let mut recoloured = 0;
    for (x, y, p) in changed.enumerate_pixels_mut() {
        let (dx, dy) = (x as i32 - cx as i32, y as i32 - cy as i32);
        // Only the leg's own (blue) pixels near its middle.
        if dx * dx + dy * dy <= 100 && p[2] > p[0] + 60 {
            p[2] = p[2].saturating_sub(40);
            p[0] = p[0].saturating_add(40);
            recoloured += 1;
        }
    }
    assert!(
        recoloured > MAX_DIFFERING,
        "only {recoloured} leg pixels near ({cx}, {cy})"
    );
    let (differing, _) = compare(&reference, &changed);
    assert_eq!(differing, recoloured);
    assert!(
        differing > MAX_DIFFERING,
        "a one-leg colour change passes: {differing} pixels"
    );
}
