//! The workspace under cone and clearance limits against an independent brute force: a
//! 3-D grid of positions each tested with [`super::super::pose_within_limits`] (plain inverse
//! kinematics and the limit checks, none of the column code).

use super::*;

/// The volume of the positions held at `orientation`, counted on an `n³` grid of cell
/// centres over the workspace's extent (padded), and the grid's cell volume.
fn brute_force_volume(
    g: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    ws: &ConstantOrientationWorkspace,
    n: usize,
) -> (f64, f64) {
    let [ex, ey, ez] = ws.extent.unwrap_or_else(|| panic!("empty"));
    let pad = 4.0 * ws.cell;
    let (lo, hi) = (
        [ex[0] - pad, ey[0] - pad, (ez[0] - pad).max(0.0)],
        [ex[1] + pad, ey[1] + pad, ez[1] + pad],
    );
    let cell: [f64; 3] = std::array::from_fn(|k| (hi[k] - lo[k]) / n as f64);
    let [roll, pitch, yaw] = orientation;
    let count: usize = (0..n)
        .into_par_iter()
        .map(|i| {
            let mut count = 0;
            for j in 0..n {
                for k in 0..n {
                    let centre = Vector3::new(
                        lo[0] + (i as f64 + 0.5) * cell[0],
                        lo[1] + (j as f64 + 0.5) * cell[1],
                        lo[2] + (k as f64 + 0.5) * cell[2],
                    );
                    // The spans are platform-centre positions; the pose is the centre's too
                    // (no pivot offset in these geometries).
                    let pose = Pose::new(centre, roll, pitch, yaw);
                    count += usize::from(pose_within_limits(g, limits, &pose));
                }
            }
            count
        })
        .sum();
    let cell_volume = cell[0] * cell[1] * cell[2];
    (count as f64 * cell_volume, cell_volume)
}

/// The workspace's volume equals the brute force on an `n³` grid within its error bound,
/// 1 % and one brute-force cell (the brute force counts whole cells: its error is of the
/// order of the boundary's area times half a cell; measured here, the two agree to 0.05 %).
fn agrees_with_brute_force(
    g: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    ws: &ConstantOrientationWorkspace,
    n: usize,
) {
    let (brute, cell) = brute_force_volume(g, limits, orientation, ws, n);
    let tolerance = ws.volume_error + 0.01 * ws.volume + cell;
    assert!(
        (brute - ws.volume).abs() < tolerance,
        "brute force {brute} vs {} ± {}",
        ws.volume,
        ws.volume_error
    );
}

/// Every span's midpoint is held; each end not on the base plane is an edge: held 1e-9 m
/// inside, not 1e-9 m outside. Returns how many ends were checked.
fn ends_are_edges(
    g: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    ws: &ConstantOrientationWorkspace,
) -> usize {
    let [roll, pitch, yaw] = orientation;
    let held = |x: f64, y: f64, z: f64| {
        pose_within_limits(
            g,
            limits,
            &Pose::new(Vector3::new(x, y, z), roll, pitch, yaw),
        )
    };
    let mut checked = 0;
    for &[x, y, z0, z1] in ws.spans.iter().step_by(3) {
        assert!(held(x, y, 0.5 * (z0 + z1)), "({x}, {y}) [{z0}, {z1}]");
        if z0 > 1e-9 {
            assert!(
                held(x, y, z0 + 1e-9) && !held(x, y, z0 - 1e-9),
                "({x}, {y}) from {z0}"
            );
            checked += 1;
        }
        assert!(
            held(x, y, z1 - 1e-9) && !held(x, y, z1 + 1e-9),
            "({x}, {y}) to {z1}"
        );
        checked += 1;
    }
    checked
}

/// The seed platform turned 30° in yaw, where adjacent legs come close: cones at both
/// joints and a leg radius that removes a sixth of the volume (0.295 → 0.250 m³).
#[test]
fn linear_cones_and_clearance_agree_with_brute_force_and_end_on_edges() {
    let g = crate::io::scenario::Scenario::preset("seed")
        .unwrap_or_else(|e| panic!("{e}"))
        .geometry;
    let orientation = [5.0, -3.0, 30.0].map(Angle::from_degrees);
    let limits = Limits {
        base_cone: Some(Angle::from_degrees(50.0)),
        platform_cone: Some(Angle::from_degrees(60.0)),
        leg_radius: Some(0.06),
        ..Limits::default()
    };
    let free = constant_orientation_workspace(&g, &Limits::default(), orientation, 96)
        .unwrap_or_else(|e| panic!("{e}"));
    let ws = constant_orientation_workspace(&g, &limits, orientation, 96)
        .unwrap_or_else(|e| panic!("{e}"));
    let clearance_only = Limits {
        leg_radius: Some(0.06),
        ..Limits::default()
    };
    let without_cones = constant_orientation_workspace(&g, &clearance_only, orientation, 96)
        .unwrap_or_else(|e| panic!("{e}"));
    // Each limit binds.
    assert!(ws.volume < 0.9 * without_cones.volume && without_cones.volume < 0.9 * free.volume);
    assert!(ends_are_edges(&g, &limits, orientation, &ws) > 100);
    assert!(ends_are_edges(&g, &clearance_only, orientation, &without_cones) > 100);
    for (limits, ws) in [(&limits, &ws), (&clearance_only, &without_cones)] {
        agrees_with_brute_force(&g, limits, orientation, ws, 96);
    }
}

/// The servo-desk platform tilted, with its rod cones (they remove an eighth of the
/// volume) and a clearance large enough to bind (another twentieth).
#[test]
fn rotary_rod_cones_and_clearance_agree_with_brute_force_and_end_on_edges() {
    let s = crate::io::scenario::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let g = &s.geometry;
    let orientation = [4.0, -6.0, 12.0].map(Angle::from_degrees);
    let servo_only = constant_orientation_workspace(g, &Limits::default(), orientation, 64)
        .unwrap_or_else(|e| panic!("{e}"));
    let cones = Limits {
        base_cone: Some(Angle::from_degrees(55.0)),
        platform_cone: Some(Angle::from_degrees(55.0)),
        ..Limits::default()
    };
    let tight = Limits {
        leg_radius: Some(0.011),
        ..cones
    };
    let with_cones = constant_orientation_workspace(g, &cones, orientation, 64)
        .unwrap_or_else(|e| panic!("{e}"));
    let ws = constant_orientation_workspace(g, &tight, orientation, 64)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        ws.volume < 0.97 * with_cones.volume && with_cones.volume < 0.95 * servo_only.volume,
        "{} {} {}",
        ws.volume,
        with_cones.volume,
        servo_only.volume
    );
    for (limits, ws) in [(&cones, &with_cones), (&tight, &ws)] {
        assert!(ends_are_edges(g, limits, orientation, ws) > 50);
        agrees_with_brute_force(g, limits, orientation, ws, 80);
    }
}
