//! Values several commands take: triples, positions, angles, poses, inertia, mass, a
//! camera, each within the accepted ranges of `stewart_kinematics::ground::bounds`.

use std::ops::RangeInclusive;

use stewart_kinematics::ground::bounds;

use super::ArgError;

/// Three comma-separated finite numbers, such as `0,0,0.8`.
pub(crate) fn parse_triple(text: &str) -> Result<[f64; 3], ArgError> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let [a, b, c] = parts.as_slice() else {
        return Err(ArgError::not_a(text, "three comma-separated numbers"));
    };
    let number = |s: &str| -> Result<f64, ArgError> {
        let v: f64 = s.parse().map_err(|_| ArgError::not_a(s, "a number"))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(ArgError::NotFinite { text: s.to_owned() })
        }
    };
    Ok([number(a)?, number(b)?, number(c)?])
}

/// Three numbers, each checked against its accepted range (see `stewart_kinematics::ground::bounds`).
fn parse_bounded(
    text: &str,
    ranges: [(&'static str, RangeInclusive<f64>, &str); 3],
) -> Result<[f64; 3], ArgError> {
    let v = parse_triple(text)?;
    for (x, (name, range, unit)) in v.iter().zip(&ranges) {
        bounds::check(*x, range, unit).map_err(|reason| ArgError::Component { name, reason })?;
    }
    Ok(v)
}

/// ROLL,PITCH,YAW in degrees, each within ±3600°.
pub(crate) fn parse_angles(text: &str) -> Result<[f64; 3], ArgError> {
    let a = || bounds::symmetric(bounds::ANGLE_DEG);
    parse_bounded(
        text,
        [("roll", a(), "°"), ("pitch", a(), "°"), ("yaw", a(), "°")],
    )
}

/// X,Y,Z in metres, each within ±1000 m.
pub(crate) fn parse_position(text: &str) -> Result<[f64; 3], ArgError> {
    let m = || bounds::symmetric(bounds::LENGTH_M);
    parse_bounded(text, [("x", m(), "m"), ("y", m(), "m"), ("z", m(), "m")])
}

/// The inertia tensor's entries in kg·m², IXX,IYY,IZZ,IXY,IXZ,IYZ: three principal
/// moments (each from 0 to 1e6; the products then zero), or all six (products within
/// ±1e6).
pub(crate) fn parse_inertia(text: &str) -> Result<[f64; 6], ArgError> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 3 && parts.len() != 6 {
        return Err(ArgError::not_a(
            text,
            "three moments IXX,IYY,IZZ or six entries IXX,IYY,IZZ,IXY,IXZ,IYZ",
        ));
    }
    const NAMES: [&str; 6] = ["Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"];
    let mut values = [0.0; 6];
    for (k, s) in parts.iter().enumerate() {
        let v: f64 = s.parse().map_err(|_| ArgError::not_a(s, "a number"))?;
        let range = if k < 3 {
            0.0..=bounds::INERTIA_KG_M2
        } else {
            bounds::symmetric(bounds::INERTIA_KG_M2)
        };
        bounds::check(v, &range, "kg·m²").map_err(|reason| ArgError::Component {
            name: NAMES[k],
            reason,
        })?;
        values[k] = v;
    }
    Ok(values)
}

/// AZ,EL,DIST: degrees within ±3600°, and a distance above 0 up to 1e4 m.
pub(crate) fn parse_camera(text: &str) -> Result<[f64; 3], ArgError> {
    let a = || bounds::symmetric(bounds::ANGLE_DEG);
    let v = parse_bounded(
        text,
        [
            ("azimuth", a(), "°"),
            ("elevation", a(), "°"),
            ("distance", 0.0..=bounds::CAMERA_DISTANCE_M, "m"),
        ],
    )?;
    if v[2] <= 0.0 {
        return Err(ArgError::out_of_range(
            Some("distance"),
            "more than 0 m",
            v[2],
        ));
    }
    Ok(v)
}

/// A mass in kilograms: more than 0, at most 1e6.
pub(crate) fn parse_mass(text: &str) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number of kilograms"))?;
    if v.is_finite() && v > 0.0 && v <= bounds::MASS_KG {
        Ok(v)
    } else {
        Err(ArgError::out_of_range(
            Some("the mass"),
            "more than 0 and at most 1e6 kg",
            text,
        ))
    }
}

/// A box width in metres: at least a micrometre (finer boxes than that would spend any
/// budget before deciding anything), at most 1000.
pub(crate) fn parse_width(text: &str) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number of metres"))?;
    if (1e-6..=bounds::LENGTH_M).contains(&v) {
        Ok(v)
    } else {
        Err(ArgError::out_of_range(
            Some("the width"),
            "at least 1e-6 and at most 1000 m",
            text,
        ))
    }
}

/// X,Y,Z,ROLL,PITCH,YAW: metres within ±1000 m, degrees within ±3600°.
pub(crate) fn parse_pose(text: &str) -> Result<[f64; 6], ArgError> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 6 {
        return Err(ArgError::not_a(
            text,
            "six comma-separated numbers (x, y, z in metres, roll, pitch, yaw in degrees)",
        ));
    }
    let position = parse_position(&parts[..3].join(","))?;
    let angles = parse_angles(&parts[3..].join(","))?;
    Ok([
        position[0],
        position[1],
        position[2],
        angles[0],
        angles[1],
        angles[2],
    ])
}

/// A number within `range`, `what` naming it and `words` saying the range.
fn within(
    text: &str,
    what: &'static str,
    words: &'static str,
    range: RangeInclusive<f64>,
) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number"))?;
    if range.contains(&v) {
        Ok(v)
    } else {
        Err(ArgError::out_of_range(Some(what), words, text))
    }
}

/// The OMCT's amplitude scale: 0.001 to 10.
pub(crate) fn parse_amplitude_scale(text: &str) -> Result<f64, ArgError> {
    within(text, "the amplitude scale", "from 0.001 to 10", 1e-3..=10.0)
}

/// A test frequency, rad/s: 0.01 to 100.
pub(crate) fn parse_frequency(text: &str) -> Result<f64, ArgError> {
    within(
        text,
        "the frequency",
        "from 0.01 to 100 rad/s",
        0.01..=100.0,
    )
}

/// A transport delay, milliseconds: 0 to 1000.
pub(crate) fn parse_latency_ms(text: &str) -> Result<f64, ArgError> {
    within(text, "the latency", "from 0 to 1000 ms", 0.0..=1000.0)
}
