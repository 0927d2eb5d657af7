//! Reading a stream of template frames back: the stand-in controller's side. Bytes are
//! matched against the template piece by piece; where they do not match, one byte is
//! skipped (counted) and matching starts again, so a stream joined in the middle of a frame,
//! or a damaged byte, costs one frame.

use super::{FieldType, Template, TemplatePiece};

/// The numbers of one frame: each actuator's field as written (`None` where the template
/// has none for it; the last, when it has several).
pub type TemplateFrame = [Option<u32>; 6];

/// Reads frames of one template out of a byte stream.
#[derive(Clone, Debug)]
pub struct TemplateDecoder {
    template: Template,
    buffer: Vec<u8>,
    skipped: u64,
}

/// How matching the buffer's start went.
enum Match {
    /// A frame of this many bytes.
    Frame(TemplateFrame, usize),
    /// Not a frame here.
    No,
    /// Could be one: more bytes are needed.
    Wait,
}

impl TemplateDecoder {
    /// A decoder of `template`'s frames.
    pub fn new(template: Template) -> Self {
        Self {
            template,
            buffer: Vec::new(),
            skipped: 0,
        }
    }

    /// Bytes that matched no frame, so far.
    pub fn skipped(&self) -> u64 {
        self.skipped
    }

    /// Whether bytes wait that may begin a frame.
    pub fn pending(&self) -> bool {
        !self.buffer.is_empty()
    }

    /// Forget the bytes waiting (a datagram that stands alone ended).
    pub fn reset(&mut self) {
        self.buffer.clear();
    }

    /// Take `bytes` in; [`TemplateDecoder::next_frame`] gives the frames they complete.
    pub fn push(&mut self, bytes: &[u8]) {
        self.buffer.extend_from_slice(bytes);
    }

    /// The next whole frame, if the bytes in hold one.
    pub fn next_frame(&mut self) -> Option<TemplateFrame> {
        loop {
            match self.match_start() {
                Match::Frame(frame, len) => {
                    self.buffer.drain(..len);
                    return Some(frame);
                }
                Match::Wait => return None,
                Match::No => {
                    self.buffer.remove(0);
                    self.skipped += 1;
                }
            }
        }
    }

    fn match_start(&self) -> Match {
        let b = &self.buffer;
        if b.is_empty() {
            return Match::Wait;
        }
        let mut frame = [None; 6];
        let mut at = 0;
        for piece in self.template.pieces() {
            match *piece {
                TemplatePiece::Byte(want) => match b.get(at) {
                    None => return Match::Wait,
                    Some(&got) if got == want => at += 1,
                    Some(_) => return Match::No,
                },
                TemplatePiece::Field { actuator, kind } => match read(kind, &b[at..]) {
                    Read::Value(n, len) => {
                        frame[actuator] = Some(n);
                        at += len;
                    }
                    Read::Wait => return Match::Wait,
                    Read::No => return Match::No,
                },
            }
        }
        Match::Frame(frame, at)
    }
}

enum Read {
    Value(u32, usize),
    Wait,
    No,
}

/// A field of `kind` at the start of `b`.
fn read(kind: FieldType, b: &[u8]) -> Read {
    let fixed = |len: usize, value: fn(&[u8]) -> u32| match b.get(..len) {
        None => Read::Wait,
        Some(bytes) => match value(bytes) {
            n if n <= kind.largest() => Read::Value(n, len),
            _ => Read::No,
        },
    };
    let be = |bytes: &[u8]| bytes.iter().fold(0u32, |n, &x| (n << 8) | u32::from(x));
    match kind {
        FieldType::U8 => fixed(1, be),
        FieldType::U10Be | FieldType::U12Be | FieldType::U16Be => fixed(2, be),
        FieldType::U16Le => fixed(2, |x| u32::from(u16::from_le_bytes([x[0], x[1]]))),
        FieldType::U24Be => fixed(3, be),
        FieldType::U32Be => fixed(4, be),
        FieldType::Dec3 => match b.get(..3) {
            None => Read::Wait,
            Some(d) if d.iter().all(u8::is_ascii_digit) => {
                Read::Value(d.iter().fold(0, |n, &x| n * 10 + u32::from(x - b'0')), 3)
            }
            Some(_) => Read::No,
        },
        FieldType::Dec => {
            let digits = b.iter().take_while(|x| x.is_ascii_digit()).count();
            if digits == 0 && b.is_empty() {
                return Read::Wait;
            }
            // Up to five digits; the byte after them must have come (the number may go on).
            if digits == 0 || digits > 5 {
                return Read::No;
            }
            if digits == b.len() {
                return Read::Wait;
            }
            let n = b[..digits]
                .iter()
                .fold(0u32, |n, &x| n * 10 + u32::from(x - b'0'));
            if n <= kind.largest() {
                Read::Value(n, digits)
            } else {
                Read::No
            }
        }
    }
}
