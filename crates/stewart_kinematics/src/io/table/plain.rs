//! The rows of a plain table on all cores: text with no quote character and no bare
//! carriage return, so that every record is one line and every field the text between
//! two commas — what the csv crate reads it as, field for field (trimmed, blank lines
//! skipped, the same errors at the same lines), in a fraction of the time. Tables with
//! quotes or old Mac line ends go through the csv crate on one thread instead. A chunk
//! that is not plain makes the whole table go that way: an error found in an earlier
//! chunk is found again there.

use rayon::prelude::*;

use super::{TableError, parse_cell};

/// Bytes of text per task: large enough that scheduling is noise.
const CHUNK_BYTES: usize = 1 << 20;

/// Whether `text` is plain: no `"` (no quoted field) and every `\r` followed by `\n`
/// (the csv crate ends a record at a bare `\r` too; line numbers count `\n` only).
fn is_plain(text: &[u8]) -> bool {
    // One search for either (the usual answer: neither).
    memchr::memchr2(b'"', b'\r', text).is_none()
        || (memchr::memchr(b'"', text).is_none()
            && memchr::memchr_iter(b'\r', text).all(|i| text.get(i + 1) == Some(&b'\n')))
}

/// What the rows of a plain table hold: the chosen columns' values, row after row, and
/// each row's line (from 1).
pub(super) struct Rows {
    pub values: Vec<f64>,
    pub lines: Vec<u64>,
    /// While chunks are read: the line this chunk's lines count from, and how many
    /// lines it has.
    first_line: u64,
    line_count: u64,
}

/// The rows of `bytes`, whose first line is line `first_line`: `fields` per record, of
/// which `columns` (name, position) are kept; `None` when the text is not plain or not
/// UTF-8 (each chunk is checked as it is read: a `\n` never splits a character), and the
/// csv crate then reads it.
pub(super) fn read(
    bytes: &[u8],
    first_line: u64,
    file: &str,
    fields: usize,
    columns: &[(&str, usize)],
) -> Option<Result<Rows, TableError>> {
    // Chunk boundaries just after a '\n', so that each chunk holds whole lines.
    let mut starts = vec![0];
    while let Some(&last) = starts.last() {
        let from = last + CHUNK_BYTES;
        if from >= bytes.len() {
            break;
        }
        match bytes[from..].iter().position(|&b| b == b'\n') {
            Some(i) if from + i + 1 < bytes.len() => starts.push(from + i + 1),
            _ => break,
        }
    }
    starts.push(bytes.len());
    let spans: Vec<(usize, usize)> = starts.windows(2).map(|w| (w[0], w[1])).collect();
    let last = columns
        .iter()
        .map(|&(_, position)| position)
        .max()
        .unwrap_or(0);
    // Each chunk read with its lines counted from 0, then placed after the lines of the
    // chunks before it.
    let parts: Vec<Option<Result<Rows, TableError>>> = spans
        .par_iter()
        .map(|&(a, b)| {
            let chunk = &bytes[a..b];
            let text = std::str::from_utf8(chunk).ok()?;
            is_plain(chunk).then(|| read_chunk(text, file, fields, last, columns))
        })
        .collect();
    let parts = parts.into_iter().collect::<Option<Vec<_>>>()?;
    let mut line = first_line;
    let mut placed = Vec::with_capacity(parts.len());
    for part in parts {
        match part {
            Ok(mut rows) => {
                rows.first_line = line;
                line += rows.line_count;
                placed.push(rows);
            }
            // The earliest chunk's error is the file's first.
            Err(mut e) => {
                e.shift_line(line);
                return Some(Err(e));
            }
        }
    }
    Some(Ok(join(placed)))
}

/// The rows of every chunk in one table, copied on all cores (each part's lines made the
/// file's).
fn join(parts: Vec<Rows>) -> Rows {
    let values_len = parts.iter().map(|p| p.values.len()).sum();
    let lines_len = parts.iter().map(|p| p.lines.len()).sum();
    let mut rows = Rows {
        values: vec![0.0; values_len],
        lines: vec![0; lines_len],
        first_line: 0,
        line_count: 0,
    };
    let mut slots = Vec::with_capacity(parts.len());
    let (mut values, mut lines) = (rows.values.as_mut_slice(), rows.lines.as_mut_slice());
    for part in parts {
        let (v, rest_v) = values.split_at_mut(part.values.len());
        let (l, rest_l) = lines.split_at_mut(part.lines.len());
        slots.push((part, v, l));
        (values, lines) = (rest_v, rest_l);
    }
    // Each part is freed as soon as it is copied.
    slots.into_par_iter().for_each(|(part, values, lines)| {
        values.copy_from_slice(&part.values);
        for (to, from) in lines.iter_mut().zip(&part.lines) {
            *to = part.first_line + from;
        }
    });
    rows
}

/// The rows of whole lines `text`, their lines counted from 0; `last` is the last field
/// position any column needs.
fn read_chunk(
    text: &str,
    file: &str,
    fields: usize,
    last: usize,
    columns: &[(&str, usize)],
) -> Result<Rows, TableError> {
    let lines_here = text.len() / 16 + 1;
    let mut rows = Rows {
        values: Vec::with_capacity(lines_here * columns.len()),
        lines: Vec::with_capacity(lines_here),
        first_line: 0,
        line_count: 0,
    };
    let mut cells: Vec<&str> = Vec::with_capacity(last + 1);
    let mut line = 0;
    // Each line, found by a vector-wide search for its end.
    let mut start = 0;
    let ends = memchr::memchr_iter(b'\n', text.as_bytes()).chain(std::iter::once(text.len()));
    for end in ends {
        if end == text.len() && start == end {
            break; // no text after the last line end
        }
        let record = &text[start..end];
        start = end + 1;
        let record = record.strip_suffix('\r').unwrap_or(record);
        if record.trim().is_empty() || is_comment(record) {
            // A blank line, or a comment line (blanked beforehand, or here).
            line += 1;
            continue;
        }
        let found = split_fields(record, last, &mut cells);
        if found != fields {
            return Err(TableError::FieldCount {
                file: file.to_owned(),
                line,
                expected: fields as u64,
                found: found as u64,
            });
        }
        for &(name, position) in columns {
            rows.values
                .push(parse_cell(cells[position], file, line, name)?);
        }
        rows.lines.push(line);
        line += 1;
    }
    rows.line_count = line;
    Ok(rows)
}

/// Whether `record` is a comment line: its first character other than a space or a tab
/// is `#` (as `blank_comments` sees one).
fn is_comment(record: &str) -> bool {
    record.trim_start_matches([' ', '\t']).starts_with('#')
}

/// The trimmed fields of `record` (split at every comma) up to position `last` into
/// `cells`, and how many fields it has: past `last` commas are only counted, a pass the
/// compiler makes vector-wide (a table's unused columns cost little).
fn split_fields<'a>(record: &'a str, last: usize, cells: &mut Vec<&'a str>) -> usize {
    cells.clear();
    let bytes = record.as_bytes();
    let mut from = 0;
    while cells.len() <= last {
        match next_comma(bytes, from) {
            Some(at) => {
                cells.push(trim(&record[from..at]));
                from = at + 1;
            }
            None => {
                cells.push(trim(&record[from..]));
                return cells.len();
            }
        }
    }
    cells.len() + 1 + bytes[from..].iter().filter(|&&b| b == b',').count()
}

/// `field` trimmed ([`str::trim`]), with no look at its characters when it starts and
/// ends with a visible ASCII one (as numbers do): every whitespace character is either
/// ASCII at or below the space, or not ASCII.
fn trim(field: &str) -> &str {
    let visible = |b: Option<&u8>| b.is_some_and(|&b| b > b' ' && b.is_ascii());
    let bytes = field.as_bytes();
    if visible(bytes.first()) && visible(bytes.last()) {
        field
    } else {
        field.trim()
    }
}

/// The position of the first comma in `bytes` from `from` on, looked for eight bytes at
/// a time: in a word of them XOR-ed with commas, a comma is a zero byte, and
/// `(w − 0x01…01) & !w & 0x80…80` marks the lowest zero byte exactly (a borrow can only
/// mark bytes above it).
fn next_comma(bytes: &[u8], from: usize) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGHS: u64 = 0x8080_8080_8080_8080;
    let mut at = from;
    while let Some(word) = bytes.get(at..at + 8) {
        let mut eight = [0; 8];
        eight.copy_from_slice(word);
        let w = u64::from_le_bytes(eight) ^ (ONES * u64::from(b','));
        let zeros = w.wrapping_sub(ONES) & !w & HIGHS;
        if zeros != 0 {
            return Some(at + (zeros.trailing_zeros() / 8) as usize);
        }
        at += 8;
    }
    bytes[at.min(bytes.len())..]
        .iter()
        .position(|&b| b == b',')
        .map(|i| at + i)
}

#[cfg(test)]
mod tests {
    use super::{next_comma, split_fields, trim};

    #[test]
    fn fields_are_trimmed_as_str_trim_trims_them() {
        for c in (0..0x3100)
            .filter_map(char::from_u32)
            .chain(['\u{feff}', '\u{205f}'])
        {
            for field in [
                format!("{c}"),
                format!("{c}1"),
                format!("1{c}"),
                format!("{c}1.5{c}"),
                format!(" {c}"),
            ] {
                assert_eq!(trim(&field), field.trim(), "{:?}", c);
            }
        }
    }

    #[test]
    fn the_next_comma_is_found_at_every_offset_and_in_every_byte_of_a_word() {
        // Commas in every byte of a word, multi-byte characters, and bytes that borrow:
        // 0x2d ('-', one above a comma) and 0x2b after a comma.
        let texts: [&[u8]; 2] = [
            "a,bc,,defghijkl,\u{2c}é,,x,0.14999999998815644,\u{ac}\u{12c},y".as_bytes(),
            b"--,+-,---------,",
        ];
        for bytes in texts {
            for from in 0..=bytes.len() {
                let expected = bytes[from..]
                    .iter()
                    .position(|&b| b == b',')
                    .map(|i| from + i);
                assert_eq!(next_comma(bytes, from), expected, "from {from}");
            }
        }
    }

    #[test]
    fn fields_are_split_at_every_comma_and_trimmed_whatever_the_blocks() {
        for record in [
            "",
            ",",
            "a",
            " 1 , 2 ,3",
            ",,,",
            "0.00001000001000001,1.8849574770617427e-6,0.14999999998815644,0.8000005026553273,x",
            "\u{a0}1\u{3000},é,,ü",
        ] {
            for pad in 0..40 {
                let padded = format!("{}{record}", " ".repeat(pad));
                let expected: Vec<&str> = padded.split(',').map(str::trim).collect();
                for last in 0..6 {
                    let mut cells = Vec::new();
                    let found = split_fields(&padded, last, &mut cells);
                    assert_eq!(found, expected.len(), "{padded:?}");
                    assert_eq!(
                        cells,
                        expected[..expected.len().min(last + 1)],
                        "{padded:?}"
                    );
                }
            }
        }
    }
}
