//! X-Plane (11 and 12), from Laminar Research's *Exchanging Data with X-Plane* (the
//! `Instructions` folder of an installation) and `DataRefs.txt`
//! (<https://developer.x-plane.com/datarefs/>). Integers and floats are little-endian.
//!
//! - **`DATA`** (the Data Output screen): `DATA`, one byte, then records of 36 bytes — an
//!   `i32` index and eight `f32` values. Two are read: index 4 (*Mach, VVI, g-load*: values
//!   4, 5, 6 are the normal, axial and side g-load) and index 16 (*angular velocities*:
//!   values 0, 1, 2 are Q, P, R in rad/s).
//! - **`RREF`**: a client subscribes to datarefs with 413-byte requests (`RREF`, a zero
//!   byte, `i32` sends per second (0 stops), `i32` index of the client's choosing, the
//!   dataref's path in 400 zero-padded bytes); X-Plane answers with `RREF`, one byte
//!   (0, `,` or `O` by version: not read), then (`i32` index, `f32` value) pairs. The studio
//!   subscribes to [`RREF_DATAREFS`] with indices 0 to 5: `g_nrml`, `g_axil`, `g_side` (g)
//!   and `P`, `Q`, `R` (°/s).
//!
//! X-Plane's body axes are x forward, y right, z down; ours are x forward, y left, z up.
//! The g-loads' signs are those of the aircraft's force axes in Laminar's `DataRefs.txt`
//! (<https://developer.x-plane.com/datarefs/>; X-Plane 10.41's copy at
//! <http://www.xsquawkbox.net/xpsdk/docs/DataRefs.txt>): `g_axil`, `g_side` and `g_nrml`
//! are "total g-forces on the plane as a multiple" along the plane, sideways and downward
//! (their own lines give no sign), measured along the axes of `faxil_plug_acf` ("ACF Z
//! axis, positive pushes airplane backward"), `fside_plug_acf` ("ACF X axis, positive
//! pushes airplane to the right") and `fnrml_plug_acf` ("ACF Y axis, positive pushes
//! airplane up"). So a take-off roll reads `g_axil < 0`, a push to the right `g_side > 0`,
//! and level flight `g_nrml = 1`. Independent plugins read them the same way: px4xplane
//! (`src/MAVLinkManager.cpp`: `x = -g_axil, y = +g_side` forward-right-down, checked
//! against recorded flights), MatrixPilot's HILSIM (`Tools/HILSIM_XPlane/HILSIM.cpp`) and
//! the Mdx motion platform's telemetry plugin (`-g_axil` surge, `-g_side` sway). In ours:
//! `ax = −g·axial`, `ay = −g·side`, `az = g·(normal − 1)` (level flight: no acceleration),
//! and the rates are `wx = P`, `wy = −Q`, `wz = −R`. Neither form has a
//! time (the receiver's clock is used). A datagram without every value is refused.

use super::fields::{f32_at, i32_at};
use super::{GRAVITY, Reading, VehicleError, VehicleFormat, VehicleSample};

/// The datarefs the studio subscribes to, at indices 0 to 5: the normal, axial and side
/// g-loads, and the roll, pitch and yaw rates in °/s.
pub const RREF_DATAREFS: [&str; 6] = [
    "sim/flightmodel/forces/g_nrml",
    "sim/flightmodel/forces/g_axil",
    "sim/flightmodel/forces/g_side",
    "sim/flightmodel/position/P",
    "sim/flightmodel/position/Q",
    "sim/flightmodel/position/R",
];

/// The length of an `RREF` request.
pub const RREF_REQUEST_BYTES: usize = 413;

/// The port X-Plane listens at.
pub const XPLANE_PORT: u16 = 49000;

/// An `RREF` request: send `dataref` `per_second` times a second (0: stop) under `index`.
/// A path longer than 399 bytes is cut (X-Plane's own are far shorter).
pub fn rref_request(per_second: i32, index: i32, dataref: &str) -> [u8; RREF_REQUEST_BYTES] {
    let mut out = [0u8; RREF_REQUEST_BYTES];
    out[..4].copy_from_slice(b"RREF");
    out[5..9].copy_from_slice(&per_second.to_le_bytes());
    out[9..13].copy_from_slice(&index.to_le_bytes());
    let path = dataref.as_bytes();
    let len = path.len().min(399);
    out[13..13 + len].copy_from_slice(&path[..len]);
    out
}

/// The requests that subscribe to (or, at 0 a second, unsubscribe from) the studio's
/// datarefs.
pub fn rref_subscriptions(per_second: i32) -> Vec<[u8; RREF_REQUEST_BYTES]> {
    (0..)
        .zip(RREF_DATAREFS)
        .map(|(index, dataref)| rref_request(per_second, index, dataref))
        .collect()
}

/// A `DATA` datagram: the g-loads and angular velocities, in our axes.
pub(crate) fn data(bytes: &[u8]) -> Result<Reading, VehicleError> {
    const HEADER: usize = 5;
    const RECORD: usize = 36;
    if bytes.len() < HEADER || !(bytes.len() - HEADER).is_multiple_of(RECORD) {
        return Err(VehicleError::Length {
            format: VehicleFormat::XPlaneData,
            got: bytes.len(),
            expected: "5 plus a multiple of 36",
        });
    }
    let mut g_loads = None;
    let mut rates = None;
    for record in bytes[HEADER..].chunks_exact(RECORD) {
        let value = |j: usize| f32_at(record, 4 + 4 * j);
        match i32_at(record, 0) {
            Some(4) => g_loads = Some([value(4), value(5), value(6)]),
            Some(16) => rates = Some([value(0), value(1), value(2)].map(f64::to_degrees)),
            _ => {}
        }
    }
    let (Some([normal, axial, side]), Some([q, p, r])) = (g_loads, rates) else {
        return Err(VehicleError::XPlaneMissing(
            "DATA",
            "records 4 (g-loads) and 16 (angular velocities)",
        ));
    };
    Ok(ours([normal, axial, side], [p, q, r]))
}

/// An `RREF` reply carrying all six of [`RREF_DATAREFS`].
pub(crate) fn rref(bytes: &[u8]) -> Result<Reading, VehicleError> {
    const HEADER: usize = 5;
    const PAIR: usize = 8;
    if bytes.len() < HEADER || !(bytes.len() - HEADER).is_multiple_of(PAIR) {
        return Err(VehicleError::Length {
            format: VehicleFormat::XPlaneRref,
            got: bytes.len(),
            expected: "5 plus a multiple of 8",
        });
    }
    let mut values = [None; 6];
    for pair in bytes[HEADER..].chunks_exact(PAIR) {
        // Another client's subscriptions on the same port are not ours to read.
        if let Some(slot) =
            (i32_at(pair, 0).and_then(|i| usize::try_from(i).ok())).and_then(|i| values.get_mut(i))
        {
            *slot = Some(f32_at(pair, 4));
        }
    }
    let [
        Some(normal),
        Some(axial),
        Some(side),
        Some(p),
        Some(q),
        Some(r),
    ] = values
    else {
        return Err(VehicleError::XPlaneMissing(
            "RREF",
            "indices 0 to 5 (g_nrml, g_axil, g_side, P, Q, R)",
        ));
    };
    Ok(ours([normal, axial, side], [p, q, r]))
}

/// X-Plane's g-loads `[normal, axial, side]` (g) and rates `[P, Q, R]` (°/s) in our axes.
fn ours([normal, axial, side]: [f64; 3], [p, q, r]: [f64; 3]) -> Reading {
    Reading::Sample(VehicleSample {
        t: None,
        accel: [-GRAVITY * axial, -GRAVITY * side, GRAVITY * (normal - 1.0)],
        rates_deg_s: [p, -q, -r],
    })
}

/// A `DATA` datagram holding records 4 and 16 (for tests and sample files): the g-loads
/// `[normal, axial, side]` and the rates `[Q, P, R]` (rad/s).
pub fn xplane_datagram(g_loads: [f32; 3], rates: [f32; 3]) -> Vec<u8> {
    let mut out = b"DATA*".to_vec();
    let mut record = |index: i32, values: [f32; 8]| {
        out.extend(index.to_le_bytes());
        for v in values {
            out.extend(v.to_le_bytes());
        }
    };
    let [n, a, s] = g_loads;
    record(4, [0.5, -999.0, 0.0, -999.0, n, a, s, -999.0]);
    let [q, p, r] = rates;
    record(16, [q, p, r, -999.0, -999.0, -999.0, -999.0, -999.0]);
    out
}
