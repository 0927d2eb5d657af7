//! Plane slices through the constant-orientation workspace for figures: on a grid over a
//! horizontal (x, y at a height) or vertical (x, z at a y) plane, whether each point is
//! reachable within the stroke and limits, and how well conditioned (or how stiff) the
//! platform is there.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::analysis::dynamics;
use crate::analysis::workspace;
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// Which plane a slice lies in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Plane {
    /// x (across) and y (up the page) at a height z.
    Horizontal,
    /// x (across) and z (up the page) at a lateral offset y.
    Vertical,
}

/// A slice: a grid of cells, row by row from the bottom, each the normalised condition
/// number at its centre (infinite when singular) or `None` when out of reach.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Slice {
    /// The plane.
    pub plane: Plane,
    /// The fixed coordinate: z for a horizontal slice, y for a vertical one, metres.
    pub at: f64,
    /// The ranges across and up, metres (cell edges).
    pub range: [[f64; 2]; 2],
    /// Cells across and up.
    pub cells: [usize; 2],
    /// The cells, `cells[0]` per row, bottom row first.
    pub values: Vec<Option<f64>>,
}

impl Slice {
    /// The centre of cell (`i` across, `j` up), metres.
    pub fn centre(&self, i: usize, j: usize) -> [f64; 2] {
        std::array::from_fn(|a| {
            let k = if a == 0 { i } else { j };
            let [lo, hi] = self.range[a];
            lo + (k as f64 + 0.5) * (hi - lo) / self.cells[a] as f64
        })
    }

    /// The value of cell (`i`, `j`).
    pub fn get(&self, i: usize, j: usize) -> Option<f64> {
        self.values[j * self.cells[0] + i]
    }
}

/// Where a slice lies: the orientation, plane, fixed coordinate, ranges and cells.
struct SlicePlace {
    orientation: [Angle; 3],
    plane: Plane,
    at: f64,
    range: [[f64; 2]; 2],
    cells: [usize; 2],
}

/// The largest grid a slice takes, cells a side.
pub const MAX_SLICE_CELLS: usize = 1024;

/// The slice through the workspace at `orientation` in `plane` at `at` over `range`,
/// `cells` a side (each 2 ..= [`MAX_SLICE_CELLS`]).
pub fn workspace_slice(
    geometry: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    plane: Plane,
    at: f64,
    range: [[f64; 2]; 2],
    cells: [usize; 2],
) -> Slice {
    let place = SlicePlace {
        orientation,
        plane,
        at,
        range,
        cells,
    };
    slice_of(geometry, limits, &place, |pose| {
        let c = geometry.actuated_conditioning(pose)?;
        Some(c.condition_number.unwrap_or(f64::INFINITY))
    })
}

/// The same grid as [`workspace_slice`], each reachable cell holding the
/// lowest stiffness of the platform there for actuators of stiffness `k`: the smallest
/// eigenvalue of `K` with its rotations measured at the characteristic length (see
/// [`crate::analysis::dynamics::lowest_stiffness`]), N/m.
#[allow(clippy::too_many_arguments)]
pub fn stiffness_slice(
    geometry: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    plane: Plane,
    at: f64,
    range: [[f64; 2]; 2],
    cells: [usize; 2],
    k: f64,
) -> Slice {
    let place = SlicePlace {
        orientation,
        plane,
        at,
        range,
        cells,
    };
    slice_of(geometry, limits, &place, |pose| {
        dynamics::lowest_stiffness(geometry, pose, k)
    })
}

/// A slice at `place` whose reachable cells hold `value` of their pose (`None`: out
/// of reach there too).
fn slice_of(
    geometry: &Geometry,
    limits: &Limits,
    place: &SlicePlace,
    value: impl Fn(&Pose) -> Option<f64> + Sync,
) -> Slice {
    let SlicePlace {
        orientation,
        plane,
        at,
        range,
        cells,
    } = *place;
    let cells = cells.map(|c| c.clamp(2, MAX_SLICE_CELLS));
    let mut slice = Slice {
        plane,
        at,
        range,
        cells,
        values: Vec::new(),
    };
    let [roll, pitch, yaw] = orientation;
    slice.values = (0..cells[0] * cells[1])
        .into_par_iter()
        .map(|k| {
            let [a, b] = slice.centre(k % cells[0], k / cells[0]);
            let position = match plane {
                Plane::Horizontal => [a, b, at],
                Plane::Vertical => [a, at, b],
            };
            let pose = Pose::new(position.into(), roll, pitch, yaw);
            if !workspace::pose_within_limits(geometry, limits, &pose) {
                return None;
            }
            value(&pose)
        })
        .collect();
    slice
}
