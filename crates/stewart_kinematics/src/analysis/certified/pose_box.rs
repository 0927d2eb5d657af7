//! A box of poses — an interval for each of x, y, z (metres) and roll, pitch, yaw
//! (radians) — and what interval arithmetic says of the rig over it: the platform joints,
//! the legs and the inverse Jacobian, each holding its value at every pose of the box.

use crate::ground::interval::Interval;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// An interval 3-vector.
pub type IVec3 = [Interval; 3];

/// Poses whose coordinates lie in six intervals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseBox {
    /// x, y, z, metres; then roll, pitch, yaw, radians.
    pub coordinates: [Interval; 6],
}

impl PoseBox {
    /// The single pose `pose`.
    pub fn at(pose: &Pose) -> Self {
        Self {
            coordinates: pose.to_coordinates().map(Interval::point),
        }
    }

    /// The same box with coordinate `k` (0…5) replaced by `range`.
    pub fn with(mut self, k: usize, range: Interval) -> Self {
        self.coordinates[k] = range;
        self
    }

    /// The widest coordinate, its width measured in metres (angles by `length`, the
    /// distance a rotation moves the joints per radian).
    pub fn widest(&self, length: f64) -> usize {
        let mut best = 0;
        let mut width = -1.0;
        for (k, c) in self.coordinates.iter().enumerate() {
            let w = if k < 3 { c.width() } else { c.width() * length };
            if w > width {
                width = w;
                best = k;
            }
        }
        best
    }

    /// The two halves across coordinate `k`.
    pub fn split(&self, k: usize) -> [Self; 2] {
        let [a, b] = self.coordinates[k].split();
        [self.with(k, a), self.with(k, b)]
    }

    /// The rotation `Rz(yaw)·Ry(pitch)·Rx(roll)` over the box, row by row.
    pub fn rotation(&self) -> [IVec3; 3] {
        let [.., roll, pitch, yaw] = self.coordinates;
        let (sr, cr) = (roll.sin(), roll.cos());
        let (sp, cp) = (pitch.sin(), pitch.cos());
        let (sy, cy) = (yaw.sin(), yaw.cos());
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    }
}

/// `m · v`.
fn times(m: &[IVec3; 3], v: &IVec3) -> IVec3 {
    std::array::from_fn(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
}

/// `a − b` for point vectors, enclosed (the difference of two floats may not be one).
fn difference(a: &nalgebra::Vector3<f64>, b: &nalgebra::Vector3<f64>) -> IVec3 {
    std::array::from_fn(|k| Interval::point(a[k]) - Interval::point(b[k]))
}

/// `a × b`.
pub fn cross(a: &IVec3, b: &IVec3) -> IVec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The rig over a box of poses: for each leg the vector from the pivot point to the
/// platform joint and the leg from base joint to platform joint.
#[derive(Clone, Copy, Debug)]
pub struct BoxLegs {
    /// `R (a_i − c)`: pivot point to platform joint `i`.
    pub arms: [IVec3; 6],
    /// `q_i − b_i`: base joint to platform joint `i`.
    pub legs: [IVec3; 6],
}

impl BoxLegs {
    /// The legs of `geometry` over `pose_box`.
    pub fn of(geometry: &Geometry, pose_box: &PoseBox) -> Self {
        let r = pose_box.rotation();
        let c = geometry.pivot();
        let position: IVec3 = std::array::from_fn(|k| pose_box.coordinates[k]);
        let base = geometry.base_joints();
        let mut arms = [[Interval::point(0.0); 3]; 6];
        let mut legs = arms;
        for (i, a) in geometry.platform_joints().iter().enumerate() {
            let arm = times(&r, &difference(a, &c));
            arms[i] = arm;
            // q_i − b_i = position + R (a_i − c) + (c − b_i)
            let offset = difference(&c, &base[i]);
            legs[i] = std::array::from_fn(|k| position[k] + arm[k] + offset[k]);
        }
        Self { arms, legs }
    }

    /// Each leg's length.
    pub fn lengths(&self) -> [Interval; 6] {
        self.legs.map(|l| {
            (l[0].sqr() + l[1].sqr() + l[2].sqr())
                .sqrt()
                .unwrap_or(Interval::ENTIRE)
        })
    }

    /// The inverse Jacobian's rows scaled by each leg's length, `[l_iᵀ, (r_i × l_i)ᵀ]`
    /// (a row scaled by a positive number keeps the matrix regular or singular), with the
    /// rotation columns divided by `length` (the characteristic length) so that the six
    /// columns share a unit.
    pub fn jacobian(&self, length: f64) -> [[Interval; 6]; 6] {
        std::array::from_fn(|i| {
            let l = &self.legs[i];
            let m = cross(&self.arms[i], l);
            let inv = 1.0 / length;
            [l[0], l[1], l[2], m[0] * inv, m[1] * inv, m[2] * inv]
        })
    }
}
