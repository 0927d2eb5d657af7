//! Natural modes at a pose: `K v = ω² M v` solved through the Cholesky factor of `M`.

use nalgebra::{Matrix6, Vector6};

use super::{DynamicsError, DynamicsSettings};
use crate::analysis::dynamics;
use crate::analysis::forces::Payload;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// The names of the six coordinates of twists, wrenches and mode vectors, in order.
pub const AXES: [&str; 6] = ["x", "y", "z", "rx", "ry", "rz"];

/// Stiffness, mass matrix and natural modes at a pose (about the platform frame's
/// origin, base-frame axes, SI units).
#[derive(Clone, Debug, PartialEq)]
pub struct Modes {
    /// `K = J_aᵀ diag(k) J_a`: N/m, N/rad (= N·m/m), N·m/rad blocks.
    pub stiffness: Matrix6<f64>,
    /// `M`: kg, kg·m, kg·m² blocks.
    pub mass_matrix: Matrix6<f64>,
    /// Natural frequencies, Hz, ascending.
    pub frequencies_hz: [f64; 6],
    /// Mode shapes, unit vectors (x, y, z in m, rx, ry, rz in rad), in the order of the
    /// frequencies; each with its largest component positive.
    pub modes: [Vector6<f64>; 6],
}

impl Modes {
    /// The components of mode `k` that make up most of it, largest first: `(axis,
    /// component)` for every component at least a third of the largest.
    pub fn dominant(&self, k: usize) -> Vec<(&'static str, f64)> {
        dominant(&self.modes[k])
    }

    /// Whether mode `k` is a direction without stiffness (a singular pose): its frequency
    /// is at most a millionth of the stiffest mode's, zero as far as the numbers tell.
    pub fn without_stiffness(&self, k: usize) -> bool {
        self.frequencies_hz[k] <= 1e-6 * self.frequencies_hz[5]
    }
}

/// The components of a mode vector that make up most of it, largest first: `(axis,
/// component)` for every component at least a third of the largest.
pub fn dominant(v: &Vector6<f64>) -> Vec<(&'static str, f64)> {
    let largest = v.amax();
    let mut parts: Vec<(&'static str, f64)> = (0..6)
        .filter(|&i| v[i].abs() >= largest / 3.0)
        .map(|i| (AXES[i], v[i]))
        .collect();
    parts.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
    parts
}

/// Stiffness, mass matrix and natural modes at `pose` for the actuator stiffness of
/// `dynamics` (which must be given).
pub fn modes(
    geometry: &Geometry,
    pose: &Pose,
    payload: &Payload,
    dynamics: &DynamicsSettings,
) -> Result<Modes, DynamicsError> {
    let k = dynamics
        .actuator_stiffness
        .ok_or(DynamicsError::NoStiffness)?;
    if geometry.rotary().is_none()
        && let Some(leg) = geometry.leg_without_direction(pose)
    {
        return Err(DynamicsError::LegWithoutDirection { leg: leg + 1 });
    }
    let stiffness = dynamics::stiffness(geometry, pose, k)?;
    let mass_matrix = dynamics::mass_matrix(geometry, pose, payload, dynamics)?;
    let (frequencies_hz, modes) = generalised_modes(&stiffness, &mass_matrix)?;
    Ok(Modes {
        stiffness,
        mass_matrix,
        frequencies_hz,
        modes,
    })
}

/// The pose `pose` moved by the small motion `v` (x, y, z in m, rx, ry, rz in rad:
/// a mode vector, about the platform frame's origin in base-frame axes) scaled by
/// `s`: the origin moves by `s v_xyz` and the platform turns by `s v_r` about it.
pub fn moved_along(geometry: &Geometry, pose: &Pose, v: &Vector6<f64>, s: f64) -> Pose {
    let c = geometry.pivot();
    let origin = geometry.platform_centre(pose) + s * v.fixed_rows::<3>(0).into_owned();
    let turn = nalgebra::Rotation3::new(s * v.fixed_rows::<3>(3).into_owned());
    let rotation = turn * nalgebra::Rotation3::from_matrix_unchecked(pose.rotation());
    let (roll, pitch, yaw) = rotation.euler_angles();
    use crate::model::angle::Angle;
    Pose::new(
        origin - c + rotation * c,
        Angle::from_radians(roll),
        Angle::from_radians(pitch),
        Angle::from_radians(yaw),
    )
}

/// How far the platform joints move, at most, for the motion `v` (as in
/// [`moved_along`]) at `pose`, per unit of `s`, metres.
pub fn joint_travel(geometry: &Geometry, pose: &Pose, v: &Vector6<f64>) -> f64 {
    let r = pose.rotation();
    let (t, w) = (
        v.fixed_rows::<3>(0).into_owned(),
        v.fixed_rows::<3>(3).into_owned(),
    );
    geometry
        .platform_joints()
        .iter()
        .map(|a| (t + w.cross(&(r * a))).norm())
        .fold(0.0, f64::max)
}

/// Frequencies (Hz, ascending) and unit mode vectors of `K v = ω² M v`.
fn generalised_modes(
    k: &Matrix6<f64>,
    m: &Matrix6<f64>,
) -> Result<([f64; 6], [Vector6<f64>; 6]), DynamicsError> {
    // `K v = ω² M v` is solved for `K / k_s` and `M / m_s` (entries at most 1), and ω²
    // scaled back as a product of square roots: any accepted mass or stiffness, however
    // small or large, then stays far from overflow (a milligram payload made `L⁻¹ K L⁻ᵀ`
    // infinite, and its frequencies NaN).
    let m_s = m.amax();
    let k_s = k.amax();
    if !(m_s > 0.0 && m_s.is_finite() && k_s.is_finite()) {
        return Err(DynamicsError::MassMatrixNotPositive);
    }
    let k_s = if k_s > 0.0 { k_s } else { 1.0 };
    let (k, m) = (k / k_s, m / m_s);
    let (k, m) = (&k, &m);
    let root_ratio = k_s.sqrt() / m_s.sqrt();
    let symmetric = (m + m.transpose()) * 0.5;
    let cholesky = symmetric
        .cholesky()
        .ok_or(DynamicsError::MassMatrixNotPositive)?;
    let l = cholesky.l();
    // A positive diagonal that is tiny against the largest is a motion without inertia.
    let d = l.diagonal();
    let weighty = d.min() > 1e-9 * d.max();
    if !weighty {
        return Err(DynamicsError::MassMatrixNotPositive);
    }
    let l_inv = l
        .try_inverse()
        .ok_or(DynamicsError::MassMatrixNotPositive)?;
    let a = l_inv * k * l_inv.transpose();
    let a = (a + a.transpose()) * 0.5;
    let eigen = a.symmetric_eigen();
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
    let mut frequencies = [0.0; 6];
    let mut modes = [Vector6::zeros(); 6];
    for (slot, &i) in order.iter().enumerate() {
        let lambda = eigen.eigenvalues[i].max(0.0);
        frequencies[slot] = lambda.sqrt() * root_ratio / std::f64::consts::TAU;
        let w = eigen.eigenvectors.column(i).into_owned();
        let mut v = l_inv.transpose() * w;
        v /= v.norm();
        let largest = v.iamax();
        if v[largest] < 0.0 {
            v = -v;
        }
        modes[slot] = v;
    }
    // Nothing that is not a number leaves here to be printed as one.
    let finite = frequencies.iter().all(|f| f.is_finite())
        && modes.iter().all(|v| v.iter().all(|c| c.is_finite()));
    if !finite {
        return Err(DynamicsError::MassMatrixNotPositive);
    }
    Ok((frequencies, modes))
}
