//! The forward problem as polynomials: Study's kinematic mapping.
//!
//! A placement `q = R a + t` is written with eight homogeneous coordinates
//! `z = (e, g)`: `e` a quaternion for the rotation (`R a = e a ē / (e·e)`) and
//! `g = t e / 2`, so `t = 2 g ē / (e·e)`. Real placements are the points with
//! `e·g = 0` (Study's quadric) and `e ≠ 0`. Leg `i` from base joint `b` to platform
//! joint `a` with length `L` has `|R a + t − b|² = L²`; multiplied by `e·e` it becomes
//! a quadratic form in `z`:
//!
//! ```text
//! k (e·e) + 4 (g·g) + 4 gᵀ(Rₐ − L_b) e − 2 (Rₐ e)·(L_b e) = 0,   k = |a|² + |b|² − L²
//! ```
//!
//! where `Rₐ e = e a` and `L_b e = b e` are quaternion products (`a`, `b` pure
//! quaternions). Six such quadrics and Study's quadric are seven homogeneous quadratic
//! equations in `P⁷`: the system whose 40 isolated solutions are the assembly modes of a
//! general platform. The points with `e = 0` solve every leg equation as soon as
//! `g·g = 0`: a surface of spurious solutions that the solver sets aside.
//!
//! Everything here is a polynomial identity, so it holds for complex coordinates and
//! parameters too, which the homotopy in [`super::homotopy`] needs.

use nalgebra::{Complex, Matrix3, SMatrix, SVector, Vector3};

/// A complex number.
pub type C = Complex<f64>;
/// Study coordinates `(e0, e1, e2, e3, g0, g1, g2, g3)`.
pub type Coords = SVector<C, 8>;
/// An 8×8 complex matrix: a quadratic form or a Jacobian.
pub type Square = SMatrix<C, 8, 8>;
type Quat = SMatrix<C, 4, 4>;

/// The parameters of one leg: platform joint `a`, base joint `b` (or horn tip) and
/// `k = |a|² + |b|² − L²`. Complex so that a homotopy can pass through complex platforms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegParams {
    /// Platform joint, platform frame.
    pub a: [C; 3],
    /// Base joint (the fixed end), base frame.
    pub b: [C; 3],
    /// `|a|² + |b|² − L²` (with the bilinear square for complex points).
    pub k: C,
}

impl LegParams {
    /// A real leg from platform joint `a` to base joint `b` with length `length`.
    pub fn real(a: &Vector3<f64>, b: &Vector3<f64>, length: f64) -> Self {
        Self {
            a: [a.x, a.y, a.z].map(C::from),
            b: [b.x, b.y, b.z].map(C::from),
            k: C::from(a.norm_squared() + b.norm_squared() - length * length),
        }
    }

    /// The leg `(1 − s)·self + s·other` (parameters interpolated linearly).
    pub fn lerp(&self, other: &Self, s: f64) -> Self {
        let mix = |x: C, y: C| x * (1.0 - s) + y * s;
        Self {
            a: std::array::from_fn(|i| mix(self.a[i], other.a[i])),
            b: std::array::from_fn(|i| mix(self.b[i], other.b[i])),
            k: mix(self.k, other.k),
        }
    }

    /// `other − self`: the rate of change of [`LegParams::lerp`] with `s`.
    pub fn towards(&self, other: &Self) -> Self {
        Self {
            a: std::array::from_fn(|i| other.a[i] - self.a[i]),
            b: std::array::from_fn(|i| other.b[i] - self.b[i]),
            k: other.k - self.k,
        }
    }
}

/// `q ↦ q·p` for the pure quaternion `p`, as a matrix on `(w, x, y, z)`.
fn right_product(p: &[C; 3]) -> Quat {
    let z = C::from(0.0);
    let [x, y, w] = *p;
    Quat::new(
        z, -x, -y, -w, //
        x, z, w, -y, //
        y, -w, z, x, //
        w, y, -x, z,
    )
}

/// `q ↦ p·q` for the pure quaternion `p`, as a matrix on `(w, x, y, z)`.
fn left_product(p: &[C; 3]) -> Quat {
    let z = C::from(0.0);
    let [x, y, w] = *p;
    Quat::new(
        z, -x, -y, -w, //
        x, z, -w, y, //
        y, w, z, -x, //
        w, -y, x, z,
    )
}

/// The symmetric matrix `M` of leg `p`'s equation `zᵀ M z = 0`.
pub fn leg_quadric(p: &LegParams) -> Square {
    let ra = right_product(&p.a);
    let lb = left_product(&p.b);
    let cross = ra.transpose() * lb;
    let ee = Quat::identity() * p.k - (cross + cross.transpose());
    let ge = (ra - lb) * C::from(2.0);
    assemble(&ee, &ge, C::from(4.0))
}

/// `dM/ds` for the leg `p + s·dp` at `s = 0` (`M` is quadratic in the parameters).
pub fn leg_quadric_rate(p: &LegParams, dp: &LegParams) -> Square {
    let (ra, lb) = (right_product(&p.a), left_product(&p.b));
    let (dra, dlb) = (right_product(&dp.a), left_product(&dp.b));
    let cross = dra.transpose() * lb + ra.transpose() * dlb;
    let ee = Quat::identity() * dp.k - (cross + cross.transpose());
    let ge = (dra - dlb) * C::from(2.0);
    assemble(&ee, &ge, C::from(0.0))
}

/// The 8×8 symmetric matrix with blocks `ee`, `ge` (g rows, e columns) and `gg·I`.
fn assemble(ee: &Quat, ge: &Quat, gg: C) -> Square {
    let mut m = Square::zeros();
    m.fixed_view_mut::<4, 4>(0, 0).copy_from(ee);
    m.fixed_view_mut::<4, 4>(4, 0).copy_from(ge);
    m.fixed_view_mut::<4, 4>(0, 4).copy_from(&ge.transpose());
    m.fixed_view_mut::<4, 4>(4, 4)
        .copy_from(&(Quat::identity() * gg));
    m
}

/// Study's quadric `e·g` and its gradient.
pub fn study_condition(z: &Coords) -> (C, Coords) {
    let mut value = C::from(0.0);
    let mut gradient = Coords::zeros();
    for i in 0..4 {
        value += z[i] * z[4 + i];
        gradient[i] = z[4 + i];
        gradient[4 + i] = z[i];
    }
    (value, gradient)
}

/// The Study coordinates of the placement `q = R a + t` (`R` a rotation matrix).
#[cfg(test)]
pub fn coords_of(rotation: &Matrix3<f64>, translation: &Vector3<f64>) -> Coords {
    let q = nalgebra::UnitQuaternion::from_matrix(rotation);
    let e = [q.w, q.i, q.j, q.k];
    let t = [translation.x, translation.y, translation.z];
    // g = t e / 2 with t pure.
    let te = left_product(&t.map(C::from)) * nalgebra::Vector4::from(e.map(C::from));
    let mut z = Coords::zeros();
    for i in 0..4 {
        z[i] = C::from(e[i]);
        z[4 + i] = te[i] * 0.5;
    }
    z
}

/// The rotation and translation of real Study coordinates (`e ≠ 0`).
pub fn placement_of(z: &SVector<f64, 8>) -> (Matrix3<f64>, Vector3<f64>) {
    let e = nalgebra::Quaternion::new(z[0], z[1], z[2], z[3]);
    let g = nalgebra::Quaternion::new(z[4], z[5], z[6], z[7]);
    let n = e.norm_squared();
    let rotation = nalgebra::UnitQuaternion::from_quaternion(e).to_rotation_matrix();
    // t = 2 g ē / (e·e): the vector part (its scalar part is 2 e·g / n = 0).
    let t = (g * e.conjugate()) * (2.0 / n);
    (rotation.into_inner(), t.imag())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::pose::Pose;

    fn value(m: &Square, z: &Coords) -> C {
        (z.transpose() * m * z)[0]
    }

    #[test]
    fn a_real_placement_solves_its_own_leg_equations_and_studys_quadric() {
        let pose = Pose::from_xyz_rpy_deg([0.3, -0.2, 0.9], [12.0, -25.0, 70.0]);
        let (r, t) = (pose.rotation(), pose.position);
        let z = coords_of(&r, &t);
        assert!(study_condition(&z).0.norm() < 1e-15);
        let a = Vector3::new(0.4, -0.7, 0.15);
        let b = Vector3::new(-1.1, 0.3, -0.2);
        let length = (r * a + t - b).norm();
        let m = leg_quadric(&LegParams::real(&a, &b, length));
        assert!(value(&m, &z).norm() < 1e-14, "{}", value(&m, &z));
        // A wrong length leaves (e·e)(L² − L'²) = L² − L'² (e is a unit quaternion).
        let m = leg_quadric(&LegParams::real(&a, &b, length + 0.1));
        let expected = length * length - (length + 0.1) * (length + 0.1);
        assert!((value(&m, &z) - C::from(expected)).norm() < 1e-13);
        // And the coordinates give the placement back.
        let real = z.map(|c| c.re);
        let (r2, t2) = placement_of(&real);
        assert!((r2 - r).amax() < 1e-14 && (t2 - t).amax() < 1e-14);
        // Scaling the coordinates does not change the placement.
        let (r3, t3) = placement_of(&(real * -3.7));
        assert!((r3 - r).amax() < 1e-14 && (t3 - t).amax() < 1e-14);
    }

    #[test]
    fn the_rate_of_the_quadric_matches_a_difference_quotient() {
        let p = LegParams {
            a: [C::new(0.3, 0.1), C::new(-0.2, 0.4), C::new(0.5, -0.3)],
            b: [C::new(-0.6, 0.2), C::new(0.1, 0.1), C::new(0.7, 0.5)],
            k: C::new(0.2, -0.9),
        };
        let q = LegParams {
            a: [C::new(1.3, -0.1), C::new(0.2, 0.4), C::new(-0.5, 0.3)],
            b: [C::new(0.6, 0.2), C::new(-0.4, 0.8), C::new(0.3, -0.5)],
            k: C::new(-0.7, 0.3),
        };
        let (s, h) = (0.37, 1e-6);
        let exact = leg_quadric_rate(&p.lerp(&q, s), &p.towards(&q));
        let quotient =
            (leg_quadric(&p.lerp(&q, s + h)) - leg_quadric(&p.lerp(&q, s - h))) / C::from(2.0 * h);
        assert!((exact - quotient).norm() < 1e-8);
    }
}
