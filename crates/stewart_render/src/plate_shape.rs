//! The outline of a plate: the convex hull of its joints seen along the plate's normal.
//!
//! A plate is drawn in its frame's `z = 0` plane; joints off that plane (on brackets, a
//! raised centre) stand on posts from the plate, so an as-built layout reads at a glance.

use glam::{Mat3, Vec2, Vec3};

/// The plate's outline and the posts of its off-plane joints, in world coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct PlateShape {
    /// Corners of the outline, counter-clockwise about the normal.
    pub corners: Vec<Vec3>,
    /// A point inside the outline (the corners' mean).
    pub centre: Vec3,
    /// The plate's normal (its frame's z axis).
    pub normal: Vec3,
    /// Posts from the plate up (or down) to each joint that is off the plate's plane.
    pub posts: Vec<(Vec3, Vec3)>,
}

/// The shape of a plate whose frame is at `origin` with axes `rotation`, for joints
/// `joints` (world coordinates). Joints within `flat` of the plane get no post.
pub fn plate_shape(origin: Vec3, rotation: Mat3, joints: &[Vec3], flat: f32) -> PlateShape {
    let to_local = rotation.transpose();
    let local: Vec<Vec3> = joints.iter().map(|j| to_local * (*j - origin)).collect();
    let on_plane = |p: Vec2| origin + rotation * p.extend(0.0);
    let hull = convex_hull(&local.iter().map(|p| p.truncate()).collect::<Vec<_>>());
    let corners: Vec<Vec3> = hull.iter().map(|&p| on_plane(p)).collect();
    let mean = hull.iter().copied().sum::<Vec2>() / (hull.len().max(1) as f32);
    let posts = local
        .iter()
        .zip(joints)
        .filter(|(l, _)| l.z.abs() > flat)
        .map(|(l, j)| (on_plane(l.truncate()), *j))
        .collect();
    PlateShape {
        corners,
        centre: on_plane(mean),
        normal: rotation * Vec3::Z,
        posts,
    }
}

/// The convex hull of `points`, counter-clockwise, without collinear points (Andrew's
/// monotone chain).
pub fn convex_hull(points: &[Vec2]) -> Vec<Vec2> {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    sorted.dedup();
    if sorted.len() < 3 {
        return sorted;
    }
    let turn = |o: Vec2, a: Vec2, b: Vec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<Vec2> = Vec::with_capacity(2 * sorted.len());
    for pass in [false, true] {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Vec2>> = if pass {
            Box::new(sorted.iter().rev())
        } else {
            Box::new(sorted.iter())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_of_a_hexagon_with_an_inner_point_is_the_hexagon() {
        let mut points: Vec<Vec2> = (0..6)
            .map(|k| Vec2::from_angle(k as f32 * std::f32::consts::FRAC_PI_3))
            .collect();
        points.push(Vec2::new(0.1, -0.2));
        let hull = convex_hull(&points);
        assert_eq!(hull.len(), 6);
        // Counter-clockwise: every turn is to the left.
        for k in 0..6 {
            let (a, b, c) = (hull[k], hull[(k + 1) % 6], hull[(k + 2) % 6]);
            assert!((b - a).perp_dot(c - b) > 0.0);
        }
        assert!(!hull.contains(&Vec2::new(0.1, -0.2)));
    }

    #[test]
    fn off_plane_joints_get_posts_from_their_foot_on_the_plate() {
        let joints = [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.3),
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(0.0, -1.0, -0.2),
        ];
        let shape = plate_shape(Vec3::ZERO, Mat3::IDENTITY, &joints, 1e-4);
        assert_eq!(shape.corners.len(), 4);
        assert!(shape.corners.iter().all(|c| c.z == 0.0));
        assert_eq!(
            shape.posts,
            vec![
                (Vec3::new(0.0, 1.0, 0.0), joints[1]),
                (Vec3::new(0.0, -1.0, 0.0), joints[3])
            ]
        );
        // A turned and moved plate: the posts run along its normal.
        let rotation = Mat3::from_rotation_x(0.5);
        let origin = Vec3::new(0.2, -0.1, 1.0);
        let world: Vec<Vec3> = joints.iter().map(|j| origin + rotation * *j).collect();
        let turned = plate_shape(origin, rotation, &world, 1e-4);
        for (foot, joint) in &turned.posts {
            assert!((*joint - *foot).normalize().cross(turned.normal).length() < 1e-5);
        }
    }
}
