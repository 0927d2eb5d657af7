//! Captures built here byte by byte from the pcap and pcapng file formats (the frames
//! inside by `etherparse`'s builder), read back.

use super::*;
use etherparse::PacketBuilder;
use proptest::prelude::*;

fn udp4(payload: &[u8], port: u16) -> Vec<u8> {
    let mut out = Vec::new();
    PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv4([192, 168, 1, 10], [192, 168, 1, 20], 64)
        .udp(5300, port)
        .write(&mut out, payload)
        .unwrap_or_else(|e| panic!("{e}"));
    out
}

fn udp6(payload: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv6([1; 16], [2; 16], 64)
        .udp(5300, 20777)
        .write(&mut out, payload)
        .unwrap_or_else(|e| panic!("{e}"));
    out
}

fn tcp4(payload: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    PacketBuilder::ethernet2([1; 6], [2; 6])
        .ipv4([10, 0, 0, 1], [10, 0, 0, 2], 64)
        .tcp(40000, 80, 1, 1024)
        .write(&mut out, payload)
        .unwrap_or_else(|e| panic!("{e}"));
    out
}

/// A UDP packet whose IPv4 header says more fragments follow.
fn fragment(payload: &[u8]) -> Vec<u8> {
    let mut p = udp4(payload, 4444);
    // Ethernet (14 bytes), then IPv4: flags and fragment offset at bytes 6 and 7.
    p[14 + 6] |= 0x20;
    p
}

/// A legacy pcap (little-endian, microseconds, Ethernet) of `packets`: (seconds,
/// microseconds, frame, bytes captured of it).
fn pcap(packets: &[(u32, u32, Vec<u8>, Option<usize>)]) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend(0xa1b2_c3d4u32.to_le_bytes()); // magic
    out.extend(2u16.to_le_bytes()); // version 2.4
    out.extend(4u16.to_le_bytes());
    out.extend(0i32.to_le_bytes()); // thiszone
    out.extend(0u32.to_le_bytes()); // sigfigs
    out.extend(65535u32.to_le_bytes()); // snaplen
    out.extend(1u32.to_le_bytes()); // LINKTYPE_ETHERNET
    for (sec, usec, frame, captured) in packets {
        let caplen = captured.unwrap_or(frame.len());
        out.extend(sec.to_le_bytes());
        out.extend(usec.to_le_bytes());
        out.extend((caplen as u32).to_le_bytes());
        out.extend((frame.len() as u32).to_le_bytes());
        out.extend(&frame[..caplen]);
    }
    out
}

/// A pcapng block: type, total length, body padded to 32 bits, total length again.
fn block(kind: u32, body: &[u8]) -> Vec<u8> {
    let padded = body.len().div_ceil(4) * 4;
    let total = (12 + padded) as u32;
    let mut out = Vec::new();
    out.extend(kind.to_le_bytes());
    out.extend(total.to_le_bytes());
    out.extend(body);
    out.resize(8 + padded, 0);
    out.extend(total.to_le_bytes());
    out
}

/// A pcapng file: one section, one interface with `link` and nanosecond timestamps
/// (`if_tsresol` = 9), and `packets` (nanoseconds, frame).
fn pcapng(link: u16, packets: &[(u64, Vec<u8>)]) -> Vec<u8> {
    let mut shb = Vec::new();
    shb.extend(0x1a2b_3c4du32.to_le_bytes()); // byte-order magic
    shb.extend(1u16.to_le_bytes()); // version 1.0
    shb.extend(0u16.to_le_bytes());
    shb.extend((-1i64).to_le_bytes()); // section length unknown
    let mut out = block(0x0a0d_0d0a, &shb);
    let mut idb = Vec::new();
    idb.extend(link.to_le_bytes());
    idb.extend(0u16.to_le_bytes()); // reserved
    idb.extend(0u32.to_le_bytes()); // snaplen: none
    idb.extend(9u16.to_le_bytes()); // option if_tsresol
    idb.extend(1u16.to_le_bytes());
    idb.extend([9, 0, 0, 0]); // 10^-9, padded
    idb.extend([0, 0, 0, 0]); // opt_endofopt
    out.extend(block(1, &idb));
    for (ns, frame) in packets {
        let mut epb = Vec::new();
        epb.extend(0u32.to_le_bytes()); // interface 0
        epb.extend(((ns >> 32) as u32).to_le_bytes());
        epb.extend((*ns as u32).to_le_bytes());
        epb.extend((frame.len() as u32).to_le_bytes());
        epb.extend((frame.len() as u32).to_le_bytes());
        epb.extend(frame);
        epb.resize(20 + frame.len().div_ceil(4) * 4, 0);
        out.extend(block(6, &epb));
    }
    out
}

#[test]
fn a_pcap_gives_its_udp_datagrams_in_order_and_counts_the_rest() {
    let file = pcap(&[
        (1000, 500_000, udp4(b"first", 20777), None),
        (1000, 516_667, tcp4(b"GET /"), None),
        (1000, 533_333, udp6(b"second"), None),
        (1000, 550_000, fragment(b"half of a datagram"), None),
        (
            1000,
            566_667,
            udp4(b"cut by the snapshot length", 4444),
            Some(50),
        ),
        (1001, 0, udp4(b"third", 4444), None),
    ]);
    let c = read(file.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c.packets, 6);
    let got: Vec<(usize, &[u8])> = (c.datagrams.iter())
        .map(|d| (d.packet, d.payload.as_slice()))
        .collect();
    assert_eq!(
        got,
        [(1, &b"first"[..]), (3, &b"second"[..]), (6, &b"third"[..])]
    );
    let times: Vec<f64> = c.datagrams.iter().map(|d| d.time_s).collect();
    assert!((times[1] - 0.033_333).abs() < 1e-9 && (times[2] - 0.5).abs() < 1e-9);
    assert_eq!(
        c.skipped,
        Skipped {
            not_udp: 1,
            fragments: 1,
            cut: 1,
            other_link: 0
        }
    );
    assert_eq!(c.ends_inside, None);
}

#[test]
fn a_pcapng_reads_the_same_with_its_interfaces_clock() {
    let ns = 1_700_000_000_000_000_000u64;
    let file = pcapng(1, &[(ns, udp4(b"a", 1)), (ns + 16_666_667, udp4(b"b", 1))]);
    let c = read(file.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c.datagrams.len(), 2);
    assert_eq!(c.datagrams[1].payload, b"b");
    assert!((c.datagrams[1].time_s - 0.016_666_667).abs() < 1e-6);
    // Raw IP (LINKTYPE_RAW, 101) as `tcpdump -i tun0` writes it: no Ethernet header.
    let raw = udp4(b"raw", 4444)[14..].to_vec();
    let c = read(pcapng(101, &[(0, raw)]).as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        c.datagrams.first().map(|d| d.payload.as_slice()),
        Some(&b"raw"[..])
    );
    // Bluetooth (LINKTYPE_BLUETOOTH_HCI_H4, 187): counted, not read.
    let c = read(pcapng(187, &[(0, vec![1, 2, 3])]).as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c.skipped.other_link, 1);
}

#[test]
fn a_capture_cut_short_gives_what_came_before_and_says_where() {
    let file = pcap(&[
        (1, 0, udp4(b"one", 1), None),
        (1, 10, udp4(b"two", 1), None),
    ]);
    let whole = file.len();
    let cut = &file[..whole - 10];
    let c = read(cut).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c.datagrams.len(), 1);
    let first_end = 24 + 16 + udp4(b"one", 1).len();
    assert_eq!(c.ends_inside, Some(first_end as u64));
}

#[test]
fn what_is_not_a_capture_or_is_damaged_is_refused_with_the_place() {
    assert!(matches!(
        read(&b"t,ax,ay,az,wx,wy,wz\n0,0,0,0,0,0,0\n"[..]),
        Err(CaptureError::NotACapture)
    ));
    assert!(matches!(read(&[][..]), Err(CaptureError::NotACapture)));
    // A pcapng packet of an interface never described.
    let mut file = pcapng(1, &[(0, udp4(b"x", 1))]);
    let epb = file.len() - (12 + 20 + udp4(b"x", 1).len().div_ceil(4) * 4);
    file[epb + 8] = 7;
    let e = read(file.as_slice()).err();
    assert!(
        matches!(e, Some(CaptureError::Damaged { packet: 0, byte }) if byte == epb as u64),
        "{e:?}"
    );
    let words = e.map(|e| e.to_string()).unwrap_or_default();
    assert!(words.contains(&format!("at byte {epb}")), "{words}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Any bytes, and any bytes changed in a real capture: read or refused, never a panic.
    #[test]
    fn no_capture_makes_the_reader_panic(
        noise in proptest::collection::vec(any::<u8>(), 0..600),
        changes in proptest::collection::vec((any::<usize>(), any::<u8>()), 0..8),
    ) {
        let _ = read(noise.as_slice());
        for mut file in [
            pcap(&[(1, 0, udp4(b"telemetry", 1), None), (1, 5, fragment(b"y"), None)]),
            pcapng(1, &[(0, udp6(b"telemetry")), (9, tcp4(b"z"))]),
        ] {
            for &(at, byte) in &changes {
                let n = file.len();
                file[at % n] = byte;
            }
            let _ = read(file.as_slice());
        }
    }
}

/// A pcapng file in either byte order: one interface (Ethernet) with the resolution byte
/// `tsresol` (`if_tsresol`: a power of ten, or of two with the high bit set) and the offset
/// `tsoffset` in seconds (`if_tsoffset`), and `packets` (ticks, frame).
fn pcapng_clocked(big: bool, tsresol: u8, tsoffset: i64, packets: &[(u64, Vec<u8>)]) -> Vec<u8> {
    let u16b = |v: u16| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let u32b = |v: u32| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let i64b = |v: i64| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let block = |kind: u32, body: &[u8]| {
        let padded = body.len().div_ceil(4) * 4;
        let total = (12 + padded) as u32;
        let mut out = Vec::new();
        out.extend(u32b(kind));
        out.extend(u32b(total));
        out.extend(body);
        out.resize(8 + padded, 0);
        out.extend(u32b(total));
        out
    };
    let mut shb = Vec::new();
    shb.extend(u32b(0x1a2b_3c4d)); // byte-order magic, in the section's order
    shb.extend(u16b(1));
    shb.extend(u16b(0));
    shb.extend(i64b(-1));
    let mut out = block(0x0a0d_0d0a, &shb);
    let mut idb = Vec::new();
    idb.extend(u16b(1)); // Ethernet
    idb.extend(u16b(0));
    idb.extend(u32b(0));
    idb.extend(u16b(9)); // if_tsresol
    idb.extend(u16b(1));
    idb.extend([tsresol, 0, 0, 0]);
    idb.extend(u16b(14)); // if_tsoffset
    idb.extend(u16b(8));
    idb.extend(i64b(tsoffset));
    idb.extend([0, 0, 0, 0]);
    out.extend(block(1, &idb));
    for (ticks, frame) in packets {
        let mut epb = Vec::new();
        epb.extend(u32b(0));
        epb.extend(u32b((ticks >> 32) as u32));
        epb.extend(u32b(*ticks as u32));
        epb.extend(u32b(frame.len() as u32));
        epb.extend(u32b(frame.len() as u32));
        epb.extend(frame);
        epb.resize(20 + frame.len().div_ceil(4) * 4, 0);
        out.extend(block(6, &epb));
    }
    out
}

#[test]
fn pcapng_clocks_of_powers_of_two_and_offsets_in_either_byte_order_are_read() {
    // 100 datagrams 10 ms apart, at 2^-20 s a tick (if_tsresol 0x94) after an offset of
    // 1.7e9 s: the times are 10 ms apart to within a tick, in both byte orders.
    let tick = 2f64.powi(-20);
    let packets: Vec<(u64, Vec<u8>)> = (0..100u64)
        .map(|k| {
            (
                ((k as f64 * 0.01) / tick).round() as u64 + 12_345,
                udp4(b"x", 4444),
            )
        })
        .collect();
    for big in [false, true] {
        let file = pcapng_clocked(big, 0x80 | 20, 1_700_000_000, &packets);
        let c = read(file.as_slice()).unwrap_or_else(|e| panic!("{big}: {e}"));
        assert_eq!(c.datagrams.len(), 100, "{big}");
        for (k, d) in c.datagrams.iter().enumerate() {
            assert!(
                (d.time_s - k as f64 * 0.01).abs() <= tick,
                "{big}: {k}: {}",
                d.time_s
            );
            assert_eq!(d.port, 4444);
        }
    }
    // A power of ten (10^-3) and a negative offset, big-endian.
    let file = pcapng_clocked(true, 3, -5, &[(1000, udp4(b"a", 1)), (1250, udp4(b"b", 1))]);
    let c = read(file.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(c.datagrams[1].time_s, 0.25);
    // A resolution beyond 64 bits is refused as that, naming it (it was called damage).
    for byte in [0x80 | 70, 30] {
        let file = pcapng_clocked(false, byte, 0, &[(1, udp4(b"a", 1))]);
        let e = read(file.as_slice()).map(|_| ()).map_err(|e| e.to_string());
        let expected = if byte == 30 { "10^-30 s" } else { "2^-70 s" };
        assert!(
            e.as_ref().is_err_and(|e| e.contains(expected)),
            "{byte:#x}: {e:?}"
        );
    }
}

#[test]
fn a_modified_pcap_is_a_capture_and_read() {
    // Kuznetzov's "modified" pcap (magic a1b2cd34): each record header has 8 more bytes
    // (interface index, protocol, packet type, padding).
    let mut out = Vec::new();
    out.extend(0xa1b2_cd34u32.to_le_bytes());
    out.extend(2u16.to_le_bytes());
    out.extend(4u16.to_le_bytes());
    out.extend(0i32.to_le_bytes());
    out.extend(0u32.to_le_bytes());
    out.extend(65535u32.to_le_bytes());
    out.extend(1u32.to_le_bytes());
    for (usec, payload) in [(0u32, &b"one"[..]), (500_000, b"two")] {
        let frame = udp4(payload, 4444);
        out.extend(7u32.to_le_bytes());
        out.extend(usec.to_le_bytes());
        out.extend((frame.len() as u32).to_le_bytes());
        out.extend((frame.len() as u32).to_le_bytes());
        out.extend([0u8; 8]);
        out.extend(&frame);
    }
    assert!(is_capture(&out));
    let c = read(out.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    let got: Vec<(&[u8], f64)> = c
        .datagrams
        .iter()
        .map(|d| (d.payload.as_slice(), d.time_s))
        .collect();
    assert_eq!(got, [(&b"one"[..], 0.0), (&b"two"[..], 0.5)]);
    // In big-endian order it is refused by name.
    let mut big = out.clone();
    big[..4].copy_from_slice(&[0xa1, 0xb2, 0xcd, 0x34]);
    assert!(is_capture(&big));
    assert!(matches!(
        read(big.as_slice()),
        Err(CaptureError::BigEndianModified)
    ));
}
