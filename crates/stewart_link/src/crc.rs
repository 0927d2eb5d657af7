//! CRC-16/CCITT-FALSE: polynomial 0x1021 (x¹⁶ + x¹² + x⁵ + 1), initial value 0xFFFF, no
//! reflection of input or output, no final XOR. Its check value (the CRC of the ASCII
//! bytes `123456789`) is 0x29B1. Bitwise, so that firmware can copy it line for line.

/// The generator polynomial, x¹⁶ + x¹² + x⁵ + 1 without the x¹⁶ term.
pub const POLYNOMIAL: u16 = 0x1021;
/// The register's starting value.
pub const INITIAL: u16 = 0xFFFF;

/// CRC-16/CCITT-FALSE of `bytes`.
pub fn crc16(bytes: &[u8]) -> u16 {
    let mut crc = INITIAL;
    for &b in bytes {
        crc ^= u16::from(b) << 8;
        for _ in 0..8 {
            crc = if crc & 0x8000 != 0 {
                (crc << 1) ^ POLYNOMIAL
            } else {
                crc << 1
            };
        }
    }
    crc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_check_value() {
        // The check value of CRC-16/CCITT-FALSE in the CRC catalogue (Greg Cook's
        // "Catalogue of parametrised CRC algorithms", also called CRC-16/IBM-3740).
        assert_eq!(crc16(b"123456789"), 0x29B1);
        assert_eq!(crc16(b""), 0xFFFF);
        // One flipped bit changes it.
        assert_ne!(crc16(b"123456788"), 0x29B1);
    }
}
