//! CSV in and out for the commands: input from a file or standard input, numbers out in
//! the shortest form that reads back to the same f64.

use std::io::{Read, Write};
use std::path::Path;

use anyhow::Result;
use stewart_kinematics::io::file::{FileKind, read_file};

/// Open `path` for reading (`-` is standard input) and give `read` the reader and the
/// name to use in messages.
pub(crate) fn read_input<T>(
    path: &Path,
    read: impl FnOnce(&mut dyn Read, &str) -> Result<T>,
) -> Result<T> {
    if path.as_os_str() == "-" {
        return read(&mut std::io::stdin().lock(), "standard input");
    }
    let name = path.display().to_string();
    // The gate: a regular file only, within the tables' cap (a FIFO or device refused
    // by name instead of waited on or read for ever).
    let bytes = read_file(path, FileKind::Table)?;
    read(&mut bytes.as_slice(), &name)
}

/// The whole of `path` (`-` is standard input) read as `kind` (a table, a capture: what a
/// refusal names), within the tables' cap, and the name to use in messages: a file's bytes
/// as the gate read them, once (a recording or a capture is not copied a second time).
pub(crate) fn read_input_bytes(path: &Path, kind: FileKind) -> Result<(Vec<u8>, String)> {
    use stewart_kinematics::ground::text::{MAX_TABLE_BYTES, read_capped};
    if path.as_os_str() == "-" {
        let name = "standard input";
        let bytes = read_capped(&mut std::io::stdin().lock(), MAX_TABLE_BYTES)
            .map_err(|e| anyhow::anyhow!("{name} {e}"))?;
        return Ok((bytes, name.to_owned()));
    }
    Ok((read_file(path, kind)?, path.display().to_string()))
}

/// A CSV text being built: a header, then rows of numbers.
pub(crate) struct CsvText {
    text: String,
}

impl CsvText {
    /// Start with the header `columns`.
    pub(crate) fn with_header<S: AsRef<str>>(columns: &[S]) -> Self {
        Self {
            text: header_line(columns),
        }
    }

    /// Append one row.
    pub(crate) fn row(&mut self, values: impl IntoIterator<Item = f64>) {
        push_row(&mut self.text, values);
    }

    /// The text.
    pub(crate) fn into_string(self) -> String {
        self.text
    }
}

/// Rows formatted per task when a table is written on all cores.
const ROWS_PER_TASK: usize = 4096;
/// Rows formatted before they are written (bounds the memory of a large table).
const ROWS_PER_BATCH: usize = 16 * ROWS_PER_TASK;

/// Write a whole table: the header, then rows `0..count` whose values `row(k)` gives.
/// Numbers are formatted on all cores, batch by batch, and written in order, each batch
/// while the next is formatted (the write's copy into the system's buffers no longer
/// waits for the formatting, nor the formatting for it).
pub(crate) fn write_table<F, I>(
    out: &mut dyn Write,
    columns: &[&str],
    count: usize,
    row: F,
) -> std::io::Result<()>
where
    F: Fn(usize) -> I + Sync,
    I: IntoIterator<Item = f64>,
{
    use rayon::prelude::*;
    out.write_all(header_line(columns).as_bytes())?;
    let format = |batch: usize| -> Vec<String> {
        let end = (batch + ROWS_PER_BATCH).min(count);
        let starts: Vec<usize> = (batch..end).step_by(ROWS_PER_TASK).collect();
        starts
            .par_iter()
            .map(|&first| {
                let mut text = String::with_capacity(200 * ROWS_PER_TASK);
                for k in first..(first + ROWS_PER_TASK).min(end) {
                    push_row(&mut text, row(k));
                }
                text
            })
            .collect()
    };
    let write = |out: &mut dyn Write, texts: &[String]| {
        texts.iter().try_for_each(|t| out.write_all(t.as_bytes()))
    };
    let mut formatted: Vec<String> = Vec::new();
    for batch in (0..count).step_by(ROWS_PER_BATCH) {
        let (next, written) = std::thread::scope(|scope| {
            let next = scope.spawn(|| format(batch));
            let written = write(out, &formatted);
            (next.join(), written)
        });
        written?;
        formatted = next.unwrap_or_else(|panic| std::panic::resume_unwind(panic));
    }
    write(out, &formatted)
}

fn header_line<S: AsRef<str>>(columns: &[S]) -> String {
    let names: Vec<&str> = columns.iter().map(AsRef::as_ref).collect();
    names.join(",") + "\n"
}

fn push_row(text: &mut String, values: impl IntoIterator<Item = f64>) {
    for x in values {
        write_number(text, x);
    }
    if text.ends_with(',') {
        text.pop();
    }
    text.push('\n');
}

/// Append `x` and a comma, in the shortest form that reads back to the same f64: plain
/// decimals for magnitudes in [1e-5, 1e16) and zero, exponent form for tiny or huge ones —
/// the text of Rust's `{}` and `{:e}` (whole numbers without `.0`), written by `zmij`
/// (the CSV writer's hot spot: 1 M rows hold 13 M numbers; `zmij` takes two thirds of
/// `ryu`'s time here), whose one difference from `ryu`'s text, the `+` of a positive
/// exponent, is dropped.
fn write_number(out: &mut String, x: f64) {
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format(x);
    let text = text.strip_suffix(".0").unwrap_or(text);
    // Only a number this large has a positive exponent (looked for in no other).
    if x.abs() >= 1e16
        && let Some((mantissa, exponent)) = text.split_once('e')
    {
        out.push_str(mantissa);
        out.push('e');
        out.push_str(exponent.strip_prefix('+').unwrap_or(exponent));
    } else {
        out.push_str(text);
    }
    out.push(',');
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_read_back_exactly() {
        for x in [
            0.0,
            -0.0,
            1.0,
            0.1,
            1.0 / 3.0,
            -5.878304635907295e-17,
            1e-5,
            9.99e-6,
            1e300,
            123456.789,
            f64::MIN_POSITIVE,
        ] {
            let mut s = String::new();
            write_number(&mut s, x);
            let text = s.trim_end_matches(',');
            assert_eq!(text.parse::<f64>().ok(), Some(x), "{text}");
            assert!(text.len() <= 24, "{text}");
        }
        let mut csv = CsvText::with_header(&["a", "b"]);
        csv.row([1.0, -5.878304635907295e-17]);
        assert_eq!(csv.into_string(), "a,b\n1,-5.878304635907295e-17\n");
    }

    /// The text `{}` gives in [1e-5, 1e16) and at zero, `{:e}` elsewhere: what the tables
    /// held before `ryu` wrote them.
    fn formatted(x: f64) -> String {
        let a = x.abs();
        if a == 0.0 || (1e-5..1e16).contains(&a) {
            format!("{x},")
        } else {
            format!("{x:e},")
        }
    }

    #[test]
    fn numbers_are_written_as_rust_formats_them() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            // splitmix64
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        let mut values = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e16,
            1e-5,
            f64::MAX,
            f64::MIN_POSITIVE,
        ];
        values.extend([5e-324, 1e15, 123456789.0, 2f64.powi(53), 0.1 + 0.2, -1e-300]);
        for e in -320..=308 {
            let p = 10f64.powi(e);
            values.extend([
                p,
                p.next_up(),
                p.next_down(),
                -p,
                1.5 * p,
                9.999999999999999 * p,
            ]);
        }
        for _ in 0..300_000 {
            let r = next();
            // Any finite bit pattern, a pose-like value, and a whole number.
            let bits = f64::from_bits(r);
            if bits.is_finite() {
                values.push(bits);
            }
            values.push((r >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0);
            values.push((r % 100_000) as f64 - 50_000.0);
        }
        let mut ties = 0;
        for x in values {
            let mut s = String::new();
            write_number(&mut s, x);
            let rust = formatted(x);
            if s != rust {
                // Where x lies exactly halfway between two shortest texts, `ryu` may take
                // the other one: the same length, the same value read back, a last digit
                // one apart.
                let (ours, theirs) = (s.trim_end_matches(','), rust.trim_end_matches(','));
                assert_eq!(ours.len(), theirs.len(), "{ours} against {theirs}");
                assert_eq!(ours.parse::<f64>().ok(), Some(x), "{ours}");
                let differing = ours.bytes().zip(theirs.bytes()).filter(|(a, b)| a != b);
                assert_eq!(differing.count(), 1, "{ours} against {theirs}");
                ties += 1;
            }
        }
        assert!(ties < 100, "{ties} ties");
    }
}
