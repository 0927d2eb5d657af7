//! Shared fixtures of the unit tests.

use crate::model::geometry::{Geometry, GeometryParams};
use crate::model::layout::Layout;

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

/// The desktop servo platform of `tests/fixtures/rotary.toml` (hobby servos, 25 mm horns,
/// 120 mm rods), without a servo range.
pub(crate) fn servo_geometry() -> Geometry {
    let mut p = GeometryParams::from_layout(0.08, 0.06, 0.117, Layout::seed());
    p.base = crate::model::geometry::PlateJoints::Circle {
        radius: 0.08,
        angles: [350.0, 10.0, 110.0, 130.0, 230.0, 250.0]
            .map(crate::model::angle::Angle::from_degrees),
    };
    p.platform = crate::model::geometry::PlateJoints::Circle {
        radius: 0.06,
        angles: [345.0, 15.0, 105.0, 135.0, 225.0, 255.0]
            .map(crate::model::angle::Angle::from_degrees),
    };
    p.actuator = crate::model::actuator::Actuator::Rotary(
        crate::model::rotary::RotaryActuators::new(
            0.025,
            0.12,
            [255.0, 105.0, 15.0, 225.0, 135.0, 345.0],
            None,
        )
        .unwrap_or_else(|e| panic!("{e}")),
    );
    Geometry::new(p).unwrap_or_else(|e| panic!("{e}"))
}
