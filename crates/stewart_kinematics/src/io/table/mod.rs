//! Reading numeric CSV tables with errors that point at the file, line and column.
//!
//! Lines are the file's own lines counted from 1, the header being line 1. Blank lines
//! and lines starting with `#` are skipped. Cells are trimmed. NaN and infinity are
//! refused like any other bad number.

use std::io::Read;

use thiserror::Error;

/// Why a table could not be read. Every variant names the file and, where there is one, the line and column.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TableError {
    /// The file could not be read at all.
    #[error("{file}: {message}")]
    Unreadable {
        /// File name as the user gave it.
        file: String,
        /// What went wrong.
        message: String,
    },
    /// A column the table must have is not in the header.
    #[error(
        "{file}, line {line}: the header has no `{column}` column (expected columns: {expected})"
    )]
    MissingColumn {
        /// File name.
        file: String,
        /// Line of the header.
        line: u64,
        /// The column missing.
        column: String,
        /// All columns that are required.
        expected: String,
    },
    /// A column named twice.
    #[error("{file}, line {line}: the header names column `{column}` twice")]
    DuplicateColumn {
        /// File name.
        file: String,
        /// Line of the header.
        line: u64,
        /// The column.
        column: String,
    },
    /// A cell that is not a number.
    #[error("{file}, line {line}, column `{column}`: `{text}` is not a number")]
    NotANumber {
        /// File name.
        file: String,
        /// Line of the cell.
        line: u64,
        /// Column of the cell.
        column: String,
        /// The cell's text.
        text: String,
    },
    /// A cell that is NaN or infinite.
    #[error("{file}, line {line}, column `{column}`: {text} is not a finite number")]
    NotFinite {
        /// File name.
        file: String,
        /// Line of the cell.
        line: u64,
        /// Column of the cell.
        column: String,
        /// The cell's text.
        text: String,
    },
    /// A row with another number of cells than the header.
    #[error("{file}, line {line}: {found} fields where the header has {expected}")]
    FieldCount {
        /// File name.
        file: String,
        /// Line of the row.
        line: u64,
        /// Cells in the header.
        expected: u64,
        /// Cells in the row.
        found: u64,
    },
    /// A table without data rows.
    #[error("{file}: the table has a header but no data rows")]
    NoRows {
        /// File name.
        file: String,
    },
    /// A value that is a number but not an acceptable one.
    #[error("{file}, line {line}, column `{column}`: {message}")]
    BadValue {
        /// File name.
        file: String,
        /// Line of the cell.
        line: u64,
        /// Column of the cell.
        column: String,
        /// What is wrong with it.
        message: String,
    },
}

/// The requested numeric columns of a CSV table, stored row after row in one flat
/// vector (no allocation per row).
#[derive(Clone, Debug, PartialEq)]
pub struct NumericTable {
    /// File name, for messages.
    pub file: String,
    /// Names of the columns held, in the order of each row's values (required ones
    /// first, then the optional ones present).
    pub columns: Vec<String>,
    /// The values, `columns.len()` per row.
    values: Vec<f64>,
    /// Line of each row in the file, from 1.
    lines: Vec<u64>,
}

impl NumericTable {
    /// Position of column `name` in each row's values, if the table has it.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// Number of data rows (never zero: a table without rows is refused).
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// Whether the table has no rows (never true for a table that was read).
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// Values of row `k`, in the order of [`NumericTable::columns`].
    pub fn row(&self, k: usize) -> &[f64] {
        let n = self.columns.len();
        &self.values[k * n..(k + 1) * n]
    }

    /// Every row's values, in order.
    pub fn rows(&self) -> impl ExactSizeIterator<Item = &[f64]> + '_ {
        self.values.chunks_exact(self.columns.len().max(1))
    }

    /// Every value, row after row (`columns.len()` per row).
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Line of row `k` in the file, from 1.
    pub fn line(&self, k: usize) -> u64 {
        self.lines[k]
    }

    /// Lines of every row in the file.
    pub fn lines(&self) -> &[u64] {
        &self.lines
    }

    /// Check every value of column `name` (if present) against `range` (see
    /// [`crate::ground::bounds`]); the first value outside is an error naming its line.
    pub fn check_range(
        &self,
        name: &str,
        range: &std::ops::RangeInclusive<f64>,
        unit: &str,
    ) -> Result<(), TableError> {
        self.check_ranges(&[(name, range.clone(), unit)])
    }

    /// [`NumericTable::check_range`] of each `(name, range, unit)` in turn: the first
    /// value outside in the first column that has one is the error. One pass over the
    /// rows on all cores sees that every value is in range (no early exit within a block,
    /// so that it vectorises); only a table with a value outside is searched for the first.
    pub fn check_ranges(
        &self,
        checks: &[(&str, std::ops::RangeInclusive<f64>, &str)],
    ) -> Result<(), TableError> {
        use rayon::prelude::*;
        let present: Vec<(usize, &std::ops::RangeInclusive<f64>)> = checks
            .iter()
            .filter_map(|(name, range, _)| Some((self.index(name)?, range)))
            .collect();
        let width = self.columns.len().max(1);
        let inside = self.values.par_chunks(width * 4096).all(|block| {
            present.iter().all(|&(c, range)| {
                block[c..]
                    .iter()
                    .step_by(width)
                    .fold(true, |ok, v| ok & range.contains(v))
            })
        });
        if inside {
            return Ok(());
        }
        for (name, range, unit) in checks {
            let Some(c) = self.index(name) else { continue };
            for (k, row) in self.rows().enumerate() {
                if let Err(e) = crate::ground::bounds::check(row[c], range, unit) {
                    return Err(TableError::BadValue {
                        file: self.file.clone(),
                        line: self.lines[k],
                        column: (*name).to_owned(),
                        message: e.to_string(),
                    });
                }
            }
        }
        Ok(())
    }

    /// The lines of every row, the table given up for them.
    pub fn into_lines(self) -> Vec<u64> {
        self.lines
    }

    /// Read `required` columns (all must be present) and whichever `optional` columns
    /// are present from CSV text; other columns are ignored. Time and memory are linear
    /// in the size of the input.
    pub fn read(
        input: impl Read,
        file: &str,
        required: &[&str],
        optional: &[&str],
    ) -> Result<Self, TableError> {
        let bytes = crate::ground::text::read_capped(input, crate::ground::text::MAX_TABLE_BYTES)
            .map_err(|message| TableError::Unreadable {
            file: file.to_owned(),
            message,
        })?;
        Self::read_bytes(bytes, file, required, optional)
    }

    /// [`NumericTable::read`] of bytes already read (no copy of them is made).
    pub fn read_bytes(
        bytes: Vec<u8>,
        file: &str,
        required: &[&str],
        optional: &[&str],
    ) -> Result<Self, TableError> {
        if let Some(table) = Self::read_plain_bytes(&bytes, file, required, optional) {
            return Ok(table);
        }
        Self::read_text(&text_of(bytes, file)?, file, required, optional, true)
    }

    /// A plain table read straight from its bytes on all cores ([`plain`]: each chunk
    /// checked to be UTF-8 as it is read, comment lines skipped there), with no pass over
    /// the whole text before: `None` for anything else — another encoding, a byte-order
    /// mark, a comment before the header, quotes, any error — which the full path then
    /// reads (and says what is wrong with, in its words).
    fn read_plain_bytes(
        bytes: &[u8],
        file: &str,
        required: &[&str],
        optional: &[&str],
    ) -> Option<Self> {
        const BOM: &[u8] = &[0xEF, 0xBB, 0xBF];
        if crate::ground::text::foreign_encoding(bytes).is_some() || bytes.starts_with(BOM) {
            return None;
        }
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .flexible(true)
            .from_reader(bytes);
        let header = reader.headers().ok()?.clone();
        let rest = usize::try_from(reader.position().byte()).ok()?;
        let before = bytes.get(..rest)?;
        if before.contains(&b'#') || !ends_a_line(bytes, rest) {
            return None;
        }
        let (columns, positions) = chosen_columns(&header, 1, file, required, optional).ok()?;
        let first_line = 1 + memchr::memchr_iter(b'\n', before).count() as u64;
        let kept: Vec<(&str, usize)> = columns
            .iter()
            .map(String::as_str)
            .zip(positions.iter().copied())
            .collect();
        let rows = plain::read(&bytes[rest..], first_line, file, header.len(), &kept)?.ok()?;
        (!rows.lines.is_empty()).then(|| Self {
            file: file.to_owned(),
            columns,
            values: rows.values,
            lines: rows.lines,
        })
    }

    /// [`NumericTable::read`] of the text, its rows read on all cores when the text is
    /// plain ([`plain`]) and `on_all_cores`, else by the csv crate.
    fn read_text(
        text: &str,
        file: &str,
        required: &[&str],
        optional: &[&str],
        on_all_cores: bool,
    ) -> Result<Self, TableError> {
        let mut lines = LineCounter::new(text);
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .flexible(true)
            .has_headers(false)
            .from_reader(text.as_bytes());
        let unreadable = |e: csv::Error| TableError::Unreadable {
            file: file.to_owned(),
            message: describe_csv_error(&e),
        };
        // The header is the first line that is not blank or a comment (blanked when read).
        let mut header = csv::StringRecord::new();
        while reader.read_record(&mut header).map_err(unreadable)? && is_blank(&header) {}
        // No header line at all (an empty file, or only comments): named as line 1.
        let header_line = if header.is_empty() {
            1
        } else {
            lines.of(header.position())
        };
        let (columns, positions) = chosen_columns(&header, header_line, file, required, optional)?;
        let rest = reader.position().byte() as usize;
        if on_all_cores
            && ends_a_line(text.as_bytes(), rest)
            && let Some(text_after) = text.get(rest..)
        {
            let first_line = 1 + text.as_bytes()[..rest]
                .iter()
                .filter(|&&b| b == b'\n')
                .count() as u64;
            let kept: Vec<(&str, usize)> = columns
                .iter()
                .map(String::as_str)
                .zip(positions.iter().copied())
                .collect();
            if let Some(rows) =
                plain::read(text_after.as_bytes(), first_line, file, header.len(), &kept)
            {
                let rows = rows?;
                if rows.lines.is_empty() {
                    return Err(TableError::NoRows {
                        file: file.to_owned(),
                    });
                }
                return Ok(Self {
                    file: file.to_owned(),
                    columns,
                    values: rows.values,
                    lines: rows.lines,
                });
            }
        }
        let mut values = Vec::new();
        let mut row_lines = Vec::new();
        let mut record = csv::StringRecord::new();
        while reader.read_record(&mut record).map_err(unreadable)? {
            let line = lines.of(record.position());
            if is_blank(&record) {
                continue; // a blank line, or a comment line (blanked when read)
            }
            if record.len() != header.len() {
                return Err(TableError::FieldCount {
                    file: file.to_owned(),
                    line,
                    expected: header.len() as u64,
                    found: record.len() as u64,
                });
            }
            for (name, &pos) in columns.iter().zip(&positions) {
                let text = record.get(pos).unwrap_or("");
                values.push(parse_cell(text, file, line, name)?);
            }
            row_lines.push(line);
        }
        if row_lines.is_empty() {
            return Err(TableError::NoRows {
                file: file.to_owned(),
            });
        }
        Ok(Self {
            file: file.to_owned(),
            columns,
            values,
            lines: row_lines,
        })
    }
}

/// The columns a table keeps, required then optional ones present, and where each is in
/// the `header` (on line `header_line`): refused when a name repeats or a required one is
/// missing.
fn chosen_columns(
    header: &csv::StringRecord,
    header_line: u64,
    file: &str,
    required: &[&str],
    optional: &[&str],
) -> Result<(Vec<String>, Vec<usize>), TableError> {
    for (i, name) in header.iter().enumerate() {
        if header.iter().skip(i + 1).any(|other| other == name) {
            return Err(TableError::DuplicateColumn {
                file: file.to_owned(),
                line: header_line,
                column: name.to_owned(),
            });
        }
    }
    let mut columns = Vec::new();
    let mut positions = Vec::new();
    for name in required {
        let Some(pos) = header.iter().position(|h| h == *name) else {
            return Err(TableError::MissingColumn {
                file: file.to_owned(),
                line: header_line,
                column: (*name).to_owned(),
                expected: required.join(","),
            });
        };
        columns.push((*name).to_owned());
        positions.push(pos);
    }
    for name in optional {
        if let Some(pos) = header.iter().position(|h| h == *name) {
            columns.push((*name).to_owned());
            positions.push(pos);
        }
    }
    Ok((columns, positions))
}

/// Line numbers of byte offsets that only move forward: counting resumes where the
/// last call stopped, so a whole file costs one pass.
struct LineCounter<'a> {
    bytes: &'a [u8],
    at: usize,
    line: u64,
}

impl<'a> LineCounter<'a> {
    fn new(text: &'a str) -> Self {
        Self {
            bytes: text.as_bytes(),
            at: 0,
            line: 1,
        }
    }

    /// Line (from 1) of the record starting at `pos`. A record's position may point at
    /// the blank lines before it (the csv crate skips them); those are stepped over.
    fn of(&mut self, pos: Option<&csv::Position>) -> u64 {
        let Some(p) = pos else { return 1 };
        let start = (p.byte() as usize).min(self.bytes.len());
        let skip = self.bytes[start..]
            .iter()
            .take_while(|b| matches!(b, b'\n' | b'\r'))
            .count();
        let target = start + skip;
        if target < self.at {
            // Never happens for records read in order; count afresh to stay correct.
            self.at = 0;
            self.line = 1;
        }
        self.line += self.bytes[self.at..target]
            .iter()
            .filter(|&&b| b == b'\n')
            .count() as u64;
        self.at = target;
        self.line
    }
}

/// The whole input as text with comment lines blanked (see [`blank_comments`]), or an
/// error naming the encoding or the first line that is not UTF-8.
fn text_of(mut bytes: Vec<u8>, file: &str) -> Result<String, TableError> {
    let unreadable = |message: String| TableError::Unreadable {
        file: file.to_owned(),
        message,
    };
    if let Some(encoding) = crate::ground::text::foreign_encoding(&bytes) {
        return Err(unreadable(format!("{encoding}; save it as UTF-8 text")));
    }
    // A table with no `#` has no comment line: one fast search instead of a pass.
    if bytes.contains(&b'#') {
        blank_comments(&mut bytes);
    }
    crate::ground::text::decode(bytes).map_err(unreadable)
}

/// Blank every comment line (first non-blank character `#`) in place, keeping its line
/// ending (and a byte-order mark before the first), so that byte offsets and line numbers
/// stay those of the file.
fn blank_comments(bytes: &mut [u8]) {
    const BOM: &[u8] = &[0xEF, 0xBB, 0xBF];
    let mut start = if bytes.starts_with(BOM) { BOM.len() } else { 0 };
    while start < bytes.len() {
        let end = bytes[start..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |i| start + i);
        let line = &mut bytes[start..end];
        let first = line.iter().position(|b| !matches!(b, b' ' | b'\t'));
        if first.is_some_and(|i| line[i] == b'#') {
            for b in line.iter_mut() {
                if *b != b'\r' {
                    *b = b' ';
                }
            }
        }
        start = end + 1;
    }
}

impl TableError {
    /// The error of a piece of text whose lines were counted from 0, moved to the file's
    /// lines: its line (where it has one) plus `first`.
    fn shift_line(&mut self, first: u64) {
        match self {
            Self::MissingColumn { line, .. }
            | Self::DuplicateColumn { line, .. }
            | Self::NotANumber { line, .. }
            | Self::NotFinite { line, .. }
            | Self::FieldCount { line, .. }
            | Self::BadValue { line, .. } => *line += first,
            _ => {}
        }
    }
}

/// Whether the header, read up to byte `rest`, ended with a line: a plain table's chunks
/// see lines as `\n` ends them, and a header ended by a bare `\r` (the csv crate ends a
/// record there too) would leave them a line that is not one.
fn ends_a_line(bytes: &[u8], rest: usize) -> bool {
    match rest.checked_sub(1).and_then(|i| bytes.get(i)) {
        None | Some(b'\n') => true,
        Some(b'\r') => bytes.get(rest) == Some(&b'\n'),
        Some(_) => false,
    }
}

fn parse_cell(text: &str, file: &str, line: u64, column: &str) -> Result<f64, TableError> {
    let value: f64 = text.parse().map_err(|_| TableError::NotANumber {
        file: file.to_owned(),
        line,
        column: column.to_owned(),
        text: text.to_owned(),
    })?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(TableError::NotFinite {
            file: file.to_owned(),
            line,
            column: column.to_owned(),
            text: text.to_owned(),
        })
    }
}

/// Whether a record is a blank line, or a comment line blanked when read: one empty field
/// (fields are trimmed).
fn is_blank(record: &csv::StringRecord) -> bool {
    record.len() == 1 && record.get(0).is_some_and(str::is_empty)
}

fn describe_csv_error(e: &csv::Error) -> String {
    match e.kind() {
        csv::ErrorKind::Io(io) => format!("cannot be read ({io})"),
        _ => e.to_string(),
    }
}

mod plain;

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<NumericTable, TableError> {
        NumericTable::read(text.as_bytes(), "poses.csv", &["x", "y"], &["t"])
    }

    #[test]
    fn reads_required_and_optional_columns_and_skips_others() {
        let t =
            read("note, y ,x\n# a comment\nfoo,2,1\n\nbar,4,3\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.columns, ["x", "y"]);
        assert_eq!((t.line(0), t.row(0)), (3, &[1.0, 2.0][..]));
        assert_eq!((t.line(1), t.row(1)), (5, &[3.0, 4.0][..]));
        assert_eq!(t.len(), 2);
        assert_eq!(t.index("t"), None);
        let t = read("t,x,y\n0.5,1,2\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.index("t"), Some(2));
        assert_eq!(t.row(0), &[1.0, 2.0, 0.5]);
    }

    #[test]
    fn comment_and_blank_lines_before_the_header_are_skipped() {
        for (text, first) in [
            ("# my poses\nx,y\n1,2\n", 3),
            ("  # indented\n\n   \nx,y\n1,2\n", 5),
            ("# a\r\n# b\r\nt,x,y\r\n0,1,2\r\n", 4),
            ("\u{feff}# saved by a spreadsheet\nx,y\n1,2\n", 3),
        ] {
            let t = read(text).unwrap_or_else(|e| panic!("{text:?}: {e}"));
            assert_eq!(t.columns[..2], ["x", "y"], "{text:?}");
            assert_eq!((t.line(0), t.row(0)[..2].to_vec()), (first, vec![1.0, 2.0]));
        }
        // The header's line is the one named when it lacks a column.
        assert_eq!(
            read("# note\nx,z\n1,2\n").unwrap_err().to_string(),
            "poses.csv, line 2: the header has no `y` column (expected columns: x,y)"
        );
        // No header at all: as for an empty file, the first column is missing on line 1.
        for text in ["# only a comment\n", "\n# a\n# b\n", ""] {
            assert_eq!(
                read(text).unwrap_err().to_string(),
                "poses.csv, line 1: the header has no `x` column (expected columns: x,y)"
            );
        }
    }

    #[test]
    fn errors_point_at_file_line_and_column() {
        let msg = |text: &str| read(text).unwrap_err().to_string();
        assert_eq!(
            msg("x,z\n1,2\n"),
            "poses.csv, line 1: the header has no `y` column (expected columns: x,y)"
        );
        assert_eq!(
            msg("x,y\n1,2\n1,abc\n"),
            "poses.csv, line 3, column `y`: `abc` is not a number"
        );
        assert_eq!(
            msg("x,y\n1,2\nNaN,1\n"),
            "poses.csv, line 3, column `x`: NaN is not a finite number"
        );
        assert_eq!(
            msg("x,y\n1,inf\n"),
            "poses.csv, line 2, column `y`: inf is not a finite number"
        );
        assert_eq!(
            msg("x,y\n1,2,3\n"),
            "poses.csv, line 2: 3 fields where the header has 2"
        );
        assert_eq!(
            msg("x,y\n"),
            "poses.csv: the table has a header but no data rows"
        );
        assert_eq!(
            msg("x,y,x\n1,2,3\n"),
            "poses.csv, line 1: the header names column `x` twice"
        );
        assert_eq!(
            msg("x,y\n1,\n"),
            "poses.csv, line 2, column `y`: `` is not a number"
        );
        let bad_utf8: &[u8] = b"x,y\n1,2\n\xff,1\n";
        let e = NumericTable::read(bad_utf8, "poses.csv", &["x", "y"], &[]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "poses.csv: line 3, column 1 is not valid UTF-8 (byte 0xFF; the file may be in Latin-1 or another legacy encoding): save it as UTF-8 text"
        );
    }
}

#[cfg(test)]
mod plain_tests {
    use super::*;
    use proptest::prelude::*;

    /// The table read as [`NumericTable::read_bytes`] reads it (straight from the bytes
    /// where it can), then decoded first (comment lines blanked) and read on all cores
    /// where it can be, and last by the csv crate alone.
    fn all_ways(bytes: &[u8]) -> [Result<NumericTable, TableError>; 3] {
        let read = |cores| {
            let text = text_of(bytes.to_vec(), "t.csv")?;
            NumericTable::read_text(&text, "t.csv", &["x", "y"], &["t"], cores)
        };
        [
            NumericTable::read_bytes(bytes.to_vec(), "t.csv", &["x", "y"], &["t"]),
            read(true),
            read(false),
        ]
    }

    fn both(text: &str) -> [Result<NumericTable, TableError>; 3] {
        all_ways(text.as_bytes())
    }

    /// Every reading agrees with the csv crate's: the same rows, lines and columns, or the
    /// same error.
    fn agree(text: &str) {
        agree_bytes(text.as_bytes());
    }

    fn agree_bytes(bytes: &[u8]) {
        let text = String::from_utf8_lossy(bytes);
        let [fast, cores, csv] = all_ways(bytes);
        for reading in [fast, cores] {
            match (reading, &csv) {
                (Ok(a), Ok(b)) => {
                    assert_eq!(a.columns, b.columns, "{text:?}");
                    assert_eq!(a.lines, b.lines, "{text:?}");
                    assert_eq!(
                        a.values.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                        b.values.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                        "{text:?}"
                    );
                }
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{text:?}"),
                (a, b) => panic!(
                    "{text:?}: {:?} against {:?}",
                    a.map(|t| t.lines),
                    b.as_ref().map(|t| &t.lines)
                ),
            }
        }
    }

    #[test]
    fn tables_read_from_bytes_as_decoded_text_is_read() {
        for bytes in [
            &b"\xEF\xBB\xBFx,y\n1,2\n"[..],
            b"x,y\n1,2\n3,\xFF4\n",
            b"x,y\n1,2\n# caf\xE9\n3,4\n",
            b"x,y # units\n1,2\n",
            b"x,y\n1,2\n3,#4\n",
            b"x,y\n1,2\n\t \t# tabbed, \"quoted\"\n3,4\n",
            b"x,y\n1,2\n\x00",
            b"x,\xFFy\n1,2\n",
            b"q,r\n1,2\n",
            // A header ended by a bare carriage return, then a comment line.
            b"x,y\r# c\n1,2\n",
            b"\xEF\xBB\xBFx,y\r# c\n1,2\n",
            b"x,y\r\n# c\n1,2\n",
            b"x,y",
            b"x,y\r",
        ] {
            agree_bytes(bytes);
        }
    }

    #[test]
    fn plain_tables_read_as_the_csv_crate_reads_them() {
        for text in [
            "x,y\n1,2\n3,4\n",
            "x,y\n1,2\n3,4",
            "x,y\r\n1,2\r\n\r\n3,4\r\n",
            "\n\nx,y\n\n1,2\n   \n\t\n3,4\n\n",
            "# note\nx,y\n# a comment\n1,2\n  # indented comment\n3,4\n",
            " x , y ,t\n 1 , 2 ,0.5\n\t3\t,\t4\t,1\n",
            "t,note,y,x\n0,a,2,1\n1,b,4,3\n",
            "x,y\n\u{a0}1\u{3000},2\n",
            "x,y\n1\n",
            "x,y\n1,2,3\n",
            "x,y\n1,a\n",
            "x,y\n1,\n",
            "x,y\n1,NaN\n",
            "x,y\n1,inf\n",
            "x,y\n1,1e999\n",
            "x,y\n",
            "x,y\n\n# only a comment\n",
            "x,y\n\"1\",2\n",
            "x,y\n1,\"2\n3\"\n",
            "x,y\r1,2\r3,4\r",
            "x,y\n1,2\r3,4\n",
            "x,y\n1,2\n\r",
            "x\n1\n",
            "x,x,y\n1,2,3\n",
        ] {
            agree(text);
        }
    }

    #[test]
    fn line_numbers_and_errors_hold_across_chunks() {
        // Several chunks of rows, with blank and comment lines between them; then the same
        // with an error far in, and with a quote far in (the csv crate reads it all).
        let mut text = String::from("t,x,y\n");
        for k in 0..200_000 {
            text.push_str(&format!("{k},{}.25,-{k}e-3\n", k % 97));
            if k % 1_000 == 0 {
                text.push_str("\n# a comment\n");
            }
        }
        assert!(text.len() > 3 << 20);
        agree(&text);
        // Read straight from the bytes, comment lines and all (not left to the full path).
        let fast = NumericTable::read_plain_bytes(text.as_bytes(), "t.csv", &["x", "y"], &["t"]);
        assert_eq!(fast.map(|t| t.len()), Some(200_000));
        let [t, _, _] = both(&text);
        let t = t.unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.len(), 200_000);
        assert_eq!(t.line(199_999) as usize, text.lines().count());
        let late = text.len() * 3 / 4;
        let line_end = late + text[late..].find('\n').unwrap_or(0);
        for insert in ["1,2,oops\n", "1,2\n", "\"7\",8,9\n", "1,2,3\r4,5,6\n"] {
            let mut broken = text.clone();
            broken.insert_str(line_end + 1, insert);
            agree(&broken);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2_000))]
        #[test]
        fn random_tables_read_alike(body in proptest::collection::vec(
            prop::sample::select(vec!["1", "-2.5", "e3", ",", " ", "\t", "\n", "\r\n", "\r", "\"", "#", "x", "NaN", "\u{a0}"]),
            0..40,
        )) {
            agree(&format!("x,y\n{}", body.concat()));
        }
    }
}
