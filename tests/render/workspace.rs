//! The workspace surface and the conditioning slice drawn into the 3D view: a reference
//! image, and checks that do not depend on rasteriser details.

use std::sync::Arc;
use stewart_kinematics::analysis::workspace;

use glam::Vec3;
use stewart_kinematics::analysis::workspace::{Plane, Slice, WorkspaceSurface};
use stewart_kinematics::{Angle, Scenario, model::limits::Limits};
use stewart_render::analysis::AnalysisMesh;
use stewart_render::colormap;
use stewart_render::theme::linear;
use stewart_render::{DrawList, Image, Overlays, Theme};

use crate::snapshots::{SIZE, check};
use crate::{offscreen, project, seed_camera};

/// The paired preset: well conditioned near home (the seed's layout is singular
/// everywhere, its slices all past the threshold).
fn paired() -> Scenario {
    Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"))
}

/// The surface at `rpy` (degrees) on a 128-column grid.
fn surface(s: &Scenario, rpy: [f64; 3], theme: &Theme) -> Arc<AnalysisMesh> {
    let ws = workspace::constant_orientation_workspace(
        &s.geometry,
        &Limits::default(),
        rpy.map(Angle::from_degrees),
        128,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    Arc::new(AnalysisMesh::surface(
        &WorkspaceSurface::from_workspace(&ws),
        linear(theme.workspace),
    ))
}

/// The level slice 0.2 m under the home height (where the workspace is wider than the
/// platform) over ±0.8 m.
fn slice(s: &Scenario) -> Slice {
    workspace::workspace_slice(
        &s.geometry,
        &Limits::default(),
        [Angle::ZERO; 3],
        Plane::Horizontal,
        s.geometry.home_pose().position.z - 0.2,
        [[-0.8, 0.8], [-0.8, 0.8]],
        [64, 64],
    )
}

/// The seed view of `s` at home with `analysis` drawn, with the platform or (`bare`)
/// without anything else.
fn draw_with(s: &Scenario, analysis: Vec<Arc<AnalysisMesh>>, theme: &Theme, bare: bool) -> Image {
    let g = &s.geometry;
    let frame = g.scene_frame(&g.home_pose(), Vec::new());
    let mut list = if bare {
        DrawList::default()
    } else {
        DrawList::build(&frame, theme, &Overlays::default())
    };
    list.analysis = analysis;
    offscreen()
        .render(&list, &seed_camera(g), theme, SIZE.0, SIZE.1)
        .unwrap_or_else(|e| panic!("{e}"))
}

fn draw(s: &Scenario, analysis: Vec<Arc<AnalysisMesh>>, theme: &Theme) -> Image {
    draw_with(s, analysis, theme, false)
}

fn pixel(f: &Image, (x, y): (u32, u32)) -> [i32; 3] {
    let k = 4 * (y * f.width + x) as usize;
    [0, 1, 2].map(|c| i32::from(f.rgba[k + c]))
}

fn differing(a: &Image, b: &Image) -> usize {
    a.rgba
        .chunks(4)
        .zip(b.rgba.chunks(4))
        .filter(|(p, q)| (0..3).any(|c| (i32::from(p[c]) - i32::from(q[c])).abs() > 8))
        .count()
}

#[test]
fn the_workspace_surface_and_slice_match_their_reference() {
    let s = paired();
    let theme = Theme::DARK;
    let condition_max = s.checks.condition_max;
    let frame = draw(
        &s,
        vec![
            surface(&s, [0.0; 3], &theme),
            Arc::new(AnalysisMesh::slice(&slice(&s), condition_max, 0.85)),
        ],
        &theme,
    );
    check("paired_workspace_dark", &frame);
}

#[test]
fn the_surface_tints_the_view_and_follows_the_orientation() {
    let s = paired();
    let theme = Theme::DARK;
    let bare = draw(&s, Vec::new(), &theme);
    let level = draw(&s, vec![surface(&s, [0.0; 3], &theme)], &theme);
    let tilted = draw(&s, vec![surface(&s, [0.0, 0.0, 25.0], &theme)], &theme);
    let pixels = (SIZE.0 * SIZE.1) as usize;
    // The translucent surface covers a good part of the view around the platform…
    let covered = differing(&bare, &level);
    assert!(covered > pixels / 20, "{covered} of {pixels} pixels tinted");
    // …and a yaw of 25° reshapes it.
    let changed = differing(&level, &tilted);
    assert!(changed > pixels / 100, "{changed} pixels changed");
}

#[test]
fn slice_cells_show_their_condition_colour() {
    // Drawn alone and opaque, each reachable cell shows its own colour (lit from above:
    // within a shading factor) at its centre's pixel.
    let s = paired();
    let theme = Theme::DARK;
    let cut = slice(&s);
    let condition_max = s.checks.condition_max;
    let bare = draw_with(&s, Vec::new(), &theme, true);
    let shown = draw_with(
        &s,
        vec![Arc::new(AnalysisMesh::slice(&cut, condition_max, 1.0))],
        &theme,
        true,
    );
    let camera = seed_camera(&s.geometry);
    let mut tested = 0;
    let mut kinds = std::collections::BTreeSet::new();
    for j in (2..62).step_by(6) {
        for i in (2..62).step_by(6) {
            let Some(k) = cut.get(i, j) else {
                continue;
            };
            kinds.insert(colormap::condition_colour(k, condition_max));
            let [x, y] = cut.centre(i, j);
            let at = project(
                &camera,
                Vec3::new(x as f32, y as f32, cut.at as f32),
                SIZE.0,
                SIZE.1,
            );
            let want = colormap::condition_colour(k, condition_max).map(i32::from);
            let distance = |p: [i32; 3]| (0..3).map(|c| (p[c] - want[c]).abs()).sum::<i32>();
            let (before, after) = (pixel(&bare, at), pixel(&shown, at));
            // The hue is the cell's: its colour scaled by the lighting.
            let scale = (0..3).map(|c| after[c]).sum::<i32>() as f64
                / (0..3).map(|c| want[c]).sum::<i32>().max(1) as f64;
            let scaled = want.map(|c| (c as f64 * scale) as i32);
            let off = (0..3)
                .map(|c| (after[c] - scaled[c]).abs())
                .max()
                .unwrap_or(0);
            assert!(
                off < 40 && distance(after) < distance(before),
                "cell ({i}, {j}) κ = {k:.2} at {at:?}: {before:?} → {after:?}, want {want:?} × {scale:.2}"
            );
            tested += 1;
        }
    }
    assert!(tested >= 10, "only {tested} reachable test cells");
    assert!(kinds.len() >= 3, "only {} colours: {kinds:?}", kinds.len());
}

#[test]
fn a_stiffness_slice_is_yellow_where_the_platform_is_stiffest() {
    // The paired platform's lowest stiffness over the level slice, drawn alone and opaque:
    // the stiffest cell shows viridis' yellow end, the softest its dark end.
    let s = paired();
    let theme = Theme::DARK;
    let g = &s.geometry;
    let cut = workspace::stiffness_slice(
        g,
        &Limits::default(),
        [Angle::ZERO; 3],
        Plane::Horizontal,
        g.home_pose().position.z - 0.2,
        [[-0.8, 0.8], [-0.8, 0.8]],
        [64, 64],
        1.0,
    );
    let values: Vec<(usize, f64)> = cut
        .values
        .iter()
        .enumerate()
        .filter_map(|(k, v)| v.map(|v| (k, v)))
        .collect();
    let stiffest = values
        .iter()
        .copied()
        .fold((0, f64::MIN), |a, b| if b.1 > a.1 { b } else { a });
    let softest = values
        .iter()
        .copied()
        .fold((0, f64::MAX), |a, b| if b.1 < a.1 { b } else { a });
    let shown = draw_with(
        &s,
        vec![Arc::new(AnalysisMesh::stiffness_slice(
            &cut,
            [softest.1, stiffest.1],
            1.0,
        ))],
        &theme,
        true,
    );
    if let Some(dir) = std::env::var_os("STEWART_LOOK_DIR") {
        let path = std::path::Path::new(&dir).join("stiffness_slice.png");
        image::save_buffer(
            &path,
            &shown.rgba,
            SIZE.0,
            SIZE.1,
            image::ExtendedColorType::Rgba8,
        )
        .unwrap_or_else(|e| panic!("{e}"));
    }
    let camera = seed_camera(g);
    let at = |k: usize| {
        let [x, y] = cut.centre(k % cut.cells[0], k / cut.cells[0]);
        project(
            &camera,
            Vec3::new(x as f32, y as f32, cut.at as f32),
            SIZE.0,
            SIZE.1,
        )
    };
    let yellow = pixel(&shown, at(stiffest.0));
    let dark = pixel(&shown, at(softest.0));
    // Yellow: red and green well above blue; the dark end: blue above green, dim.
    assert!(
        yellow[0] > yellow[2] + 60 && yellow[1] > yellow[2] + 60,
        "{yellow:?}"
    );
    assert!(
        dark[2] > dark[1] && dark.iter().sum::<i32>() < yellow.iter().sum::<i32>(),
        "{dark:?}"
    );
}
