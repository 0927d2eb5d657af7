//! Bytes as a person reads them in a narrow panel: rows of eight, each byte in hex and,
//! beside the row, the same bytes as text (printable ASCII as it is, anything else `·`),
//! so that a text protocol and a binary one are both recognised at a glance.

/// Bytes in each row.
pub(crate) const PER_ROW: usize = 8;

/// The rows: `FF FF 03 E8 …  ··.·` — hex, padded to a full row, then the text.
pub(crate) fn rows(bytes: &[u8]) -> Vec<String> {
    bytes
        .chunks(PER_ROW)
        .map(|row| {
            let hex: Vec<String> = row.iter().map(|b| format!("{b:02X}")).collect();
            let text: String = row
                .iter()
                .map(|&b| {
                    if (0x20..0x7f).contains(&b) {
                        char::from(b)
                    } else {
                        '·'
                    }
                })
                .collect();
            format!("{:<width$}  {text}", hex.join(" "), width = 3 * PER_ROW - 1)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::rows;

    #[test]
    fn each_row_shows_eight_bytes_in_hex_and_as_text() {
        let bytes = b"A1=512\r\n\xff\x00Z";
        let r = rows(bytes);
        assert_eq!(
            r,
            [
                "41 31 3D 35 31 32 0D 0A  A1=512··",
                "FF 00 5A                 ··Z"
            ]
        );
        assert!(rows(&[]).is_empty());
    }
}
