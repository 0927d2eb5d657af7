//! A rotary platform's servo angles for a pose and the home height where its servos stand
//! level: both from inverse kinematics (the platform joints), then the servos' closed form.

use nalgebra::Vector3;

use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;
use crate::solve::servo_closure;

impl Geometry {
    /// The home height at which the servos stand level (mean servo angle zero) with the
    /// platform centred and level, for a rotary platform: where the horns have the most
    /// travel both ways. `None` for linear legs, or when no height between the base and
    /// `a + s` above it gets there. Found by a scan for the sign change of the mean
    /// angle, then bisection to the last bit.
    pub fn servo_home_height(&self) -> Option<f64> {
        let servos = self.rotary()?;
        let mean_angle = |h: f64| -> Option<f64> {
            let pose = Pose::new(
                Vector3::new(0.0, 0.0, h),
                Angle::ZERO,
                Angle::ZERO,
                Angle::ZERO,
            );
            let joints = self.inverse(&pose).platform_joints;
            let angles = servo_closure::servo_angles(servos, self.base_joints(), &joints).ok()?;
            Some(angles.iter().map(|a| a.radians()).sum::<f64>() / 6.0)
        };
        let top = servos.horn_length() + servos.rod_length() + self.pivot().z.abs();
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

    /// The six servo angles that hold `pose`, for a rotary platform (`None` for linear
    /// legs), or the first servo that cannot reach its joint.
    pub fn servo_angles(&self, pose: &Pose) -> Option<Result<[Angle; 6], Unreachable>> {
        let servos = self.rotary()?;
        let joints = self.inverse(pose).platform_joints;
        Some(servo_closure::servo_angles(
            servos,
            self.base_joints(),
            &joints,
        ))
    }
}
