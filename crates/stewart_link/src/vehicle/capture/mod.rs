//! The UDP datagrams of a packet capture — pcap or pcapng, as Wireshark and tcpdump write
//! them, the way rig builders share a lap — in capture order, with their capture times.
//!
//! The file and its link layers (Ethernet, Linux cooked capture v1 and v2, raw IP,
//! loopback) are read by `pcap-parser`, the IP and UDP headers by `etherparse`. Packets
//! that are not UDP (TCP, ICMP, ARP), IP fragments (a datagram split in several packets is
//! not put together again: telemetry datagrams fit one), packets the capture cut short
//! (its snapshot length) and link layers of other kinds are counted, not read. A file
//! that is not a capture, or is damaged, is refused naming the packet and the byte; a file
//! that ends inside a packet (a capture stopped abruptly) gives the packets before it and
//! says where it ends.

use etherparse::{EtherType, NetSlice, SlicedPacket, TransportSlice};
use pcap_parser::data::{PacketData, get_packetdata};
use pcap_parser::{Linktype, PcapBlockOwned, PcapError, create_reader};
use thiserror::Error;

/// One UDP datagram of a capture.
#[derive(Clone, Debug, PartialEq)]
pub struct Datagram {
    /// The packet's number in the capture, from 1 (as Wireshark counts).
    pub packet: usize,
    /// When it was captured, seconds since the first packet.
    pub time_s: f64,
    /// The UDP destination port.
    pub port: u16,
    /// The UDP payload.
    pub payload: Vec<u8>,
}

/// What a capture held besides its UDP datagrams.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Skipped {
    /// Packets of another protocol (TCP, ICMP, ARP, …).
    pub not_udp: usize,
    /// IP fragments.
    pub fragments: usize,
    /// Packets the capture cut short (its snapshot length), or whose headers do not read.
    pub cut: usize,
    /// Packets of a link layer not read (Bluetooth, USB, …).
    pub other_link: usize,
}

/// The UDP datagrams of a capture.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Capture {
    /// The datagrams, in capture order.
    pub datagrams: Vec<Datagram>,
    /// What was not read.
    pub skipped: Skipped,
    /// The packets in the file.
    pub packets: usize,
    /// The byte at which the file ends inside a packet (a capture stopped abruptly), if it
    /// does.
    pub ends_inside: Option<u64>,
}

/// Why a capture cannot be read.
#[derive(Debug, Error)]
pub enum CaptureError {
    /// Neither pcap nor pcapng.
    #[error("not a packet capture (pcap or pcapng): its first bytes are neither format's")]
    NotACapture,
    /// The file is damaged where the packet after `packet` would start.
    #[error("the capture is damaged after packet {packet}, at byte {byte}")]
    Damaged {
        /// The last packet read, from 1 (0: none).
        packet: usize,
        /// Where the damage starts.
        byte: u64,
    },
    /// Kuznetzov's "modified" pcap written on a big-endian machine, which is not read.
    #[error(
        "a \"modified\" pcap (magic a1b2cd34) in big-endian byte order, which is not read: \
         save it again as pcapng (Wireshark: File → Save As)"
    )]
    BigEndianModified,
    /// An interface's clock finer than this reader counts (`if_tsresol`).
    #[error(
        "the capture's interface counts time in units of {} s (if_tsresol byte {byte:#04x}), finer than this reader counts (at most 2^63 or 10^19 ticks a second)",
        if byte & 0x80 == 0 { format!("10^-{}", byte & 0x7f) } else { format!("2^-{}", byte & 0x7f) }
    )]
    Resolution {
        /// The `if_tsresol` byte.
        byte: u8,
    },
    /// The file could not be read.
    #[error("the capture could not be read after packet {packet}")]
    Read {
        /// The last packet read.
        packet: usize,
    },
}

/// Whether `bytes` begin as a capture does: pcap (microsecond, nanosecond, or Kuznetzov's
/// "modified" form, in either byte order) or pcapng.
pub fn is_capture(bytes: &[u8]) -> bool {
    const MAGICS: [[u8; 4]; 7] = [
        [0xd4, 0xc3, 0xb2, 0xa1],
        [0xa1, 0xb2, 0xc3, 0xd4],
        [0x4d, 0x3c, 0xb2, 0xa1],
        [0xa1, 0xb2, 0x3c, 0x4d],
        [0x34, 0xcd, 0xb2, 0xa1],
        [0xa1, 0xb2, 0xcd, 0x34],
        [0x0a, 0x0d, 0x0d, 0x0a],
    ];
    bytes
        .get(..4)
        .is_some_and(|m| MAGICS.iter().any(|k| k == m))
}

/// The buffer the reader starts with, bytes (grown for a larger packet, up to
/// [`MAX_BLOCK`]).
const BUFFER: usize = 1 << 16;
/// The largest block read, bytes.
const MAX_BLOCK: usize = 1 << 24;

/// Read the UDP datagrams of the capture `input` (a whole file, read beforehand under its
/// size cap).
pub fn read(input: &[u8]) -> Result<Capture, CaptureError> {
    if input.starts_with(&[0xa1, 0xb2, 0xcd, 0x34]) {
        return Err(CaptureError::BigEndianModified);
    }
    let mut reader = create_reader(BUFFER, input).map_err(|e| match e {
        PcapError::Eof | PcapError::HeaderNotRecognized => CaptureError::NotACapture,
        PcapError::ReadError => CaptureError::Read { packet: 0 },
        _ => CaptureError::Damaged { packet: 0, byte: 0 },
    })?;
    let mut state = State::default();
    let mut offset: u64 = 0;
    let mut capacity = BUFFER;
    loop {
        let packet = state.capture.packets;
        let damaged = CaptureError::Damaged {
            packet,
            byte: offset,
        };
        match reader.next() {
            Ok((size, block)) => {
                if state.take(&block).is_none() {
                    return Err(match state.resolution {
                        Some(byte) => CaptureError::Resolution { byte },
                        None => damaged,
                    });
                }
                offset += size as u64;
                reader.consume(size);
            }
            Err(PcapError::Eof) => break,
            Err(PcapError::Incomplete(_)) => {
                if reader.reader_exhausted() {
                    state.capture.ends_inside = Some(offset);
                    break;
                }
                reader.refill().map_err(|_| CaptureError::Read { packet })?;
            }
            Err(PcapError::BufferTooSmall) => {
                capacity *= 2;
                if capacity > MAX_BLOCK || !reader.grow(capacity) {
                    return Err(damaged);
                }
                reader.refill().map_err(|_| CaptureError::Read { packet })?;
            }
            Err(PcapError::UnexpectedEof) => {
                state.capture.ends_inside = Some(offset);
                break;
            }
            Err(PcapError::ReadError) => return Err(CaptureError::Read { packet }),
            Err(_) => return Err(damaged),
        }
    }
    Ok(state.capture)
}

/// A link layer and its clock: the ticks a second of a pcapng interface's timestamps
/// (`if_tsresol`: a power of ten, or of two when its high bit is set) and its offset in
/// whole seconds (`if_tsoffset`, in the section's byte order); a legacy file's seconds and
/// fraction are read as they are.
#[derive(Clone, Copy, Debug)]
struct Link {
    kind: Linktype,
    per_second: u64,
    offset_s: i64,
}

/// A packet's time: whole seconds and the fraction of the next, kept apart so that a large
/// offset or tick count costs the times between packets no precision.
#[derive(Clone, Copy, Debug, Default)]
struct Stamp {
    whole: i128,
    fraction: f64,
}

impl Stamp {
    /// `ticks` of `per_second` a second after `offset_s`.
    fn of(offset_s: i64, ticks: u64, per_second: u64) -> Stamp {
        Stamp {
            whole: i128::from(offset_s) + i128::from(ticks / per_second),
            fraction: (ticks % per_second) as f64 / per_second as f64,
        }
    }

    /// Seconds since `start`.
    fn since(self, start: Stamp) -> f64 {
        (self.whole - start.whole) as f64 + (self.fraction - start.fraction)
    }
}

impl Link {
    /// A pcapng interface, in a section of the byte order `big_endian`.
    /// A resolution finer than 64 bits of ticks a second counts is refused by its
    /// `if_tsresol` byte (`Err(Some(byte))`); a malformed option is damage (`Err(None)`).
    fn of_interface(
        idb: &pcap_parser::InterfaceDescriptionBlock<'_>,
        big_endian: bool,
    ) -> Result<Link, Option<u8>> {
        let mut per_second = 1_000_000u64;
        let mut offset_s = 0;
        for option in &idb.options {
            let value = option.as_bytes().map_err(|_| None)?;
            match option.code {
                pcap_parser::OptionCode::IfTsresol => {
                    let &[resolution] = value else {
                        return Err(None);
                    };
                    let exponent = u32::from(resolution & 0x7f);
                    per_second = match resolution & 0x80 {
                        0 => 10u64.checked_pow(exponent),
                        _ => 2u64.checked_pow(exponent),
                    }
                    .ok_or(Some(resolution))?;
                }
                pcap_parser::OptionCode::IfTsoffset => {
                    let bytes = <[u8; 8]>::try_from(value).map_err(|_| None)?;
                    offset_s = match big_endian {
                        true => i64::from_be_bytes(bytes),
                        false => i64::from_le_bytes(bytes),
                    };
                }
                _ => {}
            }
        }
        Ok(Link {
            kind: idb.linktype,
            per_second,
            offset_s,
        })
    }
}

/// What reading has gathered: the interfaces described, the first packet's time, the
/// last packet's, and the capture.
#[derive(Default)]
struct State {
    links: Vec<Link>,
    /// The current pcapng section's byte order.
    big_endian: bool,
    first: Option<Stamp>,
    last: Stamp,
    capture: Capture,
    /// The `if_tsresol` byte of an interface whose clock is too fine, once one is met.
    resolution: Option<u8>,
}

impl State {
    /// Take one block: a file or interface header (its link layer and clock), or a packet.
    /// `None`: a packet of an interface never described (the file is damaged).
    fn take(&mut self, block: &PcapBlockOwned<'_>) -> Option<()> {
        use pcap_parser::Block;
        let (link, time, data, cut) = match block {
            PcapBlockOwned::LegacyHeader(h) => {
                let per_second = if h.is_nanosecond_precision() {
                    1_000_000_000
                } else {
                    1_000_000
                };
                self.links = vec![Link {
                    kind: h.network,
                    per_second,
                    offset_s: 0,
                }];
                return Some(());
            }
            PcapBlockOwned::Legacy(b) => {
                let link = *self.links.first()?;
                let time = Stamp {
                    whole: i128::from(b.ts_sec),
                    fraction: f64::from(b.ts_usec) / link.per_second as f64,
                };
                (link, time, b.data, b.caplen < b.origlen)
            }
            PcapBlockOwned::NG(Block::SectionHeader(shb)) => {
                // A new section describes its interfaces anew, in its own byte order.
                self.links.clear();
                self.big_endian = shb.big_endian();
                return Some(());
            }
            PcapBlockOwned::NG(Block::InterfaceDescription(idb)) => {
                match Link::of_interface(idb, self.big_endian) {
                    Ok(link) => self.links.push(link),
                    Err(resolution) => {
                        self.resolution = resolution;
                        return None;
                    }
                }
                return Some(());
            }
            PcapBlockOwned::NG(Block::EnhancedPacket(epb)) => {
                let link = *self.links.get(usize::try_from(epb.if_id).ok()?)?;
                let ticks = (u64::from(epb.ts_high) << 32) | u64::from(epb.ts_low);
                let time = Stamp::of(link.offset_s, ticks, link.per_second);
                (link, time, epb.data, epb.caplen < epb.origlen)
            }
            // A simple packet has no time: it is taken at the previous packet's.
            PcapBlockOwned::NG(Block::SimplePacket(spb)) => {
                (*self.links.first()?, self.last, spb.data, false)
            }
            // Statistics, name resolution, comments: nothing to read.
            PcapBlockOwned::NG(_) => return Some(()),
        };
        self.last = time;
        let capture = &mut self.capture;
        capture.packets += 1;
        let start = *self.first.get_or_insert(time);
        let skipped = &mut capture.skipped;
        if cut {
            skipped.cut += 1;
            return Some(());
        }
        match udp_payload(link.kind, data) {
            Payload::Udp(port, payload) => capture.datagrams.push(Datagram {
                packet: capture.packets,
                time_s: time.since(start),
                port,
                payload: payload.to_vec(),
            }),
            Payload::NotUdp => skipped.not_udp += 1,
            Payload::Fragment => skipped.fragments += 1,
            Payload::Unreadable => skipped.cut += 1,
            Payload::OtherLink => skipped.other_link += 1,
        }
        Some(())
    }
}

/// What a packet carries.
enum Payload<'a> {
    /// The destination port and the payload.
    Udp(u16, &'a [u8]),
    NotUdp,
    Fragment,
    Unreadable,
    OtherLink,
}

/// The UDP payload of a packet on `link`.
fn udp_payload(link: Linktype, data: &[u8]) -> Payload<'_> {
    let sliced = match get_packetdata(data, link, data.len()) {
        Some(PacketData::L2(frame)) if link == Linktype::ETHERNET => {
            SlicedPacket::from_ethernet(frame)
        }
        Some(PacketData::L3(ether_type, packet)) => {
            SlicedPacket::from_ether_type(EtherType(ether_type), packet)
        }
        Some(PacketData::L4(17, datagram)) => {
            return match etherparse::UdpSlice::from_slice(datagram) {
                Ok(udp) => Payload::Udp(udp.destination_port(), udp.payload()),
                Err(_) => Payload::Unreadable,
            };
        }
        Some(PacketData::L4(..)) => return Payload::NotUdp,
        Some(PacketData::L2(_) | PacketData::Unsupported(_)) => return Payload::OtherLink,
        None => return Payload::Unreadable,
    };
    let Ok(packet) = sliced else {
        return Payload::Unreadable;
    };
    let fragment = match &packet.net {
        Some(NetSlice::Ipv4(ip)) => ip.is_payload_fragmented(),
        Some(NetSlice::Ipv6(ip)) => ip.is_payload_fragmented(),
        _ => false,
    };
    match packet.transport {
        _ if fragment => Payload::Fragment,
        Some(TransportSlice::Udp(udp)) => Payload::Udp(udp.destination_port(), udp.payload()),
        _ => Payload::NotUdp,
    }
}

#[cfg(test)]
mod tests;
