mod cubic;
mod energy;
mod jet;

use nalgebra::{Matrix3, Vector3, Vector6};

use super::*;
use crate::analysis::forces;
use crate::model::angle::Angle;
use energy::Model;
use jet::Jet;
use parts::joint_acceleration;

/// A small deterministic generator (xorshift64*), uniform in `[lo, hi)`.
struct Random(u64);

impl Random {
    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        lo + (hi - lo) * (bits as f64 / (1u64 << 53) as f64)
    }

    fn vec3(&mut self, r: f64) -> [f64; 3] {
        [self.next(-r, r), self.next(-r, r), self.next(-r, r)]
    }
}

/// A physical payload: point masses around the centre of mass make its inertia (a full
/// tensor, products of inertia included).
fn random_payload(rng: &mut Random, size: f64) -> Payload {
    let mass = rng.next(0.5, 80.0);
    let mut inertia = Matrix3::zeros();
    for _ in 0..4 {
        let p = Vector3::from(rng.vec3(size));
        let m = mass / 4.0;
        inertia += m * (Matrix3::identity() * p.norm_squared() - p * p.transpose());
    }
    let com = Vector3::from(rng.vec3(0.3 * size));
    Payload::new(mass, com, inertia).unwrap_or_else(|e| panic!("{e}"))
}

fn random_dynamics(rng: &mut Random, size: f64, mass: f64) -> DynamicsSettings {
    DynamicsSettings {
        actuator_stiffness: Some(rng.next(1e4, 1e7)),
        actuator_friction: rng.next(0.0, 50.0) * mass,
        cylinder_mass_kg: rng.next(0.0, 0.1) * mass,
        cylinder_com_m: rng.next(0.0, 0.5) * size,
        cylinder_inertia_kg_m2: rng.next(0.0, 0.01) * mass * size * size,
        rod_mass_kg: rng.next(0.0, 0.1) * mass,
        rod_com_m: rng.next(0.0, 0.5) * size,
        rod_inertia_kg_m2: rng.next(0.0, 0.01) * mass * size * size,
        horn_mass_kg: rng.next(0.0, 0.1) * mass,
        horn_com_m: rng.next(0.0, 0.02),
        horn_inertia_kg_m2: rng.next(0.0, 1e-3) * mass * size * size,
    }
}

/// The crate's motion state for pose coordinates `x0` (angles in radians) moving at `xd`
/// with `xdd`: the twist and its rate from the rotation's jets (`[ω]× = Ṙ Rᵀ`,
/// `[α]× = skew(R̈ Rᵀ)`).
fn state_of(x0: &[f64; 6], xd: &[f64; 6], xdd: &[f64; 6]) -> MotionState {
    let jets: [Jet; 6] = std::array::from_fn(|k| Jet::new(x0[k], xd[k], xdd[k]));
    let r = Model::rotation(&jets);
    let m = |f: fn(&Jet) -> f64| Matrix3::from_fn(|i, j| f(&r[i][j]));
    let (value, rate, accel) = (m(|j| j.v), m(|j| j.d1), m(|j| j.d2));
    let vee = |w: Matrix3<f64>| {
        Vector3::new(
            w[(2, 1)] - w[(1, 2)],
            w[(0, 2)] - w[(2, 0)],
            w[(1, 0)] - w[(0, 1)],
        ) * 0.5
    };
    let omega = vee(rate * value.transpose());
    let alpha = vee(accel * value.transpose());
    let pose = Pose::new(
        Vector3::new(x0[0], x0[1], x0[2]),
        Angle::from_radians(x0[3]),
        Angle::from_radians(x0[4]),
        Angle::from_radians(x0[5]),
    );
    MotionState {
        pose,
        twist: Vector6::new(xd[0], xd[1], xd[2], omega.x, omega.y, omega.z),
        twist_rate: Vector6::new(xdd[0], xdd[1], xdd[2], alpha.x, alpha.y, alpha.z),
    }
}

/// A random pose near `home` and random rates (`speed` m/s, rad/s; `accel` m/s², rad/s²).
fn random_motion(
    rng: &mut Random,
    home: f64,
    reach: f64,
    tilt: f64,
    speed: f64,
    accel: f64,
) -> [[f64; 6]; 3] {
    let x0 = [
        rng.next(-reach, reach),
        rng.next(-reach, reach),
        home + rng.next(-reach, reach),
        rng.next(-tilt, tilt),
        rng.next(-tilt, tilt),
        rng.next(-2.0 * tilt, 2.0 * tilt),
    ];
    let xd = std::array::from_fn(|_| rng.next(-speed, speed));
    let xdd = std::array::from_fn(|_| rng.next(-accel, accel));
    [x0, xd, xdd]
}

fn relative_gap(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

/// Linear legs with a pivot offset from the platform's centre.
fn offset_pivot_geometry() -> Geometry {
    let mut p = crate::test_support::paired_geometry().params().clone();
    p.pivot = Vector3::new(0.03, -0.02, 0.12);
    Geometry::new(p).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_rotation_of_the_energy_model_is_the_crates() {
    let mut rng = Random(7);
    for _ in 0..50 {
        let x: [f64; 6] = std::array::from_fn(|_| rng.next(-1.5, 1.5));
        let jets = x.map(Jet::c);
        let r = Model::rotation(&jets);
        let pose = state_of(&x, &[0.0; 6], &[0.0; 6]).pose;
        let crate_r = pose.rotation();
        for i in 0..3 {
            for j in 0..3 {
                assert!((r[i][j].v - crate_r[(i, j)]).abs() < 1e-15);
            }
        }
    }
}

#[test]
fn leg_inverse_dynamics_match_lagrange_on_random_motions() {
    let mut rng = Random(0x5eed);
    for g in [
        crate::test_support::paired_geometry(),
        offset_pivot_geometry(),
    ] {
        lagrange_agrees(&g, &mut rng, [0.5, 1.0], [0.8, 0.15, 0.3, 1.0, 10.0]);
    }
}

#[test]
fn servo_inverse_dynamics_match_lagrange_on_random_motions() {
    let mut rng = Random(0xd0e5);
    let g = crate::test_support::servo_geometry();
    let home = g.home_pose().position.z;
    lagrange_agrees(&g, &mut rng, [0.05, 0.1], [home, 0.01, 0.1, 0.2, 5.0]);
}

/// On 200 random motions of `g` (payload and part sizes `[payload, parts]`, motion
/// `[home, reach, tilt, speed, accel]` as [`random_motion`] takes them), the inverse
/// dynamics equal Lagrange's equations of the energy model to 1e-9.
fn lagrange_agrees(
    g: &Geometry,
    rng: &mut Random,
    [payload_size, parts]: [f64; 2],
    motion: [f64; 5],
) {
    let [home, reach, tilt, speed, accel] = motion;
    for case in 0..200 {
        let payload = random_payload(rng, payload_size);
        let dynamics = random_dynamics(rng, parts, payload.mass);
        let [x0, xd, xdd] = random_motion(rng, home, reach, tilt, speed, accel);
        let expected = Model::new(g, &payload, &dynamics).efforts(&x0, &xd, &xdd);
        let got = inverse_dynamics(g, &state_of(&x0, &xd, &xdd), &payload, &dynamics)
            .unwrap_or_else(|e| panic!("{e}"));
        let gap = relative_gap(&got, &expected);
        assert!(gap < 1e-9, "case {case}: {got:?} vs {expected:?} ({gap:e})");
    }
}

#[test]
fn massless_legs_give_the_forces_of_leg_forces() {
    let mut rng = Random(42);
    for g in [
        crate::test_support::paired_geometry(),
        offset_pivot_geometry(),
        crate::test_support::servo_geometry(),
    ] {
        let home = g.home_pose().position.z;
        let size = g.characteristic_length();
        for _ in 0..100 {
            let payload = random_payload(&mut rng, size);
            let [x0, xd, xdd] = random_motion(&mut rng, home, 0.1 * size, 0.1, 0.3, 3.0);
            let state = state_of(&x0, &xd, &xdd);
            let omega = state.twist.fixed_rows::<3>(3).into_owned();
            let alpha = state.twist_rate.fixed_rows::<3>(3).into_owned();
            let r_c = state.pose.rotation() * (payload.centre_of_mass - g.pivot());
            let a_c = joint_acceleration(&state.twist, &state.twist_rate, &r_c);
            let old = forces::leg_forces(&g, &state.pose, &payload, &a_c, &omega, &alpha)
                .unwrap_or_else(|| panic!("singular"));
            let new = inverse_dynamics(&g, &state, &payload, &DynamicsSettings::default())
                .unwrap_or_else(|e| panic!("{e}"));
            let gap = relative_gap(&new, &old);
            assert!(gap < 1e-13, "{new:?} vs {old:?} ({gap:e})");
        }
    }
}

#[test]
fn the_mass_matrix_holds_the_kinetic_energy_of_every_body() {
    let mut rng = Random(99);
    for g in [
        offset_pivot_geometry(),
        crate::test_support::servo_geometry(),
    ] {
        let home = g.home_pose().position.z;
        let size = g.characteristic_length();
        for case in 0..100 {
            let payload = random_payload(&mut rng, size);
            let dynamics = random_dynamics(&mut rng, size, payload.mass);
            let [x0, xd, _] = random_motion(&mut rng, home, 0.1 * size, 0.1, 0.5, 0.0);
            let model = Model::new(&g, &payload, &dynamics);
            let jets: [Jet; 6] = std::array::from_fn(|k| Jet::new(x0[k], xd[k], 0.0));
            let expected = model.kinetic_energy(&jets);
            // The twist about the platform frame's origin.
            let origin = model.origin(&jets);
            let state = state_of(&x0, &xd, &[0.0; 6]);
            let mut t = state.twist;
            for k in 0..3 {
                t[k] = origin[k].d1;
            }
            let m =
                mass_matrix(&g, &state.pose, &payload, &dynamics).unwrap_or_else(|e| panic!("{e}"));
            let got = 0.5 * (t.transpose() * m * t)[0];
            assert!(
                (got - expected).abs() < 1e-12 * expected,
                "case {case}: {got} vs {expected}"
            );
        }
    }
}
