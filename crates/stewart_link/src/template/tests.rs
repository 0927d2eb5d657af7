//! Templates against frames computed by hand, their refusals, and reading them back.

use super::*;
use proptest::prelude::*;

/// Six legs with a stroke of 0.5 to 0.7 m.
const RANGES: [(f64, f64); 6] = [(0.5, 0.7); 6];

#[test]
fn a_template_writes_the_bytes_computed_by_hand() {
    let t = Template::parse("<255><255>{a1:u16be}{a2:u16le}{a3:u8}{a4:u10be}<10><13>")
        .unwrap_or_else(|e| panic!("{e}"));
    // Leg 1 at the bottom, 2 at the top, 3 a quarter up, 4 at 0.6 m (the middle).
    let values = [0.5, 0.7, 0.55, 0.6, 0.6, 0.6];
    let mut out = Vec::new();
    t.encode(&values, &RANGES, &mut out);
    // 0.25 × 255 = 63.75 → 64 (0x40); 0.5 × 1023 = 511.5 → 512 (0x0200).
    assert_eq!(
        out,
        [
            0xff, 0xff, 0x00, 0x00, 0xff, 0xff, 0x40, 0x02, 0x00, 0x0a, 0x0d
        ]
    );
    assert_eq!(out.len(), t.max_len());
    let wide = Template::parse("{a1:u12be}{a2:u24be}{a3:u32be}|{a4:dec}|{a5:dec3}|{a6:dec}<10>")
        .unwrap_or_else(|e| panic!("{e}"));
    out.clear();
    wide.encode(&[0.6, 0.6, 0.7, 0.55, 0.6, 0.5], &RANGES, &mut out);
    // 0.5 × 4095 = 2047.5 → 2048 (0x0800); 0.5 × 16777215 = 8388607.5 → 8388608
    // (0x800000); the top of u32; 0.25 × 65535 = 16383.75 → 16384; 0.5 × 999 = 499.5 → 500;
    // the bottom: "0".
    let mut expected = vec![0x08, 0x00, 0x80, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff];
    expected.extend(b"|16384|500|0\n");
    assert_eq!(out, expected);
}

#[test]
fn literal_characters_and_an_smc3_style_frame() {
    let t = Template::parse("[A{a1:u10be}][B{a2:u10be}]").unwrap_or_else(|e| panic!("{e}"));
    let mut out = Vec::new();
    t.encode(&[0.7, 0.5, 0.6, 0.6, 0.6, 0.6], &RANGES, &mut out);
    assert_eq!(out, [b'[', b'A', 0x03, 0xff, b']', b'[', b'B', 0, 0, b']']);
}

#[test]
fn values_outside_the_range_are_written_at_its_end() {
    assert_eq!(scaled(0.8, (0.5, 0.7), FieldType::U8), 255);
    assert_eq!(scaled(0.1, (0.5, 0.7), FieldType::U8), 0);
    assert_eq!(scaled(f64::NAN, (0.5, 0.7), FieldType::U8), 0);
    assert_eq!(scaled(0.6, (0.7, 0.5), FieldType::U8), 0);
    assert_eq!(scaled(0.6, (0.5, 0.7), FieldType::U32Be), 2_147_483_648);
    assert!((unscaled(512, (0.5, 0.7), FieldType::U10Be) - 0.600_097_75).abs() < 1e-8);
}

#[test]
fn a_bad_template_is_refused_at_its_column() {
    let refused = |text: &str| {
        Template::parse(text)
            .err()
            .map(|e| (e.column, e.fault.to_string()))
            .unwrap_or_else(|| panic!("{text} was taken"))
    };
    let (column, what) = refused("<255>{a7:u16be}");
    assert_eq!(column, 6);
    assert!(what.contains("`a7` names no actuator"), "{what}");
    let (column, what) = refused("<255><255>{a1:u17be}");
    assert_eq!(column, 11);
    assert!(what.contains("`u17be` is not a type"), "{what}");
    let (column, what) = refused("{a1:u8}<256>");
    assert_eq!(column, 8);
    assert!(what.contains("<256> is over 255"), "{what}");
    let (column, what) = refused("<255><255><10>");
    assert_eq!(column, 14);
    assert!(what.contains("no actuator"), "{what}");
    assert_eq!(refused("{a1:u8").0, 1);
    assert_eq!(refused("{a1:u8}>").0, 8);
    assert_eq!(refused("{a1:u8}é").0, 8);
    assert_eq!(refused("{a1:u8}\t").0, 8);
    assert_eq!(refused("").0, 1);
    assert!(refused("{a1}").1.contains("is not {aK:T}"));
    // A decimal number needs a byte that is not a digit after it.
    let (column, what) = refused("<255>{a1:dec}{a2:dec},");
    assert_eq!(column, 6);
    assert!(what.contains("{a1:dec} has no end"), "{what}");
    assert_eq!(refused("A{a1:u8}{a2:dec}").0, 9);
    assert_eq!(refused("{a1:dec}7").0, 1);
    assert!(Template::parse("{a1:dec},{a2:dec}<10>").is_ok());
    assert!(refused("<x>").1.contains("<x> is not a byte"));
    let e = Template::parse("<255>{a0:u8}").err().map(|e| e.to_string());
    assert_eq!(
        e.as_deref(),
        Some("template column 6: `a0` names no actuator: a1 to a6")
    );
}

#[test]
fn frames_are_read_back_from_a_stream_joined_anywhere() {
    let t = Template::parse("<255><255>{a1:u16be}{a2:dec}<44>{a3:dec3}<10>")
        .unwrap_or_else(|e| panic!("{e}"));
    let mut stream = Vec::new();
    let frames = [[0.5, 0.7, 0.6], [0.6, 0.55, 0.7], [0.7, 0.5, 0.5]];
    for f in frames {
        t.encode(&[f[0], f[1], f[2], 0.6, 0.6, 0.6], &RANGES, &mut stream);
    }
    // Joined three bytes into the first frame: two frames come back whole.
    let mut d = TemplateDecoder::new(t.clone());
    for chunk in stream[3..].chunks(4) {
        d.push(chunk);
    }
    let mut got = Vec::new();
    while let Some(frame) = d.next_frame() {
        got.push(frame);
    }
    assert_eq!(
        got,
        [
            [Some(32768), Some(16384), Some(999), None, None, None],
            [Some(65535), Some(0), Some(0), None, None, None],
        ]
    );
    assert!(d.skipped() >= 1);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Any values encode to a frame that reads back to the same numbers, at most half a
    /// step from the values (the resolution); any bytes read without a panic.
    #[test]
    fn every_frame_reads_back_within_half_a_step(
        values in proptest::array::uniform6(0.5f64..=0.7),
        kinds in proptest::array::uniform6(0usize..9),
        noise in proptest::collection::vec(any::<u8>(), 0..200),
    ) {
        let text: String = (0..6)
            .map(|k| format!("<255>{{a{}:{}}}", k + 1, FieldType::ALL[kinds[k]].1))
            .collect::<String>() + "<10>";
        let t = Template::parse(&text).unwrap_or_else(|e| panic!("{e}"));
        let mut out = Vec::new();
        t.encode(&values, &RANGES, &mut out);
        let mut d = TemplateDecoder::new(t.clone());
        d.push(&out);
        let frame = d.next_frame().unwrap_or_else(|| panic!("no frame in {out:?}"));
        for k in 0..6 {
            let kind = FieldType::ALL[kinds[k]].0;
            let n = frame[k].unwrap_or_else(|| panic!("actuator {k}"));
            prop_assert_eq!(n, scaled(values[k], RANGES[k], kind));
            let step = 0.2 / f64::from(kind.largest());
            prop_assert!((unscaled(n, RANGES[k], kind) - values[k]).abs() <= 0.5 * step + 1e-12);
        }
        let mut d = TemplateDecoder::new(t);
        d.push(&noise);
        while d.next_frame().is_some() {}
    }
}
