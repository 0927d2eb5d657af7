//! The viewer in a real window: under Xvfb when there is no display.

use std::process::Command;

use crate::tempdir;

/// `stewart view` with `args` in a virtual X display (`xvfb-run`), to be run.
fn xvfb_view(args: &[&str]) -> Command {
    let mut command = Command::new("xvfb-run");
    command
        .args([
            "-a",
            "-s",
            "-screen 0 1600x900x24",
            env!("CARGO_BIN_EXE_stewart-e2e"),
            "view",
        ])
        .args(args);
    command
}

/// Run `stewart view` with `args` in a virtual X display, or fail clearly.
fn view_under_xvfb(args: &[&str]) -> std::process::Output {
    xvfb_view(args).output().unwrap_or_else(|e| {
        panic!("xvfb-run is needed for this test (Debian: apt-get install xvfb xauth): {e}")
    })
}

#[test]
fn the_viewer_opens_draws_the_platform_and_saves_a_screenshot() {
    let dir = tempdir();
    let shot = dir.path().join("view.png");
    let o = view_under_xvfb(&[
        "--preset",
        "paired",
        "--screenshot",
        &shot.display().to_string(),
        "--frames",
        "8",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&shot)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    assert_eq!(img.dimensions(), (1280, 720));
    // The 3D view shows the platform (violet) and the legs (blue); the panels show text.
    let red = img
        .pixels()
        .filter(|p| platform_violet(p[0], p[1], p[2]))
        .count();
    let blue = img
        .pixels()
        .filter(|p| p[2] > 150 && p[0] < 80 && p[1] < 120)
        .count();
    assert!(red > 2000, "platform pixels: {red}");
    assert!(blue > 1000, "leg pixels: {blue}");
}

#[test]
fn without_a_display_the_viewer_says_what_to_do() {
    let o = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args(["view"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("needs a display") && err.contains("xvfb-run"),
        "{err}"
    );
}

#[test]
fn presentation_mode_is_light_large_and_has_no_control_panel() {
    let dir = tempdir();
    let shot = dir.path().join("present.png");
    let o = view_under_xvfb(&[
        "--preset",
        "circle",
        "--presentation",
        "--size",
        "960x540",
        "--screenshot",
        &shot.display().to_string(),
        "--frames",
        "6",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&shot)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    assert_eq!(img.dimensions(), (960, 540));
    // Light everywhere: the left strip where the controls would be is light too, and
    // most of the window is near white.
    let light = |p: &image::Rgba<u8>| p[0] > 200 && p[1] > 200 && p[2] > 200;
    let strip = (0..540).filter(|&y| light(img.get_pixel(150, y))).count();
    assert!(strip > 300, "light pixels down x = 150: {strip}");
    let total = img.pixels().filter(|p| light(p)).count();
    assert!(total > 960 * 540 / 2, "light pixels: {total}");
    // The platform is still drawn.
    let red = img
        .pixels()
        .filter(|p| platform_violet(p[0], p[1], p[2]))
        .count();
    assert!(red > 500, "platform pixels: {red}");
}

#[test]
fn the_viewer_remembers_its_session_and_a_broken_one_is_no_crash() {
    let dir = tempdir();
    let config = dir.path().join("config");
    // An interactive run, closed by SIGTERM as a window manager or Ctrl-C would.
    let o = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1600x900x24", "sh", "-c"])
        .arg(format!(
            "{} view --preset servo-desk --light --size 1000x600 & pid=$!; sleep 6; kill -TERM $pid; wait $pid",
            env!("CARGO_BIN_EXE_stewart-e2e")
        ))
        .env("STEWART_CONFIG_DIR", &config)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let saved: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(config.join("session.json")).unwrap_or_else(|e| panic!("{e}")),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(saved["origin"], "preset servo-desk");
    assert_eq!(saved["light_theme"], true);
    assert_eq!(saved["window"], serde_json::json!([1000, 600]));
    assert!(
        saved["scenario"]
            .as_str()
            .is_some_and(|t| t.contains("kind = \"rotary\""))
    );
    // The next run without a scenario starts there: the servo platform, light, 1000×600.
    let shot = dir.path().join("again.png");
    let again = |shot: &std::path::Path| {
        xvfb_view(&[
            "--screenshot",
            &shot.display().to_string(),
            "--frames",
            "6",
            "--from-session",
        ])
        .env("STEWART_CONFIG_DIR", &config)
        .output()
        .unwrap_or_else(|e| panic!("{e}"))
    };
    let o = again(&shot);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&shot)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    assert_eq!(img.dimensions(), (1000, 600));
    let white = img
        .pixels()
        .filter(|p| p[0] > 245 && p[1] > 245 && p[2] > 245)
        .count();
    assert!(white > 100_000, "not the light theme: {white} white pixels");
    // Without --from-session a screenshot run does not depend on the session left there.
    let plain = dir.path().join("plain.png");
    let o = xvfb_view(&[
        "--screenshot",
        &plain.display().to_string(),
        "--frames",
        "6",
    ])
    .env("STEWART_CONFIG_DIR", &config)
    .output()
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&plain)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    assert_eq!(img.dimensions(), (1280, 720));
    // A damaged session: a fresh start at the default size, no crash.
    std::fs::write(config.join("session.json"), "{ damaged").unwrap_or_else(|e| panic!("{e}"));
    let o = again(&shot);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&shot)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    assert_eq!(img.dimensions(), (1280, 720));
}

#[test]
fn a_whole_window_screenshot_at_twice_the_density_is_the_same_window_sharper() {
    let dir = tempdir();
    let shot = |scale: &str| {
        let path = dir.path().join(format!("window-{scale}.png"));
        let o = view_under_xvfb(&[
            "--preset",
            "paired",
            "--lang",
            "zh",
            "--size",
            "640x400",
            "--screenshot",
            &path.display().to_string(),
            "--screenshot-scale",
            scale,
            "--frames",
            "6",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        image::open(&path)
            .unwrap_or_else(|e| panic!("{e}"))
            .to_rgb8()
    };
    let (one, two, uhd) = (shot("1"), shot("2"), shot("4k"));
    assert_eq!(one.dimensions(), (640, 400));
    assert_eq!(two.dimensions(), (1280, 800));
    assert_eq!(uhd.dimensions(), (3840, 2400));
    // Averaged down 2 × 2, the 2× image is the 1× one: the same layout, not a crop.
    let mut total = 0u64;
    for (x, y, p) in one.enumerate_pixels() {
        for c in 0..3 {
            let block: u32 = (0..4)
                .map(|k| u32::from(two.get_pixel(2 * x + k % 2, 2 * y + k / 2)[c]))
                .sum();
            total += u64::from((block / 4).abs_diff(u32::from(p[c])));
        }
    }
    let mean = total as f64 / (640.0 * 400.0 * 3.0);
    // Text rasterised at two densities differs by a few levels (6.4 with the Chinese panels
    // at 11 pt); a crop of the 2× image (its top-left quarter) differs four times as much.
    let mut cropped = 0u64;
    for (x, y, p) in one.enumerate_pixels() {
        for c in 0..3 {
            cropped += u64::from(two.get_pixel(x, y)[c].abs_diff(p[c]));
        }
    }
    let crop = cropped as f64 / (640.0 * 400.0 * 3.0);
    assert!(
        mean < 8.0 && crop > 3.0 * mean,
        "mean difference {mean:.2} per channel; a crop would differ by {crop:.2}"
    );
    // The platform is drawn in all three, about four times the pixels at twice the
    // density (more: the leg labels' 11-pixel minimum hides more of it in the small 1×
    // view).
    let red = |img: &image::RgbImage| {
        img.pixels()
            .filter(|p| platform_violet(p[0], p[1], p[2]))
            .count()
    };
    let ratio = red(&two) as f64 / red(&one).max(1) as f64;
    assert!(
        (3.0..8.0).contains(&ratio),
        "{ratio}: {} at 2×, {} at 1×",
        red(&two),
        red(&one)
    );
    assert!(red(&uhd) > 8 * red(&one));
}

/// The platform's violet (blue above red above green), through its translucency.
fn platform_violet(r: u8, g: u8, b: u8) -> bool {
    let [r, g, b] = [r, g, b].map(i32::from);
    b > r + 10 && r > g + 10
}
