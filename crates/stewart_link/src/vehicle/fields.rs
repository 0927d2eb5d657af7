//! Little-endian fields at byte offsets of a datagram. A field that runs past the end reads
//! as NaN (a number the sample check refuses, naming it), never a panic.

/// The `f32` at byte `at`, widened.
pub(crate) fn f32_at(bytes: &[u8], at: usize) -> f64 {
    word(bytes, at).map_or(f64::NAN, |w| f64::from(f32::from_le_bytes(w)))
}

/// The `u32` at byte `at` (`None` past the end).
pub(crate) fn u32_at(bytes: &[u8], at: usize) -> Option<u32> {
    word(bytes, at).map(u32::from_le_bytes)
}

/// The `i32` at byte `at` (`None` past the end).
pub(crate) fn i32_at(bytes: &[u8], at: usize) -> Option<i32> {
    word(bytes, at).map(i32::from_le_bytes)
}

/// The `u16` at byte `at` (`None` past the end).
pub(crate) fn u16_at(bytes: &[u8], at: usize) -> Option<u16> {
    let b = bytes.get(at..at.checked_add(2)?)?;
    Some(u16::from_le_bytes([b[0], b[1]]))
}

/// The three `f32` from byte `at`, widened.
pub(crate) fn vector_at(bytes: &[u8], at: usize) -> [f64; 3] {
    [0, 4, 8].map(|k| f32_at(bytes, at + k))
}

fn word(bytes: &[u8], at: usize) -> Option<[u8; 4]> {
    let b = bytes.get(at..at.checked_add(4)?)?;
    Some([b[0], b[1], b[2], b[3]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_read_little_endian_and_past_the_end_reads_nothing() {
        let bytes = [0x00, 0x00, 0x80, 0x3f, 0x01, 0x02];
        assert_eq!(f32_at(&bytes, 0), 1.0);
        assert_eq!(u32_at(&bytes, 0), Some(0x3f80_0000));
        assert_eq!(u16_at(&bytes, 4), Some(0x0201));
        assert!(f32_at(&bytes, 3).is_nan());
        assert_eq!(u32_at(&bytes, usize::MAX - 1), None);
        assert_eq!(i32_at(&bytes, 5), None);
        assert_eq!(u16_at(&bytes, 5), None);
    }
}
