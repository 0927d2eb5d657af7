//! CSV in and out for the commands: input from a file or standard input, numbers out in
//! the shortest form that reads back to the same f64.

use std::fmt::Write as _;
use std::io::{Read, Write};
use std::path::Path;

use anyhow::{Context, Result};

/// Open `path` for reading (`-` is standard input) and give `read` the reader and the
/// name to use in messages.
pub fn read_input<T>(
    path: &Path,
    read: impl FnOnce(&mut dyn Read, &str) -> Result<T>,
) -> Result<T> {
    if path.as_os_str() == "-" {
        return read(&mut std::io::stdin().lock(), "standard input");
    }
    let name = path.display().to_string();
    let mut file = std::fs::File::open(path).with_context(|| format!("cannot read `{name}`"))?;
    read(&mut file, &name)
}

/// A CSV text being built: a header, then rows of numbers.
pub struct CsvText {
    text: String,
}

impl CsvText {
    /// Start with the header `columns`.
    pub fn with_header<S: AsRef<str>>(columns: &[S]) -> Self {
        Self {
            text: header_line(columns),
        }
    }

    /// Append one row.
    pub fn row(&mut self, values: impl IntoIterator<Item = f64>) {
        push_row(&mut self.text, values);
    }

    /// The text.
    pub fn into_string(self) -> String {
        self.text
    }
}

/// Rows formatted per task when a table is written on all cores.
const ROWS_PER_TASK: usize = 4096;
/// Rows formatted before they are written (bounds the memory of a large table).
const ROWS_PER_BATCH: usize = 64 * ROWS_PER_TASK;

/// Write a whole table: the header, then rows `0..count` whose values `row(k)` gives.
/// Numbers are formatted on all cores, batch by batch, and written in order.
pub fn write_table<F, I>(
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
    for batch in (0..count).step_by(ROWS_PER_BATCH) {
        let end = (batch + ROWS_PER_BATCH).min(count);
        let starts: Vec<usize> = (batch..end).step_by(ROWS_PER_TASK).collect();
        let texts: Vec<String> = starts
            .par_iter()
            .map(|&first| {
                let mut text = String::with_capacity(200 * ROWS_PER_TASK);
                for k in first..(first + ROWS_PER_TASK).min(end) {
                    push_row(&mut text, row(k));
                }
                text
            })
            .collect();
        for text in texts {
            out.write_all(text.as_bytes())?;
        }
    }
    Ok(())
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
/// decimals for ordinary magnitudes, exponent form for tiny or huge ones.
fn write_number(out: &mut String, x: f64) {
    let a = x.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || (1e-5..1e16).contains(&a) {
        write!(out, "{x},")
    } else {
        write!(out, "{x:e},")
    };
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
}
