//! What the app's live-cue benchmarks share: the platform they cue and the peer that takes
//! their set-points.

use stewart_kinematics::Scenario;

#[path = "../../../stewart_link/benches/support/drained_peer.rs"]
mod drained_peer;

pub use drained_peer::drained_peer;

/// The seed platform with its stroke, the default washout and the limiter on (each sample
/// costs a bisection over the limits).
pub fn limited_seed() -> Scenario {
    let mut s = Scenario::seed();
    let limited = [
        "geometry.leg_min=0.55",
        "geometry.leg_max=1.3",
        "cueing.workspace_limiter=true",
    ];
    stewart_kinematics::io::settings::apply_all(&mut s, limited).unwrap_or_else(|e| panic!("{e}"));
    s
}
