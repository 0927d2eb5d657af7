//! A rotary platform's servo angles for a pose and the home height where its servos stand
//! level: both from inverse kinematics (the platform joints), then the servos' closed form.

use nalgebra::Vector3;

use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;
use crate::solve::servo_closure;

/// See [`Geometry::servo_home_height`].
pub(crate) fn servo_home_height(geometry: &Geometry) -> Option<f64> {
    let servos = geometry.rotary()?;
    let mean_angle = |h: f64| -> Option<f64> {
        let pose = Pose::new(
            Vector3::new(0.0, 0.0, h),
            Angle::ZERO,
            Angle::ZERO,
            Angle::ZERO,
        );
        let joints = geometry.inverse(&pose).platform_joints;
        let angles = servo_closure::servo_angles(servos, geometry.base_joints(), &joints).ok()?;
        Some(angles.iter().map(|a| a.radians()).sum::<f64>() / 6.0)
    };
    let top = servos.horn_length() + servos.rod_length() + geometry.pivot().z.abs();
    let steps = 400;
    let mut last: Option<(f64, f64)> = None;
    for k in 1..=steps {
        let h = top * f64::from(k) / f64::from(steps);
        let Some(m) = mean_angle(h) else {
            last = None;
            continue;
        };
        if let Some((h0, m0)) = last
            && m0 <= 0.0
            && m >= 0.0
        {
            let (mut lo, mut hi) = (h0, h);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                match mean_angle(mid) {
                    Some(v) if v < 0.0 => lo = mid,
                    Some(_) => hi = mid,
                    None => break,
                }
            }
            return Some(0.5 * (lo + hi));
        }
        last = Some((h, m));
    }
    None
}

/// See [`Geometry::servo_angles`].
pub(crate) fn servo_angles(
    geometry: &Geometry,
    pose: &Pose,
) -> Option<Result<[Angle; 6], Unreachable>> {
    let servos = geometry.rotary()?;
    let joints = geometry.inverse(pose).platform_joints;
    Some(servo_closure::servo_angles(
        servos,
        geometry.base_joints(),
        &joints,
    ))
}
