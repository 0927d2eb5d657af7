//! The studio's own forms: the seven numbers `t,ax,ay,az,wx,wy,wz` — the time (s, the
//! sender's clock), the specific force along x (forward), y (left), z (up) in m/s²,
//! gravity excluded, and the rotation rates about them in °/s: the columns of
//! `stewart cue` — as text (separated by commas, spaces or tabs; a trailing line break
//! allowed) or as seven little-endian `f32` (28 bytes).

use super::fields::f32_at;
use super::{Reading, VehicleError, VehicleSample};

/// The length of the binary form.
pub const BINARY_BYTES: usize = 28;

/// `bytes` as text, when they are printable (controls only as white space).
pub(crate) fn as_text(bytes: &[u8]) -> Option<&str> {
    std::str::from_utf8(bytes)
        .ok()
        .filter(|t| t.chars().all(|c| !c.is_control() || c.is_whitespace()))
}

/// The seven numbers of a text datagram.
pub(crate) fn text(text: &str) -> Result<VehicleSample, VehicleError> {
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
    Ok(sample(values))
}

/// The seven `f32` of a binary datagram.
pub(crate) fn binary(bytes: &[u8]) -> Reading {
    Reading::Sample(sample(std::array::from_fn(|i| f32_at(bytes, 4 * i))))
}

fn sample(v: [f64; 7]) -> VehicleSample {
    VehicleSample {
        t: Some(v[0]),
        accel: [v[1], v[2], v[3]],
        rates_deg_s: [v[4], v[5], v[6]],
    }
}
