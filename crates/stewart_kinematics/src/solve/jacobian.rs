//! The inverse Jacobian, its singular values and a dimensionally sound conditioning.
//!
//! **Twist convention.** The platform's twist is `(v, ω)`: `v` the velocity of the
//! *pivot point* (the platform centre when no pivot is set) and `ω` the angular velocity,
//! both in the base frame. With `u_i` the unit vector of leg `i` and
//! `r_i = R (a_i − c)` the vector from the pivot point to platform joint `i`,
//!
//! ```text
//! L̇_i = u_i · (v + ω × r_i) = [u_iᵀ, (r_i × u_i)ᵀ] · (v, ω)
//! ```
//!
//! so row `i` of the inverse Jacobian `J` is `[u_iᵀ, (r_i × u_i)ᵀ]` (with `c = 0`:
//! `[u_iᵀ, ((R a_i) × u_i)ᵀ]`). Statics follow from the same matrix: leg forces `f`
//! (along the legs, pushing the platform) exert on the platform the wrench `Jᵀ f`
//! (force, and moment about the pivot point).
//!
//! **Units.** The first three columns are dimensionless, the last three are metres, so
//! the singular values of `J` mix units and its condition number depends on the unit of
//! length. The conditioning reported here is that of `J·diag(1, 1, 1, 1/ℓ, 1/ℓ, 1/ℓ)` with
//! the characteristic length `ℓ` = the platform radius: a rotation of `1/ℓ` rad/s moves
//! the platform joints at about 1 m/s, like a translation of 1 m/s.

use nalgebra::{Matrix6, SVD, Vector3, Vector6};
use serde::{Deserialize, Serialize};

use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::solve::servo_closure;

/// Relative size (σ_min/σ_max) below which the normalised Jacobian counts as rank
/// deficient. Rounding alone gives about 1e-16; real near-singular poses of sensible
/// platforms sit far above 1e-9, and no actuator could tell the difference below it.
pub const RANK_TOLERANCE: f64 = 1e-9;

/// How well the legs control the platform at one pose.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Conditioning {
    /// Singular values of the normalised Jacobian, largest first.
    pub singular_values: [f64; 6],
    /// The characteristic length ℓ used to normalise rotations, metres.
    pub characteristic_length: f64,
    /// `σ_max / σ_min`, or `None` when the Jacobian is rank deficient (singular); for servos
    /// also divided by the worst servo's transmission ([`Geometry::servo_conditioning`]).
    pub condition_number: Option<f64>,
    /// The twist the legs control least (right singular vector of σ_min): translation
    /// velocity (m/s) and ℓ·angular velocity (m/s), unit length overall.
    pub weakest_twist: [f64; 6],
}

impl Conditioning {
    /// What stands for the conditioning of a pose some servo cannot reach: no singular
    /// values, no condition number.
    pub fn unreachable(characteristic_length: f64) -> Self {
        Self {
            singular_values: [0.0; 6],
            characteristic_length,
            condition_number: None,
            weakest_twist: [0.0; 6],
        }
    }

    /// Whether the pose is singular (rank-deficient Jacobian).
    pub fn is_singular(&self) -> bool {
        self.condition_number.is_none()
    }

    /// Inverse condition number σ_min/σ_max (0 when singular to working precision).
    pub fn inverse_condition(&self) -> f64 {
        self.condition_number.map_or(0.0, |c| 1.0 / c)
    }
}

/// See [`Geometry::jacobian`].
pub(crate) fn jacobian(geometry: &Geometry, pose: &Pose) -> Matrix6<f64> {
    let r = pose.rotation();
    let c = geometry.pivot();
    let solution = geometry.inverse(pose);
    let mut j = Matrix6::zeros();
    for i in 0..6 {
        let u = solution.unit(i);
        let arm = r * (geometry.platform_joints()[i] - c);
        let m = arm.cross(&u);
        j.fixed_view_mut::<1, 3>(i, 0).copy_from(&u.transpose());
        j.fixed_view_mut::<1, 3>(i, 3).copy_from(&m.transpose());
    }
    j
}

/// See [`Geometry::leg_without_direction`].
pub(crate) fn leg_without_direction(geometry: &Geometry, pose: &Pose) -> Option<usize> {
    let tiny = 1e-9 * geometry.characteristic_length();
    let solution = geometry.inverse(pose);
    (0..6).find(|&i| solution.lengths[i].is_nan() || solution.lengths[i] <= tiny)
}

/// See [`Geometry::characteristic_length`].
pub(crate) fn characteristic_length(geometry: &Geometry) -> f64 {
    let sum: f64 = geometry
        .platform_joints()
        .iter()
        .map(|a| a.norm_squared())
        .sum();
    (sum / 6.0).sqrt()
}

/// See [`Geometry::servo_jacobian`].
pub(crate) fn servo_jacobian(
    geometry: &Geometry,
    pose: &Pose,
) -> Option<Result<Matrix6<f64>, crate::model::rotary::Unreachable>> {
    let servos = geometry.rotary()?;
    let joints = geometry.inverse(pose).platform_joints;
    let angles = match servo_closure::servo_angles(servos, geometry.base_joints(), &joints) {
        Ok(a) => a,
        Err(e) => return Some(Err(e)),
    };
    let r = pose.rotation();
    let c = geometry.pivot();
    let mut j = Matrix6::zeros();
    for i in 0..6 {
        let tip = servos.horn_tip(i, &geometry.base_joints()[i], angles[i]);
        let d = joints[i] - tip;
        let (sb, cb) = servos.horn_angles()[i].radians().sin_cos();
        let (st, ct) = angles[i].radians().sin_cos();
        let h = servos.horn_length() * Vector3::new(-st * cb, -st * sb, ct);
        let arm = r * (geometry.platform_joints()[i] - c);
        let scale = 1.0 / d.dot(&h);
        let m = arm.cross(&d);
        j.fixed_view_mut::<1, 3>(i, 0)
            .copy_from(&(d.transpose() * scale));
        j.fixed_view_mut::<1, 3>(i, 3)
            .copy_from(&(m.transpose() * scale));
    }
    Some(Ok(j))
}

/// See [`Geometry::servo_conditioning`].
pub(crate) fn servo_conditioning(geometry: &Geometry, pose: &Pose) -> Option<Conditioning> {
    let j = geometry.servo_jacobian(pose)?.ok()?;
    geometry.servo_conditioning_of(&j)
}

/// See [`Geometry::servo_conditioning_of`].
pub(crate) fn servo_conditioning_of(geometry: &Geometry, j: &Matrix6<f64>) -> Option<Conditioning> {
    let servos = geometry.rotary()?;
    let scaled = j * servos.horn_length();
    let ell = geometry.characteristic_length();
    let mut conditioning = conditioning_of(&scaled, ell);
    // Row i's translation part is d_i / (d_i · h_i): its length is 1 / (|h_i| τ_i).
    let mut unit_rows = scaled;
    let mut worst_transmission = f64::INFINITY;
    for i in 0..6 {
        let length = scaled.fixed_view::<1, 3>(i, 0).norm();
        worst_transmission = worst_transmission.min(1.0 / length);
        unit_rows.row_mut(i).scale_mut(1.0 / length);
    }
    let rods = conditioning_of(&unit_rows, ell).condition_number;
    conditioning.condition_number = conditioning
        .condition_number
        .and(rods)
        .map(|k| k / worst_transmission)
        .filter(|k| k.is_finite() && k * RANK_TOLERANCE < 1.0);
    Some(conditioning)
}

/// See [`Geometry::conditioning`].
pub(crate) fn conditioning(geometry: &Geometry, pose: &Pose) -> Conditioning {
    conditioning_of(&geometry.jacobian(pose), geometry.characteristic_length())
}

/// Most SVD sweeps: a finite 6×6 matrix converges in a few dozen.
const SVD_MAX_ITERATIONS: usize = 1000;

/// Conditioning of an inverse Jacobian with rotation columns in metres, normalised by `ell`.
pub fn conditioning_of(j: &Matrix6<f64>, ell: f64) -> Conditioning {
    let scale = Vector6::new(1.0, 1.0, 1.0, 1.0 / ell, 1.0 / ell, 1.0 / ell);
    let normalised = j * Matrix6::from_diagonal(&scale);
    // Bounded: nalgebra's `SVD::new` iterates without limit and never returns on NaN.
    // A matrix that is not finite, or does not converge, has no conditioning: singular.
    let svd = normalised
        .iter()
        .all(|v| v.is_finite())
        .then(|| SVD::try_new(normalised, false, true, f64::EPSILON, SVD_MAX_ITERATIONS))
        .flatten();
    let Some(svd) = svd else {
        return Conditioning {
            singular_values: [0.0; 6],
            characteristic_length: ell,
            condition_number: None,
            weakest_twist: [0.0; 6],
        };
    };
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&a, &b| svd.singular_values[b].total_cmp(&svd.singular_values[a]));
    let singular_values: [f64; 6] = std::array::from_fn(|k| svd.singular_values[order[k]]);
    let weakest = order[5];
    let weakest_twist = match &svd.v_t {
        Some(v_t) => std::array::from_fn(|k| v_t[(weakest, k)]),
        None => [0.0; 6],
    };
    let (max, min) = (singular_values[0], singular_values[5]);
    let condition_number = (max > 0.0 && min > RANK_TOLERANCE * max).then(|| max / min);
    Conditioning {
        singular_values,
        characteristic_length: ell,
        condition_number,
        weakest_twist,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::geometry::GeometryParams;
    use crate::model::layout::Layout;
    use proptest::prelude::*;

    /// Leg rates by finite differences of inverse kinematics for a twist (v, ω) about
    /// the pivot point: move the pivot by v·h and rotate by ω·h (rotation composed in the
    /// base frame, about the pivot point).
    fn numeric_rates(g: &Geometry, pose: &Pose, v: Vector3<f64>, w: Vector3<f64>) -> Vector6<f64> {
        let h = 1e-6;
        let lengths_after = |s: f64| {
            let r = nalgebra::Rotation3::new(w * s * h).matrix() * pose.rotation();
            let c = g.pivot();
            let pivot_point = pose.position + c; // where the pivot point is: p + c − R c + R c
            let joints: Vec<Vector3<f64>> = g
                .platform_joints()
                .iter()
                .map(|a| pivot_point + v * s * h + r * (a - c))
                .collect();
            Vector6::from_fn(|i, _| (joints[i] - g.base_joints()[i]).norm())
        };
        (lengths_after(1.0) - lengths_after(-1.0)) / (2.0 * h)
    }

    proptest! {
        #[test]
        fn jacobian_matches_finite_differences_of_inverse_kinematics(
            x in -0.2f64..0.2, y in -0.2f64..0.2, z in 0.6f64..1.0,
            r in -20.0f64..20.0, p in -20.0f64..20.0, w in -30.0f64..30.0,
            vx in -1.0f64..1.0, vy in -1.0f64..1.0, vz in -1.0f64..1.0,
            wx in -1.0f64..1.0, wy in -1.0f64..1.0, wz in -1.0f64..1.0,
            cz in -0.3f64..0.3,
        ) {
            let mut params = GeometryParams::from_layout(1.0, 0.6, 0.8, Layout::paired(20.0));
            params.pivot = Vector3::new(0.05, 0.0, cz);
            let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
            let pose = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
            let v = Vector3::new(vx, vy, vz);
            let om = Vector3::new(wx, wy, wz);
            let analytic = g.jacobian(&pose) * Vector6::new(vx, vy, vz, wx, wy, wz);
            let numeric = numeric_rates(&g, &pose, v, om);
            prop_assert!((analytic - numeric).abs().max() < 1e-7, "{analytic} vs {numeric}");
        }
    }

    proptest! {
        /// The servo Jacobian against finite differences of the closed-form servo angles.
        #[test]
        fn servo_jacobian_matches_finite_differences_of_servo_angles(
            x in -0.01f64..0.01, y in -0.01f64..0.01, z in 0.11f64..0.125,
            r in -5.0f64..5.0, p in -5.0f64..5.0, w in -10.0f64..10.0,
            vx in -1.0f64..1.0, vy in -1.0f64..1.0, vz in -1.0f64..1.0,
            wx in -1.0f64..1.0, wy in -1.0f64..1.0, wz in -1.0f64..1.0,
        ) {
            let g = crate::test_support::servo_geometry();
            let pose = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
            let Some(Ok(j)) = g.servo_jacobian(&pose) else {
                return Ok(()); // out of reach
            };
            let h = 1e-7;
            let angles_after = |s: f64| {
                let rot = nalgebra::Rotation3::new(Vector3::new(wx, wy, wz) * s * h).matrix()
                    * pose.rotation();
                let c = g.pivot();
                let pivot_point = pose.position + c;
                let joints: [Vector3<f64>; 6] = std::array::from_fn(|i| {
                    pivot_point + Vector3::new(vx, vy, vz) * s * h + rot * (g.platform_joints()[i] - c)
                });
                let servos = g.rotary().unwrap_or_else(|| panic!("not rotary"));
                servo_closure::servo_angles(servos, g.base_joints(), &joints).map(|a| Vector6::from_fn(|i, _| a[i].radians()))
            };
            let (Ok(after), Ok(before)) = (angles_after(1.0), angles_after(-1.0)) else {
                return Ok(());
            };
            let numeric = (after - before) / (2.0 * h);
            let analytic = j * Vector6::new(vx, vy, vz, wx, wy, wz);
            let scale = 1.0 + numeric.abs().max();
            prop_assert!((analytic - numeric).abs().max() < 1e-5 * scale, "{analytic} vs {numeric}");
        }
    }

    /// The last point of `inside..outside` where `reachable` holds, by bisection (60 halvings).
    fn last_reachable(mut inside: f64, mut outside: f64, reachable: impl Fn(f64) -> bool) -> f64 {
        for _ in 0..60 {
            let mid = 0.5 * (inside + outside);
            if reachable(mid) {
                inside = mid
            } else {
                outside = mid
            }
        }
        inside
    }

    #[test]
    fn servo_conditioning_is_good_at_home_and_degrades_at_the_edge_of_reach() {
        let g = crate::test_support::servo_geometry();
        let home = g
            .servo_conditioning(&g.home_pose())
            .unwrap_or_else(|| panic!("no conditioning at home"));
        let kappa_home = home.condition_number.unwrap_or(f64::INFINITY);
        assert!(kappa_home < 20.0, "{kappa_home}");
        // Slide the platform sideways until a servo cannot follow: just before, its rod
        // pulls almost across its horn's motion (the others do not, so that row alone
        // grows and the matrix loses rank).
        let h = g.home_height();
        let at = |x: f64| g.servo_conditioning(&Pose::from_xyz_rpy_deg([x, 0.0, h], [0.0; 3]));
        assert!(at(0.2).is_none(), "still reachable at 0.2 m");
        let x = last_reachable(0.0, 0.2, |x| at(x).is_some());
        let last = at(x)
            .and_then(|c| c.condition_number)
            .unwrap_or(f64::INFINITY);
        assert!(
            last > 30.0 * kappa_home,
            "{last} at x = {x} (home {kappa_home})"
        );
        assert!(
            Geometry::seed()
                .servo_conditioning(&Geometry::seed().home_pose())
                .is_none()
        );
    }

    /// servo-desk in pure heave, raised until all six servos reach the edge of reach at
    /// once: every row grows alike, so their ratio stayed 12.3 and no check flagged it.
    #[test]
    fn all_six_servos_at_the_edge_of_reach_together_are_near_singular() {
        let s =
            crate::io::scenario::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let g = &s.geometry;
        let at = |z: f64| g.servo_conditioning(&Pose::from_xyz_rpy_deg([0.0, 0.0, z], [0.0; 3]));
        let home = g.home_height();
        assert!(at(home + 0.2).is_none(), "still reachable 0.2 m above home");
        let inside = last_reachable(home, home + 0.2, |z| at(z).is_some());
        let edge = at(inside).unwrap_or_else(|| panic!("unreachable at {inside}"));
        let kappa = edge.condition_number.unwrap_or(f64::INFINITY);
        assert!(kappa > 1e3, "condition {kappa} at z = {inside}");
        // A tenth of a millimetre below the edge the rods are still nearly across their horns
        // (the transmission falls as the square root of the distance to the edge: 28 at 1 mm).
        let near = at(inside - 1e-4).and_then(|c| c.condition_number);
        assert!(
            near.is_some_and(|k| k > 30.0),
            "{near:?} at z = {}",
            inside - 1e-4
        );
        // At home the servos pull well: the verdict is the rods' own conditioning, scaled by
        // a transmission close to 1.
        let home_kappa = at(home).and_then(|c| c.condition_number);
        assert!(home_kappa.is_some_and(|k| k < 30.0), "{home_kappa:?}");
        let samples = crate::model::trajectory::Samples {
            times: vec![0.0],
            poses: vec![Pose::from_xyz_rpy_deg([0.0, 0.0, inside - 1e-4], [0.0; 3])],
        };
        let checked = crate::analysis::checks::check_motion(
            g,
            &s.limits,
            &samples,
            &crate::analysis::checks::CheckSettings::default(),
        );
        assert!(
            checked
                .findings
                .iter()
                .any(|f| f.kind == crate::analysis::checks::FindingKind::NearSingular),
            "{:?}",
            checked.findings
        );
    }

    #[test]
    fn paired_layout_is_well_conditioned_at_home() {
        let g = crate::test_support::paired_geometry();
        let c = g.conditioning(&g.home_pose());
        assert!(!c.is_singular());
        assert!(c.singular_values[5] > 0.1, "{:?}", c.singular_values);
        assert!(c.condition_number.is_some_and(|k| k < 20.0));
    }

    #[test]
    fn seed_geometry_is_rank_deficient_not_badly_conditioned() {
        // The seed's two regular hexagons: σ_min is rounding noise at any pose, and the
        // verdict is "singular", never a huge condition number.
        let g = Geometry::seed();
        for pose in [
            g.home_pose(),
            Pose::from_xyz_rpy_deg([0.1, -0.05, 0.85], [5.0, -3.0, 12.0]),
        ] {
            let c = g.conditioning(&pose);
            assert!(c.singular_values[5] < 1e-12, "{:?}", c.singular_values);
            assert!(c.is_singular());
            assert_eq!(c.inverse_condition(), 0.0);
        }
    }

    #[test]
    fn characteristic_length_makes_the_measure_unit_free() {
        // The same platform in millimetres has the same normalised singular values.
        let g = crate::test_support::paired_geometry();
        let mut mm = g.params().clone();
        mm.base = crate::model::geometry::PlateJoints::Points(mm.base.points().map(|p| p * 1000.0));
        mm.platform =
            crate::model::geometry::PlateJoints::Points(mm.platform.points().map(|p| p * 1000.0));
        mm.home_height *= 1000.0;
        let g_mm = Geometry::new(mm).unwrap_or_else(|e| panic!("{e}"));
        let a = g.conditioning(&g.home_pose()).singular_values;
        let b = g_mm.conditioning(&g_mm.home_pose()).singular_values;
        for k in 0..6 {
            assert!((a[k] - b[k]).abs() < 1e-12, "{a:?} vs {b:?}");
        }
    }
}
