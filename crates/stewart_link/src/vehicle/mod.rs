//! Vehicle motion coming in as UDP datagrams, for motion cueing: the studio's own forms
//! and the telemetry that games send, told apart per datagram by magic and size, so one
//! port takes any of them.
//!
//! Every form becomes a [`VehicleSample`] in the studio's vehicle axes — x forward, y left,
//! z up (right-handed) — with the specific force in m/s², gravity excluded, and the
//! rotation rates in °/s: the columns `stewart cue` reads. Each format's module says how
//! its axes, units and clock are turned into ours, and from which published layout:
//!
//! | format | module | how it is recognised |
//! |---|---|---|
//! | generic text `t,ax,ay,az,wx,wy,wz` | [`generic`] | seven numbers, printable |
//! | generic binary, seven `f32` | [`generic`] | 28 bytes |
//! | X-Plane `DATA` | [`xplane`] | `DATA` |
//! | X-Plane `RREF` replies | [`xplane`] | `RREF` |
//! | Forza Data Out (Sled, Dash, Horizon, Motorsport 2023) | [`forza`] | 232, 311, 324 or 331 bytes |
//! | EA SPORTS F1 24 and F1 25 (`Motion` and `Motion Ex`) | [`f1`] | a header whose `packetFormat` is a year |
//! | BeamNG.drive MotionSim | [`beamng`] | `BNG1`, 88 bytes |
//! | OutGauge (BeamNG, Live for Speed): a dashboard, no motion | [`beamng`] | 92 or 96 bytes |
//! | Live for Speed OutSim (classic, and `LFST` packs) | [`outsim`] | 64 or 68 bytes; `LFST` |
//!
//! A [`VehicleDecoder`] keeps what spans datagrams: F1's two packets of one frame are paired,
//! and the games' millisecond clocks are unwrapped. This module owns all of vehicle input:
//! decoding, the [`timeline`] that times samples, the [`intake`] loop with its tally by
//! format, packet [`capture`]s (pcap, pcapng) and their [`replay`]. Anything that cannot be read is
//! refused with the reason (the receiver counts it), never a panic.

pub mod beamng;
pub mod capture;
pub mod f1;
pub mod forza;
pub mod generic;
pub mod intake;
pub mod outsim;
pub mod replay;
pub mod timeline;
pub mod xplane;

mod fields;

use thiserror::Error;

/// The largest |time| of a sample, seconds: the bound of every table's times
/// (`stewart_kinematics::ground::bounds::TIME_S`), so that every sample written reads back.
pub const MAX_TIME_S: f64 = 1e6;

/// The largest |specific force| of a sample along any axis, m/s² (beyond any vehicle).
pub const MAX_ACCEL_M_S2: f64 = 1e4;

/// The largest |rotation rate| of a sample about any axis, °/s (beyond any vehicle).
pub const MAX_RATE_DEG_S: f64 = 1e5;

/// The one range rule of vehicle motion, wherever it comes from (a game's datagram, a
/// capture, a CSV table, Python): each column of `t, ax, ay, az, wx, wy, wz` with its
/// largest magnitude and unit.
pub const COLUMN_BOUNDS: [(&str, f64, &str); 7] = [
    ("t", MAX_TIME_S, "s"),
    ("ax", MAX_ACCEL_M_S2, "m/s²"),
    ("ay", MAX_ACCEL_M_S2, "m/s²"),
    ("az", MAX_ACCEL_M_S2, "m/s²"),
    ("wx", MAX_RATE_DEG_S, "°/s"),
    ("wy", MAX_RATE_DEG_S, "°/s"),
    ("wz", MAX_RATE_DEG_S, "°/s"),
];

/// Standard gravity, m/s² (games that give g-loads give them in g).
pub const GRAVITY: f64 = 9.80665;

/// One sample of vehicle motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VehicleSample {
    /// The sender's time, seconds (`None`: the format has no clock; the arrival time is
    /// used).
    pub t: Option<f64>,
    /// Specific force along the vehicle's x, y, z (forward, left, up), m/s², gravity
    /// excluded.
    pub accel: [f64; 3],
    /// Rotation rates about x, y, z, °/s.
    pub rates_deg_s: [f64; 3],
}

/// The formats a datagram can be in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VehicleFormat {
    /// `t,ax,ay,az,wx,wy,wz` as text.
    Text,
    /// The same seven numbers as little-endian `f32`.
    Binary,
    /// X-Plane's `DATA` (the Data Output screen).
    XPlaneData,
    /// X-Plane's `RREF` replies to a dataref subscription.
    XPlaneRref,
    /// Forza Data Out, the 232-byte *Sled* form.
    ForzaSled,
    /// Forza Motorsport 7's 311-byte *Dash* form.
    ForzaDash,
    /// Forza Horizon 4 and 5 (324 bytes).
    ForzaHorizon,
    /// Forza Motorsport (2023), 331 bytes.
    ForzaMotorsport2023,
    /// EA SPORTS F1 24's and F1 25's UDP telemetry.
    F1,
    /// BeamNG.drive's MotionSim (`BNG1`).
    BeamNg,
    /// OutGauge (BeamNG.drive, Live for Speed): dashboard data, no motion.
    OutGauge,
    /// Live for Speed's classic OutSim packet.
    OutSim,
    /// Live for Speed's OutSim pack with the `LFST` header (`OutSim Opts`).
    OutSimPack,
}

impl VehicleFormat {
    /// Every format.
    pub const ALL: [VehicleFormat; 13] = [
        VehicleFormat::Text,
        VehicleFormat::Binary,
        VehicleFormat::XPlaneData,
        VehicleFormat::XPlaneRref,
        VehicleFormat::ForzaSled,
        VehicleFormat::ForzaDash,
        VehicleFormat::ForzaHorizon,
        VehicleFormat::ForzaMotorsport2023,
        VehicleFormat::F1,
        VehicleFormat::BeamNg,
        VehicleFormat::OutGauge,
        VehicleFormat::OutSim,
        VehicleFormat::OutSimPack,
    ];

    /// The format's place in [`VehicleFormat::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The format's name, as people know it (the same in every language).
    pub fn name(self) -> &'static str {
        match self {
            VehicleFormat::Text => "generic text",
            VehicleFormat::Binary => "generic f32",
            VehicleFormat::XPlaneData => "X-Plane DATA",
            VehicleFormat::XPlaneRref => "X-Plane RREF",
            VehicleFormat::ForzaSled => "Forza Sled",
            VehicleFormat::ForzaDash => "Forza Motorsport 7 Dash",
            VehicleFormat::ForzaHorizon => "Forza Horizon",
            VehicleFormat::ForzaMotorsport2023 => "Forza Motorsport (2023)",
            VehicleFormat::F1 => "F1 24/25",
            VehicleFormat::BeamNg => "BeamNG MotionSim",
            VehicleFormat::OutGauge => "OutGauge",
            VehicleFormat::OutSim => "LFS OutSim",
            VehicleFormat::OutSimPack => "LFS OutSim (LFST)",
        }
    }
}

/// What a datagram that could be read brings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reading {
    /// A sample of the vehicle's motion.
    Sample(VehicleSample),
    /// The game is in its menus or paused (Forza's `IsRaceOn = 0`): the cue fades to
    /// neutral as it does when the input stalls.
    Idle,
    /// A datagram of the game's that carries no motion for the studio (F1's other packets,
    /// an OutGauge dashboard), or the first half of a pair (F1's `Motion` before its
    /// `Motion Ex`): not an error, nothing to use.
    Ignored,
}

/// One datagram, decoded: its format (when it was recognised) and what it brings, or why
/// it was refused.
#[derive(Clone, Debug, PartialEq)]
pub struct Decoded {
    /// The format recognised (`None`: none was).
    pub format: Option<VehicleFormat>,
    /// What the datagram brings.
    pub reading: Result<Reading, VehicleError>,
}

/// Why a datagram was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum VehicleError {
    /// Text that is not seven numbers.
    #[error("a text datagram must be t,ax,ay,az,wx,wy,wz (seven numbers), got {0}")]
    Text(String),
    /// A number that is NaN or infinite, or beyond any vehicle (`|a| > 1e4 m/s²`,
    /// `|ω| > 1e5 °/s`), or a time beyond the studio's tables (`|t| > 1e6 s`, about 11.6
    /// days: what `stewart cue` reads back; the games' millisecond clocks count from their
    /// first reading).
    #[error("{name} = {value} is not a finite number within its bounds")]
    Value {
        /// Which column (ours) or field (the format's).
        name: &'static str,
        /// The value.
        value: f64,
    },
    /// A datagram whose length its format does not allow.
    #[error("{format:?}: {got} bytes, not {expected}")]
    Length {
        /// The format its magic or header names.
        format: VehicleFormat,
        /// The length received.
        got: usize,
        /// The lengths allowed, in words.
        expected: &'static str,
    },
    /// An X-Plane datagram without the values a sample needs.
    #[error("an X-Plane {0} datagram needs {1}")]
    XPlaneMissing(&'static str, &'static str),
    /// An F1 packet of another year's format (the games can send the two years before
    /// theirs: choose the game's own year in its telemetry settings).
    #[error(
        "an F1 packet of the {0} format: set the game's UDP Format (Settings → Telemetry \
         Settings) to 2025 in F1 25 or 2024 in F1 24"
    )]
    F1Format(u16),
    /// An F1 packet whose player car index is not one of its 22 cars.
    #[error("an F1 packet names car {0} as the player's, of 22")]
    F1Car(u8),
    /// Neither text nor any format recognised.
    #[error("not a vehicle sample: {0} bytes in none of the formats read")]
    Unknown(usize),
}

/// Reads datagrams of any format, keeping what spans them: F1's `Motion` and `Motion Ex`
/// of one frame paired, and the games' millisecond clocks unwrapped.
#[derive(Debug, Default)]
pub struct VehicleDecoder {
    f1: f1::Pairing,
    forza_clock: WrappingClock,
    outsim_clock: WrappingClock,
}

impl VehicleDecoder {
    /// A decoder that has seen nothing.
    pub fn new() -> Self {
        Self::default()
    }

    /// Decode one datagram.
    pub fn decode(&mut self, bytes: &[u8]) -> Decoded {
        let (format, reading) = self.read(bytes);
        Decoded {
            format,
            reading: reading.and_then(checked),
        }
    }

    fn read(&mut self, bytes: &[u8]) -> (Option<VehicleFormat>, Result<Reading, VehicleError>) {
        let n = bytes.len();
        let magic = bytes.get(..4).unwrap_or(&[]);
        match magic {
            b"DATA" => return (Some(VehicleFormat::XPlaneData), xplane::data(bytes)),
            b"RREF" => return (Some(VehicleFormat::XPlaneRref), xplane::rref(bytes)),
            b"BNG1" => return (Some(VehicleFormat::BeamNg), beamng::motion_sim(bytes)),
            b"LFST" => {
                let reading = outsim::pack(bytes, &mut self.outsim_clock);
                return (Some(VehicleFormat::OutSimPack), reading);
            }
            _ => {}
        }
        // Printable bytes are text first (a text line may have any length).
        let text = generic::as_text(bytes).map(generic::text);
        match text {
            Some(Ok(sample)) => return (Some(VehicleFormat::Text), Ok(Reading::Sample(sample))),
            // Printable bytes that are not seven numbers are a text error — but 28 of them
            // may be seven f32 that happen to print.
            Some(Err(e)) if n != generic::BINARY_BYTES => return (None, Err(e)),
            _ => {}
        }
        let format = match n {
            generic::BINARY_BYTES => Some(VehicleFormat::Binary),
            forza::SLED_BYTES => Some(VehicleFormat::ForzaSled),
            forza::DASH_BYTES => Some(VehicleFormat::ForzaDash),
            forza::HORIZON_BYTES => Some(VehicleFormat::ForzaHorizon),
            forza::MOTORSPORT_2023_BYTES => Some(VehicleFormat::ForzaMotorsport2023),
            outsim::CLASSIC_BYTES | outsim::CLASSIC_WITH_ID_BYTES => Some(VehicleFormat::OutSim),
            beamng::OUTGAUGE_BYTES | beamng::OUTGAUGE_WITH_ID_BYTES => {
                Some(VehicleFormat::OutGauge)
            }
            _ if f1::is_f1(bytes) => Some(VehicleFormat::F1),
            _ => None,
        };
        let reading = match format {
            Some(VehicleFormat::Binary) => Ok(generic::binary(bytes)),
            Some(
                VehicleFormat::ForzaSled
                | VehicleFormat::ForzaDash
                | VehicleFormat::ForzaHorizon
                | VehicleFormat::ForzaMotorsport2023,
            ) => Ok(forza::sled(bytes, &mut self.forza_clock)),
            Some(VehicleFormat::OutSim) => Ok(outsim::classic(bytes, &mut self.outsim_clock)),
            Some(VehicleFormat::OutGauge) => Ok(Reading::Ignored),
            Some(VehicleFormat::F1) => f1::packet(bytes, &mut self.f1),
            _ => match text {
                Some(Err(e)) => Err(e),
                _ => Err(VehicleError::Unknown(n)),
            },
        };
        (format, reading)
    }
}

/// Decode one datagram alone (no F1 pairing, no clock unwrapping across datagrams): the
/// sample, or why there is none.
pub fn decode(bytes: &[u8]) -> Result<VehicleSample, VehicleError> {
    match VehicleDecoder::new().decode(bytes).reading? {
        Reading::Sample(sample) => Ok(sample),
        Reading::Idle | Reading::Ignored => Err(VehicleError::Unknown(bytes.len())),
    }
}

/// A sample whose every number is finite and within the bounds of a vehicle (a zero
/// that an axis turned negative reads as zero).
fn checked(reading: Reading) -> Result<Reading, VehicleError> {
    let Reading::Sample(mut sample) = reading else {
        return Ok(reading);
    };
    for v in sample.accel.iter_mut().chain(&mut sample.rates_deg_s) {
        *v += 0.0;
    }
    let [ax, ay, az] = sample.accel;
    let [wx, wy, wz] = sample.rates_deg_s;
    let values = [sample.t.unwrap_or(0.0), ax, ay, az, wx, wy, wz];
    for (&(name, bound, _), value) in COLUMN_BOUNDS.iter().zip(values) {
        if !(value.is_finite() && value.abs() <= bound) {
            return Err(VehicleError::Value { name, value });
        }
    }
    Ok(Reading::Sample(sample))
}

/// A `u32` millisecond clock that wraps to 0 (after 49.7 days), unwrapped and read as
/// seconds since its first reading: a reading near the bottom after one near the top
/// (within a sixteenth of the range of each end) is the next lap of the counter; any other
/// reading below the last is the game's clock going back (a restart), kept as it is (an
/// earlier time, which the receiver refuses as older than the last), so no stream of
/// readings can add laps faster than the counter does.
///
/// Counting from the first reading keeps the times small whatever the game's clock reads
/// (Forza's counts from the PC's start: 11.6 days are 1e6 s) and exact: the difference of
/// two readings is taken in whole milliseconds before it becomes seconds, so a capture
/// across the counter's wrap gives the very times of the same capture away from it.
#[derive(Clone, Copy, Debug, Default)]
pub struct WrappingClock {
    last: Option<u32>,
    laps: u64,
    /// The first reading, unwrapped, milliseconds.
    origin: Option<u64>,
}

impl WrappingClock {
    /// Seconds since the first reading for the reading `ms`.
    pub fn seconds(&mut self, ms: u32) -> f64 {
        const EDGE: u32 = u32::MAX / 16;
        // 200 laps are 27 years: more can only come from readings sent to fool it, and they
        // stop there (seconds stay within the samples' bound; the receiver's clock starts
        // again after a stall).
        const MAX_LAPS: u64 = 200;
        if let Some(last) = self.last
            && last > u32::MAX - EDGE
            && ms < EDGE
        {
            self.laps = (self.laps + 1).min(MAX_LAPS);
        }
        self.last = Some(ms);
        let total = (self.laps << 32) + u64::from(ms);
        let origin = *self.origin.get_or_insert(total);
        // Both below 2^40: the difference is exact, and so is its conversion.
        let since = total as i64 - origin as i64;
        since as f64 / 1000.0
    }
}

#[cfg(test)]
mod tests;
