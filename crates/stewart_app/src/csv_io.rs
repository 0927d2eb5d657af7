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

/// CSV rows written straight to a writer (no whole-file string): what large tables use.
pub struct CsvWriter<'a> {
    out: &'a mut dyn Write,
    line: String,
}

impl<'a> CsvWriter<'a> {
    /// Write the header `columns` to `out`.
    pub fn new<S: AsRef<str>>(out: &'a mut dyn Write, columns: &[S]) -> std::io::Result<Self> {
        out.write_all(header_line(columns).as_bytes())?;
        Ok(Self {
            out,
            line: String::with_capacity(256),
        })
    }

    /// Write one row.
    pub fn row(&mut self, values: impl IntoIterator<Item = f64>) -> std::io::Result<()> {
        self.line.clear();
        push_row(&mut self.line, values);
        self.out.write_all(self.line.as_bytes())
    }
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
