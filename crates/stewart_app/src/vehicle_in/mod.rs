//! Vehicle motion coming in, the one home of the app's side of it: a recording as CSV
//! ([`table`]), a packet capture of a game's datagrams ([`capture`]), and live datagrams
//! over UDP cued as they come ([`live_cue`], with X-Plane's subscription kept up by
//! [`xplane_rref`]). Decoding, clocks and the tally by format are `stewart_link::vehicle`'s;
//! every way in reads through its intake and checks values by its one range rule.

pub(crate) mod capture;
pub mod live_cue;
pub(crate) mod table;
pub(crate) mod xplane_rref;
