//! The one error a value on the command line is refused with: what was written and why,
//! worded as clap shows it after the option's name (`error: invalid value '…' for
//! '--rate <HZ>': …`).

use std::fmt;

use stewart_kinematics::ground::bounds::OutOfBounds;
use stewart_link::template::TemplateError;

/// Why a value given on the command line is refused.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ArgError {
    /// `text` is not what the option takes: `expected` (a number, a number of hertz, a
    /// size like 1280x720, one of the choices…).
    NotA {
        /// What was written.
        text: String,
        /// What the option takes, with an article.
        expected: String,
    },
    /// `text` reads as a number, but not a finite one.
    NotFinite {
        /// What was written.
        text: String,
    },
    /// A number outside its range.
    OutOfRange {
        /// What the number is (none where the option's name says it).
        quantity: Option<&'static str>,
        /// The range, in words.
        range: String,
        /// The number as given.
        got: String,
    },
    /// One of several numbers in one value (`x` of `X,Y,Z`) outside its range.
    Component {
        /// The number's name.
        name: &'static str,
        /// Why.
        reason: OutOfBounds,
    },
    /// A side of an image outside the sizes that can be drawn.
    Pixels {
        /// The side asked for.
        got: u32,
        /// The smallest side.
        min: u32,
        /// The largest side.
        max: u32,
    },
    /// A readout title longer than a line holds.
    LongTitle {
        /// Its characters.
        chars: usize,
        /// The most a line holds.
        max: usize,
    },
    /// A readout title with a control character (a line break, a tab…).
    TitleControl {
        /// The character.
        found: char,
    },
    /// An output template refused at a column.
    Template(TemplateError),
    /// `template` without the template itself.
    TemplateNotWritten,
}

impl ArgError {
    /// `text` is not `expected`.
    pub(crate) fn not_a(text: &str, expected: impl Into<String>) -> Self {
        Self::NotA {
            text: text.to_owned(),
            expected: expected.into(),
        }
    }

    /// `got` is outside `range`.
    pub(crate) fn out_of_range(
        quantity: Option<&'static str>,
        range: impl Into<String>,
        got: impl ToString,
    ) -> Self {
        Self::OutOfRange {
            quantity,
            range: range.into(),
            got: got.to_string(),
        }
    }
}

impl fmt::Display for ArgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotA { text, expected } => write!(f, "`{text}` is not {expected}"),
            Self::NotFinite { text } => write!(f, "{text} is not a finite number"),
            Self::OutOfRange {
                quantity,
                range,
                got,
            } => {
                if let Some(quantity) = quantity {
                    write!(f, "{quantity} ")?;
                }
                write!(f, "must be {range}, got {got}")
            }
            Self::Component { name, reason } => write!(f, "{name} {reason}"),
            Self::Pixels { got, min, max } => write!(f, "{got} pixels is outside {min}..={max}"),
            Self::LongTitle { chars, max } => {
                write!(
                    f,
                    "the title has {chars} characters; at most {max} fit a line"
                )
            }
            Self::TitleControl { found } => write!(
                f,
                "the title must be one line of text, without control characters (found U+{:04X})",
                u32::from(*found)
            ),
            Self::Template(e) => write!(f, "{e}"),
            Self::TemplateNotWritten => write!(
                f,
                "a template is written out: template:<255><255>{{a1:u16be}}…{{a6:u16be}}"
            ),
        }
    }
}

impl std::error::Error for ArgError {}
