//! The frame against the byte-exact examples of `docs/PROTOCOL.md` (their CRCs checked
//! with Python's `binascii.crc_hqx(data, 0xFFFF)`, an independent CRC-16/CCITT-FALSE), round
//! trips, and the stream decoder's resynchronisation.

use proptest::prelude::*;

use super::*;

fn bytes(hex: &str) -> Vec<u8> {
    hex.split_whitespace()
        .map(|h| u8::from_str_radix(h, 16).unwrap_or_else(|e| panic!("{h}: {e}")))
        .collect()
}

/// The examples of `docs/PROTOCOL.md`: the frame, and its bytes as printed there.
fn examples() -> [(Frame, &'static str); 3] {
    [
        (
            Frame {
                kind: FrameKind::SetPoint,
                sequence: 1,
                flags: Flags {
                    armed: true,
                    ..Flags::default()
                },
                unit: ValueUnit::Centidegree,
                values: [1250, -300, 0, 4500, -9000, 17],
            },
            "A5 5A 01 01 01 00 01 01 E2 04 00 00 D4 FE FF FF 00 00 00 00 94 11 00 00 D8 DC FF FF 11 00 00 00 49 5A",
        ),
        (
            Frame {
                kind: FrameKind::SetPoint,
                sequence: 0x1234,
                flags: Flags::default(),
                unit: ValueUnit::Micrometre,
                values: [980_204; 6],
            },
            "A5 5A 01 01 34 12 00 00 EC F4 0E 00 EC F4 0E 00 EC F4 0E 00 EC F4 0E 00 EC F4 0E 00 EC F4 0E 00 E5 2D",
        ),
        (
            Frame {
                kind: FrameKind::Telemetry,
                sequence: 65535,
                flags: Flags {
                    armed: true,
                    estop: true,
                    home: false,
                },
                unit: ValueUnit::PulseMicrosecond,
                values: [1500, 1500, 1000, 2000, 1500, 1500],
            },
            "A5 5A 01 02 FF FF 03 02 DC 05 00 00 DC 05 00 00 E8 03 00 00 D0 07 00 00 DC 05 00 00 DC 05 00 00 70 BD",
        ),
    ]
}

#[test]
fn the_encoder_writes_the_documented_bytes() {
    for (frame, hex) in examples() {
        assert_eq!(frame.encode().to_vec(), bytes(hex), "{frame:?}");
        let back = Frame::decode(&frame.encode()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(back, frame);
    }
    // The documentation holds the same bytes.
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/PROTOCOL.md"
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    for (_, hex) in examples() {
        assert!(doc.contains(hex), "docs/PROTOCOL.md lacks {hex}");
    }
    // …and the first example as a text line.
    let line = crate::text::line(&examples()[0].0).unwrap_or_default();
    assert_eq!(line, "S,1,1250,-300,0,4500,-9000,17\n");
    assert!(doc.contains(line.trim_end()));
}

#[test]
fn damaged_frames_say_what_is_wrong() {
    let good = examples()[0].0.encode();
    let mut flipped = good;
    flipped[10] ^= 0x04;
    assert!(matches!(
        Frame::decode(&flipped),
        Err(DecodeError::Crc { .. })
    ));
    // A field changed with its CRC recomputed is refused for the field.
    let with = |at: usize, v: u8| {
        let mut b = good;
        b[at] = v;
        let crc = crc16(&b[2..32]).to_le_bytes();
        b[32..].copy_from_slice(&crc);
        Frame::decode(&b)
    };
    assert_eq!(with(2, 2), Err(DecodeError::Version(2)));
    assert_eq!(with(3, 9), Err(DecodeError::Kind(9)));
    assert_eq!(with(6, 0x08), Err(DecodeError::Flags(0x08)));
    assert_eq!(with(7, 3), Err(DecodeError::Unit(3)));
    let mut unsynced = good;
    unsynced[0] = 0;
    assert_eq!(Frame::decode(&unsynced), Err(DecodeError::Sync));
}

#[test]
fn the_stream_decoder_skips_noise_and_damaged_frames() {
    let [a, b, c] = examples().map(|(f, _)| f);
    let mut damaged = b.encode();
    damaged[20] ^= 0xFF;
    let mut stream: Vec<u8> = vec![0x00, 0xA5, 0x13, 0x5A, 0xA5];
    stream.extend(a.encode());
    stream.extend([0xA5, 0x5A, 0x01]); // a frame cut short …
    stream.extend(damaged); // … then a damaged one
    stream.extend(c.encode());
    let mut d = FrameDecoder::new();
    let out: Vec<Result<Frame, DecodeError>> = stream.iter().filter_map(|&x| d.push(x)).collect();
    let frames: Vec<Frame> = out.iter().filter_map(|r| r.ok()).collect();
    assert_eq!(frames, vec![a, c]);
    assert!(
        out.iter()
            .any(|r| matches!(r, Err(DecodeError::Crc { .. })))
    );
}

#[test]
fn fixed_point_rounds_and_refuses_what_does_not_fit() {
    assert_eq!(ValueUnit::Micrometre.to_fixed(0.980_204_4), Some(980_204));
    assert_eq!(ValueUnit::Centidegree.to_fixed(-89.996), Some(-9000));
    assert_eq!(ValueUnit::PulseMicrosecond.to_fixed(1500.4), Some(1500));
    assert_eq!(ValueUnit::Micrometre.to_fixed(f64::NAN), None);
    assert_eq!(ValueUnit::Micrometre.to_fixed(3000.0), None); // 3 km in µm overflows i32
    assert_eq!(ValueUnit::Centidegree.to_natural(-9000), -90.0);
}

proptest! {
    /// Any frame survives the wire, and any single flipped bit is caught.
    #[test]
    fn round_trip_and_single_bit_errors(
        seq in any::<u16>(), flags in 0u8..8, unit in 0u8..3, kind in 1u8..3,
        values in proptest::array::uniform6(any::<i32>()), bit in 16usize..(8 * FRAME_LEN),
    ) {
        let frame = Frame {
            kind: FrameKind::from_code(kind).unwrap_or(FrameKind::SetPoint),
            sequence: seq,
            flags: Flags::from_byte(flags).unwrap_or_default(),
            unit: ValueUnit::from_code(unit).unwrap_or(ValueUnit::Micrometre),
            values,
        };
        let bytes = frame.encode();
        prop_assert_eq!(Frame::decode(&bytes), Ok(frame));
        let mut damaged = bytes;
        damaged[bit / 8] ^= 1 << (bit % 8);
        prop_assert!(Frame::decode(&damaged).is_err());
    }
}
