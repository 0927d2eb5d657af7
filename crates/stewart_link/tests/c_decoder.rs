//! The plain-C decoder of `examples/firmware/` (what an STM32 or Arduino runs), built with
//! the system C compiler (strict C99, warnings as errors) and fed frames the Rust encoder
//! produced: good frames in order, noise, a damaged frame, a field it must refuse, and a
//! sequence gap. Its C encoder must write the bytes the Rust encoder writes.

mod common;

use stewart_link::crc::crc16;
use stewart_link::{Flags, Frame, FrameKind, ValueUnit};

/// A harness around the decoder: bytes on standard input, one line per outcome.
const HARNESS: &str = r#"
#include <stdio.h>
#include "stewart_link.h"

int main(void) {
    stewart_decoder d;
    stewart_decoder_init(&d);
    int c;
    while ((c = getchar()) != EOF) {
        stewart_frame f;
        int s = stewart_decoder_push(&d, (uint8_t)c, &f);
        if (s == STEWART_FRAME) {
            printf("F %u %u %u %u", f.kind, f.sequence, f.flags, f.unit);
            for (int k = 0; k < 6; k++) printf(" %ld", (long)f.values[k]);
            printf("\n");
            uint8_t again[STEWART_FRAME_LEN];
            stewart_encode(&f, again);
            printf("B");
            for (int k = 0; k < STEWART_FRAME_LEN; k++) printf(" %02X", again[k]);
            printf("\n");
        } else if (s == STEWART_BAD_CRC) {
            printf("E crc\n");
        } else if (s == STEWART_BAD_FIELD) {
            printf("E field\n");
        }
    }
    printf("lost %lu bad %lu\n", (unsigned long)d.lost, (unsigned long)d.bad);
    return 0;
}
"#;

fn frame(sequence: u16, values: [i32; 6]) -> Frame {
    Frame {
        kind: FrameKind::SetPoint,
        sequence,
        flags: Flags {
            armed: true,
            ..Flags::default()
        },
        unit: ValueUnit::Centidegree,
        values,
    }
}

#[test]
fn the_c_decoder_reads_what_the_rust_encoder_writes() {
    let frames = [
        frame(65534, [1250, -300, 0, 4500, -9000, 17]),
        frame(65535, [i32::MIN, i32::MAX, -1, 1, 0, 123_456]),
        frame(0, [1, 2, 3, 4, 5, 6]),
        // 1 and 2 are lost here: a gap of two.
        frame(3, [7, 8, 9, 10, 11, 12]),
    ];
    let mut stream: Vec<u8> = vec![0x00, 0xA5, 0xA5, 0x11];
    stream.extend(frames[0].encode());
    stream.extend(frames[1].encode());
    let mut damaged = frames[2].encode();
    damaged[9] ^= 0x10;
    stream.extend(damaged);
    // A unit code the decoder does not know, with a correct CRC.
    let mut unknown = frames[2].encode();
    unknown[7] = 9;
    let crc = crc16(&unknown[2..32]).to_le_bytes();
    unknown[32..].copy_from_slice(&crc);
    stream.extend(unknown);
    stream.extend(frames[2].encode());
    stream.extend([0x5A, 0xA5]);
    stream.extend(frames[3].encode());

    let text = common::build_and_run(
        "cc",
        &["-std=c99"],
        &common::firmware_dir(""),
        &[common::firmware_dir("stewart_link.c")],
        HARNESS,
        &stream,
    );
    let lines: Vec<&str> = text.lines().collect();
    let hex = |f: &Frame| {
        f.encode()
            .iter()
            .map(|b| format!(" {b:02X}"))
            .collect::<String>()
    };
    let decoded = |f: &Frame| {
        let v: Vec<String> = f.values.iter().map(i32::to_string).collect();
        format!("F 1 {} 1 1 {}", f.sequence, v.join(" "))
    };
    let expected = vec![
        decoded(&frames[0]),
        format!("B{}", hex(&frames[0])),
        decoded(&frames[1]),
        format!("B{}", hex(&frames[1])),
        "E crc".to_owned(),
        "E field".to_owned(),
        decoded(&frames[2]),
        format!("B{}", hex(&frames[2])),
        decoded(&frames[3]),
        format!("B{}", hex(&frames[3])),
        "lost 2 bad 2".to_owned(),
    ];
    assert_eq!(lines, expected, "{text}");
}
