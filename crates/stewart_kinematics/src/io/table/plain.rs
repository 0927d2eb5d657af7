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
    !text.contains(&b'"')
        && (!text.contains(&b'\r')
            || text
                .iter()
                .enumerate()
                .all(|(i, &b)| b != b'\r' || text.get(i + 1) == Some(&b'\n')))
}

/// What the rows of a plain table hold: the chosen columns' values, row after row, and
/// each row's line (from 1).
pub(super) struct Rows {
    pub values: Vec<f64>,
    pub lines: Vec<u64>,
}

/// The rows of `text`, whose first line is line `first_line`: `fields` per record, of
/// which `columns` (name, position) are kept; `None` when the text is not plain (then the
/// csv crate reads it).
pub(super) fn read(
    text: &str,
    first_line: u64,
    file: &str,
    fields: usize,
    columns: &[(&str, usize)],
) -> Option<Result<Rows, TableError>> {
    let bytes = text.as_bytes();
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
    // The line each chunk starts on.
    let newlines: Vec<u64> = spans
        .par_iter()
        .map(|&(a, b)| bytes[a..b].iter().filter(|&&c| c == b'\n').count() as u64)
        .collect();
    let firsts: Vec<u64> = newlines
        .iter()
        .scan(first_line, |line, n| {
            let here = *line;
            *line += n;
            Some(here)
        })
        .collect();
    let parts: Vec<Option<Result<Rows, TableError>>> = spans
        .par_iter()
        .zip(&firsts)
        .map(|(&(a, b), &line)| {
            let chunk = &text[a..b];
            is_plain(chunk.as_bytes()).then(|| read_chunk(chunk, line, file, fields, columns))
        })
        .collect();
    let mut rows = Rows {
        values: Vec::new(),
        lines: Vec::new(),
    };
    for part in parts {
        // The earliest chunk's error is the file's first.
        match part? {
            Ok(part) => {
                rows.values.extend_from_slice(&part.values);
                rows.lines.extend_from_slice(&part.lines);
            }
            Err(e) => return Some(Err(e)),
        }
    }
    Some(Ok(rows))
}

/// The rows of whole lines `text`, the first on line `line`.
fn read_chunk(
    text: &str,
    mut line: u64,
    file: &str,
    fields: usize,
    columns: &[(&str, usize)],
) -> Result<Rows, TableError> {
    let lines_here = text.len() / 16 + 1;
    let mut rows = Rows {
        values: Vec::with_capacity(lines_here * columns.len()),
        lines: Vec::with_capacity(lines_here),
    };
    let mut cells: Vec<&str> = Vec::with_capacity(fields);
    for record in text.split_terminator('\n') {
        let record = record.strip_suffix('\r').unwrap_or(record);
        if record.trim().is_empty() {
            // A blank line, or a comment line (blanked when read).
            line += 1;
            continue;
        }
        split_fields(record, &mut cells);
        if cells.len() != fields {
            return Err(TableError::FieldCount {
                file: file.to_owned(),
                line,
                expected: fields as u64,
                found: cells.len() as u64,
            });
        }
        for &(name, position) in columns {
            rows.values
                .push(parse_cell(cells[position], file, line, name)?);
        }
        rows.lines.push(line);
        line += 1;
    }
    Ok(rows)
}

/// The trimmed fields of `record` (split at every comma) into `cells`. Commas are found 32
/// bytes at a time as a bit mask (a comparison the compiler makes one vector instruction),
/// then taken bit by bit: fields are short, and a branch or a search call per byte or per
/// field costs more.
fn split_fields<'a>(record: &'a str, cells: &mut Vec<&'a str>) {
    const BLOCK: usize = 32;
    cells.clear();
    let bytes = record.as_bytes();
    let mut from = 0;
    let mut push_commas = |base: usize, mut mask: u32| {
        while mask != 0 {
            let at = base + mask.trailing_zeros() as usize;
            cells.push(record[from..at].trim());
            from = at + 1;
            mask &= mask - 1;
        }
    };
    // Bit i set where byte i of a block (at most 32 bytes) is a comma.
    let commas = |block: &[u8]| {
        block
            .iter()
            .enumerate()
            .fold(0_u32, |m, (i, &b)| m | (u32::from(b == b',') << i))
    };
    let mut blocks = bytes.chunks_exact(BLOCK);
    let mut base = 0;
    for block in &mut blocks {
        push_commas(base, commas(block));
        base += BLOCK;
    }
    push_commas(base, commas(blocks.remainder()));
    cells.push(record[from..].trim());
}

#[cfg(test)]
mod tests {
    use super::split_fields;

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
                let mut cells = Vec::new();
                split_fields(&padded, &mut cells);
                let expected: Vec<&str> = padded.split(',').map(str::trim).collect();
                assert_eq!(cells, expected, "{padded:?}");
            }
        }
    }
}
