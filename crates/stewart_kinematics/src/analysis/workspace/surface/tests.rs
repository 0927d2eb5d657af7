use std::collections::HashMap;

use super::*;
use crate::analysis::workspace;
use crate::io::scenario::Scenario;
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;

fn preset(name: &str) -> Geometry {
    Scenario::preset(name)
        .unwrap_or_else(|e| panic!("{e}"))
        .geometry
}

/// A workspace of hand-made columns `(i, j, low, high)` on a grid of unit cells.
fn columns(cols: &[(usize, usize, f64, f64)]) -> ConstantOrientationWorkspace {
    let spans: Vec<[f64; 4]> = cols
        .iter()
        .map(|&(i, j, lo, hi)| [10.0 + i as f64, -5.0 + j as f64, lo, hi])
        .collect();
    ConstantOrientationWorkspace {
        orientation: [Angle::ZERO; 3],
        resolution: 8,
        cell: 1.0,
        volume: spans.iter().map(|s| s[3] - s[2]).sum(),
        volume_error: 0.0,
        extent: super::super::extent_of(&spans),
        spans,
    }
}

/// Every directed edge is matched by its reverse as often as it occurs: the mesh is
/// closed and its faces are oriented consistently (a vertex where the boundary touches
/// itself may carry an edge twice).
fn assert_closed(s: &WorkspaceSurface) {
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &s.triangles {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(
            edges.get(&(b, a)),
            Some(&n),
            "edge {a}→{b} ×{n} has no partner"
        );
    }
}

#[test]
fn a_block_of_equal_columns_is_a_box_around_the_whole_cells() {
    let mut cols = Vec::new();
    for i in 0..3 {
        for j in 0..4 {
            cols.push((i, j, 0.5, 2.0));
        }
    }
    let s = WorkspaceSurface::from_workspace(&columns(&cols));
    assert_closed(&s);
    // 3 × 4 whole cells, height 1.5: the column sum exactly.
    assert!((s.enclosed_volume() - 3.0 * 4.0 * 1.5).abs() < 1e-12);
    // Two per column, two more for each of the 10 on the boundary.
    assert_eq!(s.positions.len(), 24 + 20);
    let xs = s.positions.iter().map(|p| p[0]);
    assert_eq!(xs.clone().fold(f64::INFINITY, f64::min), 9.5);
    assert_eq!(xs.fold(f64::NEG_INFINITY, f64::max), 12.5);
    assert_eq!(s.split_columns, 0);
}

#[test]
fn three_columns_of_a_square_make_one_prism_with_a_rim() {
    // The corner (1, 1) is missing: one triangle of area 1/2, height 3, and a rim around
    // it, short of the three whole cells (9) where the diagonal cuts them.
    let s = WorkspaceSurface::from_workspace(&columns(&[
        (0, 0, 1.0, 4.0),
        (1, 0, 1.0, 4.0),
        (0, 1, 1.0, 4.0),
    ]));
    assert_closed(&s);
    let v = s.enclosed_volume();
    assert!(v > 1.5 + 3.0 * 1.0 && v < 9.0, "{v}");
    // 2 caps; each of 3 boundary edges: two strips and a wall of 2 triangles.
    assert_eq!(s.triangles.len(), 2 + 3 * 6);
}

#[test]
fn heights_are_interpolated_linearly_between_column_centres() {
    // A ramp: high = 1 + i on a 3 × 2 block, low = 0. The wedge over the centres holds
    // 4, the rim (at the boundary columns' heights) 8: the column sum, 12.
    let mut cols = Vec::new();
    for i in 0..3 {
        for j in 0..2 {
            cols.push((i, j, 0.0, 1.0 + i as f64));
        }
    }
    let s = WorkspaceSurface::from_workspace(&columns(&cols));
    assert_closed(&s);
    assert!((s.enclosed_volume() - 12.0).abs() < 1e-12);
}

#[test]
fn a_split_column_is_drawn_whole_with_its_gap_as_a_cavity() {
    let ws = columns(&[
        (0, 0, 0.0, 1.0),
        (0, 0, 2.0, 3.0),
        (1, 0, 0.0, 3.0),
        (0, 1, 0.0, 3.0),
        (1, 1, 0.0, 3.0),
    ]);
    let s = WorkspaceSurface::from_workspace(&ws);
    assert_eq!(s.split_columns, 1);
    assert_closed(&s);
    // The 2 × 2 cells, 3 high, less the gap of one cell from 1 to 2: the column sum.
    assert!((s.enclosed_volume() - ws.volume).abs() < 1e-12);
    assert!((ws.volume - 11.0).abs() < 1e-12);
}

#[test]
fn nothing_reachable_gives_an_empty_surface() {
    let s = WorkspaceSurface::from_workspace(&columns(&[]));
    assert!(s.triangles.is_empty() && s.positions.is_empty());
    // Lone columns and a diagonal pair enclose nothing either.
    let s = WorkspaceSurface::from_workspace(&columns(&[(0, 0, 0.0, 1.0), (1, 1, 0.0, 1.0)]));
    assert!(s.triangles.is_empty());
    assert_eq!(s.enclosed_volume(), 0.0);
}

/// The surface's volume at `n` columns a side and its error bound: the difference from
/// the surface at `n / 2`, as the workspace's own bound is made.
fn surface_volume(g: &Geometry, orientation: [Angle; 3], n: usize) -> (f64, f64) {
    let at = |n| {
        let ws = workspace::constant_orientation_workspace(g, &Limits::default(), orientation, n)
            .unwrap_or_else(|e| panic!("{e}"));
        WorkspaceSurface::from_workspace(&ws).enclosed_volume()
    };
    let v = at(n);
    (v, (v - at(n / 2)).abs())
}

#[test]
fn the_enclosed_volume_agrees_with_the_column_sum_within_their_error_bounds() {
    let cases = [
        ("paired", [0.0, 0.0, 0.0], 128),
        ("paired", [0.0, 0.0, 0.0], 512),
        ("paired", [5.0, -3.0, 10.0], 256),
        ("seed", [8.0, 0.0, -12.0], 256),
        ("servo-desk", [0.0, 0.0, 0.0], 96),
    ];
    for (name, rpy, n) in cases {
        let g = preset(name);
        let orientation = rpy.map(Angle::from_degrees);
        let ws = workspace::constant_orientation_workspace(&g, &Limits::default(), orientation, n)
            .unwrap_or_else(|e| panic!("{e}"));
        let s = WorkspaceSurface::from_workspace(&ws);
        assert_closed(&s);
        let (v, bound) = surface_volume(&g, orientation, n);
        assert_eq!(v, s.enclosed_volume());
        assert!(
            (v - ws.volume).abs() <= ws.volume_error + bound,
            "{name} {rpy:?} at {n}: surface {v} ± {bound}, columns {} ± {}",
            ws.volume,
            ws.volume_error
        );
        // Every vertex lies within the workspace's extent, widened by a cell in x and y
        // (the rim reaches the outer edge of the boundary cells).
        let [ex, ey, ez] = ws.extent.unwrap_or_else(|| panic!("empty"));
        for p in &s.positions {
            for (k, e) in [ex, ey, ez].iter().enumerate() {
                let pad = if k < 2 { ws.cell } else { 0.0 } + 1e-12;
                assert!(p[k] >= e[0] - pad && p[k] <= e[1] + pad);
            }
        }
    }
}

#[test]
fn the_enclosed_volume_converges_to_the_fine_column_sum_at_second_order() {
    // A tilted platform whose columns split under the inner stroke spheres: the cavities
    // count. Reference: 1024 columns a side (its own bound ~1e-7 m³).
    let g = preset("paired");
    let orientation = [5.0, -3.0, 10.0].map(Angle::from_degrees);
    let reference =
        workspace::constant_orientation_workspace(&g, &Limits::default(), orientation, 1024)
            .unwrap_or_else(|e| panic!("{e}"));
    let deviation = |n| (surface_volume(&g, orientation, n).0 - reference.volume).abs();
    let (coarse, fine) = (deviation(128), deviation(512));
    assert!(
        fine < coarse / 8.0,
        "128: {coarse:e}, 512: {fine:e} (reference {} ± {})",
        reference.volume,
        reference.volume_error
    );
    assert!(fine < 1e-5 * reference.volume, "{fine:e}");
}

#[test]
fn the_upper_surface_holds_every_columns_highest_reachable_point() {
    // Each upper vertex is a reachable pose (inside by a hair) and a hair above it is not.
    let g = preset("paired");
    let ws =
        workspace::constant_orientation_workspace(&g, &Limits::default(), [Angle::ZERO; 3], 64)
            .unwrap_or_else(|e| panic!("{e}"));
    let s = WorkspaceSurface::from_workspace(&ws);
    let pose = |p: [f64; 3]| crate::model::pose::Pose::level_at(0.0).with_position(p.into());
    // The columns' own vertices come first, upper then lower.
    assert_eq!(s.split_columns, 0);
    for p in s.positions[..2 * ws.spans.len()].iter().step_by(2) {
        assert!(workspace::pose_within_limits(
            &g,
            &Limits::default(),
            &pose([p[0], p[1], p[2] - 1e-9])
        ));
        assert!(!workspace::pose_within_limits(
            &g,
            &Limits::default(),
            &pose([p[0], p[1], p[2] + 1e-6])
        ));
    }
}

#[test]
fn every_other_column_is_a_lighter_mesh_of_the_same_workspace() {
    let g = preset("paired");
    let orientation = [5.0, -3.0, 10.0].map(Angle::from_degrees);
    let fine = workspace::constant_orientation_workspace(&g, &Limits::default(), orientation, 256)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(fine.every(1), fine);
    let light = fine.every(2);
    assert_eq!(light.resolution, 128);
    assert!((light.cell - 2.0 * fine.cell).abs() < 1e-15);
    // About a quarter of the columns, the same volume within its widened bound.
    let ratio = light.spans.len() as f64 / fine.spans.len() as f64;
    assert!((ratio - 0.25).abs() < 0.02, "{ratio}");
    assert!((light.volume - fine.volume).abs() <= light.volume_error);
    assert!((light.volume - fine.volume).abs() < 2e-3 * fine.volume);
    let s = WorkspaceSurface::from_workspace(&light);
    assert_closed(&s);
    assert!((s.enclosed_volume() - fine.volume).abs() < 2e-3 * fine.volume);
}
