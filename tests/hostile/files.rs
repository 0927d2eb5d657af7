//! Random and mutated scenario files and CSV tables through the real binary: every run
//! ends, with a result or one located error, and leaves no output behind a refusal.

use proptest::prelude::*;

use crate::run::{names, path, run, tempdir, write};

/// Values a hostile file puts where a number was.
const EXTREMES: [&str; 16] = [
    "1e308",
    "-1e308",
    "1e20",
    "-1e20",
    "0",
    "-0.0",
    "1e-320",
    "4096",
    "-1",
    "nan",
    "inf",
    "-inf",
    "18446744073709551615",
    "1e6",
    "1e-9",
    "\"text\"",
];

/// One change to a file's text.
#[derive(Clone, Debug)]
enum Mutation {
    /// Replace the n-th number with an extreme value.
    Number(usize, usize),
    /// Delete the n-th line.
    DeleteLine(usize),
    /// Repeat the n-th line.
    DuplicateLine(usize),
    /// Insert bytes (possibly not UTF-8, possibly NUL) at a position.
    Insert(usize, Vec<u8>),
    /// Cut the file at a position.
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), 0..EXTREMES.len()).prop_map(|(n, v)| Mutation::Number(n, v)),
        1 => any::<usize>().prop_map(Mutation::DeleteLine),
        1 => any::<usize>().prop_map(Mutation::DuplicateLine),
        1 => (any::<usize>(), proptest::collection::vec(any::<u8>(), 1..6))
            .prop_map(|(p, b)| Mutation::Insert(p, b)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
    ]
}

/// Byte ranges of the numbers in `text`.
fn numbers(text: &[u8]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let starts = text[i].is_ascii_digit()
            || (text[i] == b'-' && text.get(i + 1).is_some_and(u8::is_ascii_digit));
        let after_word = i > 0 && (text[i - 1].is_ascii_alphanumeric() || text[i - 1] == b'_');
        if starts && !after_word {
            let mut j = i + 1;
            while j < text.len() && (text[j].is_ascii_digit() || b".eE+-".contains(&text[j])) {
                j += 1;
            }
            out.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let lines = |t: &Vec<u8>| -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        let mut start = 0;
        for (i, b) in t.iter().enumerate() {
            if *b == b'\n' {
                v.push((start, i + 1));
                start = i + 1;
            }
        }
        if start < t.len() {
            v.push((start, t.len()));
        }
        v
    };
    match m {
        Mutation::Number(n, v) => {
            let found = numbers(text);
            if !found.is_empty() {
                let (a, b) = found[n % found.len()];
                text.splice(a..b, EXTREMES[*v].bytes());
            }
        }
        Mutation::DeleteLine(n) => {
            let l = lines(text);
            if !l.is_empty() {
                let (a, b) = l[n % l.len()];
                text.drain(a..b);
            }
        }
        Mutation::DuplicateLine(n) => {
            let l = lines(text);
            if !l.is_empty() {
                let (a, b) = l[n % l.len()];
                let copy: Vec<u8> = text[a..b].to_vec();
                text.splice(b..b, copy);
            }
        }
        Mutation::Insert(p, bytes) => {
            let p = p % (text.len() + 1);
            text.splice(p..p, bytes.iter().copied());
        }
        Mutation::Truncate(p) => {
            let p = p % (text.len() + 1);
            text.truncate(p);
        }
    }
}

/// The files mutated: every preset, and the rotary-servo test scenario.
fn mutated_file(k: usize) -> &'static str {
    crate::run::PRESETS.get(k).copied().unwrap_or("rotary")
}

fn preset_text(name: &str) -> Vec<u8> {
    if name == "rotary" {
        let file = concat!(env!("CARGO_MANIFEST_DIR"), "/cli/rotary.toml");
        return std::fs::read(file).unwrap_or_else(|e| panic!("{e}"));
    }
    stewart_kinematics::io::scenario::presets::text(name)
        .unwrap_or_else(|| panic!("no preset {name}"))
        .as_bytes()
        .to_vec()
}

proptest! {
    #![proptest_config(crate::run::config())]

    /// A preset with a few random mutations, through `check` and `solve --out`.
    #[test]
    fn mutated_scenarios_end_with_a_result_or_one_located_error(
        preset in 0..=crate::run::PRESETS.len(),
        mutations in proptest::collection::vec(mutation(), 1..4),
    ) {
        let dir = tempdir();
        let mut text = preset_text(mutated_file(preset));
        for m in &mutations {
            apply(&mut text, m);
        }
        let scenario = write(dir.path(), "s.toml", &text);
        let o = run(&["check", "--scenario", &scenario]);
        o.assert_promises();
        let out = path(dir.path(), "out.csv");
        let o = run(&["solve", "--scenario", &scenario, "--out", &out]);
        o.assert_promises();
        if o.code == Some(2) {
            prop_assert_eq!(names(dir.path()), vec!["s.toml".to_owned()]);
            prop_assert!(o.stderr.contains("s.toml"), "the error names the file: {}", o.stderr);
        } else {
            let csv = std::fs::read_to_string(&out).unwrap_or_default();
            crate::run::assert_no_nonfinite(&csv, &o.shown());
        }
    }

    /// Random CSV tables (cells from numbers, extremes, garbage, quotes; ragged rows;
    /// random bytes) through `solve --poses`, `fk --legs` and `calibrate --measurements`.
    #[test]
    fn random_tables_end_with_a_result_or_one_located_error(
        header in prop_oneof![
            Just("x,y,z,roll_deg,pitch_deg,yaw_deg".to_owned()),
            Just("t,x,y,z,roll_deg,pitch_deg,yaw_deg".to_owned()),
            Just("L1,L2,L3,L4,L5,L6".to_owned()),
            Just("t,L1,L2,L3,L4,L5,L6".to_owned()),
            Just("x,y,z,roll_deg,pitch_deg,yaw_deg,L1,L2,L3,L4,L5,L6".to_owned()),
            "[a-zA-Z0-9_,\"]{0,40}",
        ],
        rows in proptest::collection::vec(
            proptest::collection::vec(
                prop_oneof![
                    4 => (-2.0..2.0f64).prop_map(|v| v.to_string()),
                    2 => (0..EXTREMES.len()).prop_map(|i| EXTREMES[i].to_owned()),
                    1 => "[ -~]{0,12}",
                    1 => Just(String::new()),
                    1 => Just("\"1,5\"".to_owned()),
                ],
                0..9,
            ),
            0..12,
        ),
        tail in proptest::collection::vec(any::<u8>(), 0..8),
    ) {
        let dir = tempdir();
        let mut text = header.into_bytes();
        text.push(b'\n');
        for row in rows {
            text.extend(row.join(",").bytes());
            text.push(b'\n');
        }
        text.extend(tail);
        let table = write(dir.path(), "t.csv", &text);
        for command in [
            vec!["solve", "--preset", "paired", "--poses", &table],
            vec!["fk", "--preset", "paired", "--legs", &table],
            vec!["calibrate", "--preset", "paired", "--measurements", &table],
        ] {
            let out = path(dir.path(), "out.csv");
            let mut args = command.clone();
            args.extend(["--out", out.as_str()]);
            let o = run(&args);
            o.assert_promises();
            if o.code == Some(2) {
                prop_assert_eq!(names(dir.path()), vec!["t.csv".to_owned()]);
                prop_assert!(o.stderr.contains("t.csv"), "the error names the file: {}", o.stderr);
            } else {
                let csv = std::fs::read_to_string(&out).unwrap_or_default();
                crate::run::assert_no_nonfinite(&csv, &o.shown());
                let _ = std::fs::remove_file(&out);
            }
        }
    }
}

#[test]
fn foreign_encodings_and_binary_files_are_named() {
    let dir = tempdir();
    let utf16: Vec<u8> = "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,0\n"
        .encode_utf16()
        .flat_map(u16::to_le_bytes)
        .collect();
    let latin1 = b"x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,0 # caf\xe9\n".to_vec();
    for (name, bytes, expected) in [
        ("u16.csv", utf16.clone(), "is UTF-16 text"),
        (
            "l1.csv",
            latin1,
            "line 2, column 20 is not valid UTF-8 (byte 0xE9",
        ),
        (
            "bin.csv",
            b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x01\x00".to_vec(),
            "is not a text file",
        ),
    ] {
        let table = write(dir.path(), name, &bytes);
        let o = run(&["solve", "--poses", &table]);
        o.assert_refused();
        assert!(o.stderr.contains(expected), "{name}: {}", o.stderr);
    }
    let scenario = write(dir.path(), "u16.toml", &utf16);
    let o = run(&["check", "--scenario", &scenario]);
    o.assert_refused();
    assert!(o.stderr.contains("is UTF-16 text"), "{}", o.stderr);
}

#[test]
fn endless_inputs_are_cut_off_not_read_forever() {
    // A device is refused before it is opened; a file over the cap before it is read.
    let o = run(&["check", "--scenario", "/dev/zero"]);
    o.assert_refused();
    assert!(o.stderr.contains("is a device, not a file"), "{}", o.stderr);
    let dir = tempdir();
    let big = dir.path().join("big.toml");
    let file = std::fs::File::create(&big).unwrap_or_else(|e| panic!("{e}"));
    file.set_len(17 << 20).unwrap_or_else(|e| panic!("{e}"));
    let o = run(&["check", "--scenario", &big.display().to_string()]);
    o.assert_refused();
    assert!(o.stderr.contains("larger than 16 MiB"), "{}", o.stderr);
}

#[test]
fn bad_joint_coordinates_are_one_located_error_and_nothing_is_written() {
    let dir = tempdir();
    let good = String::from_utf8(preset_text("dietmaier")).unwrap_or_else(|e| panic!("{e}"));
    let first = "  [0.0, 0.0, 0.0],\n";
    for (name, text, expected) in [
        (
            "mixed.toml",
            good.replace("home_height =", "base_radius = 1.0\nhome_height ="),
            "line 12, column 15: `base_radius` and `base_joints_m` both describe the base joints",
        ),
        (
            "five.toml",
            good.replacen(first, "", 1),
            "`base_joints_m` must list 6 points [x, y, z] (one per leg), got 5",
        ),
        (
            "seven.toml",
            good.replacen(first, &format!("{first}{first}"), 1),
            "got 7",
        ),
        (
            "two.toml",
            good.replacen("[0.0, 0.0, 0.0]", "[0.0, 0.0]", 1),
            "line 14, column 3: `base_joints_m[0]` must be a point [x, y, z] in metres, got 2 numbers",
        ),
        (
            "nan.toml",
            good.replacen("[1.107915, 0.0, 0.0]", "[1.107915, nan, 0.0]", 1),
            "line 15, column 14: `base_joints_m[1][1]` must be a finite number, got NaN",
        ),
        (
            "inf.toml",
            good.replacen("[1.107915, 0.0, 0.0]", "[1.107915, 0.0, -inf]", 1),
            "`base_joints_m[1][2]` must be a finite number, got -inf",
        ),
        (
            "same.toml",
            good.replacen("[1.107915, 0.0, 0.0]", "[0.0, 0.0, 0.0]", 1),
            "line 15, column 3: base joints 1 and 2 coincide",
        ),
        (
            "far.toml",
            good.replacen("[1.107915, 0.0, 0.0]", "[1e300, 0.0, 0.0]", 1),
            "geometry.base_joints_m[1][0]",
        ),
    ] {
        let scenario = write(dir.path(), name, text.as_bytes());
        let out = path(dir.path(), "out.csv");
        let o = run(&["solve", "--scenario", &scenario, "--out", &out]);
        o.assert_refused();
        assert!(
            o.stderr.contains(name) && o.stderr.contains(expected),
            "{name}: {}",
            o.stderr
        );
        assert_eq!(o.stderr.lines().count(), 1, "{name}: {}", o.stderr);
        assert!(
            !std::path::Path::new(&out).exists(),
            "{name}: an output was written"
        );
        std::fs::remove_file(&scenario).unwrap_or_else(|e| panic!("{e}"));
    }
}
