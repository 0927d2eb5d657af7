//! A packet capture's telemetry read as the live link reads it: the datagrams to one port,
//! in capture order, through one [`Intake`] (any format, F1's halves paired, clocks
//! unwrapped, repeated stamps placed between their neighbours), each sample at its own
//! clock or, for formats without one, at its capture time.
//!
//! A capture often holds more than the game's stream (a network's chatter: mDNS, SSDP,
//! another game). Only the datagrams to one UDP port are telemetry: the port asked for, or
//! by default the one whose datagrams give the most samples of motion; the datagrams to the
//! others are counted per port, never decoded into the motion.

use std::collections::BTreeMap;

use super::capture::Datagram;
use super::intake::{Intake, Intaken, Tally};
use super::timeline::{PushOutcome, Step, Timed};

/// The telemetry of one port of a capture.
#[derive(Clone, Debug, Default)]
pub struct Replay {
    /// The port read (`None`: the capture held no UDP datagram).
    pub port: Option<u16>,
    /// The samples placed, oldest first, each with its capture packet number (from 1).
    pub samples: Vec<(Timed, usize)>,
    /// What the port's datagrams were.
    pub tally: Tally,
    /// The datagrams to other ports, per port.
    pub other_ports: BTreeMap<u16, usize>,
}

/// Read the telemetry of `port` (`None`: the port whose datagrams give the most samples)
/// in `datagrams`, a silence of `stall_s` seconds taken as a stall (the sender's clock may
/// start again after it), as the live link takes it.
pub fn replay(datagrams: &[Datagram], port: Option<u16>, stall_s: f64) -> Replay {
    let port = port.or_else(|| telemetry_port(datagrams));
    let mut out = Replay {
        port,
        ..Replay::default()
    };
    let mut intake = Intake::new(stall_s);
    // The packets of the samples held on a repeated stamp, oldest first.
    let mut held = Vec::new();
    for d in datagrams {
        if Some(d.port) != port {
            *out.other_ports.entry(d.port).or_default() += 1;
            continue;
        }
        let (_, what, placed) = intake.take(&d.payload, d.time_s);
        if what == Intaken::Sample(PushOutcome::Held) {
            held.push(d.packet);
        }
        let released = placed.len().saturating_sub(1);
        let packets = held.drain(..released.min(held.len())).chain([d.packet]);
        for (timed, packet) in placed.iter().zip(packets) {
            match (timed.step, out.samples.last_mut()) {
                (Step::Same, Some(last)) => *last = (*timed, packet),
                _ => out.samples.push((*timed, packet)),
            }
        }
    }
    intake.finish();
    out.tally = intake.tally().clone();
    out
}

/// The port whose datagrams give the most samples of motion (the lowest of equals), or, when
/// none gives any, the one with the most datagrams.
pub fn telemetry_port(datagrams: &[Datagram]) -> Option<u16> {
    let mut ports: BTreeMap<u16, (usize, usize)> = BTreeMap::new();
    let mut intakes: BTreeMap<u16, Intake> = BTreeMap::new();
    for d in datagrams {
        let intake = intakes.entry(d.port).or_default();
        let (_, what, _) = intake.take(&d.payload, d.time_s);
        let counts = ports.entry(d.port).or_default();
        counts.1 += 1;
        if matches!(
            what,
            Intaken::Sample(PushOutcome::Placed | PushOutcome::Held)
        ) {
            counts.0 += 1;
        }
    }
    let best = ports.iter().max_by(|a, b| a.1.cmp(b.1).then(b.0.cmp(a.0)));
    best.map(|(port, _)| *port)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn datagram(packet: usize, port: u16, time_s: f64, payload: &[u8]) -> Datagram {
        Datagram {
            packet,
            time_s,
            port,
            payload: payload.to_vec(),
        }
    }

    #[test]
    fn the_port_of_the_motion_is_read_and_the_others_counted() {
        // 64 bytes of mDNS-like noise to 5353 (the length of a Live for Speed OutSim
        // packet), and two text samples to 4123.
        let noise = [7u8; 64];
        let datagrams = [
            datagram(1, 5353, 0.0, &noise),
            datagram(2, 4123, 0.0, b"0,1,0,0,0,0,0"),
            datagram(3, 5353, 0.005, &noise),
            datagram(4, 4123, 0.01, b"0.01,2,0,0,0,0,0"),
        ];
        let r = replay(&datagrams, None, Intake::STALL_S);
        assert_eq!(r.port, Some(4123));
        assert_eq!(r.samples.len(), 2);
        assert_eq!(r.samples[1].1, 4);
        assert_eq!(r.other_ports.get(&5353), Some(&2));
        assert_eq!(r.tally.datagrams, 2);
        // Asked for, the other port is read (and gives no motion of ours).
        let r = replay(&datagrams, Some(5353), Intake::STALL_S);
        assert_eq!(r.port, Some(5353));
        assert!(r.samples.iter().all(|(_, p)| *p == 1 || *p == 3));
        assert_eq!(r.other_ports.get(&4123), Some(&2));
    }

    #[test]
    fn a_held_sample_keeps_its_own_packet() {
        let text = |t: f64, ax: f64| format!("{t},{ax},0,0,0,0,0");
        let datagrams = [
            datagram(1, 9, 0.0, text(0.0, 1.0).as_bytes()),
            datagram(2, 9, 0.0, text(0.0, 2.0).as_bytes()),
            datagram(3, 9, 0.0, text(0.02, 3.0).as_bytes()),
        ];
        let r = replay(&datagrams, None, Intake::STALL_S);
        let got: Vec<(f64, usize)> = r.samples.iter().map(|(t, p)| (t.t, *p)).collect();
        assert_eq!(got, vec![(0.0, 1), (0.01, 2), (0.02, 3)]);
    }
}
