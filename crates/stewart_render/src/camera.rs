//! An orbit camera: azimuth and elevation around a target, at a distance. Pure glam; no
//! window or input types (the viewer turns mouse motion into these numbers).

use glam::{Mat4, Vec3};

/// Vertical field of view, degrees.
pub(crate) const FOV_Y_DEG: f32 = 30.0;

/// A camera orbiting `target`. Angles follow MATLAB's `view(az, el)`: azimuth measured
/// counter-clockwise (seen from above) from the −y axis, elevation above the xy plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// Azimuth, degrees.
    pub azimuth_deg: f32,
    /// Elevation, degrees (clamped to ±89.5).
    pub elevation_deg: f32,
    /// Distance from the target, metres.
    pub distance: f32,
    /// The point looked at, metres.
    pub target: Vec3,
}

impl OrbitCamera {
    /// The seed's view (azimuth 135°, elevation 20°) framing a sphere of `radius` around `centre`.
    pub fn seed_view(centre: Vec3, radius: f32) -> Self {
        Self::framing(135.0, 20.0, centre, radius)
    }

    /// The seed's view framing a platform at home: the whole base and platform with a
    /// margin, looking at a point a little under half the home height above the base
    /// joints' centroid. Exports, the viewer's "Reset view" and the render tests all use
    /// this one framing.
    pub fn seed_view_of(geometry: &stewart_kinematics::Geometry) -> Self {
        let h = geometry.home_height() as f32;
        let base = geometry.base_joints();
        let centre = base.iter().sum::<nalgebra::Vector3<f64>>() / 6.0;
        let top = geometry.inverse(&geometry.home_pose()).platform_joints;
        // The farthest joint from the centroid, horizontally (the larger plate's radius
        // for joints on circles).
        let reach = base
            .iter()
            .chain(top.iter())
            .map(|j| (j - centre).xy().norm())
            .fold(0.0, f64::max);
        Self::seed_view(
            Vec3::new(centre.x as f32, centre.y as f32, 0.45 * h),
            reach as f32 * 1.15,
        )
    }

    /// A camera at the given angles whose view holds a sphere of `radius` around `centre`
    /// (with a 10 % margin, for any aspect ratio of at least 1).
    pub fn framing(azimuth_deg: f32, elevation_deg: f32, centre: Vec3, radius: f32) -> Self {
        let half = (FOV_Y_DEG * 0.5).to_radians();
        Self {
            azimuth_deg,
            elevation_deg,
            distance: 1.1 * radius / half.sin(),
            target: centre,
        }
    }

    /// Unit vector from the target towards the eye.
    pub fn direction(&self) -> Vec3 {
        let az = self.azimuth_deg.to_radians();
        let el = self.elevation_deg.clamp(-89.5, 89.5).to_radians();
        Vec3::new(el.cos() * az.sin(), -el.cos() * az.cos(), el.sin())
    }

    /// The eye position, metres.
    pub fn eye(&self) -> Vec3 {
        self.target + self.direction() * self.distance
    }

    /// View-projection matrix (right-handed, depth 0..1 as WebGPU wants) for `aspect` = width / height.
    pub fn view_proj(&self, aspect: f32) -> Mat4 {
        let view = glam::camera::rh::view::look_at_mat4(self.eye(), self.target, Vec3::Z);
        let near = (self.distance * 0.01).max(1e-3);
        let far = self.distance * 10.0;
        let proj = glam::camera::rh::proj::directx::perspective(
            FOV_Y_DEG.to_radians(),
            aspect.max(1e-3),
            near,
            far,
        );
        proj * view
    }

    /// Rotate by mouse-like deltas, degrees.
    pub fn orbit(&mut self, d_azimuth: f32, d_elevation: f32) {
        self.azimuth_deg = (self.azimuth_deg + d_azimuth).rem_euclid(360.0);
        self.elevation_deg = (self.elevation_deg + d_elevation).clamp(-89.5, 89.5);
    }

    /// Move closer (`factor` < 1) or away (> 1).
    pub fn zoom(&mut self, factor: f32) {
        self.distance = (self.distance * factor).clamp(1e-3, 1e4);
    }

    /// The camera for a view `aspect` = width / height: framings are made for views at
    /// least as wide as high, so a narrower view backs off until the same width fits.
    pub fn fitted_to(&self, aspect: f32) -> Self {
        let mut c = *self;
        c.distance /= aspect.clamp(1e-3, 1.0);
        c
    }

    /// Zoom by `factor` toward the point under the cursor: `ndc` is the cursor in
    /// normalised device coordinates (−1..1, y up) of a view `aspect` = width / height
    /// wide. The point of the target's view plane under the cursor stays under it.
    pub fn zoom_toward(&mut self, factor: f32, ndc: glam::Vec2, aspect: f32) {
        let before = self.distance;
        self.zoom(factor);
        let applied = self.distance / before;
        let half_h = before * (FOV_Y_DEG.to_radians() * 0.5).tan();
        let half_w = half_h * aspect;
        self.pan(
            ndc.x * half_w * (1.0 - applied),
            ndc.y * half_h * (1.0 - applied),
        );
    }

    /// Shift the target in the view plane by `right` and `up`, in metres.
    pub fn pan(&mut self, right: f32, up: f32) {
        let forward = -self.direction();
        let right_axis = forward.cross(Vec3::Z).normalize_or_zero();
        let up_axis = right_axis.cross(forward);
        self.target += right_axis * right + up_axis * up;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zooming_keeps_the_point_under_the_cursor() {
        let mut c = OrbitCamera::seed_view(Vec3::new(0.0, 0.0, 0.4), 1.0);
        let aspect = 16.0 / 9.0;
        let cursor = glam::Vec2::new(0.5, -0.3);
        // The point of the target's view plane under the cursor, found by unprojecting.
        let inverse = c.view_proj(aspect).inverse();
        let near = inverse.project_point3(cursor.extend(0.0));
        let far = inverse.project_point3(cursor.extend(1.0));
        let normal = c.direction();
        let s = (c.target - near).dot(normal) / (far - near).dot(normal);
        let point = near + (far - near) * s;
        for factor in [0.5, 0.9, 1.3] {
            let mut z = c;
            z.zoom_toward(factor, cursor, aspect);
            let seen = z.view_proj(aspect).project_point3(point);
            assert!(
                (seen.truncate() - cursor).length() < 1e-4,
                "{factor}: {seen}"
            );
            assert!((z.distance - c.distance * factor).abs() < 1e-5);
        }
        // At the centre of the view zooming does not move the target.
        let target = c.target;
        c.zoom_toward(0.5, glam::Vec2::ZERO, aspect);
        assert!((c.target - target).length() < 1e-6);
    }

    #[test]
    fn azimuth_follows_matlab() {
        // view(0, 0) looks from −y; view(90, 0) from +x; view(135, 20) from +x+y, above.
        let at = |az: f32, el: f32| {
            OrbitCamera {
                azimuth_deg: az,
                elevation_deg: el,
                distance: 1.0,
                target: Vec3::ZERO,
            }
            .direction()
        };
        assert!((at(0.0, 0.0) - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-6);
        assert!((at(90.0, 0.0) - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-6);
        let seed = at(135.0, 20.0);
        assert!(seed.x > 0.0 && seed.y > 0.0 && (seed.z - 20f32.to_radians().sin()).abs() < 1e-6);
    }

    #[test]
    fn the_target_projects_to_the_centre_and_the_framed_sphere_fits() {
        let cam = OrbitCamera::seed_view(Vec3::new(0.0, 0.0, 0.4), 1.2);
        let vp = cam.view_proj(16.0 / 9.0);
        let c = vp.project_point3(cam.target);
        assert!(c.x.abs() < 1e-5 && c.y.abs() < 1e-5 && (0.0..1.0).contains(&c.z));
        // Points on the sphere stay inside the view (|x|, |y| < 1).
        for p in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z] {
            let q = vp.project_point3(cam.target + p * 1.2);
            assert!(q.x.abs() < 1.0 && q.y.abs() < 1.0, "{q}");
        }
    }

    #[test]
    fn orbit_pan_zoom() {
        let mut cam = OrbitCamera::seed_view(Vec3::ZERO, 1.0);
        let d = cam.distance;
        cam.zoom(0.5);
        assert!((cam.distance - 0.5 * d).abs() < 1e-6);
        cam.orbit(300.0, 100.0);
        assert!((cam.azimuth_deg - 75.0).abs() < 1e-4 && cam.elevation_deg == 89.5);
        let mut cam = OrbitCamera::seed_view(Vec3::ZERO, 1.0);
        cam.pan(1.0, 0.0);
        // Panning right moves the target perpendicular to the view direction, horizontally.
        assert!(cam.target.z.abs() < 1e-6 && cam.target.dot(cam.direction()).abs() < 1e-6);
    }
}
