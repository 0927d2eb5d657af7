//! Dynamics speed: inverse dynamics with leg masses per pose (legs and servos), and the
//! natural modes at a pose.
//!
//! `cargo bench -p stewart_kinematics --bench dynamics`. Target: inverse dynamics under
//! 2 µs per pose.

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, Vector3};
use std::hint::black_box;
use stewart_kinematics::Scenario;
use stewart_kinematics::analysis::dynamics;
use stewart_kinematics::analysis::dynamics::{DynamicsSettings, MotionState, motion_states};
use stewart_kinematics::analysis::forces::Payload;

fn heavy_legs(scale: f64) -> DynamicsSettings {
    DynamicsSettings {
        actuator_stiffness: Some(2e7),
        actuator_friction: 50.0,
        cylinder_mass_kg: 2.0,
        cylinder_com_m: 0.2 * scale,
        cylinder_inertia_kg_m2: 0.05 * scale * scale,
        rod_mass_kg: 1.0,
        rod_com_m: 0.25 * scale,
        rod_inertia_kg_m2: 0.02 * scale * scale,
        horn_mass_kg: 0.02,
        horn_com_m: 0.01,
        horn_inertia_kg_m2: 2e-6,
    }
}

fn states(preset: &str) -> (Scenario, Vec<MotionState>, Payload) {
    let scenario = Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}"));
    let states = motion_states(&scenario.motion.sample());
    let size = scenario.geometry.characteristic_length();
    let payload = Payload::new(
        60.0,
        Vector3::new(0.0, 0.0, 0.1 * size),
        Matrix3::from_diagonal(&Vector3::new(3.0, 3.0, 5.0)) * (size * size),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    (scenario, states, payload)
}

fn bench(c: &mut Criterion) {
    for (name, preset, scale) in [
        ("inverse_dynamics_legs", "paired", 1.0),
        ("inverse_dynamics_servos", "servo-desk", 0.1),
    ] {
        let (scenario, states, payload) = states(preset);
        let g = scenario.geometry;
        let dynamics = heavy_legs(scale);
        let n = states.len();
        c.bench_function(name, |b| {
            let mut k = 0;
            b.iter(|| {
                let f = dynamics::inverse_dynamics(&g, black_box(&states[k]), &payload, &dynamics);
                k = (k + 1) % n;
                f
            })
        });
    }
    let (scenario, states, payload) = states("paired");
    let g = scenario.geometry;
    let dynamics = heavy_legs(1.0);
    c.bench_function("modes_legs", |b| {
        let mut k = 0;
        b.iter(|| {
            let m = dynamics::modes(&g, black_box(&states[k].pose), &payload, &dynamics);
            k = (k + 1) % states.len();
            m
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
