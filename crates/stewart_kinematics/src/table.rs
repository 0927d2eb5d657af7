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

/// One data row: its line in the file and its values, in the order the columns were asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Line of the row in the file, from 1.
    pub line: u64,
    /// Values of the requested columns (required ones first, then the optional ones present).
    pub values: Vec<f64>,
}

/// The requested numeric columns of a CSV table.
#[derive(Clone, Debug, PartialEq)]
pub struct NumericTable {
    /// File name, for messages.
    pub file: String,
    /// Names of the columns held, in the order of [`Row::values`].
    pub columns: Vec<String>,
    /// The data rows.
    pub rows: Vec<Row>,
}

impl NumericTable {
    /// Position of column `name` in [`Row::values`], if the table has it.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.columns.iter().position(|c| c == name)
    }

    /// Read `required` columns (all must be present) and whichever `optional` columns
    /// are present from CSV text; other columns are ignored.
    pub fn read(
        input: impl Read,
        file: &str,
        required: &[&str],
        optional: &[&str],
    ) -> Result<Self, TableError> {
        let text = blank_comments(&read_text(input, file)?);
        // Lines are found from byte offsets: the csv crate's own line count skips blank lines.
        // A record's position may point at the blank lines before it; skip those.
        let line_of = |pos: Option<&csv::Position>| {
            pos.map_or(1, |p| {
                let start = p.byte() as usize;
                let skip = text.as_bytes()[start.min(text.len())..]
                    .iter()
                    .take_while(|b| matches!(b, b'\n' | b'\r'))
                    .count();
                line_at(&text, start + skip)
            })
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .flexible(true)
            .from_reader(text.as_bytes());
        let unreadable = |e: csv::Error| TableError::Unreadable {
            file: file.to_owned(),
            message: describe_csv_error(&e),
        };
        let header = reader.headers().map_err(unreadable)?.clone();
        let header_line = line_of(header.position());
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
        let mut rows = Vec::new();
        for record in reader.records() {
            let record = record.map_err(unreadable)?;
            let line = line_of(record.position());
            if record.len() == 1 && record.get(0).is_some_and(str::is_empty) {
                continue; // a blank line
            }
            if record.len() != header.len() {
                return Err(TableError::FieldCount {
                    file: file.to_owned(),
                    line,
                    expected: header.len() as u64,
                    found: record.len() as u64,
                });
            }
            let mut values = Vec::with_capacity(positions.len());
            for (name, &pos) in columns.iter().zip(&positions) {
                let text = record.get(pos).unwrap_or("");
                values.push(parse_cell(text, file, line, name)?);
            }
            rows.push(Row { line, values });
        }
        if rows.is_empty() {
            return Err(TableError::NoRows {
                file: file.to_owned(),
            });
        }
        Ok(Self {
            file: file.to_owned(),
            columns,
            rows,
        })
    }
}

/// The whole input as text, or an error naming the first line that is not UTF-8.
fn read_text(mut input: impl Read, file: &str) -> Result<String, TableError> {
    let mut bytes = Vec::new();
    input
        .read_to_end(&mut bytes)
        .map_err(|e| TableError::Unreadable {
            file: file.to_owned(),
            message: format!("cannot be read ({e})"),
        })?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let line = 1 + e.as_bytes()[..valid]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        TableError::Unreadable {
            file: file.to_owned(),
            message: format!("line {line} is not valid UTF-8 text"),
        }
    })
}

/// The text with every comment line (first non-blank character `#`) emptied, so that
/// byte offsets and line numbers stay those of the file.
fn blank_comments(text: &str) -> String {
    text.split_inclusive('\n')
        .map(|line| {
            if line.trim_start().starts_with('#') {
                if line.ends_with("\r\n") {
                    "\r\n"
                } else if line.ends_with('\n') {
                    "\n"
                } else {
                    ""
                }
            } else {
                line
            }
        })
        .collect()
}

/// Line number (from 1) of byte offset `byte` in `text`.
pub(crate) fn line_at(text: &str, byte: usize) -> u64 {
    1 + text.as_bytes()[..byte.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count() as u64
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

fn describe_csv_error(e: &csv::Error) -> String {
    match e.kind() {
        csv::ErrorKind::Io(io) => format!("cannot be read ({io})"),
        _ => e.to_string(),
    }
}

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
        assert_eq!(
            t.rows[0],
            Row {
                line: 3,
                values: vec![1.0, 2.0]
            }
        );
        assert_eq!(
            t.rows[1],
            Row {
                line: 5,
                values: vec![3.0, 4.0]
            }
        );
        assert_eq!(t.index("t"), None);
        let t = read("t,x,y\n0.5,1,2\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.index("t"), Some(2));
        assert_eq!(t.rows[0].values, vec![1.0, 2.0, 0.5]);
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
        assert_eq!(e.to_string(), "poses.csv: line 3 is not valid UTF-8 text");
    }
}
