//! The ground every layer stands on: the accepted range of every kind of number
//! ([`bounds`]), the rules input text is read by ([`text`]: a size cap, plain words for
//! text that is not UTF-8), and interval arithmetic with outward rounding ([`interval`],
//! for bounds that hold over whole boxes of poses). Any layer may use them; they use no
//! layer.

pub mod bounds;
pub mod interval;
pub mod text;
