//! Output templates: the byte strings hobby boards read, written as FlyPT Mover's and
//! SimTools' output strings are — `<255><255>{a1:u16be}{a2:u16be}…<10><13>`.
//!
//! - `<N>` is the byte N (0–255);
//! - `{aK:T}` is actuator K's value (K = 1–6) scaled linearly from its range — the stroke
//!   or the servo range: the minimum → 0, the maximum → the type's largest value, rounded
//!   to nearest — written as `T`:
//!
//! | `T` | bytes | largest |
//! |---|---|---|
//! | `u8` | 1 | 255 |
//! | `u10be` | 2, big-endian | 1023 |
//! | `u12be` | 2, big-endian | 4095 |
//! | `u16be` | 2, big-endian | 65535 |
//! | `u16le` | 2, little-endian | 65535 |
//! | `u24be` | 3, big-endian | 16777215 |
//! | `u32be` | 4, big-endian | 4294967295 |
//! | `dec` | the decimal digits of the 16-bit value (1–5) | 65535 |
//! | `dec3` | three decimal digits | 999 |
//!
//! - any other printable ASCII character (a space included) is itself, as a byte: `[A` in
//!   `[A{a1:u10be}]`.
//!
//! A template that names an actuator outside 1–6, an unknown type, a byte over 255, no
//! actuator at all, or holds a character that is not printable ASCII is refused with the
//! column (counted in characters from 1) at fault. [`TemplateDecoder`] reads a stream of
//! such frames back (the stand-in controller's side).

use thiserror::Error;

mod decode;

pub use decode::{TemplateDecoder, TemplateFrame};

/// How an actuator's value is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldType {
    /// One byte.
    U8,
    /// Ten bits in two bytes, big-endian.
    U10Be,
    /// Twelve bits in two bytes, big-endian.
    U12Be,
    /// Two bytes, big-endian.
    U16Be,
    /// Two bytes, little-endian.
    U16Le,
    /// Three bytes, big-endian.
    U24Be,
    /// Four bytes, big-endian.
    U32Be,
    /// The 16-bit value in decimal digits.
    Dec,
    /// Three decimal digits, 0–999.
    Dec3,
}

impl FieldType {
    /// Every type's name, comma-separated (`u8, u10be, …`).
    pub fn names() -> String {
        (Self::ALL.iter())
            .map(|(_, n)| *n)
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Every type, with its name in templates.
    pub const ALL: [(FieldType, &'static str); 9] = [
        (FieldType::U8, "u8"),
        (FieldType::U10Be, "u10be"),
        (FieldType::U12Be, "u12be"),
        (FieldType::U16Be, "u16be"),
        (FieldType::U16Le, "u16le"),
        (FieldType::U24Be, "u24be"),
        (FieldType::U32Be, "u32be"),
        (FieldType::Dec, "dec"),
        (FieldType::Dec3, "dec3"),
    ];

    /// The largest value written (the top of the actuator's range).
    pub fn largest(self) -> u32 {
        match self {
            FieldType::U8 => 0xff,
            FieldType::U10Be => 0x3ff,
            FieldType::U12Be => 0xfff,
            FieldType::U16Be | FieldType::U16Le | FieldType::Dec => 0xffff,
            FieldType::U24Be => 0xff_ffff,
            FieldType::U32Be => u32::MAX,
            FieldType::Dec3 => 999,
        }
    }

    /// Write `n` (at most [`FieldType::largest`]).
    fn write(self, n: u32, out: &mut Vec<u8>) {
        let be = n.to_be_bytes();
        match self {
            FieldType::U8 => out.push(be[3]),
            FieldType::U10Be | FieldType::U12Be | FieldType::U16Be => out.extend(&be[2..]),
            FieldType::U16Le => out.extend([be[3], be[2]]),
            FieldType::U24Be => out.extend(&be[1..]),
            FieldType::U32Be => out.extend(be),
            FieldType::Dec => {
                // At most five digits, without leading zeros; no allocation.
                let mut digits = [0u8; 5];
                let mut k = digits.len();
                let mut rest = n;
                loop {
                    k -= 1;
                    digits[k] = b'0' + (rest % 10) as u8;
                    rest /= 10;
                    if rest == 0 {
                        break;
                    }
                }
                out.extend(&digits[k..]);
            }
            FieldType::Dec3 => out.extend([
                b'0' + (n / 100 % 10) as u8,
                b'0' + (n / 10 % 10) as u8,
                b'0' + (n % 10) as u8,
            ]),
        }
    }
}

/// One piece of a template.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TemplatePiece {
    /// A byte, as it is.
    Byte(u8),
    /// An actuator's value (`actuator`: 0–5).
    Field {
        /// Which actuator, from 0.
        actuator: usize,
        /// How it is written.
        kind: FieldType,
    },
}

/// A parsed template.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Template {
    pieces: Vec<TemplatePiece>,
    text: String,
}

/// Why a template was refused: where, and what.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
#[error("template column {column}: {fault}")]
pub struct TemplateError {
    /// The column at fault, counted in characters from 1.
    pub column: usize,
    /// What is wrong there.
    pub fault: TemplateFault,
}

/// What is wrong at a template's column. Its `Display` is the English sentence; an
/// interface in another language words each variant from its own catalogue.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum TemplateFault {
    /// `<` or `{` without its closing `>` or `}`.
    #[error("`{open}` is not closed by `{close}`")]
    NotClosed {
        /// The opening character.
        open: char,
        /// The closing one it needs.
        close: char,
    },
    /// `>` or `}` with nothing open.
    #[error("`{0}` closes nothing")]
    ClosesNothing(char),
    /// A character that is not printable ASCII.
    #[error("`{}` is not printable ASCII: write a byte as <N>", .0.escape_default())]
    NotPrintable(char),
    /// `{aK:dec}` not followed by a byte that ends its digits.
    #[error("{{a{}:dec}} has no end: follow it with a byte that is not a digit, such as `,` or <10>", .actuator + 1)]
    DecWithoutEnd {
        /// The actuator, from 0.
        actuator: usize,
    },
    /// No `{aK:T}` at all.
    #[error("no actuator: write at least one {{aK:T}}, such as {{a1:u16be}}")]
    NoActuator,
    /// `<N>` over 255.
    #[error("<{0}> is over 255: a byte is 0 to 255")]
    ByteOver(u32),
    /// `<…>` that is not a number.
    #[error("<{0}> is not a byte: write <0> to <255>")]
    NotAByte(String),
    /// `{…}` that is not `{aK:T}`.
    #[error("{{{0}}} is not {{aK:T}} (actuator K = 1 to 6, type T: {types})", types = FieldType::names())]
    NotAField(String),
    /// `{aK:…}` whose K is not 1 to 6.
    #[error("`{0}` names no actuator: a1 to a6")]
    NoSuchActuator(String),
    /// `{…:T}` whose T is not a type.
    #[error("`{0}` is not a type: {types}", types = FieldType::names())]
    NoSuchType(String),
}

impl Template {
    /// Parse `text` (without the `template:` prefix).
    pub fn parse(text: &str) -> Result<Self, TemplateError> {
        let chars: Vec<char> = text.chars().collect();
        let refuse = |column: usize, fault: TemplateFault| Err(TemplateError { column, fault });
        let mut pieces = Vec::new();
        let mut k = 0;
        while k < chars.len() {
            let column = k + 1;
            match chars[k] {
                open @ ('<' | '{') => {
                    let close = if open == '<' { '>' } else { '}' };
                    let Some(len) = chars[k + 1..].iter().position(|&c| c == close) else {
                        return refuse(column, TemplateFault::NotClosed { open, close });
                    };
                    let inside: String = chars[k + 1..k + 1 + len].iter().collect();
                    pieces.push(if open == '<' {
                        byte(&inside).map_err(|fault| TemplateError { column, fault })?
                    } else {
                        field(&inside).map_err(|fault| TemplateError { column, fault })?
                    });
                    k += len + 2;
                }
                c @ ('>' | '}') => {
                    return refuse(column, TemplateFault::ClosesNothing(c));
                }
                c if c.is_ascii() && !c.is_ascii_control() => {
                    pieces.push(TemplatePiece::Byte(c as u8));
                    k += 1;
                }
                c => {
                    return refuse(column, TemplateFault::NotPrintable(c));
                }
            }
        }
        // A `dec` field's digits end where the next byte is not a digit: it must be
        // followed by one, or no board (and no reader) can tell where the number ends.
        for (k, piece) in pieces.iter().enumerate() {
            if let TemplatePiece::Field {
                kind: FieldType::Dec,
                actuator,
            } = piece
            {
                let next = pieces.get(k + 1);
                if !matches!(next, Some(TemplatePiece::Byte(b)) if !b.is_ascii_digit()) {
                    return refuse(
                        column_of(&chars, k),
                        TemplateFault::DecWithoutEnd {
                            actuator: *actuator,
                        },
                    );
                }
            }
        }
        if !pieces
            .iter()
            .any(|p| matches!(p, TemplatePiece::Field { .. }))
        {
            return refuse(chars.len().max(1), TemplateFault::NoActuator);
        }
        Ok(Self {
            pieces,
            text: text.to_owned(),
        })
    }

    /// The pieces, in order.
    pub fn pieces(&self) -> &[TemplatePiece] {
        &self.pieces
    }

    /// The template as written.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The longest frame it writes, bytes.
    pub fn max_len(&self) -> usize {
        (self.pieces.iter())
            .map(|p| match p {
                TemplatePiece::Byte(_) => 1,
                TemplatePiece::Field { kind, .. } => match kind {
                    FieldType::U8 => 1,
                    FieldType::U24Be | FieldType::Dec3 => 3,
                    FieldType::U32Be => 4,
                    FieldType::Dec => 5,
                    _ => 2,
                },
            })
            .sum()
    }

    /// Append the frame for actuator `values` within `ranges` (`(lo, hi)` each) to `out`.
    /// A value outside its range is written at the range's end; a range that is empty or
    /// not a number writes 0.
    pub fn encode(&self, values: &[f64; 6], ranges: &[(f64, f64); 6], out: &mut Vec<u8>) {
        for piece in &self.pieces {
            match *piece {
                TemplatePiece::Byte(b) => out.push(b),
                TemplatePiece::Field { actuator, kind } => {
                    kind.write(scaled(values[actuator], ranges[actuator], kind), out);
                }
            }
        }
    }
}

/// `value` within `(lo, hi)` as a whole number from 0 to `kind`'s largest, rounded to
/// nearest.
pub fn scaled(value: f64, (lo, hi): (f64, f64), kind: FieldType) -> u32 {
    let fraction = ((value - lo) / (hi - lo)).clamp(0.0, 1.0);
    if !fraction.is_finite() || hi <= lo {
        return 0;
    }
    (fraction * f64::from(kind.largest())).round() as u32
}

/// The actuator value a field's number `n` stands for within `(lo, hi)` (the inverse of
/// [`scaled`], to its resolution).
pub fn unscaled(n: u32, (lo, hi): (f64, f64), kind: FieldType) -> f64 {
    lo + (hi - lo) * f64::from(n) / f64::from(kind.largest())
}

/// The column (from 1) where piece `index` of the template `chars` begins.
fn column_of(chars: &[char], index: usize) -> usize {
    let mut k = 0;
    for _ in 0..index {
        k += match chars.get(k) {
            Some(&open @ ('<' | '{')) => {
                let close = if open == '<' { '>' } else { '}' };
                chars[k..]
                    .iter()
                    .position(|&c| c == close)
                    .map_or(1, |len| len + 1)
            }
            _ => 1,
        };
    }
    k + 1
}

/// The byte of `<N>`.
fn byte(inside: &str) -> Result<TemplatePiece, TemplateFault> {
    match inside.trim().parse::<u32>() {
        Ok(n) if n <= 255 => Ok(TemplatePiece::Byte(n as u8)),
        Ok(n) => Err(TemplateFault::ByteOver(n)),
        Err(_) => Err(TemplateFault::NotAByte(inside.to_owned())),
    }
}

/// The field of `{aK:T}`.
fn field(inside: &str) -> Result<TemplatePiece, TemplateFault> {
    let Some((actuator, kind)) = inside.split_once(':') else {
        return Err(TemplateFault::NotAField(inside.to_owned()));
    };
    let k = (actuator.trim().strip_prefix('a'))
        .and_then(|k| k.parse::<usize>().ok())
        .filter(|k| (1..=6).contains(k))
        .ok_or_else(|| TemplateFault::NoSuchActuator(actuator.to_owned()))?;
    let kind = (FieldType::ALL.iter())
        .find(|(_, n)| *n == kind.trim())
        .map(|(t, _)| *t)
        .ok_or_else(|| TemplateFault::NoSuchType(kind.to_owned()))?;
    Ok(TemplatePiece::Field {
        actuator: k - 1,
        kind,
    })
}

#[cfg(test)]
mod tests;
