//! A packet capture of a game's telemetry (pcap or pcapng) made into vehicle motion, as
//! the live link takes the same datagrams: decoded in capture order by one
//! `stewart_link::vehicle::Decoder` (any format, F1's halves paired, clocks unwrapped), each
//! sample at its own clock or, for formats without one, at its capture time, a sample not
//! later than the last by its own clock dropped, a clockless one at the same time replacing
//! the last ([`crate::live_cue::SampleClock`], the live link's rule). The live link fades
//! the cue to neutral where the game is in its menus or the input stalls; a capture is
//! cued sample by sample, as `stewart cue` cues a CSV, and says how many such packets it
//! held.

use std::collections::BTreeMap;

use anyhow::{Result, bail};
use stewart_kinematics::analysis::cueing::VehicleMotion;
use stewart_link::capture::{self, CaptureError};
use stewart_link::vehicle::{Decoder, Reading};

use crate::live_cue::{SampleClock, Step};

/// The vehicle motion of a capture, and what else it held.
#[derive(Debug, Default)]
pub(crate) struct CapturedMotion {
    /// Time and motion of each sample used.
    pub(crate) samples: Vec<(f64, VehicleMotion)>,
    /// The capture's packet number of each sample used.
    pub(crate) packets: Vec<usize>,
    /// The capture's UDP datagrams.
    pub(crate) datagrams: usize,
    /// Datagrams per format recognised.
    pub(crate) formats: BTreeMap<&'static str, usize>,
    /// Datagrams that could not be read.
    pub(crate) malformed: usize,
    /// Samples dropped: not later than the last by their own clock.
    pub(crate) stale: usize,
    /// Datagrams saying the game was in its menus or paused.
    pub(crate) idle: usize,
    /// The capture's own counts: packets, not UDP, fragments, cut.
    pub(crate) capture: capture::Capture,
}

/// Whether `bytes` begin as a pcap or pcapng file does.
pub(crate) fn is_capture(bytes: &[u8]) -> bool {
    const MAGICS: [[u8; 4]; 5] = [
        [0xd4, 0xc3, 0xb2, 0xa1],
        [0xa1, 0xb2, 0xc3, 0xd4],
        [0x4d, 0x3c, 0xb2, 0xa1],
        [0xa1, 0xb2, 0x3c, 0x4d],
        [0x0a, 0x0d, 0x0d, 0x0a],
    ];
    bytes
        .get(..4)
        .is_some_and(|m| MAGICS.iter().any(|k| k == m))
}

/// The vehicle motion in the capture `bytes` (named `name` in errors).
pub(crate) fn read(bytes: &[u8], name: &str) -> Result<CapturedMotion> {
    let mut capture = capture::read(bytes).map_err(|e| located(e, name))?;
    let mut out = CapturedMotion::default();
    let mut decoder = Decoder::new();
    let mut clock = SampleClock::default();
    let datagrams = std::mem::take(&mut capture.datagrams);
    out.datagrams = datagrams.len();
    for datagram in datagrams {
        let decoded = decoder.decode(&datagram.payload);
        if let Some(format) = decoded.format {
            *out.formats.entry(format.name()).or_default() += 1;
        }
        let sample = match decoded.reading {
            Ok(Reading::Sample(sample)) => sample,
            Ok(Reading::Idle) => {
                out.idle += 1;
                continue;
            }
            Ok(Reading::Ignored) => continue,
            Err(_) => {
                out.malformed += 1;
                continue;
            }
        };
        let time = sample.t.unwrap_or(datagram.time_s);
        let motion = VehicleMotion {
            accel: sample.accel,
            rates_deg_s: sample.rates_deg_s,
        };
        match clock.step(sample.t, datagram.time_s) {
            Step::First | Step::By(_) => {
                out.samples.push((time, motion));
                out.packets.push(datagram.packet);
            }
            Step::Same => {
                if let (Some(last), Some(packet)) = (out.samples.last_mut(), out.packets.last_mut())
                {
                    *last = (time, motion);
                    *packet = datagram.packet;
                }
            }
            Step::Stale => out.stale += 1,
        }
    }
    out.capture = capture;
    if out.samples.is_empty() {
        bail!(
            "{name}: no vehicle motion in this capture ({}): a game's telemetry (Forza, F1 24, \
             BeamNG, Live for Speed, X-Plane) or the studio's own datagrams are read",
            out.contents()
        );
    }
    Ok(out)
}

impl CapturedMotion {
    /// What the capture held, in words: its packets and UDP datagrams, the formats and what
    /// was not used.
    pub(crate) fn contents(&self) -> String {
        let c = &self.capture;
        let mut parts = vec![format!(
            "{} packets, {} UDP datagrams",
            c.packets, self.datagrams
        )];
        let formats: Vec<String> = (self.formats.iter())
            .map(|(name, n)| format!("{n} {name}"))
            .collect();
        if !formats.is_empty() {
            parts.push(formats.join(", "));
        }
        let s = &c.skipped;
        for (n, what) in [
            (self.malformed, "malformed"),
            (self.stale, "older than the sample before (dropped)"),
            (self.idle, "in the game's menus or pause"),
            (s.not_udp, "not UDP"),
            (s.fragments, "IP fragments"),
            (s.cut, "cut short"),
            (s.other_link, "of another link layer"),
        ] {
            if n > 0 {
                parts.push(format!("{n} {what}"));
            }
        }
        if let Some(byte) = c.ends_inside {
            parts.push(format!("the file ends inside a packet at byte {byte}"));
        }
        parts.join("; ")
    }
}

/// A capture error with the file's name.
fn located(e: CaptureError, name: &str) -> anyhow::Error {
    anyhow::anyhow!("{name}: {e}")
}
