//! The scene for a pose ([`crate::model::scene::SceneFrame`]): inverse kinematics gives the
//! joints and lengths, and each leg or servo is judged against its stroke or range.

use nalgebra::Vector3;

use crate::model::geometry::{Geometry, Plate};
use crate::model::pose::Pose;
use crate::model::scene::{LegFrame, LegStatus, SceneFrame, ServoFrame};
use crate::solve::servo_closure;

/// Fraction of the stroke near either end that counts as "near the limit".
const NEAR_LIMIT: f64 = 0.05;

/// See [`Geometry::scene_frame`].
pub(crate) fn scene_frame(geometry: &Geometry, pose: &Pose, path: Vec<Vector3<f64>>) -> SceneFrame {
    let solution = geometry.inverse(pose);
    let stroke = geometry.stroke();
    let servos = servo_frames(geometry, &solution.platform_joints);
    let mut legs = std::array::from_fn(|i| {
        let length = solution.lengths[i];
        let usage = stroke.usage(length);
        let over = stroke.violation(length).is_some();
        LegFrame {
            base: geometry.base_joints()[i],
            top: solution.platform_joints[i],
            length,
            stroke_usage: usage,
            min_length: stroke.min,
            status: status_of(over, usage),
        }
    });
    if let Some(servos) = &servos {
        for (leg, servo) in legs.iter_mut().zip(servos) {
            leg.base = servo.horn_tip;
            leg.length = (leg.top - leg.base).norm();
            leg.stroke_usage = servo.range_usage;
            leg.status = servo.status;
        }
    }
    SceneFrame {
        base_joints: *geometry.base_joints(),
        platform_joints: solution.platform_joints,
        platform_centre: geometry.platform_centre(pose),
        platform_rotation: pose.rotation(),
        base_radius: geometry.plate_radius(Plate::Base),
        platform_radius: geometry.plate_radius(Plate::Platform),
        legs,
        servos,
        path,
    }
}

/// The servos of a rotary platform holding platform joints `joints` (`None` for legs).
fn servo_frames(geometry: &Geometry, joints: &[Vector3<f64>; 6]) -> Option<[ServoFrame; 6]> {
    let servos = geometry.rotary()?;
    let bases = geometry.base_joints();
    Some(std::array::from_fn(|i| {
        let (sb, cb) = servos.horn_angles()[i].radians().sin_cos();
        let solved = servo_closure::servo_angle(servos, i, &bases[i], &joints[i]).ok();
        let theta = solved
            .unwrap_or_else(|| servo_closure::closest_angle(servos, i, &bases[i], &joints[i]));
        let usage = solved.and_then(|t| {
            let (min, max) = servos.range()?;
            Some((t.radians() - min.radians()) / (max.radians() - min.radians()))
        });
        let over = solved.is_none() || usage.is_some_and(|u| !(0.0..=1.0).contains(&u));
        ServoFrame {
            shaft: bases[i],
            axis: Vector3::new(-sb, cb, 0.0),
            horn_tip: servos.horn_tip(i, &bases[i], theta),
            angle_deg: solved.map(|t| t.degrees()),
            range_usage: usage,
            status: status_of(over, usage),
        }
    }))
}

/// Over the limit, near it (within [`NEAR_LIMIT`] of an end of the usage), or normal.
fn status_of(over: bool, usage: Option<f64>) -> LegStatus {
    if over {
        LegStatus::OverLimit
    } else if usage.is_some_and(|u| !(NEAR_LIMIT..=1.0 - NEAR_LIMIT).contains(&u)) {
        LegStatus::NearLimit
    } else {
        LegStatus::Normal
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::geometry::{GeometryParams, StrokeLimits};

    #[test]
    fn leg_status_follows_the_stroke() {
        let mut p = GeometryParams::seed();
        // Home legs are 0.9802 m long.
        p.stroke = StrokeLimits::new(0.5, 0.97);
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(frame.legs.iter().all(|l| l.status == LegStatus::OverLimit));
        let mut p = GeometryParams::seed();
        p.stroke = StrokeLimits::new(0.5, 0.99);
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(frame.legs.iter().all(|l| l.status == LegStatus::NearLimit));
        let g = Geometry::seed();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(
            frame
                .legs
                .iter()
                .all(|l| l.status == LegStatus::Normal && l.stroke_usage.is_none())
        );
        assert_eq!(frame.platform_centre, Vector3::new(0.0, 0.0, 0.8));
        assert_eq!(frame.legs[2].top, frame.platform_joints[2]);
    }

    #[test]
    fn servo_frames_close_their_rods_and_flag_range_and_reach() {
        let g = crate::test_support::servo_geometry();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
        for (leg, servo) in frame.legs.iter().zip(&servos) {
            // Horn of length a on a horizontal shaft, perpendicular to the horn.
            let horn = servo.horn_tip - servo.shaft;
            assert!((horn.norm() - 0.025).abs() < 1e-15);
            assert!(horn.dot(&servo.axis).abs() < 1e-15 && servo.axis.z == 0.0);
            // The rod drawn from the horn tip to the joint has the rod's length.
            assert!((leg.length - 0.12).abs() < 1e-12, "{}", leg.length);
            assert_eq!(leg.base, servo.horn_tip);
            assert_eq!(leg.status, LegStatus::Normal);
            assert!(servo.angle_deg.is_some() && servo.range_usage.is_none());
        }
        assert!(
            g.scene_frame(&g.home_pose(), Vec::new()).legs[0]
                .min_length
                .is_none()
        );
        // Lifted out of reach: every servo is over, its horn points at its joint.
        let high = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.2], [0.0; 3]);
        let frame = g.scene_frame(&high, Vec::new());
        let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
        for (leg, servo) in frame.legs.iter().zip(&servos) {
            assert_eq!(servo.status, LegStatus::OverLimit);
            assert_eq!(servo.angle_deg, None);
            let towards = (leg.top - servo.shaft).normalize();
            let horn = (servo.horn_tip - servo.shaft).normalize();
            // The horn points as near the joint as its swing allows: the rest of the
            // joint's direction is along the shaft axis.
            let off_plane = towards - servo.axis * towards.dot(&servo.axis);
            assert!((horn - off_plane.normalize()).norm() < 1e-12);
            assert!(leg.length > 0.12);
        }
        // A servo range: usage and near/over colours.
        let mut p = g.params().clone();
        if let crate::model::actuator::Actuator::Rotary(r) = &p.actuator {
            let angles = r.horn_angles().map(|a| a.degrees());
            p.actuator = crate::model::actuator::Actuator::Rotary(
                crate::model::rotary::RotaryActuators::new(0.025, 0.12, angles, Some((-1.0, 1.0)))
                    .unwrap_or_else(|e| panic!("{e}")),
            );
        }
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let low = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.10], [0.0; 3]);
        let frame = g.scene_frame(&low, Vec::new());
        let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
        for s in &servos {
            assert!(s.angle_deg.is_some_and(|a| a < -1.0), "{s:?}");
            assert!(s.range_usage.is_some_and(|u| u < 0.0));
            assert_eq!(s.status, LegStatus::OverLimit);
        }
    }

    #[test]
    fn part_frames_stand_where_the_appearance_table_says() {
        use crate::model::angle::Angle;
        use crate::model::pose::Pose;
        let g = Geometry::seed();
        let pose = Pose::new(
            Vector3::new(0.05, -0.03, 0.85),
            Angle::from_degrees(4.0),
            Angle::from_degrees(-3.0),
            Angle::from_degrees(10.0),
        );
        let frame = g.scene_frame(&pose, Vec::new());
        // The platform frame carries each joint from the platform's own coordinates.
        let p = frame.platform_placement();
        for (a, q) in g.platform_joints().iter().zip(&frame.platform_joints) {
            assert!((p.origin + p.rotation * a - q).norm() < 1e-12);
        }
        for k in 0..6 {
            let [body, rod] = frame.leg_placements(k);
            let leg = &frame.legs[k];
            assert_eq!((body.origin, rod.origin), (leg.base, leg.top));
            assert_eq!(frame.rod_placement(k), rod);
            // +y runs along the leg: the body's +y · length reaches the platform joint.
            let tip = body.origin + body.rotation * Vector3::new(0.0, leg.length, 0.0);
            assert!((tip - leg.top).norm() < 1e-12);
            assert!(frame.horn_placement(k).is_none());
        }
        // Servos: +x along the horn, turned by the servo angle about +z from its zero
        // direction, +y up at angle 0.
        let g = crate::test_support::servo_geometry();
        let frame = g.scene_frame(
            &Pose::new(
                Vector3::new(0.004, 0.0, g.home_height() + 0.003),
                Angle::from_degrees(3.0),
                Angle::from_degrees(-2.0),
                Angle::from_degrees(5.0),
            ),
            Vec::new(),
        );
        let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
        let rotary = g.rotary().unwrap_or_else(|| panic!("rotary"));
        for (k, servo) in servos.iter().enumerate() {
            let h = frame.horn_placement(k).unwrap_or_else(|| panic!("horn"));
            assert_eq!(h.origin, servo.shaft);
            let x = h.rotation * Vector3::x();
            let tip = servo.shaft + x * rotary.horn_length();
            assert!((tip - servo.horn_tip).norm() < 1e-12);
            let beta = rotary.horn_angles()[k].radians();
            let zero = Vector3::new(beta.cos(), beta.sin(), 0.0);
            let angle = x.dot(&Vector3::z()).atan2(x.dot(&zero)).to_degrees();
            let theta = servo.angle_deg.unwrap_or_else(|| panic!("reachable"));
            assert!((angle - theta).abs() < 1e-9, "{angle} vs {theta}");
            // Turning about +z by θ takes the zero direction onto the horn.
            let z = h.rotation * Vector3::z();
            let turned = nalgebra::UnitQuaternion::from_axis_angle(
                &nalgebra::Unit::new_normalize(z),
                theta.to_radians(),
            ) * zero;
            assert!((turned - x).norm() < 1e-9);
            assert_eq!(frame.rod_placement(k).origin, servo.horn_tip);
        }
    }
}
