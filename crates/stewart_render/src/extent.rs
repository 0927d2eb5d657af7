//! How far a draw list's solids reach: points whose convex hull holds every cylinder,
//! sphere, cone, box, plate and CAD part drawn, for framing a view around them (lines, the grid
//! and screen-space text are left out).

use glam::{Mat4, Vec3};

use crate::draw_list::DrawList;
use crate::gpu_types::MeshInstance;

/// The unit meshes' bounds in model space (see `mesh.rs`).
const CYLINDER_OR_CONE: (Vec3, Vec3) = (Vec3::new(-1.0, -1.0, 0.0), Vec3::ONE);
const SPHERE: (Vec3, Vec3) = (Vec3::NEG_ONE, Vec3::ONE);
const CUBOID: (Vec3, Vec3) = (Vec3::new(-0.5, -0.5, 0.0), Vec3::new(0.5, 0.5, 1.0));

impl DrawList {
    /// Append to `out` points whose convex hull holds every solid of the list: the
    /// corners of each instance's bounding box and every plate vertex.
    pub fn solid_extent(&self, out: &mut Vec<Vec3>) {
        let kinds = [
            (&self.cylinders, CYLINDER_OR_CONE),
            (&self.cones, CYLINDER_OR_CONE),
            (&self.spheres, SPHERE),
            (&self.boxes, CUBOID),
        ];
        for (instances, bounds) in kinds {
            for instance in instances {
                corners(instance, bounds, out);
            }
        }
        for (mesh, _, _) in &self.plates {
            out.extend(mesh.vertices.iter().map(|v| Vec3::from(v.position)));
        }
        for part in &self.parts {
            corners(&part.instance, (part.bounds[0], part.bounds[1]), out);
        }
    }
}

/// The eight corners of `bounds` placed by the instance's model matrix.
fn corners(instance: &MeshInstance, (lo, hi): (Vec3, Vec3), out: &mut Vec<Vec3>) {
    let model = Mat4::from_cols_array_2d(&instance.model);
    for k in 0..8 {
        let pick = |bit: usize, a: f32, b: f32| if k & bit == 0 { a } else { b };
        let local = Vec3::new(
            pick(1, lo.x, hi.x),
            pick(2, lo.y, hi.y),
            pick(4, lo.z, hi.z),
        );
        out.push(model.transform_point3(local));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;

    #[test]
    fn the_bounds_hold_every_unit_mesh() {
        for (mesh, (lo, hi)) in [
            (Mesh::cylinder(), CYLINDER_OR_CONE),
            (Mesh::cone(), CYLINDER_OR_CONE),
            (Mesh::sphere(), SPHERE),
            (Mesh::cuboid(), CUBOID),
        ] {
            let (mut min, mut max) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
            for v in &mesh.vertices {
                let p = Vec3::from(v.position);
                assert!(p.cmpge(lo - 1e-5).all() && p.cmple(hi + 1e-5).all(), "{p}");
                min = min.min(p);
                max = max.max(p);
            }
            // Tight: the mesh reaches each face of its bounds.
            assert!((min - lo).abs().max_element() < 1e-3, "{min} {lo}");
            assert!((max - hi).abs().max_element() < 1e-3, "{max} {hi}");
        }
    }

    #[test]
    fn a_scene_reaches_its_joints_and_plates() {
        let g = stewart_kinematics::Geometry::seed();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        let list = DrawList::build(&frame, &crate::Theme::DARK, &crate::Overlays::default());
        let mut points = Vec::new();
        list.solid_extent(&mut points);
        let (mut min, mut max) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for p in &points {
            min = min.min(*p);
            max = max.max(*p);
        }
        // Every joint lies inside, and the box is not much larger than the joints' own.
        for j in frame.base_joints.iter().chain(&frame.platform_joints) {
            let j = Vec3::new(j.x as f32, j.y as f32, j.z as f32);
            assert!(
                j.cmpgt(min).all() && j.cmplt(max).all(),
                "{j} outside {min}..{max}"
            );
        }
        let top = frame
            .platform_joints
            .iter()
            .map(|j| j.z as f32)
            .fold(0.0, f32::max);
        assert!(
            max.z > top && max.z < top + 0.2 * frame.base_radius as f32,
            "{max} {top}"
        );
    }
}
