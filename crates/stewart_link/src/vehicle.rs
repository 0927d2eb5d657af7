//! Vehicle motion coming in as UDP datagrams, for motion cueing: one sample per datagram,
//! in one of three forms, told apart by their bytes.
//!
//! - **Generic text**: `t,ax,ay,az,wx,wy,wz` — seven numbers separated by commas, spaces
//!   or tabs (a trailing line break allowed): the time (s, the sender's clock), the
//!   vehicle's specific force along its x (forward), y (left), z (up) in m/s², gravity
//!   excluded, and its rotation rates about them in °/s — the columns of `stewart cue`.
//! - **Generic binary**: the same seven numbers as little-endian `f32`, 28 bytes.
//! - **X-Plane `DATA`**: `DATA`, one byte, then records of 36 bytes — an `i32` index and
//!   eight `f32` values, little-endian. Two are read: index 4 (*Mach, VVI, g-load*: values
//!   4, 5, 6 are the normal, axial and side g-load) and index 16 (*angular velocities*:
//!   values 0, 1, 2 are Q, P, R in rad/s). X-Plane's body axes are x forward, y right,
//!   z down; ours are x forward, y left, z up. So `ax = g·axial`, `ay = −g·side`,
//!   `az = g·(normal − 1)` (level flight reads 1 g normal: no acceleration), and the rates
//!   are `wx = P`, `wy = −Q`, `wz = −R`, in °/s. A datagram without both records is
//!   refused; it has no time (the receiver's clock is used).
//!
//! Anything else is refused with the reason (and counted by the receiver, never a panic).

use thiserror::Error;

/// Standard gravity, m/s² (X-Plane's g-loads are in g).
const GRAVITY: f64 = 9.80665;

/// One sample of vehicle motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VehicleSample {
    /// The sender's time, seconds (`None`: X-Plane sends none).
    pub t: Option<f64>,
    /// Specific force along the vehicle's x, y, z (forward, left, up), m/s², gravity
    /// excluded.
    pub accel: [f64; 3],
    /// Rotation rates about x, y, z, °/s.
    pub rates_deg_s: [f64; 3],
}

/// Why a datagram was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum VehicleError {
    /// Text that is not seven numbers.
    #[error("a text datagram must be t,ax,ay,az,wx,wy,wz (seven numbers), got {0}")]
    Text(String),
    /// A number that is NaN or infinite, or beyond any vehicle (`|a| > 1e4 m/s²`,
    /// `|ω| > 1e5 °/s`, `|t| > 1e9 s`).
    #[error("{name} = {value} is not a finite number within its bounds")]
    Value {
        /// Which column.
        name: &'static str,
        /// The value.
        value: f64,
    },
    /// An X-Plane `DATA` datagram whose length is not 5 plus a multiple of 36.
    #[error("an X-Plane DATA datagram is 5 bytes then 36-byte records; got {0} bytes")]
    XPlaneLength(usize),
    /// An X-Plane `DATA` datagram without the g-loads (index 4) or the angular velocities
    /// (index 16).
    #[error("an X-Plane DATA datagram needs records 4 (g-loads) and 16 (angular velocities)")]
    XPlaneMissing,
    /// Neither text, nor 28 bytes, nor `DATA`.
    #[error(
        "not a vehicle sample: {0} bytes that are neither text, 28 bytes of f32, nor X-Plane DATA"
    )]
    Unknown(usize),
}

/// The columns, in order.
const NAMES: [&str; 7] = ["t", "ax", "ay", "az", "wx", "wy", "wz"];

/// Decode one datagram.
pub fn decode(bytes: &[u8]) -> Result<VehicleSample, VehicleError> {
    if bytes.starts_with(b"DATA") {
        return xplane(bytes);
    }
    let text = std::str::from_utf8(bytes)
        .ok()
        .filter(|t| t.chars().all(|c| !c.is_control() || c.is_whitespace()))
        .map(generic_text);
    // Printable bytes are text; 28 other bytes (or 28 printable ones that are not seven
    // numbers) are seven f32.
    match text {
        Some(Ok(sample)) => return Ok(sample),
        Some(Err(e)) if bytes.len() != 28 => return Err(e),
        _ => {}
    }
    if bytes.len() == 28 {
        let values: [f64; 7] = std::array::from_fn(|i| {
            let b = [
                bytes[4 * i],
                bytes[4 * i + 1],
                bytes[4 * i + 2],
                bytes[4 * i + 3],
            ];
            f64::from(f32::from_le_bytes(b))
        });
        return checked(values);
    }
    Err(VehicleError::Unknown(bytes.len()))
}

/// The seven numbers of a text datagram.
fn generic_text(text: &str) -> Result<VehicleSample, VehicleError> {
    let shown = || {
        let mut t: String = text.trim().chars().take(60).collect();
        if text.trim().chars().count() > 60 {
            t.push('…');
        }
        format!("`{t}`")
    };
    let fields: Vec<&str> = text
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|f| !f.is_empty())
        .collect();
    if fields.len() != 7 {
        return Err(VehicleError::Text(shown()));
    }
    let mut values = [0.0; 7];
    for (v, f) in values.iter_mut().zip(&fields) {
        *v = f.parse().map_err(|_| VehicleError::Text(shown()))?;
    }
    checked(values)
}

/// The sample of `t,ax,ay,az,wx,wy,wz`, each within its bounds.
fn checked(values: [f64; 7]) -> Result<VehicleSample, VehicleError> {
    let bound = |i: usize| match i {
        0 => 1e9,
        1..=3 => 1e4,
        _ => 1e5,
    };
    for (i, &value) in values.iter().enumerate() {
        if !(value.is_finite() && value.abs() <= bound(i)) {
            return Err(VehicleError::Value {
                name: NAMES[i],
                value,
            });
        }
    }
    Ok(VehicleSample {
        t: Some(values[0]),
        accel: [values[1], values[2], values[3]],
        rates_deg_s: [values[4], values[5], values[6]],
    })
}

/// An X-Plane `DATA` datagram: the g-loads and angular velocities, in our axes.
fn xplane(bytes: &[u8]) -> Result<VehicleSample, VehicleError> {
    const HEADER: usize = 5;
    const RECORD: usize = 36;
    if bytes.len() < HEADER || !(bytes.len() - HEADER).is_multiple_of(RECORD) {
        return Err(VehicleError::XPlaneLength(bytes.len()));
    }
    let mut g_loads = None;
    let mut rates = None;
    for record in bytes[HEADER..].chunks_exact(RECORD) {
        let word = |k: usize| [record[k], record[k + 1], record[k + 2], record[k + 3]];
        let index = i32::from_le_bytes(word(0));
        let value = |j: usize| f64::from(f32::from_le_bytes(word(4 + 4 * j)));
        match index {
            4 => g_loads = Some([value(4), value(5), value(6)]),
            16 => rates = Some([value(0), value(1), value(2)]),
            _ => {}
        }
    }
    let (Some([normal, axial, side]), Some([q, p, r])) = (g_loads, rates) else {
        return Err(VehicleError::XPlaneMissing);
    };
    let sample = checked([
        0.0,
        GRAVITY * axial,
        -GRAVITY * side,
        GRAVITY * (normal - 1.0),
        p.to_degrees(),
        -q.to_degrees(),
        -r.to_degrees(),
    ])?;
    Ok(VehicleSample { t: None, ..sample })
}

/// An X-Plane `DATA` datagram holding records 4 and 16 (for tests and sample files): the
/// g-loads `[normal, axial, side]` and the rates `[Q, P, R]` (rad/s).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_forms_decode_to_the_same_motion() {
        let text = decode(b"1.25,-3.5,0.5,1,10,-20,30\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            text,
            VehicleSample {
                t: Some(1.25),
                accel: [-3.5, 0.5, 1.0],
                rates_deg_s: [10.0, -20.0, 30.0],
            }
        );
        let spaced = decode(b"1.25 -3.5\t0.5 1 10 -20 30").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(spaced, text);
        let binary: Vec<u8> = [1.25f32, -3.5, 0.5, 1.0, 10.0, -20.0, 30.0]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        assert_eq!(decode(&binary), Ok(text));
    }

    #[test]
    fn x_plane_g_loads_and_body_rates_become_our_axes() {
        // Braking at 0.5 g, 0.2 g to the right, 1.3 g pulling up; rolling right, pitching
        // up and yawing right at 0.1, 0.2, 0.3 rad/s.
        let bytes = xplane_datagram([1.3, -0.5, 0.2], [0.2, 0.1, 0.3]);
        assert_eq!(bytes.len(), 5 + 2 * 36);
        let s = decode(&bytes).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.t, None);
        let g = 9.80665;
        let close = |a: f64, b: f64| (a - b).abs() < 1e-5 * b.abs().max(1.0);
        assert!(close(s.accel[0], -0.5 * g));
        assert!(close(s.accel[1], -0.2 * g));
        assert!(close(s.accel[2], 0.3 * g));
        assert!(close(s.rates_deg_s[0], 0.1f64.to_degrees()));
        assert!(close(s.rates_deg_s[1], -0.2f64.to_degrees()));
        assert!(close(s.rates_deg_s[2], -0.3f64.to_degrees()));
    }

    #[test]
    fn malformed_datagrams_are_refused_with_the_reason() {
        assert!(matches!(decode(b"1,2,3"), Err(VehicleError::Text(_))));
        assert!(matches!(
            decode(b"1,2,3,4,5,6,x"),
            Err(VehicleError::Text(_))
        ));
        assert!(matches!(
            decode(b"1,NaN,0,0,0,0,0"),
            Err(VehicleError::Value { name: "ax", .. })
        ));
        assert!(matches!(
            decode(b"1,0,0,0,0,0,1e300"),
            Err(VehicleError::Value { name: "wz", .. })
        ));
        assert_eq!(decode(b"DATA*123"), Err(VehicleError::XPlaneLength(8)));
        let only_rates = &xplane_datagram([1.0, 0.0, 0.0], [0.0; 3])[..5];
        assert_eq!(decode(only_rates), Err(VehicleError::XPlaneMissing));
        assert_eq!(decode(&[0xff, 0x00, 0x13]), Err(VehicleError::Unknown(3)));
        let nan: Vec<u8> = [0.0f32, f32::NAN, 0.0, 0.0, 0.0, 0.0, 0.0]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        assert!(matches!(
            decode(&nan),
            Err(VehicleError::Value { name: "ax", .. })
        ));
        // Arbitrary bytes never panic.
        let mut seed = 12345u64;
        for len in 0..300 {
            let bytes: Vec<u8> = (0..len)
                .map(|_| {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (seed >> 56) as u8
                })
                .collect();
            let _ = decode(&bytes);
            let mut data = b"DATA*".to_vec();
            data.extend(&bytes);
            let _ = decode(&data);
        }
    }
}
