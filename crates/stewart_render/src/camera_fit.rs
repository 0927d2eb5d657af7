//! Framing a cloud of points tightly: for a fixed viewing direction, the camera whose
//! view holds every point with a margin, centred in the view.
//!
//! Along the view's right axis a point at lateral position `a` and depth `z` lies inside
//! a view of half-angle tangent `t` from an eye at `(e, d)` exactly when
//! `|a − e| ≤ t (z − d)`. The two planes touching the cloud are then
//! `e − t d = max(a − t z)` and `e + t d = min(a + t z)`, which give the eye's lateral
//! position and depth in closed form. The eye takes the further back of the two axes'
//! depths; the other axis, which then has room to spare, is centred by finding the
//! narrower half-angle whose tight eye has that same depth (bisection: the depth grows
//! with the angle).

use glam::Vec3;

use crate::camera::{FOV_Y_DEG, OrbitCamera};

/// One axis of the view: the points' lateral coordinates and depths, and the window
/// they must fit in, as tangents of the angle from the view's axis: centred at `centre`,
/// reaching `half` either side.
struct Axis<'a> {
    lateral: &'a [f32],
    depth: &'a [f32],
    centre: f32,
    half: f32,
}

impl Axis<'_> {
    /// The tight eye for the window shrunk by `s` about its centre: (lateral position,
    /// depth).
    fn eye(&self, s: f32) -> (f32, f32) {
        let (high, low) = (self.centre + s * self.half, s * self.half - self.centre);
        let (mut upper, mut lower) = (f32::NEG_INFINITY, f32::INFINITY);
        for (a, z) in self.lateral.iter().zip(self.depth) {
            upper = upper.max(a - high * z);
            lower = lower.min(a + low * z);
        }
        let depth = (lower - upper) / (high + low);
        (upper + high * depth, depth)
    }

    /// The lateral position that centres the points in the window for an eye at
    /// `depth`, which is at or behind this axis' own tight eye for the window shrunk by
    /// `s` (the depth grows with the window, which holds every smaller one).
    fn centred_at(&self, depth: f32, s: f32) -> f32 {
        let (mut lo, mut hi) = (0.0f32, s);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.eye(mid).1 < depth {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.eye(hi.max(1e-6)).0
    }
}

impl OrbitCamera {
    /// The camera at the given angles whose view (`aspect` = width / height) holds every
    /// one of `points` inside the central `1 − margin` of its width and height, with the
    /// points' projected extent centred on both axes. `top` (0 to 0.5) is a share of the
    /// height kept free at the top (for a readout); the points are then framed and
    /// centred in the rest. The camera is for exactly this aspect: do not pass it
    /// through [`OrbitCamera::fitted_to`]. `None` for no points or non-finite input.
    pub fn fitting_points(
        azimuth_deg: f32,
        elevation_deg: f32,
        points: &[Vec3],
        aspect: f32,
        margin: f32,
        top: f32,
    ) -> Option<Self> {
        let usable = !points.is_empty()
            && aspect.is_finite()
            && aspect > 0.0
            && (0.0..1.0).contains(&margin)
            && (0.0..=0.5).contains(&top);
        if !usable || points.iter().any(|p| !p.is_finite()) {
            return None;
        }
        let mut camera = OrbitCamera {
            azimuth_deg,
            elevation_deg,
            distance: 1.0,
            target: Vec3::ZERO,
        };
        let forward = -camera.direction();
        let right = forward.cross(Vec3::Z).normalize_or_zero();
        let up = right.cross(forward);
        let depth: Vec<f32> = points.iter().map(|p| p.dot(forward)).collect();
        let across: Vec<f32> = points.iter().map(|p| p.dot(right)).collect();
        let high: Vec<f32> = points.iter().map(|p| p.dot(up)).collect();
        let tan = (FOV_Y_DEG * 0.5).to_radians().tan();
        let horizontal = Axis {
            lateral: &across,
            depth: &depth,
            centre: 0.0,
            half: tan * aspect,
        };
        // The view's height from −1 to 1 − 2·top in normalised coordinates.
        let vertical = Axis {
            lateral: &high,
            depth: &depth,
            centre: -top * tan,
            half: (1.0 - top) * tan,
        };
        let s = 1.0 - margin;
        let (ex, dx) = horizontal.eye(s);
        let (ey, dy) = vertical.eye(s);
        // The further back eye holds both; the other axis is centred at that depth.
        let (ex, ey, d) = if dx <= dy {
            (ex, vertical.centred_at(dx, s), dx)
        } else {
            (horizontal.centred_at(dy, s), ey, dy)
        };
        let eye = right * ex + up * ey + forward * d;
        let (near, far) = depth
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(n, f), &z| {
                (n.min(z), f.max(z))
            });
        // Look at the middle of the points' depth, a little further for a flat cloud.
        camera.distance = (0.5 * (near + far) - d).max(1e-3);
        camera.target = eye + forward * camera.distance;
        Some(camera)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (no dependency for a test).
    fn cloud(seed: u64, n: usize, spread: Vec3, offset: Vec3) -> Vec<Vec3> {
        let mut s = seed;
        let mut next = move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) as f32 / (1u64 << 31) as f32) * 2.0 - 1.0
        };
        (0..n)
            .map(|_| offset + Vec3::new(next(), next(), next()) * spread)
            .collect()
    }

    #[test]
    fn every_point_is_inside_centred_and_one_axis_touches_the_margin() {
        let (seed, tall) = (Vec3::new(1.0, 1.0, 0.3), Vec3::new(0.1, 2.0, 0.1));
        let far = Vec3::new(5.0, -3.0, 1.0);
        // Azimuth, elevation, aspect, spread, offset, share of the height kept at the top.
        let cases = [
            (135.0, 20.0, 16.0 / 9.0, seed, Vec3::ZERO, 0.0),
            (
                135.0,
                20.0,
                0.98,
                Vec3::new(0.8, 0.8, 0.5),
                Vec3::Z * 0.6,
                0.0,
            ),
            (30.0, 60.0, 1.0, tall, far, 0.0),
            (
                250.0,
                -10.0,
                2.5,
                Vec3::new(0.05, 0.05, 1.5),
                Vec3::ZERO,
                0.0,
            ),
            (135.0, 20.0, 16.0 / 9.0, seed, Vec3::ZERO, 0.2),
            (30.0, 60.0, 1.0, tall, far, 0.3),
        ];
        for (k, (az, el, aspect, spread, offset, top)) in cases.into_iter().enumerate() {
            let points = cloud(k as u64 + 1, 300, spread, offset);
            let margin = 0.1;
            let camera = OrbitCamera::fitting_points(az, el, &points, aspect, margin, top)
                .unwrap_or_else(|| panic!("case {k}: no camera"));
            let vp = camera.view_proj(aspect);
            let (mut lo, mut hi) = (
                glam::Vec2::splat(f32::INFINITY),
                glam::Vec2::splat(f32::NEG_INFINITY),
            );
            for p in &points {
                let q = vp.project_point3(*p);
                assert!(
                    (0.0..1.0).contains(&q.z),
                    "case {k}: {p} is not in depth range: {q}"
                );
                lo = lo.min(q.truncate());
                hi = hi.max(q.truncate());
            }
            // The window: x from −1 to 1, y from −1 to 1 − 2·top, shrunk by the margin.
            let limit = 1.0 - margin;
            let (middle, half) = (-top, 1.0 - top);
            assert!(
                lo.x >= -limit - 1e-3 && hi.x <= limit + 1e-3,
                "case {k}: x {lo} {hi}"
            );
            assert!(
                lo.y >= middle - limit * half - 1e-3 && hi.y <= middle + limit * half + 1e-3,
                "case {k}: y {lo} {hi}"
            );
            let centre = (lo + hi) * 0.5;
            assert!(centre.x.abs() < 2e-3, "case {k}: centred at x {}", centre.x);
            assert!(
                (centre.y - middle).abs() < 2e-3,
                "case {k}: centred at y {}",
                centre.y
            );
            let reach = ((hi.x - lo.x) * 0.5).max((hi.y - lo.y) * 0.5 / half);
            assert!((reach - limit).abs() < 2e-3, "case {k}: reaches {reach}");
        }
    }

    #[test]
    fn nothing_to_frame_gives_no_camera() {
        assert!(OrbitCamera::fitting_points(0.0, 0.0, &[], 1.0, 0.1, 0.0).is_none());
        let bad = [Vec3::new(f32::NAN, 0.0, 0.0)];
        assert!(OrbitCamera::fitting_points(0.0, 0.0, &bad, 1.0, 0.1, 0.0).is_none());
        let one = [Vec3::ONE];
        assert!(OrbitCamera::fitting_points(0.0, 0.0, &one, 0.0, 0.1, 0.0).is_none());
        // One point: looked at straight, from close by.
        let c = OrbitCamera::fitting_points(0.0, 0.0, &one, 1.0, 0.1, 0.0)
            .unwrap_or_else(|| panic!("one point"));
        let q = c.view_proj(1.0).project_point3(Vec3::ONE);
        assert!(q.x.abs() < 1e-4 && q.y.abs() < 1e-4, "{q}");
    }
}
