//! Reading input text: a size cap (so that `/dev/zero` or a wrong file cannot exhaust
//! memory), and plain words for files that are not UTF-8 (UTF-16 from Windows tools,
//! Latin-1 from older ones, binary files).

use std::io::Read;

/// Largest scenario file read, bytes (a scenario is a few kilobytes).
pub const MAX_SCENARIO_BYTES: u64 = 16 << 20;

/// Largest CSV table read, bytes (a million poses take about 100 MB).
pub const MAX_TABLE_BYTES: u64 = 2 << 30;

/// An array of exactly `N` values from a file: a longer or shorter one is refused, not
/// cut (serde reads an array of `N` from the first `N` values of a longer one). For
/// `#[serde(deserialize_with = "crate::ground::text::exactly")]` on every fixed-size array field.
pub fn exactly<'de, D, T, const N: usize>(d: D) -> Result<[T; N], D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::Deserialize<'de>,
{
    let values = <Vec<T> as serde::Deserialize>::deserialize(d)?;
    let got = values.len();
    values
        .try_into()
        .map_err(|_| serde::de::Error::custom(format!("expected {N} values, got {got}")))
}

/// [`exactly`] keeping where the array was in the file.
pub fn exactly_spanned<'de, D, T, const N: usize>(d: D) -> Result<toml::Spanned<[T; N]>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::Deserialize<'de>,
{
    let values = <toml::Spanned<Vec<T>> as serde::Deserialize>::deserialize(d)?;
    let span = values.span();
    let values = values.into_inner();
    let got = values.len();
    let array: [T; N] = values
        .try_into()
        .map_err(|_| serde::de::Error::custom(format!("expected {N} values, got {got}")))?;
    Ok(toml::Spanned::new(span, array))
}

/// All of `input`, or a sentence saying why not (an I/O error, or more than `limit` bytes).
pub fn read_capped(mut input: impl Read, limit: u64) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    input
        .by_ref()
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot be read ({e})"))?;
    if bytes.len() as u64 > limit {
        return Err(format!(
            "is larger than {} MiB, the most this program reads from such a file",
            limit >> 20
        ));
    }
    Ok(bytes)
}

/// When `bytes` are plainly not UTF-8 text, what they are, as the end of a sentence
/// starting with the file's name: `is UTF-16 text`.
pub fn foreign_encoding(bytes: &[u8]) -> Option<&'static str> {
    if bytes.starts_with(&[0xFF, 0xFE, 0, 0]) || bytes.starts_with(&[0, 0, 0xFE, 0xFF]) {
        return Some("is UTF-32 text");
    }
    if bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]) {
        return Some("is UTF-16 text");
    }
    let head = &bytes[..bytes.len().min(4096)];
    let zeros = head.iter().filter(|&&b| b == 0).count();
    if zeros > 0 {
        // UTF-16 without a byte-order mark: every other byte of ASCII text is zero.
        let alternate = head.iter().skip(1).step_by(2).filter(|&&b| b == 0).count();
        let alternate_even = head.iter().step_by(2).filter(|&&b| b == 0).count();
        if head.len() >= 4
            && (2 * alternate >= head.len() / 2 || 2 * alternate_even >= head.len() / 2)
        {
            return Some("is UTF-16 text");
        }
        return Some("contains NUL bytes: it is not a text file");
    }
    None
}

/// `bytes` without a leading UTF-8 byte-order mark (which some editors write).
pub fn strip_utf8_bom(mut bytes: Vec<u8>) -> Vec<u8> {
    if bytes.starts_with(&[0xEF, 0xBB, 0xBF]) {
        bytes.drain(..3);
    }
    bytes
}

/// Where UTF-8 decoding stopped, in words: `line 3, column 7 is not valid UTF-8 (byte
/// 0xE9): …`.
pub fn not_utf8_message(bytes: &[u8], valid_up_to: usize) -> String {
    let before = &bytes[..valid_up_to.min(bytes.len())];
    let line = 1 + before.iter().filter(|&&b| b == b'\n').count();
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    let column = 1 + String::from_utf8_lossy(&before[line_start..])
        .chars()
        .count();
    let byte = bytes.get(valid_up_to).copied().unwrap_or(0);
    format!(
        "line {line}, column {column} is not valid UTF-8 (byte 0x{byte:02X}; the file may be in Latin-1 or another legacy encoding): save it as UTF-8 text"
    )
}

/// Decode `bytes` as UTF-8 text (a byte-order mark is dropped), or say in words why it
/// is not text.
pub fn decode(bytes: Vec<u8>) -> Result<String, String> {
    if let Some(what) = foreign_encoding(&bytes) {
        return Err(format!("{what}; save it as UTF-8 text"));
    }
    String::from_utf8(strip_utf8_bom(bytes)).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        not_utf8_message(e.as_bytes(), valid)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_foreign_encodings() {
        let utf16le: Vec<u8> = "x,y\n1,2\n"
            .encode_utf16()
            .flat_map(u16::to_le_bytes)
            .collect();
        assert_eq!(foreign_encoding(&utf16le), Some("is UTF-16 text"));
        let mut with_bom = vec![0xFF, 0xFE];
        with_bom.extend(&utf16le);
        assert_eq!(foreign_encoding(&with_bom), Some("is UTF-16 text"));
        assert_eq!(
            foreign_encoding(b"x,y\n\0\x01\x02\x03binary"),
            Some("contains NUL bytes: it is not a text file")
        );
        assert_eq!(foreign_encoding(b"x,y\n1,2\n"), None);
    }

    #[test]
    fn latin1_is_located() {
        let latin1 = b"a = 1\n# caf\xe9\n";
        assert_eq!(
            decode(latin1.to_vec()).unwrap_err(),
            "line 2, column 6 is not valid UTF-8 (byte 0xE9; the file may be in Latin-1 or another legacy encoding): save it as UTF-8 text"
        );
        assert_eq!(
            decode(b"\xEF\xBB\xBFa = 1\n".to_vec()).as_deref(),
            Ok("a = 1\n")
        );
    }

    #[test]
    fn reading_stops_at_the_cap() {
        let zeros = std::io::repeat(0);
        let e = read_capped(zeros, 1 << 20).unwrap_err();
        assert_eq!(
            e,
            "is larger than 1 MiB, the most this program reads from such a file"
        );
        assert_eq!(read_capped(&b"abc"[..], 3).as_deref(), Ok(&b"abc"[..]));
    }
}
