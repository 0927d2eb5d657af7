//! Headless rendering tests: shaders validate, frames show what they must, and match
//! reference images. They run on whatever adapter `Gpu::headless` finds (lavapipe in CI).

mod appearance;
mod picture;
mod shaders;
mod snapshots;
mod workspace;

use glam::Vec3;
use stewart_kinematics::{Geometry, GeometryParams, Pose, model::geometry::StrokeLimits};
use stewart_render::theme::series;
use stewart_render::{DrawList, Image, Offscreen, OrbitCamera, Overlays, Theme};

/// Render `pose` of `geometry` at `width × height` with the seed view.
pub fn render(
    offscreen: &mut Offscreen,
    geometry: &Geometry,
    pose: &Pose,
    theme: &Theme,
    width: u32,
    height: u32,
) -> (Image, OrbitCamera) {
    let camera = seed_camera(geometry);
    let overlays = Overlays::default();
    render_with(
        offscreen,
        geometry,
        pose,
        theme,
        (width, height),
        &overlays,
        camera,
    )
}

/// [`render`] with chosen overlays and camera.
pub fn render_with(
    offscreen: &mut Offscreen,
    geometry: &Geometry,
    pose: &Pose,
    theme: &Theme,
    (width, height): (u32, u32),
    overlays: &Overlays,
    camera: OrbitCamera,
) -> (Image, OrbitCamera) {
    let frame = geometry.scene_frame(pose, Vec::new());
    let list = DrawList::build(&frame, theme, overlays);
    let image = offscreen
        .render(&list, &camera, theme, width, height)
        .unwrap_or_else(|e| panic!("{e}"));
    (image, camera)
}

/// The seed's view framing the platform at home.
pub fn seed_camera(geometry: &Geometry) -> OrbitCamera {
    OrbitCamera::seed_view_of(geometry)
}

/// Pixel coordinates of a world point.
pub fn project(camera: &OrbitCamera, p: Vec3, width: u32, height: u32) -> (u32, u32) {
    let ndc = camera
        .view_proj(width as f32 / height as f32)
        .project_point3(p);
    let x = ((ndc.x + 1.0) * 0.5 * width as f32) as u32;
    let y = ((1.0 - ndc.y) * 0.5 * height as f32) as u32;
    (x.min(width - 1), y.min(height - 1))
}

/// A headless renderer, or a failed test saying why.
pub fn offscreen() -> Offscreen {
    Offscreen::new().unwrap_or_else(|e| panic!("{e}"))
}

/// The platform's violet (blue above red above green), through its translucency.
fn is_platform_violet(p: [u8; 4]) -> bool {
    let [r, g, b] = [p[0], p[1], p[2]].map(i32::from);
    b > r + 10 && r > g + 10
}

#[test]
fn the_platform_centre_shows_the_platform_colour_at_any_width() {
    let mut off = offscreen();
    let g = Geometry::seed();
    // 333 is not a multiple of 64: rows are padded on the GPU and must be unpadded.
    for (w, h) in [(320, 240), (333, 217)] {
        for theme in [Theme::DARK, Theme::LIGHT] {
            let (frame, camera) = render(&mut off, &g, &g.home_pose(), &theme, w, h);
            assert_eq!(
                (frame.width, frame.height, frame.rgba.len()),
                (w, h, (w * h * 4) as usize)
            );
            let (x, y) = project(&camera, Vec3::new(0.0, 0.0, 0.8), w, h);
            let p = frame.pixel(x, y);
            assert!(
                is_platform_violet(p),
                "{w}×{h}: pixel at the platform centre ({x}, {y}) is {p:?}"
            );
        }
    }
}

#[test]
fn themes_have_their_backgrounds() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let (dark, _) = render(&mut off, &g, &g.home_pose(), &Theme::DARK, 160, 120);
    let (light, _) = render(&mut off, &g, &g.home_pose(), &Theme::LIGHT, 160, 120);
    assert!(
        dark.pixel(2, 2)[..3].iter().all(|&c| c < 50),
        "{:?}",
        dark.pixel(2, 2)
    );
    assert_eq!(light.pixel(2, 2), [255, 255, 255, 255]);
}

#[test]
fn the_image_changes_with_the_pose_and_only_then() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let (a, _) = render(&mut off, &g, &g.home_pose(), &Theme::DARK, 200, 150);
    let (b, _) = render(&mut off, &g, &g.home_pose(), &Theme::DARK, 200, 150);
    assert_eq!(a.rgba, b.rgba, "the same pose must render the same image");
    let moved = Pose::from_xyz_rpy_deg([0.1, 0.0, 0.85], [0.0, 5.0, 10.0]);
    let (c, _) = render(&mut off, &g, &moved, &Theme::DARK, 200, 150);
    let changed = a
        .rgba
        .chunks(4)
        .zip(c.rgba.chunks(4))
        .filter(|(p, q)| p != q)
        .count();
    assert!(changed > 500, "only {changed} pixels changed");
}

#[test]
fn a_leg_over_its_stroke_shows_the_warning_colour() {
    let mut off = offscreen();
    let mut params = GeometryParams::seed();
    params.stroke = StrokeLimits::new(0.5, 0.97); // home legs are 0.98 m: every leg is over
    let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    let (w, h) = (320, 240);
    // Labels off: their boxes carry the leg colours.
    let bare = Overlays {
        labels: false,
        ..Overlays::default()
    };
    let camera = seed_camera(&g);
    let (frame, camera) = render_with(
        &mut off,
        &g,
        &g.home_pose(),
        &Theme::DARK,
        (w, h),
        &bare,
        camera,
    );
    let warning = Theme::DARK.leg_over_limit;
    let target = [0, 1, 2].map(|k| (warning[k] * 255.0) as i32);
    // Somewhere along leg 1 (the one nearest the camera at azimuth 135° is leg 2, at 60°).
    let sol = g.inverse(&g.home_pose());
    let mut best = i32::MAX;
    for i in 0..6 {
        for s in [0.3f32, 0.5, 0.7] {
            let b = sol.platform_joints[i] - sol.legs[i];
            let p = b + sol.legs[i] * s as f64;
            let (x, y) = project(&camera, Vec3::new(p.x as f32, p.y as f32, p.z as f32), w, h);
            let q = frame.pixel(x, y);
            let d = (0..3)
                .map(|k| (q[k] as i32 - target[k]).abs())
                .max()
                .unwrap_or(255);
            best = best.min(d);
        }
    }
    // Shading darkens and lightens the colour: the closest leg pixel must be within 30%.
    assert!(
        best < 80,
        "no leg pixel near the warning colour {target:?} (closest distance {best})"
    );
    let normal = render_with(
        &mut off,
        &Geometry::seed(),
        &g.home_pose(),
        &Theme::DARK,
        (w, h),
        &bare,
        camera,
    )
    .0;
    let reddish = |f: &Image| {
        f.rgba
            .chunks(4)
            .filter(|p| p[0] > 180 && p[1] < 80 && p[2] < 80)
            .count()
    };
    assert!(
        reddish(&frame) > 10 * reddish(&normal).max(1),
        "{} vs {}",
        reddish(&frame),
        reddish(&normal)
    );
}

/// Distance (largest channel difference, 0–255) from the pixel nearest `colour` among the
/// pixels at `points` (world coordinates).
fn closest_to(frame: &Image, camera: &OrbitCamera, points: &[Vec3], colour: [f32; 4]) -> i32 {
    let target = [0, 1, 2].map(|k| (colour[k] * 255.0) as i32);
    points
        .iter()
        .map(|&p| {
            let (x, y) = project(camera, p, frame.width, frame.height);
            let q = frame.pixel(x, y);
            (0..3)
                .map(|k| (q[k] as i32 - target[k]).abs())
                .max()
                .unwrap_or(255)
        })
        .min()
        .unwrap_or(255)
}

/// As [`closest_to`], searching a few pixels around each point (across a cylinder, its
/// shading runs from dark edges to a highlight on the axis).
fn closest_near(frame: &Image, camera: &OrbitCamera, points: &[Vec3], colour: [f32; 4]) -> i32 {
    let target = [0, 1, 2].map(|k| (colour[k] * 255.0) as i32);
    let mut best = 255;
    for &p in points {
        let (x, y) = project(camera, p, frame.width, frame.height);
        for dy in -4i32..=4 {
            for dx in -4i32..=4 {
                let (px, py) = (x as i32 + dx, y as i32 + dy);
                if px < 0 || py < 0 || px >= frame.width as i32 || py >= frame.height as i32 {
                    continue;
                }
                let q = frame.pixel(px as u32, py as u32);
                let d = (0..3)
                    .map(|k| (q[k] as i32 - target[k]).abs())
                    .max()
                    .unwrap_or(255);
                best = best.min(d);
            }
        }
    }
    best
}

#[test]
fn servos_show_horns_in_their_colour_and_warn_past_their_range() {
    use stewart_kinematics::Scenario;
    let mut off = offscreen();
    let s = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let pose = g.home_pose();
    let (w, h) = (480, 320);
    let single = Overlays {
        coloured_legs: false,
        ..Overlays::default()
    };
    let camera = seed_camera(g);
    let (frame, camera) = render_with(&mut off, g, &pose, &Theme::LIGHT, (w, h), &single, camera);
    let scene = g.scene_frame(&pose, Vec::new());
    let servos = scene.servos.unwrap_or_else(|| panic!("rotary scene"));
    let v = |p: nalgebra::Vector3<f64>| Vec3::new(p.x as f32, p.y as f32, p.z as f32);
    let horn_middles: Vec<Vec3> = servos
        .iter()
        .map(|s| v((s.shaft + s.horn_tip) * 0.5))
        .collect();
    let best = closest_to(&frame, &camera, &horn_middles, Theme::LIGHT.horn);
    assert!(
        best < 40,
        "no horn pixel near the horn colour (closest {best})"
    );
    // The rods' middles show the rod colour, not the horn's.
    let rod_middles: Vec<Vec3> = scene
        .legs
        .iter()
        .map(|l| v((l.base + l.top) * 0.5))
        .collect();
    let best = closest_to(&frame, &camera, &rod_middles, Theme::LIGHT.leg_rod);
    assert!(
        best < 40,
        "no rod pixel near the rod colour (closest {best})"
    );
    // A range of ±1°: every servo at home is past it, and its horn turns the warning colour.
    let mut narrow = s.clone();
    stewart_kinematics::io::settings::apply_all(
        &mut narrow,
        ["actuator.servo_min_deg=-1", "actuator.servo_max_deg=1"],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let lifted = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.125], [0.0; 3]);
    let (warned, camera) = render(&mut off, &narrow.geometry, &lifted, &Theme::LIGHT, w, h);
    let scene = narrow.geometry.scene_frame(&lifted, Vec::new());
    let servos = scene.servos.unwrap_or_else(|| panic!("rotary scene"));
    assert!(
        servos
            .iter()
            .all(|s| s.status == stewart_kinematics::model::scene::LegStatus::OverLimit)
    );
    let horn_middles: Vec<Vec3> = servos
        .iter()
        .map(|s| v((s.shaft + s.horn_tip) * 0.5))
        .collect();
    let best = closest_to(&warned, &camera, &horn_middles, Theme::LIGHT.leg_over_limit);
    assert!(
        best < 40,
        "no horn pixel near the warning colour (closest {best})"
    );
}

#[test]
fn leg_k_shows_the_plots_colour_k_in_both_themes_and_one_colour_when_asked() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let pose = Pose::from_xyz_rpy_deg([0.05, 0.0, 0.85], [0.0, 0.0, 10.0]);
    let sol = g.inverse(&pose);
    // Points along each leg's actuator body, near the base joint.
    let body = |k: usize| -> Vec<Vec3> {
        (1..7)
            .map(|i| {
                let base = sol.platform_joints[k] - sol.legs[k];
                let p = base + sol.legs[k] * (0.05 * i as f64);
                Vec3::new(p.x as f32, p.y as f32, p.z as f32)
            })
            .collect()
    };
    // From above: the legs spread apart, and their bodies (near the base joints, outside
    // the smaller platform) are not seen through the translucent platform, which tints.
    let low = OrbitCamera {
        elevation_deg: 89.0,
        ..seed_camera(&g)
    };
    let coloured = Overlays::default();
    for theme in [Theme::DARK, Theme::LIGHT] {
        let (frame, camera) = render_with(&mut off, &g, &pose, &theme, (640, 480), &coloured, low);
        for k in 0..6 {
            // Shading and the translucent plates shift the colour a little; it must stay
            // nearer its own plot colour than any other leg's.
            let near = |j: usize| closest_near(&frame, &camera, &body(k), series(j));
            let best = near(k);
            assert!(
                best < 50,
                "leg {} is not in plot colour {} (closest {best})",
                k + 1,
                k + 1
            );
            for j in (0..6).filter(|&j| j != k) {
                assert!(
                    near(j) > best,
                    "leg {} looks like leg {}'s colour",
                    k + 1,
                    j + 1
                );
            }
        }
        // One colour for all: every body in the theme's leg colour.
        let single = Overlays {
            coloured_legs: false,
            ..Overlays::default()
        };
        let (frame, camera) = render_with(&mut off, &g, &pose, &theme, (640, 480), &single, low);
        for k in 0..6 {
            let best = closest_near(&frame, &camera, &body(k), theme.leg_body);
            assert!(
                best < 50,
                "leg {} is not in the leg colour (closest {best})",
                k + 1
            );
        }
    }
}

#[test]
fn each_leg_carries_its_numbered_label_in_its_colour_and_labels_can_be_switched_off() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let pose = g.home_pose();
    let (w, h) = (1280, 720);
    let camera = seed_camera(&g);
    let (with, _) = render_with(
        &mut off,
        &g,
        &pose,
        &Theme::DARK,
        (w, h),
        &Overlays::default(),
        camera,
    );
    let bare = Overlays {
        labels: false,
        ..Overlays::default()
    };
    let (without, _) = render_with(&mut off, &g, &pose, &Theme::DARK, (w, h), &bare, camera);
    let sol = g.inverse(&pose);
    let em = 0.034 * h as f32;
    for k in 0..6 {
        // The label's box starts 0.6 em right of the point 45 % up the leg.
        let p = sol.platform_joints[k] - sol.legs[k] * 0.55;
        let (x, y) = project(&camera, Vec3::new(p.x as f32, p.y as f32, p.z as f32), w, h);
        let target = series(k).map(|c| (c * 255.0) as i32);
        let mut best = 255;
        let mut changed = 0;
        for dy in -(em as i32)..=(em as i32) {
            for dx in 0..(3.0 * em) as i32 {
                let (px, py) = (x as i32 + dx, y as i32 + dy);
                if px < 0 || py < 0 || px >= w as i32 || py >= h as i32 {
                    continue;
                }
                let q = with.pixel(px as u32, py as u32);
                changed += usize::from(q != without.pixel(px as u32, py as u32));
                let d = (0..3)
                    .map(|c| (q[c] as i32 - target[c]).abs())
                    .max()
                    .unwrap_or(255);
                best = best.min(d);
            }
        }
        assert!(
            changed > 50,
            "no label beside leg {} ({changed} pixels changed)",
            k + 1
        );
        assert!(
            best < 40,
            "label {} is not in its leg's colour (closest {best})",
            k + 1
        );
    }
}

#[test]
fn a_bad_size_is_an_error_not_a_panic() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let list = DrawList::build(
        &g.scene_frame(&g.home_pose(), Vec::new()),
        &Theme::DARK,
        &Overlays::default(),
    );
    let camera = seed_camera(&g);
    assert!(off.render(&list, &camera, &Theme::DARK, 0, 100).is_err());
    assert!(off.render(&list, &camera, &Theme::DARK, 100, 5000).is_err());
}

#[test]
fn views_prepared_with_one_renderer_stay_independent() {
    // Two views prepared one after the other, then drawn in the other order: each shows
    // its own scene (per-view buffers, not one set the last prepare overwrites).
    let mut off = offscreen();
    let g = Geometry::seed();
    let (w, h) = (160, 120);
    let home = g.home_pose();
    let moved = Pose::from_xyz_rpy_deg([0.15, 0.0, 0.8], [0.0, 0.0, 25.0]);
    let alone = |off: &mut Offscreen, pose: &Pose| render(off, &g, pose, &Theme::DARK, w, h).0;
    let home_alone = alone(&mut off, &home);
    let moved_alone = alone(&mut off, &moved);
    assert_ne!(home_alone.rgba, moved_alone.rgba);
    let camera = seed_camera(&g);
    let list = |pose: &Pose| {
        DrawList::build(
            &g.scene_frame(pose, Vec::new()),
            &Theme::DARK,
            &Overlays::default(),
        )
    };
    let (mut a, mut b) = (off.new_view(), off.new_view());
    off.prepare(&mut a, &list(&home), &camera, &Theme::DARK, w, h);
    off.prepare(&mut b, &list(&moved), &camera, &Theme::DARK, w, h);
    off.submit_prepared(&b, w, h)
        .unwrap_or_else(|e| panic!("{e}"));
    let b_frame = off.read().unwrap_or_else(|e| panic!("{e}"));
    off.submit_prepared(&a, w, h)
        .unwrap_or_else(|e| panic!("{e}"));
    let a_frame = off.read().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(a_frame.rgba, home_alone.rgba);
    assert_eq!(b_frame.rgba, moved_alone.rgba);
}

#[test]
fn renderers_on_several_threads_at_once_share_one_device_and_each_get_their_own_frames() {
    // Six threads, each with its own renderer, render their own pose several times at
    // once (drivers have deadlocked when each thread opened and dropped its own device);
    // every frame equals the one rendered alone for that pose.
    let g = Geometry::seed();
    let (w, h) = (160, 120);
    let poses: Vec<Pose> = (0..6)
        .map(|k| Pose::from_xyz_rpy_deg([0.02 * k as f64, 0.0, 0.8], [0.0, 0.0, 5.0 * k as f64]))
        .collect();
    let mut alone_renderer = offscreen();
    let alone: Vec<Image> = poses
        .iter()
        .map(|p| render(&mut alone_renderer, &g, p, &Theme::DARK, w, h).0)
        .collect();
    assert!(alone.windows(2).all(|f| f[0].rgba != f[1].rgba));
    let together: Vec<Vec<Image>> = std::thread::scope(|scope| {
        let threads: Vec<_> = poses
            .iter()
            .map(|pose| {
                let g = &g;
                scope.spawn(move || {
                    let mut off = offscreen();
                    (0..4)
                        .map(|_| render(&mut off, g, pose, &Theme::DARK, w, h).0)
                        .collect::<Vec<Image>>()
                })
            })
            .collect();
        threads
            .into_iter()
            .map(|t| {
                t.join()
                    .unwrap_or_else(|_| panic!("a rendering thread panicked"))
            })
            .collect()
    });
    for (k, frames) in together.iter().enumerate() {
        for f in frames {
            assert!(f.rgba == alone[k].rgba, "thread {k} got another frame");
        }
    }
    let (a, b) = (
        stewart_render::Gpu::shared().unwrap_or_else(|e| panic!("{e}")),
        stewart_render::Gpu::shared().unwrap_or_else(|e| panic!("{e}")),
    );
    assert!(a.device == b.device, "Gpu::shared opened a second device");
}

#[test]
fn the_measured_platform_shows_as_a_green_ghost_beside_the_commanded_one() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let home = g.home_pose();
    let camera = seed_camera(&g);
    let theme = Theme::DARK;
    let (w, h) = (480, 360);
    let commanded = DrawList::build(
        &g.scene_frame(&home, Vec::new()),
        &theme,
        &Overlays::default(),
    );
    // Measured: lifted 12 cm and tilted, as a lagging controller might report.
    let measured = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.92], [6.0, 0.0, 0.0]);
    let mut with_ghost = commanded.clone();
    with_ghost.ghost(&g.scene_frame(&measured, Vec::new()), &theme);
    assert_eq!(with_ghost.plates.len(), commanded.plates.len() + 1);
    assert_eq!(with_ghost.lines.len(), commanded.lines.len() + 12);
    let plain = off
        .render(&commanded, &camera, &theme, w, h)
        .unwrap_or_else(|e| panic!("{e}"));
    let ghosted = off
        .render(&with_ghost, &camera, &theme, w, h)
        .unwrap_or_else(|e| panic!("{e}"));
    if let Some(dir) = std::env::var_os("STEWART_LOOK_DIR") {
        let path = std::path::Path::new(&dir).join("ghost.png");
        image::save_buffer(&path, &ghosted.rgba, w, h, image::ExtendedColorType::Rgba8)
            .unwrap_or_else(|e| panic!("{e}"));
    }
    // Above the commanded platform, where only the ghost is, the ghost's green shows.
    let (x, y) = project(&camera, Vec3::new(0.0, 0.0, 0.97), w, h);
    let p = ghosted.pixel(x, y);
    let q = plain.pixel(x, y);
    assert!(
        p[1] as i32 > p[0] as i32 + 20 && p[1] as i32 > p[2] as i32 + 10,
        "ghost pixel ({x}, {y}) is {p:?}"
    );
    assert_ne!(p, q);
    // Where the translucent ghost lies over the commanded platform, the platform's violet
    // still shows through it, greener than without the ghost.
    let (x, y) = project(&camera, Vec3::new(0.0, 0.0, 0.8), w, h);
    let (over, under) = (ghosted.pixel(x, y), plain.pixel(x, y));
    assert!(is_platform_violet(under), "{under:?}");
    assert!(
        over[1] > under[1] && over[2] > over[0] + 15,
        "{over:?} over {under:?}"
    );
}

#[test]
fn presentation_labels_are_larger_and_a_yellow_label_has_dark_ink() {
    let mut off = offscreen();
    let g = Geometry::seed();
    let pose = g.home_pose();
    let (w, h) = (1280, 720);
    let camera = seed_camera(&g);
    let draw = |off: &mut Offscreen, overlays: &Overlays| {
        render_with(off, &g, &pose, &Theme::LIGHT, (w, h), overlays, camera).0
    };
    let bare = draw(
        &mut off,
        &Overlays {
            labels: false,
            ..Overlays::default()
        },
    );
    let normal = draw(&mut off, &Overlays::default());
    let large = draw(
        &mut off,
        &Overlays {
            label_scale: 1.6,
            ..Overlays::default()
        },
    );
    let changed = |img: &Image| {
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .filter(|&(x, y)| img.pixel(x, y) != bare.pixel(x, y))
            .count()
    };
    let (n, l) = (changed(&normal), changed(&large));
    assert!(l as f64 > 1.8 * n as f64, "{n} → {l} pixels");
    // L5's box is yellow-orange on white: its ink is dark, so some pixels near the label
    // are near black.
    let sol = g.inverse(&pose);
    let p = sol.platform_joints[4] - sol.legs[4] * 0.55;
    let (x, y) = project(&camera, Vec3::new(p.x as f32, p.y as f32, p.z as f32), w, h);
    let em = (0.034 * h as f32) as i32;
    let dark = (-em..=em)
        .flat_map(|dy| (0..3 * em).map(move |dx| (x as i32 + dx, y as i32 + dy)))
        .filter(|&(px, py)| px >= 0 && py >= 0 && px < w as i32 && py < h as i32)
        .filter(|&(px, py)| {
            let q = normal.pixel(px as u32, py as u32);
            q[0] < 60 && q[1] < 60 && q[2] < 60
        })
        .count();
    assert!(dark > 10, "{dark} dark pixels in L5's label");
}
