//! The mechanism written a second time, from positions alone: every body's centre of
//! mass, each slender part's direction, each horn's angle and the platform's rotation as
//! functions of the six pose coordinates (x, y, z, roll, pitch, yaw), evaluated with
//! jets. Kinetic energy is `½ Σ w |ẏ|²` over position-like quantities `y` with constant
//! weights `w` (a point mass; `I |u̇|²` of a slender part; `I θ̇²` of a horn; the
//! platform's rotation as `Σ λ_j |Ṙ e_j|²` over the principal axes `e_j` of
//! `E = ½ tr(I) 1 − I`), so Lagrange's equations in the pose coordinates read
//! `Q_k = Σ w (ÿ − g_y) · ∂y/∂x_k` — no angular velocities, no Newton–Euler.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::jet::{Jet, M3, V3, add, dot, mat_mul, mat_vec, norm, scale, sub, v3};
use crate::analysis::forces::{Payload, STANDARD_GRAVITY};
use crate::model::dynamics_settings::DynamicsSettings;
use crate::model::geometry::Geometry;

/// The servos' data.
struct Servos {
    horn: f64,
    rod: f64,
    /// Where each horn points at angle 0.
    directions: [[f64; 3]; 6],
}

/// A platform as plain numbers.
pub struct Model {
    base: [[f64; 3]; 6],
    platform: [[f64; 3]; 6],
    pivot: [f64; 3],
    servos: Option<Servos>,
    dynamics: DynamicsSettings,
    mass: f64,
    com: [f64; 3],
    /// Principal second moments `λ_j` of the payload's mass about its centre, and axes.
    second_moments: [(f64, [f64; 3]); 3],
}

/// A weighted position-like quantity; `gravity`: whether gravity pulls on it (masses).
pub struct Item {
    pub weight: f64,
    pub y: V3,
    pub gravity: bool,
}

fn arr(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl Model {
    pub fn new(g: &Geometry, payload: &Payload, dynamics: &DynamicsSettings) -> Self {
        let servos = g.rotary().map(|r| Servos {
            horn: r.horn_length(),
            rod: r.rod_length(),
            directions: std::array::from_fn(|i| {
                let (s, c) = r.horn_angles()[i].radians().sin_cos();
                [c, s, 0.0]
            }),
        });
        let i = payload.inertia;
        let e: Matrix3<f64> = Matrix3::identity() * (0.5 * i.trace()) - i;
        let eigen = e.symmetric_eigen();
        Self {
            base: g.base_joints().map(|p| arr(&p)),
            platform: g.platform_joints().map(|p| arr(&p)),
            pivot: arr(&g.pivot()),
            servos,
            dynamics: dynamics.clone(),
            mass: payload.mass,
            com: arr(&payload.centre_of_mass),
            second_moments: std::array::from_fn(|j| {
                (
                    eigen.eigenvalues[j],
                    arr(&eigen.eigenvectors.column(j).into_owned()),
                )
            }),
        }
    }

    /// `R = Rz(yaw) Ry(pitch) Rx(roll)`.
    pub fn rotation(x: &[Jet; 6]) -> M3 {
        let (one, zero) = (Jet::c(1.0), Jet::c(0.0));
        let (sr, cr) = (x[3].sin(), x[3].cos());
        let (sp, cp) = (x[4].sin(), x[4].cos());
        let (sy, cy) = (x[5].sin(), x[5].cos());
        let rx = [[one, zero, zero], [zero, cr, -sr], [zero, sr, cr]];
        let ry = [[cp, zero, sp], [zero, one, zero], [-sp, zero, cp]];
        let rz = [[cy, -sy, zero], [sy, cy, zero], [zero, zero, one]];
        mat_mul(&rz, &mat_mul(&ry, &rx))
    }

    /// A point fixed in the platform frame, in the base frame.
    fn platform_point(&self, x: &[Jet; 6], r: &M3, local: [f64; 3]) -> V3 {
        let c = v3(self.pivot);
        let offset = sub(v3(local), c);
        add(add([x[0], x[1], x[2]], c), mat_vec(r, offset))
    }

    /// The platform frame's origin.
    pub fn origin(&self, x: &[Jet; 6]) -> V3 {
        self.platform_point(x, &Self::rotation(x), [0.0; 3])
    }

    /// Servo `i`'s angle for platform joint `p` (the rod's closure solved for θ).
    fn servo_angle(&self, s: &Servos, i: usize, p: V3) -> Jet {
        let l = sub(p, v3(self.base[i]));
        let a = s.horn;
        let big_l = dot(l, l) - Jet::c(s.rod * s.rod - a * a);
        let m = l[2] * (2.0 * a);
        let h = s.directions[i];
        let n = (l[0] * h[0] + l[1] * h[1]) * (2.0 * a);
        (big_l / (m * m + n * n).sqrt()).asin() - n.atan2(m)
    }

    /// The actuator coordinates: leg lengths or servo angles.
    pub fn actuators(&self, x: &[Jet; 6]) -> [Jet; 6] {
        let r = Self::rotation(x);
        std::array::from_fn(|i| {
            let p = self.platform_point(x, &r, self.platform[i]);
            match &self.servos {
                None => norm(sub(p, v3(self.base[i]))),
                Some(s) => self.servo_angle(s, i, p),
            }
        })
    }

    /// Every weighted quantity of the kinetic and potential energy.
    pub fn items(&self, x: &[Jet; 6]) -> Vec<Item> {
        let r = Self::rotation(x);
        let mut items = vec![Item {
            weight: self.mass,
            y: self.platform_point(x, &r, self.com),
            gravity: true,
        }];
        for (lambda, axis) in self.second_moments {
            items.push(Item {
                weight: lambda,
                y: mat_vec(&r, v3(axis)),
                gravity: false,
            });
        }
        let d = &self.dynamics;
        for i in 0..6 {
            let p = self.platform_point(x, &r, self.platform[i]);
            let b = v3(self.base[i]);
            match &self.servos {
                None => {
                    let leg = sub(p, b);
                    let u = scale(leg, Jet::c(1.0) / norm(leg));
                    let cylinder = add(b, scale(u, Jet::c(d.cylinder_com_m)));
                    let rod = sub(p, scale(u, Jet::c(d.rod_com_m)));
                    items.push(Item {
                        weight: d.cylinder_mass_kg,
                        y: cylinder,
                        gravity: true,
                    });
                    items.push(Item {
                        weight: d.rod_mass_kg,
                        y: rod,
                        gravity: true,
                    });
                    items.push(Item {
                        weight: d.cylinder_inertia_kg_m2 + d.rod_inertia_kg_m2,
                        y: u,
                        gravity: false,
                    });
                }
                Some(s) => {
                    let theta = self.servo_angle(s, i, p);
                    let h = s.directions[i];
                    let (c, sn) = (theta.cos(), theta.sin());
                    let horn = [c * (s.horn * h[0]), c * (s.horn * h[1]), sn * s.horn];
                    let tip = add(b, horn);
                    let horn_com = add(b, scale(horn, Jet::c(d.horn_com_m / s.horn)));
                    let e = scale(sub(p, tip), Jet::c(1.0 / s.rod));
                    let rod_com = add(tip, scale(e, Jet::c(d.rod_com_m)));
                    let zero = Jet::c(0.0);
                    items.push(Item {
                        weight: d.horn_mass_kg,
                        y: horn_com,
                        gravity: true,
                    });
                    items.push(Item {
                        weight: d.horn_inertia_kg_m2,
                        y: [theta, zero, zero],
                        gravity: false,
                    });
                    items.push(Item {
                        weight: d.rod_mass_kg,
                        y: rod_com,
                        gravity: true,
                    });
                    items.push(Item {
                        weight: d.rod_inertia_kg_m2,
                        y: e,
                        gravity: false,
                    });
                }
            }
        }
        items
    }

    /// Kinetic energy along a motion (jets carrying the pose's rates in `d1`).
    pub fn kinetic_energy(&self, x: &[Jet; 6]) -> f64 {
        self.items(x)
            .iter()
            .map(|it| 0.5 * it.weight * it.y.iter().map(|c| c.d1 * c.d1).sum::<f64>())
            .sum()
    }

    /// Actuator efforts by Lagrange's equations for the pose `x0` moving at `xd` with
    /// `xdd` (pose coordinates and their rates; angles in radians).
    pub fn efforts(&self, x0: &[f64; 6], xd: &[f64; 6], xdd: &[f64; 6]) -> [f64; 6] {
        let along: [Jet; 6] = std::array::from_fn(|k| Jet::new(x0[k], xd[k], xdd[k]));
        let moving = self.items(&along);
        let rates = self.actuators(&along);
        let mut q = Vector6::zeros();
        let mut d = Matrix6::zeros();
        for k in 0..6 {
            let dir: [Jet; 6] =
                std::array::from_fn(|j| Jet::new(x0[j], if j == k { 1.0 } else { 0.0 }, 0.0));
            let partials = self.items(&dir);
            q[k] = moving
                .iter()
                .zip(&partials)
                .map(|(m, p)| {
                    let g = if m.gravity { -STANDARD_GRAVITY } else { 0.0 };
                    let acc = [m.y[0].d2, m.y[1].d2, m.y[2].d2 - g];
                    m.weight * (0..3).map(|c| acc[c] * p.y[c].d1).sum::<f64>()
                })
                .sum();
            let actuators = self.actuators(&dir);
            for i in 0..6 {
                d[(i, k)] = actuators[i].d1;
            }
        }
        // Q = Dᵀ (τ − c q̇).
        let balance = d
            .transpose()
            .lu()
            .solve(&q)
            .unwrap_or_else(|| panic!("singular pose in the test"));
        let c = self.dynamics.actuator_friction;
        std::array::from_fn(|i| balance[i] + c * rates[i].d1)
    }
}
