//! The moving bodies' masses and inertias for a robot description: the scenario's
//! `[payload]` (the platform) and `[dynamics]` (each leg's parts) where given, else light
//! defaults that a simulator accepts (every moving body needs some mass and inertia), each
//! default said in words for the file's comment.

use nalgebra::{Matrix3, Vector3};
use stewart_kinematics::Scenario;
use stewart_kinematics::model::dynamics_settings::LegPart;
use stewart_kinematics::solve::chains::LegChain;

use super::rig::Sample;

/// A body's mass, centre of mass and inertia tensor about it, in the body's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Inertial {
    /// kg.
    pub(crate) mass: f64,
    /// Centre of mass, body frame, m.
    pub(crate) centre: Vector3<f64>,
    /// About the centre of mass, body axes, kg·m².
    pub(crate) inertia: Matrix3<f64>,
}

/// A slender part along its body's z (a servo's horn: any axis): mass, centre of mass
/// along the part, inertia across it and about its own axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Slender {
    /// kg.
    pub(crate) mass: f64,
    /// Distance of the centre of mass from the body's origin along the part, m.
    pub(crate) along: f64,
    /// About the centre of mass, across the part, kg·m².
    pub(crate) across: f64,
    /// About the part's own axis, kg·m² (a hundredth of `across`: a slender part's spin
    /// carries no actuator force).
    pub(crate) axial: f64,
}

impl Slender {
    /// The part as a body's inertial, its axis along `axis` (a unit vector of the body's
    /// frame). A horn's is the same about every axis.
    pub(crate) fn inertial(&self, axis: &Vector3<f64>, isotropic: bool) -> Inertial {
        let inertia = if isotropic {
            Matrix3::identity() * self.across
        } else {
            // across·(I − a·aᵀ) + axial·a·aᵀ
            Matrix3::identity() * self.across + axis * axis.transpose() * (self.axial - self.across)
        };
        Inertial {
            mass: self.mass,
            centre: axis * self.along,
            inertia,
        }
    }
}

/// Every moving body's mass.
pub(crate) struct Masses {
    /// The platform with its payload.
    pub(crate) platform: Inertial,
    /// A linear leg's cylinder (from the base joint up the leg).
    pub(crate) cylinder: Slender,
    /// The rod: of a linear leg from the platform joint down the leg (its `along` is
    /// negative), of a servo from the horn's tip up the rod.
    pub(crate) rod: Slender,
    /// A servo's horn (from the shaft along the horn; the same about every axis).
    pub(crate) horn: Slender,
    /// The defaults taken, in words.
    pub(crate) defaults: Vec<String>,
}

/// The share of the platform's mass a default leg part takes.
const PART_SHARE: f64 = 0.02;

impl Masses {
    /// The masses of `scenario`'s rig, its legs as long as at `home`.
    pub(crate) fn of(scenario: &Scenario, home: &Sample) -> Self {
        let g = &scenario.geometry;
        let mut defaults = Vec::new();
        let platform = match &scenario.payload {
            Some(p) => {
                // A simulator needs every principal moment above 0; a payload may give a
                // point mass or a flat body. Raise the smallest to a millionth of m·ℓ².
                let floor = 1e-6 * p.mass * g.characteristic_length().powi(2);
                let smallest = p.inertia.symmetric_eigenvalues().min();
                let mut inertia = p.inertia;
                if smallest < floor {
                    inertia += Matrix3::identity() * (floor - smallest);
                    defaults.push(format!(
                        "platform: the [payload] inertia has a principal moment below {floor:.3e} \
                         kg·m², so each is raised by {:.3e}",
                        floor - smallest
                    ));
                }
                Inertial {
                    mass: p.mass,
                    centre: p.centre_of_mass,
                    inertia,
                }
            }
            None => {
                let r = g.plate_radius(stewart_kinematics::model::geometry::Plate::Platform);
                defaults.push(format!(
                    "platform: no [payload], so 1 kg as a thin disc of radius {r} m"
                ));
                Inertial {
                    mass: 1.0,
                    centre: Vector3::zeros(),
                    inertia: Matrix3::from_diagonal(&Vector3::new(
                        r * r / 4.0,
                        r * r / 4.0,
                        r * r / 2.0,
                    )),
                }
            }
        };
        let light = (platform.mass * PART_SHARE).max(1e-3);
        let d = &scenario.dynamics;
        let (cylinder_length, rod_length, horn_length) = match (home.chains[0], g.rotary()) {
            (LegChain::Rotary { .. }, Some(r)) => (0.0, r.rod_length(), r.horn_length()),
            (LegChain::Linear { length, .. }, _) => (length / 2.0, length / 2.0, 0.0),
            _ => (0.0, 0.0, 0.0),
        };
        let rotary = g.rotary().is_some();
        let mut part = |name: &str, given: LegPart, length: f64, sign: f64| {
            let given_mass = given.mass > 0.0;
            let mass = if given_mass { given.mass } else { light };
            let along = if given_mass { given.com } else { length / 2.0 };
            let across = if given.inertia > 0.0 {
                given.inertia
            } else {
                mass * length * length / 12.0
            }
            .max(1e-9);
            if !given_mass {
                defaults.push(format!(
                    "{name}: no mass in [dynamics], so {light} kg at the middle of its {length:.4} m"
                ));
            } else if given.inertia <= 0.0 {
                defaults.push(format!(
                    "{name}: no inertia in [dynamics], so a slender rod's m·l²/12 over {length:.4} m"
                ));
            }
            Slender {
                mass,
                along: sign * along,
                across,
                axial: across / 100.0,
            }
        };
        let cylinder = part("cylinder", d.cylinder(), cylinder_length, 1.0);
        let rod = part("rod", d.rod(), rod_length, if rotary { 1.0 } else { -1.0 });
        let horn = part("horn", d.horn(), horn_length, 1.0);
        if !rotary {
            defaults.retain(|w| !w.starts_with("horn"));
        } else {
            defaults.retain(|w| !w.starts_with("cylinder"));
        }
        Self {
            platform,
            cylinder,
            rod,
            horn,
            defaults,
        }
    }
}
