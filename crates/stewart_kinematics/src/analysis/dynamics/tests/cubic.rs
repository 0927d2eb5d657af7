//! The cubic configuration (legs along six edges of a cube standing on a vertex, as in
//! tdehaeze/stewart-simscape): its stiffness about the cube's centre has the closed form
//! `K = k · diag(2, 2, 2, Hc²/6, Hc²/6, 2 Hc²/3)`, `Hc` the cube's height (its diagonal,
//! `a √3` for side `a`), and with the mass centred there the six modes decouple.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::*;
use crate::analysis::workspace;
use crate::model::geometry::{GeometryParams, PlateJoints};

const SIDE: f64 = 0.3;
const CENTRE_HEIGHT: f64 = 0.5;

/// The cube's corners to the base frame: its diagonal (1, 1, 1) made vertical, its centre
/// at `CENTRE_HEIGHT` above the base.
fn to_base(corner: [f64; 3]) -> Vector3<f64> {
    let q = Matrix3::from_rows(&[
        Vector3::new(1.0, -1.0, 0.0).normalize().transpose(),
        Vector3::new(1.0, 1.0, -2.0).normalize().transpose(),
        Vector3::new(1.0, 1.0, 1.0).normalize().transpose(),
    ]);
    q * (Vector3::from(corner) * (SIDE / 2.0)) + Vector3::new(0.0, 0.0, CENTRE_HEIGHT)
}

/// Legs along the six edges that touch neither end of the vertical diagonal, each from
/// 10 % to 90 % of its edge; the platform frame's origin at the cube's centre at home.
fn cubic_geometry() -> Geometry {
    let lower = [[1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
    let mut edges = Vec::new();
    for l in lower {
        for axis in 0..3 {
            if l[axis] < 0.0 {
                let mut u = l;
                u[axis] = 1.0;
                edges.push((to_base(l), to_base(u)));
            }
        }
    }
    assert_eq!(edges.len(), 6);
    let centre = Vector3::new(0.0, 0.0, CENTRE_HEIGHT);
    let base = std::array::from_fn(|i| edges[i].0 + 0.1 * (edges[i].1 - edges[i].0));
    let platform = std::array::from_fn(|i| edges[i].0 + 0.9 * (edges[i].1 - edges[i].0) - centre);
    let mut p = GeometryParams::seed();
    p.base = PlateJoints::Points(base);
    p.platform = PlateJoints::Points(platform);
    p.home_height = CENTRE_HEIGHT;
    Geometry::new(p).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_cubic_configurations_stiffness_is_the_closed_form() {
    let g = cubic_geometry();
    let k = 2.5e6;
    let got = stiffness(&g, &g.home_pose(), k).unwrap_or_else(|e| panic!("{e}"));
    let hc2 = 3.0 * SIDE * SIDE;
    let expected = Matrix6::from_diagonal(&Vector6::new(
        2.0,
        2.0,
        2.0,
        hc2 / 6.0,
        hc2 / 6.0,
        2.0 * hc2 / 3.0,
    )) * k;
    let gap = (got - expected).amax() / expected.amax();
    assert!(gap < 1e-9, "{got:.6}\nvs\n{expected:.6} ({gap:e})");
}

#[test]
fn a_centred_mass_on_the_cubic_configuration_has_decoupled_modes() {
    // Also for an absurdly light payload (accepted: any positive mass), whose modes once
    // overflowed to NaN: the closed form holds at every scale.
    for scale in [1.0, 1e-12, 1e-200] {
        let g = cubic_geometry();
        let k = 1.0e6;
        let (mass, inertia) = (40.0 * scale, [1.2 * scale, 1.5 * scale, 2.0 * scale]);
        let payload = Payload::new(
            mass,
            Vector3::zeros(),
            Matrix3::from_diagonal(&Vector3::from(inertia)),
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let dynamics = DynamicsSettings {
            actuator_stiffness: Some(k),
            ..DynamicsSettings::default()
        };
        let modes =
            modes(&g, &g.home_pose(), &payload, &dynamics).unwrap_or_else(|e| panic!("{e}"));
        let hc2 = 3.0 * SIDE * SIDE;
        let w = |stiffness: f64, inertia: f64| (stiffness / inertia).sqrt() / std::f64::consts::TAU;
        let mut expected = [
            w(2.0 * k, mass),
            w(2.0 * k, mass),
            w(2.0 * k, mass),
            w(k * hc2 / 6.0, inertia[0]),
            w(k * hc2 / 6.0, inertia[1]),
            w(2.0 * k * hc2 / 3.0, inertia[2]),
        ];
        expected.sort_by(f64::total_cmp);
        for (got, want) in modes.frequencies_hz.iter().zip(expected) {
            assert!((got - want).abs() < 1e-9 * want, "{scale}: {got} vs {want}");
        }
        // The lowest is the pitch mode: k·Hc²/6 over the larger of Ixx and Iyy.
        assert!(modes.modes[0][4] > 1.0 - 1e-9, "{}", modes.modes[0]);
        assert_eq!(modes.dominant(0), vec![("ry", modes.modes[0][4])]);
    }
}

#[test]
fn a_leg_of_zero_length_is_named_not_blamed_on_the_inertia() {
    // The platform lowered until leg 1's joints meet.
    let g = cubic_geometry();
    let home = g.home_pose();
    let gap = g.base_joints()[0] - g.inverse(&home).platform_joints[0];
    let pose = Pose::new(home.position + gap, home.roll, home.pitch, home.yaw);
    assert_eq!(g.leg_without_direction(&pose), Some(0));
    let payload =
        Payload::new(40.0, Vector3::zeros(), Matrix3::identity()).unwrap_or_else(|e| panic!("{e}"));
    let dynamics = DynamicsSettings {
        actuator_stiffness: Some(1e6),
        ..DynamicsSettings::default()
    };
    let e = modes(&g, &pose, &payload, &dynamics).err();
    assert_eq!(e, Some(DynamicsError::LegWithoutDirection { leg: 1 }));
    assert_eq!(g.leg_without_direction(&home), None);
}

#[test]
fn modes_solve_the_generalised_eigenproblem() {
    // K v = ω² M v with M-orthogonal modes, on platforms with heavy legs off-centre.
    let mut rng = Random(2024);
    for g in [
        offset_pivot_geometry(),
        crate::test_support::servo_geometry(),
        cubic_geometry(),
    ] {
        let size = g.characteristic_length();
        for _ in 0..20 {
            let payload = random_payload(&mut rng, size);
            let dynamics = random_dynamics(&mut rng, size, payload.mass);
            let modes =
                modes(&g, &g.home_pose(), &payload, &dynamics).unwrap_or_else(|e| panic!("{e}"));
            let (kk, mm) = (&modes.stiffness, &modes.mass_matrix);
            for a in 0..6 {
                let v = modes.modes[a];
                assert!((v.norm() - 1.0).abs() < 1e-12);
                let lambda = (std::f64::consts::TAU * modes.frequencies_hz[a]).powi(2);
                let residual = (kk * v - lambda * mm * v).norm() / (kk * v).norm();
                assert!(residual < 1e-9, "residual {residual:e}");
                for b in 0..a {
                    let cross = (v.transpose() * mm * modes.modes[b])[0];
                    let scale = (v.transpose() * mm * v)[0];
                    assert!(
                        cross.abs() < 1e-9 * scale,
                        "modes {a} and {b} not M-orthogonal"
                    );
                }
                if a > 0 {
                    assert!(modes.frequencies_hz[a] >= modes.frequencies_hz[a - 1]);
                }
            }
        }
    }
}

#[test]
fn a_point_mass_has_no_rotational_inertia_and_is_refused() {
    let g = crate::test_support::paired_geometry();
    let payload =
        Payload::new(10.0, Vector3::zeros(), Matrix3::zeros()).unwrap_or_else(|e| panic!("{e}"));
    let dynamics = DynamicsSettings {
        actuator_stiffness: Some(1e6),
        ..DynamicsSettings::default()
    };
    assert_eq!(
        modes(&g, &g.home_pose(), &payload, &dynamics),
        Err(DynamicsError::MassMatrixNotPositive)
    );
    assert_eq!(
        modes(&g, &g.home_pose(), &payload, &DynamicsSettings::default()),
        Err(DynamicsError::NoStiffness)
    );
}

#[test]
fn moving_along_a_mode_moves_the_origin_and_turns_about_it() {
    let mut p = crate::test_support::paired_geometry().params().clone();
    p.pivot = Vector3::new(0.05, 0.0, 0.1);
    let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
    let pose = Pose::from_xyz_rpy_deg([0.02, -0.01, 0.85], [4.0, -3.0, 12.0]);
    let v = Vector6::new(0.3, -0.2, 0.5, 0.4, 0.1, -0.6).normalize();
    let s = 0.01;
    let moved = moved_along(&g, &pose, &v, s);
    let shift = g.platform_centre(&moved) - g.platform_centre(&pose);
    assert!((shift - s * v.fixed_rows::<3>(0)).norm() < 1e-15);
    let turn = moved.rotation() * pose.rotation().transpose();
    let expected = nalgebra::Rotation3::new(s * v.fixed_rows::<3>(3).into_owned());
    assert!((turn - expected.matrix()).amax() < 1e-14);
    // Every joint moves by at most the travel the mode allows (to first order).
    let travel = joint_travel(&g, &pose, &v) * s;
    let before = g.inverse(&pose).platform_joints;
    let after = g.inverse(&moved).platform_joints;
    let largest = (0..6)
        .map(|i| (after[i] - before[i]).norm())
        .fold(0.0, f64::max);
    assert!(
        (largest - travel).abs() < 1e-3 * travel,
        "{largest} vs {travel}"
    );
}

#[test]
fn the_lowest_stiffness_of_the_cubic_configuration_is_its_weakest_axis() {
    // About the cube's centre K is diagonal: k·(2, 2, 2, Hc²/6, Hc²/6, 2Hc²/3); with
    // rotations measured at ℓ the rotational terms are divided by ℓ².
    let g = cubic_geometry();
    let k = 3.0e6;
    let l = g.characteristic_length();
    let hc2 = 3.0 * SIDE * SIDE;
    let expected = k * [2.0, hc2 / 6.0 / (l * l), 2.0 * hc2 / 3.0 / (l * l)]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    let got = lowest_stiffness(&g, &g.home_pose(), k).unwrap_or_else(|| panic!("unreachable"));
    assert!(
        (got - expected).abs() < 1e-9 * expected,
        "{got} vs {expected}"
    );
    // A slice through home holds it at the home cell and nothing stiffer elsewhere is
    // assumed: every reachable cell's value is positive and finite.
    let limits = crate::model::limits::Limits::default();
    let slice = workspace::stiffness_slice(
        &g,
        &limits,
        [Angle::from_degrees(0.0); 3],
        workspace::Plane::Horizontal,
        CENTRE_HEIGHT,
        [[-0.05, 0.05], [-0.05, 0.05]],
        [5, 5],
        k,
    );
    let centre = slice
        .get(2, 2)
        .unwrap_or_else(|| panic!("home out of reach"));
    assert!((centre - expected).abs() < 1e-9 * expected);
    assert!(
        slice
            .values
            .iter()
            .flatten()
            .all(|v| v.is_finite() && *v > 0.0)
    );
}
