//! Triangle meshes: unit cylinder, unit cone, unit sphere, unit box, and plates built
//! from joints.
//!
//! Instances place them with a rotation times a scale along their own axes (radius in x
//! and y, length in z); normals are then transformed by the inverse transpose of that
//! (see `gpu_types::normal_to_world`), so a cone's sides stay lit right at any aspect.

use glam::Vec3;

use crate::gpu_types::MeshVertex;

/// Segments around round meshes.
const SEGMENTS: usize = 32;

/// An indexed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertices.
    pub vertices: Vec<MeshVertex>,
    /// Triangle indices, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
}

impl Mesh {
    fn vertex(&mut self, p: Vec3, n: Vec3) -> u32 {
        self.vertices.push(MeshVertex {
            position: p.to_array(),
            normal: n.to_array(),
        });
        (self.vertices.len() - 1) as u32
    }

    /// Add a flat disc at height `z` facing `up` (or down).
    fn disc(&mut self, z: f32, radius: f32, up: bool) {
        let n = if up { Vec3::Z } else { Vec3::NEG_Z };
        let centre = self.vertex(Vec3::new(0.0, 0.0, z), n);
        let first = self.vertices.len() as u32;
        for k in 0..SEGMENTS {
            let a = k as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            self.vertex(Vec3::new(radius * a.cos(), radius * a.sin(), z), n);
        }
        for k in 0..SEGMENTS as u32 {
            let (a, b) = (first + k, first + (k + 1) % SEGMENTS as u32);
            if up {
                self.indices.extend([centre, a, b]);
            } else {
                self.indices.extend([centre, b, a]);
            }
        }
    }

    /// Radius 1, from z = 0 to z = 1, closed at both ends.
    pub fn cylinder() -> Mesh {
        let mut m = Mesh::default();
        let first = m.vertices.len() as u32;
        for k in 0..SEGMENTS {
            let a = k as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            let n = Vec3::new(a.cos(), a.sin(), 0.0);
            m.vertex(n, n);
            m.vertex(n + Vec3::Z, n);
        }
        for k in 0..SEGMENTS as u32 {
            let (b0, t0) = (first + 2 * k, first + 2 * k + 1);
            let next = (k + 1) % SEGMENTS as u32;
            let (b1, t1) = (first + 2 * next, first + 2 * next + 1);
            m.indices.extend([b0, b1, t1, b0, t1, t0]);
        }
        m.disc(0.0, 1.0, false);
        m.disc(1.0, 1.0, true);
        m
    }

    /// Base radius 1 at z = 0, apex at z = 1.
    pub fn cone() -> Mesh {
        let mut m = Mesh::default();
        let slope = std::f32::consts::FRAC_1_SQRT_2;
        for k in 0..SEGMENTS {
            let a0 = k as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            let a1 = (k + 1) as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            let mid = 0.5 * (a0 + a1);
            let n = |a: f32| Vec3::new(a.cos() * slope, a.sin() * slope, slope);
            let p0 = m.vertex(Vec3::new(a0.cos(), a0.sin(), 0.0), n(a0));
            let p1 = m.vertex(Vec3::new(a1.cos(), a1.sin(), 0.0), n(a1));
            let apex = m.vertex(Vec3::Z, n(mid));
            m.indices.extend([p0, p1, apex]);
        }
        m.disc(0.0, 1.0, false);
        m
    }

    /// Radius 1 around the origin.
    pub fn sphere() -> Mesh {
        let mut m = Mesh::default();
        let rings = SEGMENTS / 2;
        for r in 0..=rings {
            let theta = r as f32 / rings as f32 * std::f32::consts::PI;
            for k in 0..=SEGMENTS {
                let phi = k as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
                let n = Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                );
                m.vertex(n, n);
            }
        }
        let row = SEGMENTS as u32 + 1;
        for r in 0..rings as u32 {
            for k in 0..SEGMENTS as u32 {
                let (a, b) = (r * row + k, r * row + k + 1);
                let (c, d) = ((r + 1) * row + k, (r + 1) * row + k + 1);
                m.indices.extend([a, c, d, a, d, b]);
            }
        }
        m
    }

    /// A box from (−0.5, −0.5, 0) to (0.5, 0.5, 1): flat faces with their own normals
    /// (four vertices each), placed like the cylinder (size in x and y, length in z).
    pub fn cuboid() -> Mesh {
        let mut m = Mesh::default();
        for axis in 0..3 {
            // u × v = e_axis: counter-clockwise in (u, v) faces +e_axis.
            let (mut u, mut v) = (Vec3::ZERO, Vec3::ZERO);
            u[(axis + 1) % 3] = 1.0;
            v[(axis + 2) % 3] = 1.0;
            for sign in [-1.0f32, 1.0] {
                let mut n = Vec3::ZERO;
                n[axis] = sign;
                let centre = Vec3::new(0.0, 0.0, 0.5) + 0.5 * n;
                let first = m.vertices.len() as u32;
                for (a, b) in [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
                    m.vertex(centre + a * u + b * v, n);
                }
                if sign > 0.0 {
                    m.indices
                        .extend([first, first + 1, first + 2, first, first + 2, first + 3]);
                } else {
                    m.indices
                        .extend([first, first + 2, first + 1, first, first + 3, first + 2]);
                }
            }
        }
        m
    }

    /// A plate: the polygon through `corners` (sorted around `centre`) with thickness
    /// `thickness` below it along `-normal`, in world coordinates.
    pub fn plate(centre: Vec3, normal: Vec3, corners: &[Vec3], thickness: f32) -> Mesh {
        let normal = normal.normalize_or(Vec3::Z);
        // Sort the corners by angle around the normal so the outline does not cross itself.
        let reference =
            (corners.first().copied().unwrap_or(Vec3::X) - centre).normalize_or(Vec3::X);
        let side = normal.cross(reference);
        let mut sorted: Vec<Vec3> = corners.to_vec();
        sorted.sort_by(|a, b| {
            let angle = |p: &Vec3| {
                let d = *p - centre;
                d.dot(side).atan2(d.dot(reference))
            };
            angle(a).total_cmp(&angle(b))
        });
        let below = -normal * thickness;
        let mut m = Mesh::default();
        let n = sorted.len() as u32;
        for (face_offset, face_normal) in [(Vec3::ZERO, normal), (below, -normal)] {
            let c = m.vertex(centre + face_offset, face_normal);
            let first = m.vertices.len() as u32;
            for p in &sorted {
                m.vertex(*p + face_offset, face_normal);
            }
            for k in 0..n {
                let (a, b) = (first + k, first + (k + 1) % n);
                if face_normal == normal {
                    m.indices.extend([c, a, b]);
                } else {
                    m.indices.extend([c, b, a]);
                }
            }
        }
        for k in 0..sorted.len() {
            let (p, q) = (sorted[k], sorted[(k + 1) % sorted.len()]);
            let out = (q - p).cross(normal).normalize_or_zero();
            let a = m.vertex(p, out);
            let b = m.vertex(q, out);
            let c = m.vertex(q + below, out);
            let d = m.vertex(p + below, out);
            m.indices.extend([a, d, c, a, c, b]);
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed: every edge of a non-degenerate triangle, taken by vertex positions (the
    /// meshes split vertices where normals differ), is walked once in each direction by
    /// the triangles on its two sides, so the surface has no hole and no flipped face.
    fn check_closed(m: &Mesh) {
        use std::collections::HashMap;
        let key = |i: u32| {
            let p = m.vertices[i as usize].position;
            p.map(|c| (c * 1e4).round() as i64)
        };
        let mut edges: HashMap<([i64; 3], [i64; 3]), i32> = HashMap::new();
        for t in m.indices.chunks(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(key);
            if a == b || b == c || c == a {
                continue; // a sliver at a pole: no area, no edge of the surface
            }
            for (p, q) in [(a, b), (b, c), (c, a)] {
                *edges.entry((p, q)).or_default() += 1;
            }
        }
        for (&(p, q), &n) in &edges {
            let back = edges.get(&(q, p)).copied().unwrap_or(0);
            assert_eq!(
                n, back,
                "edge {p:?} → {q:?} walked {n} times, back {back} times"
            );
        }
    }

    fn check_closed_and_outward(m: &Mesh, inside: Vec3) {
        assert_eq!(m.indices.len() % 3, 0);
        assert!(m.indices.iter().all(|&i| (i as usize) < m.vertices.len()));
        check_closed(m);
        // Every triangle faces away from an interior point (counter-clockwise outside).
        for t in m.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|k| Vec3::from_array(m.vertices[t[k] as usize].position));
            let face = (b - a).cross(c - a);
            if face.length() > 1e-6 {
                assert!(
                    face.dot((a + b + c) / 3.0 - inside) > 0.0,
                    "inward triangle {a} {b} {c}"
                );
            }
        }
    }

    #[test]
    fn the_closure_check_sees_a_hole_and_a_flipped_face() {
        let mut open = Mesh::cylinder();
        open.indices.truncate(open.indices.len() - 3);
        assert!(std::panic::catch_unwind(|| check_closed(&open)).is_err());
        let mut flipped = Mesh::cone();
        flipped.indices.swap(0, 1);
        assert!(std::panic::catch_unwind(|| check_closed(&flipped)).is_err());
    }

    #[test]
    fn meshes_are_closed_and_face_outward() {
        check_closed_and_outward(&Mesh::cylinder(), Vec3::new(0.0, 0.0, 0.5));
        check_closed_and_outward(&Mesh::cone(), Vec3::new(0.0, 0.0, 0.2));
        check_closed_and_outward(&Mesh::sphere(), Vec3::ZERO);
        check_closed_and_outward(&Mesh::cuboid(), Vec3::new(0.0, 0.0, 0.5));
        let corners: Vec<Vec3> = [5, 1, 3, 0, 2, 4]
            .iter()
            .map(|&k| {
                let a = k as f32 * std::f32::consts::FRAC_PI_3;
                Vec3::new(a.cos(), a.sin(), 1.0)
            })
            .collect();
        let plate = Mesh::plate(Vec3::Z, Vec3::Z, &corners, 0.1);
        check_closed_and_outward(&plate, Vec3::new(0.0, 0.0, 0.95));
    }

    #[test]
    fn sphere_vertices_are_on_the_unit_sphere() {
        for v in Mesh::sphere().vertices {
            assert!((Vec3::from_array(v.position).length() - 1.0).abs() < 1e-6);
        }
    }
}
