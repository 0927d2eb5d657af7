//! Shared fixtures of the unit tests.

use crate::geometry::{Geometry, GeometryParams};
use crate::layout::Layout;

/// The seed's sizes (r_b = 1.0 m, r_p = 0.6 m, h0 = 0.8 m) on the paired layout with 20°
/// between the joints of a pair, no stroke limits: a regular (not architecturally
/// singular) platform.
pub(crate) fn paired_geometry() -> Geometry {
    Geometry::new(GeometryParams::from_layout(
        1.0,
        0.6,
        0.8,
        Layout::paired(20.0),
    ))
    .unwrap_or_else(|e| panic!("{e}"))
}
