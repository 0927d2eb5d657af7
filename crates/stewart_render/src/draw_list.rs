//! From the kinematics' [`SceneFrame`] to GPU-ready instances, plates and lines.
//! Pure CPU work, tested without a GPU.

use glam::{Mat3, Mat4, Quat, Vec3};
use stewart_kinematics::scene::SceneFrame;

use crate::gpu_types::{LineVertex, MeshInstance};
use crate::mesh::Mesh;
use crate::theme::{Theme, linear};

/// What to show besides the platform itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overlays {
    /// The ground grid.
    pub grid: bool,
    /// The base frame's axes at the origin.
    pub base_axes: bool,
    /// The platform's own axes at its centre.
    pub platform_axes: bool,
    /// The path traced by the platform centre.
    pub path: bool,
}

impl Default for Overlays {
    fn default() -> Self {
        Self {
            grid: true,
            base_axes: true,
            platform_axes: false,
            path: true,
        }
    }
}

/// Everything to draw, in world coordinates (f32).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawList {
    /// Instances of the unit cylinder.
    pub cylinders: Vec<MeshInstance>,
    /// Instances of the unit sphere.
    pub spheres: Vec<MeshInstance>,
    /// Instances of the unit cone.
    pub cones: Vec<MeshInstance>,
    /// Translucent plates: mesh (world coordinates), linear colour, centre (for sorting).
    pub plates: Vec<(Mesh, [f32; 4], Vec3)>,
    /// Line segments (pairs of vertices).
    pub lines: Vec<LineVertex>,
}

fn v3(v: &nalgebra::Vector3<f64>) -> Vec3 {
    Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

/// A unit cylinder or cone (along +z) placed from `from` to `to` with `radius`.
fn along(from: Vec3, to: Vec3, radius: f32, color: [f32; 4]) -> MeshInstance {
    let d = to - from;
    let length = d.length();
    let rotation = Quat::from_rotation_arc(Vec3::Z, d.normalize_or(Vec3::Z));
    let model = Mat4::from_scale_rotation_translation(
        Vec3::new(radius, radius, length.max(1e-6)),
        rotation,
        from,
    );
    MeshInstance {
        model: model.to_cols_array_2d(),
        color,
    }
}

fn ball(at: Vec3, radius: f32, color: [f32; 4]) -> MeshInstance {
    let model = Mat4::from_scale_rotation_translation(Vec3::splat(radius), Quat::IDENTITY, at);
    MeshInstance {
        model: model.to_cols_array_2d(),
        color,
    }
}

impl DrawList {
    /// Build the draw list of `frame` in `theme`.
    pub fn build(frame: &SceneFrame, theme: &Theme, overlays: &Overlays) -> DrawList {
        let mut list = DrawList::default();
        let s = frame.base_radius.max(frame.platform_radius) as f32;
        let body_radius = 0.030 * s;
        let rod_radius = 0.017 * s;
        let joint_radius = 0.040 * s;
        let plate_thickness = 0.025 * s;

        // Legs: an actuator body from the base joint and a thinner rod from the platform
        // joint; the body is as long as the shortest leg (or 55 % of the leg).
        for leg in &frame.legs {
            let (base, top) = (v3(&leg.base), v3(&leg.top));
            let length = leg.length as f32;
            let dir = (top - base).normalize_or(Vec3::Z);
            let body_length = leg
                .min_length
                .map_or(0.55 * length, |m| (0.92 * m as f32).min(0.9 * length));
            let (body, rod) = theme.leg_colours(leg.status);
            list.cylinders.push(along(
                base,
                base + dir * body_length,
                body_radius,
                linear(body),
            ));
            list.cylinders.push(along(
                base + dir * (body_length - 0.02 * s),
                top,
                rod_radius,
                linear(rod),
            ));
        }
        for p in frame.base_joints.iter().chain(&frame.platform_joints) {
            list.spheres
                .push(ball(v3(p), joint_radius, linear(theme.joint)));
        }

        // Plates: the polygons through the joints, the base's top face at z = 0.
        let base_corners: Vec<Vec3> = frame.base_joints.iter().map(v3).collect();
        list.plates.push((
            Mesh::plate(Vec3::ZERO, Vec3::Z, &base_corners, plate_thickness),
            linear(theme.base_plate),
            Vec3::ZERO,
        ));
        let rotation = Mat3::from_cols_array(&std::array::from_fn(|k| {
            frame.platform_rotation[(k % 3, k / 3)] as f32
        }));
        let normal = rotation * Vec3::Z;
        let centre = v3(&frame.platform_centre);
        let corners: Vec<Vec3> = frame.platform_joints.iter().map(v3).collect();
        list.plates.push((
            Mesh::plate(centre, normal, &corners, plate_thickness),
            linear(theme.platform),
            centre,
        ));

        if overlays.base_axes {
            list.axes(Vec3::ZERO, Mat3::IDENTITY, 0.45 * s, 0.012 * s, theme);
        }
        if overlays.platform_axes {
            list.axes(centre, rotation, 0.30 * s, 0.009 * s, theme);
        }
        if overlays.grid {
            list.grid(1.6 * s, theme);
        }
        if overlays.path && frame.path.len() > 1 {
            let c = linear(theme.path);
            for pair in frame.path.windows(2) {
                list.lines.push(LineVertex {
                    position: v3(&pair[0]).to_array(),
                    color: c,
                });
                list.lines.push(LineVertex {
                    position: v3(&pair[1]).to_array(),
                    color: c,
                });
            }
        }
        list
    }

    /// Three arrows (shaft and cone) along the columns of `axes`.
    fn axes(&mut self, origin: Vec3, axes: Mat3, length: f32, radius: f32, theme: &Theme) {
        for k in 0..3 {
            let dir = axes.col(k);
            let color = linear(theme.axes[k]);
            let shaft_end = origin + dir * (0.82 * length);
            self.cylinders.push(along(origin, shaft_end, radius, color));
            self.cones
                .push(along(shaft_end, origin + dir * length, 2.6 * radius, color));
        }
    }

    /// A square grid on z = 0 reaching `half` metres from the origin, lines every
    /// "nice" step (1, 2 or 5 × 10ⁿ) giving about ten cells per side.
    fn grid(&mut self, half: f32, theme: &Theme) {
        let step = crate::ticks::nice_step(f64::from(half) / 5.0) as f32;
        let n = (half / step).floor() as i32;
        let extent = n as f32 * step;
        let c = linear(theme.grid);
        for k in -n..=n {
            let t = k as f32 * step;
            for (a, b) in [
                ([t, -extent, 0.0], [t, extent, 0.0]),
                ([-extent, t, 0.0], [extent, t, 0.0]),
            ] {
                self.lines.push(LineVertex {
                    position: a,
                    color: c,
                });
                self.lines.push(LineVertex {
                    position: b,
                    color: c,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::{Geometry, GeometryParams, StrokeLimits};

    #[test]
    fn legs_take_the_warning_colour_over_the_stroke() {
        let mut p = GeometryParams::seed();
        p.stroke = StrokeLimits::new(0.5, 0.97); // home legs are 0.98 m: all over
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let list = DrawList::build(
            &g.scene_frame(&g.home_pose(), Vec::new()),
            &Theme::DARK,
            &Overlays::default(),
        );
        let warning = linear(Theme::DARK.leg_over_limit);
        assert_eq!(
            list.cylinders.iter().filter(|c| c.color == warning).count(),
            12
        );
        let g = Geometry::seed();
        let list = DrawList::build(
            &g.scene_frame(&g.home_pose(), Vec::new()),
            &Theme::DARK,
            &Overlays::default(),
        );
        assert_eq!(
            list.cylinders.iter().filter(|c| c.color == warning).count(),
            0
        );
    }

    #[test]
    fn leg_cylinders_span_base_to_platform_joint() {
        let g = Geometry::seed();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        let list = DrawList::build(
            &frame,
            &Theme::LIGHT,
            &Overlays {
                grid: false,
                base_axes: false,
                platform_axes: false,
                path: false,
            },
        );
        assert_eq!(list.cylinders.len(), 12);
        assert_eq!(list.spheres.len(), 12);
        assert!(list.lines.is_empty() && list.cones.is_empty());
        // The rod's far end (model · (0, 0, 1)) is the platform joint.
        let rod = Mat4::from_cols_array_2d(&list.cylinders[1].model);
        let end = rod.transform_point3(Vec3::Z);
        assert!((end - v3(&frame.platform_joints[0])).length() < 1e-5);
        let body = Mat4::from_cols_array_2d(&list.cylinders[0].model);
        assert!((body.transform_point3(Vec3::ZERO) - v3(&frame.base_joints[0])).length() < 1e-6);
    }
}
