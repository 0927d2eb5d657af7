//! The Arduino sketch's line reader (`examples/firmware/six_servos/stewart_text.h`), built
//! with the system C compiler (strict C99 and C++, warnings as errors, as the Arduino IDE
//! builds sketches as C++) and fed the lines the Rust text encoder writes: set-points,
//! e-stop, home, then damaged and overlong lines, which it must drop without losing the
//! next good line.

mod common;

use stewart_link::text::line;
use stewart_link::{Flags, Frame, FrameKind, ValueUnit};

const HARNESS: &str = r#"
#include <stdio.h>
#include "stewart_text.h"

int main(void) {
    stewart_text_reader r;
    stewart_text_line line;
    int c;
    stewart_text_init(&r);
    while ((c = getchar()) != EOF) {
        int s = stewart_text_push(&r, (char)c, &line);
        if (s == STEWART_TEXT_LINE) {
            int k;
            printf("%c %u", line.kind, (unsigned)line.sequence);
            for (k = 0; k < 6; k++) printf(" %ld", (long)line.values[k]);
            printf("\n");
        } else if (s == STEWART_TEXT_BAD) {
            printf("bad\n");
        }
    }
    return 0;
}
"#;

fn frame(sequence: u16, flags: Flags, values: [i32; 6]) -> String {
    line(&Frame {
        kind: FrameKind::SetPoint,
        sequence,
        flags,
        unit: ValueUnit::PulseMicrosecond,
        values,
    })
    .unwrap_or_default()
}

/// Build the harness with `compiler` and `flags` and run it on `input`.
fn run(compiler: &str, flags: &[&str], input: &str) -> String {
    common::build_and_run(
        compiler,
        flags,
        &common::firmware_dir("six_servos"),
        &[],
        HARNESS,
        input.as_bytes(),
    )
}

#[test]
fn the_sketch_reads_the_lines_the_studio_writes_and_drops_bad_ones() {
    let armed = Flags {
        armed: true,
        ..Flags::default()
    };
    let stop = Flags {
        armed: true,
        estop: true,
        home: true,
    };
    let home = Flags {
        armed: true,
        home: true,
        estop: false,
    };
    let mut input = String::new();
    input += &frame(1, armed, [1500, 1620, 1200, 1500, 1955, 600]);
    input += &frame(2, armed, [-2_147_483_648, 2_147_483_647, 0, 1, -1, 1500]);
    input += &frame(3, stop, [1500; 6]);
    input += &frame(65535, home, [1490, 1500, 1510, 1500, 1500, 1500]);
    // Damaged: a missing value, a letter, an unknown kind, a value beyond 32 bits, an
    // overlong line, an empty line, Windows line ends on a good one.
    input += "S,4,1,2,3,4,5\n";
    input += "S,5,1,2,x,4,5,6\n";
    input += "Q,6\n";
    input += "S,7,1,2,3,4,5,4294967296\n";
    input += &format!("S,8,{}\n", "1".repeat(200));
    input += "\n";
    input += "S,9,1,2,3,4,5,6\r\n";
    let expected = "S 1 1500 1620 1200 1500 1955 600\n\
                    S 2 -2147483648 2147483647 0 1 -1 1500\n\
                    E 3 0 0 0 0 0 0\n\
                    H 65535 1490 1500 1510 1500 1500 1500\n\
                    bad\nbad\nbad\nbad\nbad\nbad\n\
                    S 9 1 2 3 4 5 6\n";
    assert_eq!(run("cc", &["-std=c99"], &input), expected);
    assert_eq!(run("c++", &["-std=c++11"], &input), expected);
}
