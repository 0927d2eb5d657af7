//! A packet capture of a game's telemetry (pcap or pcapng) made into vehicle motion, as
//! the live link takes the same datagrams: the datagrams to one port (`--port`, or the one
//! whose datagrams give motion) read by `stewart_link::vehicle::replay` through the live
//! link's intake (any format, F1's halves paired, clocks unwrapped, repeated stamps placed
//! between their neighbours), each sample at its own clock or, for formats without one, at
//! its capture time. The live link fades the cue to neutral where the game is in its menus
//! or the input stalls; a capture is cued sample by sample, as `stewart cue` cues a CSV,
//! and says how many such packets it held.

use anyhow::{Result, bail};
use stewart_kinematics::analysis::cueing::VehicleMotion;
use stewart_link::vehicle::capture::{self, CaptureError};
use stewart_link::vehicle::intake::Tally;
use stewart_link::vehicle::replay::{Replay, replay};

/// The vehicle motion of a capture, and what else it held.
#[derive(Debug, Default)]
pub(crate) struct CapturedMotion {
    /// Time and motion of each sample used.
    pub(crate) samples: Vec<(f64, VehicleMotion)>,
    /// The capture's packet number of each sample used.
    pub(crate) packets: Vec<usize>,
    /// The telemetry read: its port, what its datagrams were, the other ports.
    pub(crate) replay: Replay,
    /// The capture's own counts: packets, not UDP, fragments, cut.
    pub(crate) capture: capture::Capture,
}

/// Whether `bytes` begin as a pcap or pcapng file does.
pub(crate) fn is_capture(bytes: &[u8]) -> bool {
    capture::is_capture(bytes)
}

/// The vehicle motion in the capture `bytes` (named `name` in errors), of the datagrams
/// to `port` (`None`: the port whose datagrams give motion), a silence of `stall_s` taken
/// as the live link takes it.
pub(crate) fn read(
    bytes: &[u8],
    name: &str,
    port: Option<u16>,
    stall_s: f64,
) -> Result<CapturedMotion> {
    let mut capture = capture::read(bytes).map_err(|e| located(e, name))?;
    let datagrams = std::mem::take(&mut capture.datagrams);
    let mut replay = replay(&datagrams, port, stall_s);
    let mut out = CapturedMotion::default();
    for (timed, packet) in std::mem::take(&mut replay.samples) {
        let s = timed.sample;
        let motion = VehicleMotion {
            accel: s.accel,
            rates_deg_s: s.rates_deg_s,
        };
        out.samples.push((timed.t, motion));
        out.packets.push(packet);
    }
    out.capture = capture;
    out.replay = replay;
    out.capture.datagrams = datagrams;
    if out.samples.is_empty() {
        bail!(
            "{name}: no vehicle motion in this capture ({}): a game's telemetry (Forza, F1 24 and \
             25, BeamNG, Live for Speed, X-Plane) or the studio's own datagrams are read",
            out.contents()
        );
    }
    Ok(out)
}

impl CapturedMotion {
    /// What the capture held, in words: its packets and UDP datagrams, the formats and what
    /// was not used.
    pub(crate) fn contents(&self) -> String {
        let mut parts = capture_words(&self.capture, self.replay.port, &self.replay.other_ports);
        parts.extend(tally_words(&self.replay.tally));
        parts.join("; ")
    }
}

/// The ports named one by one; more are counted.
const PORTS_NAMED: usize = 8;

/// What a capture held, in words: its packets and UDP datagrams, the port read, the other
/// ports' datagrams, and what was not UDP, cut or damaged (the words `stewart cue` and
/// `stewart telemetry --input` share).
pub(crate) fn capture_words(
    capture: &capture::Capture,
    port: Option<u16>,
    other_ports: &std::collections::BTreeMap<u16, usize>,
) -> Vec<String> {
    let mut parts = vec![format!(
        "{} packets, {} UDP datagrams",
        capture.packets,
        capture.datagrams.len()
    )];
    if let Some(port) = port {
        parts.push(format!("telemetry read from port {port}"));
    }
    if !other_ports.is_empty() {
        let mut named: Vec<String> = (other_ports.iter().take(PORTS_NAMED))
            .map(|(port, n)| format!("{n} to port {port}"))
            .collect();
        if other_ports.len() > PORTS_NAMED {
            let rest: usize = other_ports.values().skip(PORTS_NAMED).sum();
            named.push(format!(
                "{rest} to {} other ports",
                other_ports.len() - PORTS_NAMED
            ));
        }
        parts.push(format!(
            "not telemetry (other ports, --port chooses): {}",
            named.join(", ")
        ));
    }
    let s = &capture.skipped;
    for (n, what) in [
        (s.not_udp, "not UDP"),
        (s.fragments, "IP fragments"),
        (s.cut, "cut short"),
        (s.other_link, "of another link layer"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}"));
        }
    }
    if let Some(byte) = capture.ends_inside {
        parts.push(format!("the file ends inside a packet at byte {byte}"));
    }
    parts
}

/// What the datagrams of a stream were, in words: the formats, then what was not used (the
/// words `stewart telemetry` and `stewart cue` share).
pub(crate) fn tally_words(tally: &Tally) -> Vec<String> {
    let mut parts = Vec::new();
    let formats: Vec<String> = (tally.formats())
        .map(|(format, n)| format!("{n} {}", format.name()))
        .collect();
    if !formats.is_empty() {
        parts.push(formats.join(", "));
    }
    for (n, what) in [
        (tally.refused, "unreadable"),
        (
            tally.restarts,
            "times the sender's clock started again (after its menus or a stall)",
        ),
        (tally.repeats, "repeating the sample before (dropped)"),
        (tally.stale, "older than the sample before (dropped)"),
        (
            tally.unplaced,
            "held on a repeated stamp at the end (dropped)",
        ),
        (tally.idle, "in the game's menus or pause"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}"));
        }
    }
    if let Some(why) = &tally.first_refusal {
        parts.push(format!("the first unreadable: {why}"));
    }
    parts
}

/// A capture error with the file's name.
fn located(e: CaptureError, name: &str) -> anyhow::Error {
    anyhow::anyhow!("{name}: {e}")
}
