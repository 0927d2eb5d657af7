//! CAD parts (`[appearance]`, the shipped `examples/cad/`): each part drawn where its frame
//! says, moving with the pose, a rod over its stroke still in the warning colour, and a
//! reference image.

use std::path::{Path, PathBuf};

use glam::Vec3;
use stewart_kinematics::io::settings;
use stewart_kinematics::model::scene::SceneFrame;
use stewart_kinematics::{Pose, Scenario};
use stewart_render::appearance::parts::PartSet;
use stewart_render::{DrawList, Image, OrbitCamera, Overlays, Theme};

use crate::snapshots::{SIZE, check};
use crate::{offscreen, project, seed_camera};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/cad")
}

/// The example scenario `name` with `assignments`, and its parts.
fn scenario(name: &str, assignments: &[&str]) -> (Scenario, PartSet) {
    let mut s = Scenario::load(&examples().join(name)).unwrap_or_else(|e| panic!("{e}"));
    settings::apply_all(&mut s, assignments.iter().copied()).unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let size = stewart_render::appearance::parts::platform_size(g);
    let parts = PartSet::load(
        &s.appearance,
        &examples(),
        g.actuator().kind(),
        size,
        None,
        false,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    (s, parts)
}

fn draw(
    s: &Scenario,
    parts: &PartSet,
    pose: &Pose,
    theme: &Theme,
) -> (Image, OrbitCamera, SceneFrame) {
    let mut off = offscreen();
    let frame = s.geometry.scene_frame(pose, Vec::new());
    let overlays = Overlays {
        labels: false,
        ..Overlays::default()
    };
    let list = DrawList::build_with_parts(&frame, theme, &overlays, parts);
    let camera = seed_camera(&s.geometry);
    let image = off
        .render(&list, &camera, theme, SIZE.0, SIZE.1)
        .unwrap_or_else(|e| panic!("{e}"));
    (image, camera, frame)
}

/// Whether a pixel within 3 of the projection of `p` passes `test`.
fn seen_near(
    frame: &Image,
    camera: &OrbitCamera,
    p: Vec3,
    test: impl Fn([i32; 3]) -> bool,
) -> bool {
    let (x, y) = project(camera, p, frame.width, frame.height);
    (-3i32..=3).any(|dy| {
        (-3i32..=3).any(|dx| {
            let (px, py) = (x as i32 + dx, y as i32 + dy);
            px >= 0
                && py >= 0
                && px < frame.width as i32
                && py < frame.height as i32
                && test(
                    frame.pixel(px as u32, py as u32)[..3]
                        .iter()
                        .map(|&c| i32::from(c))
                        .collect::<Vec<_>>()
                        .try_into()
                        .unwrap_or([0; 3]),
                )
        })
    })
}

fn v3(v: nalgebra::Vector3<f64>) -> Vec3 {
    Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

fn green([r, g, b]: [i32; 3]) -> bool {
    g > r + 40 && g > b + 30
}
fn blue([r, g, b]: [i32; 3]) -> bool {
    b > r + 40 && b > g + 20
}
fn orange([r, g, b]: [i32; 3]) -> bool {
    r > g + 30 && g > b + 20
}
fn magenta([r, g, b]: [i32; 3]) -> bool {
    r > g + 50 && b > g + 50
}
fn warning_red([r, g, b]: [i32; 3]) -> bool {
    r > g + 80 && r > b + 80
}

/// A point of the platform's top face in its own frame (on the orange plate, off the
/// dark boss at its centre), in the base frame.
fn on_platform(frame: &SceneFrame) -> Vec3 {
    let p = frame.platform_placement();
    v3(p.origin + p.rotation * nalgebra::Vector3::new(0.0, -0.42, 0.03))
}

/// The middle of leg `k`'s body (0.27 m up its +y) and of its rod's visible part.
fn on_leg(frame: &SceneFrame, k: usize) -> (Vec3, Vec3) {
    let [body, rod] = frame.leg_placements(k);
    (
        v3(body.origin + body.rotation * nalgebra::Vector3::new(0.0, 0.27, 0.0)),
        v3(rod.origin + rod.rotation * nalgebra::Vector3::new(0.0, -0.22, 0.0)),
    )
}

#[test]
fn each_part_is_drawn_where_its_frame_says_and_moves_with_the_pose() {
    let colours = [
        "appearance.base.colour=#2040ff",
        "appearance.cylinder.colour=#20c030",
        "appearance.rod.colour=#e020e0",
    ];
    let (s, parts) = scenario("seed-cad.toml", &colours);
    let tilted = Pose::from_xyz_rpy_deg([0.1, -0.06, 0.86], [7.0, -5.0, 15.0]);
    for pose in [s.geometry.home_pose(), tilted] {
        let (image, camera, frame) = draw(&s, &parts, &pose, &Theme::DARK);
        assert!(
            seen_near(&image, &camera, on_platform(&frame), orange),
            "platform at {pose:?}"
        );
        // The base's top face: seen at most points of a circle on it (legs and the
        // platform hide some), at none well outside its 1.1 m corners.
        let ring = |r: f32| {
            (0..12)
                .filter(|k| {
                    let a = (*k as f32 * 30.0 + 15.0).to_radians();
                    seen_near(
                        &image,
                        &camera,
                        Vec3::new(r * a.cos(), r * a.sin(), 0.0),
                        blue,
                    )
                })
                .count()
        };
        assert!(ring(0.85) >= 7, "base: {} of 12", ring(0.85));
        assert_eq!(ring(1.5), 0);
        for k in [0, 5] {
            let (body, rod) = on_leg(&frame, k);
            assert!(
                seen_near(&image, &camera, body, green),
                "cylinder {k} at {pose:?}"
            );
            assert!(
                seen_near(&image, &camera, rod, magenta),
                "rod {k} at {pose:?}"
            );
        }
    }
    // Moved: where the platform's point was at home, the tilted platform is not.
    let (home, camera, home_frame) = draw(&s, &parts, &s.geometry.home_pose(), &Theme::DARK);
    let (moved, _, moved_frame) = draw(&s, &parts, &tilted, &Theme::DARK);
    let (a, b) = (on_platform(&home_frame), on_platform(&moved_frame));
    assert!(project(&camera, a, SIZE.0, SIZE.1) != project(&camera, b, SIZE.0, SIZE.1));
    assert!(home.rgba != moved.rgba);
}

#[test]
fn a_cad_rod_over_its_stroke_still_turns_to_the_warning_colour() {
    // Home legs are 0.98 m: a stroke ending at 0.9 m puts every leg over it.
    let (s, parts) = scenario(
        "seed-cad.toml",
        &[
            "appearance.cylinder.colour=#20c030",
            "appearance.rod.colour=#e020e0",
            "geometry.leg_max=0.9",
        ],
    );
    let (image, camera, frame) = draw(&s, &parts, &s.geometry.home_pose(), &Theme::DARK);
    for k in 0..6 {
        let (body, rod) = on_leg(&frame, k);
        // Coloured legs: the body keeps its colour, the rod warns.
        assert!(seen_near(&image, &camera, body, green), "cylinder {k}");
        assert!(seen_near(&image, &camera, rod, warning_red), "rod {k}");
        assert!(!seen_near(&image, &camera, rod, magenta), "rod {k}");
    }
}

#[test]
fn a_servo_horn_from_a_file_turns_with_the_servo() {
    let (s, parts) = scenario("servo-cad.toml", &["appearance.horn.colour=#20c030"]);
    let pose = Pose::from_xyz_rpy_deg(
        [0.006, -0.004, s.geometry.home_height() + 0.004],
        [4.0, -3.0, 6.0],
    );
    let (image, camera, frame) = draw(&s, &parts, &pose, &Theme::LIGHT);
    let servos = frame.servos.unwrap_or_else(|| panic!("servos"));
    // Halfway along each horn, which its frame's +x carries to the tip (a servo's
    // body hides one or two from this camera).
    let seen = servos
        .iter()
        .filter(|servo| {
            seen_near(
                &image,
                &camera,
                v3((servo.shaft + servo.horn_tip) * 0.5),
                green,
            )
        })
        .count();
    assert!(seen >= 4, "{seen} horns of 6");
}

#[test]
fn the_seed_with_its_cad_parts_matches_its_reference() {
    let (s, parts) = scenario("seed-cad.toml", &[]);
    let tilted = Pose::from_xyz_rpy_deg([0.08, -0.05, 0.85], [6.0, -4.0, 12.0]);
    let (image, _, _) = draw(&s, &parts, &tilted, &Theme::DARK);
    check("cad_seed_tilted_dark", &image);
    let (s, parts) = scenario("servo-cad.toml", &[]);
    let pose = Pose::from_xyz_rpy_deg([0.01, -0.008, 0.118], [5.0, -4.0, 8.0]);
    let (image, _, _) = draw(&s, &parts, &pose, &Theme::LIGHT);
    check("cad_servo_tilted_light", &image);
}
