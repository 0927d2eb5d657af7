//! Certified analysis: what holds for *every* pose of a region, proven by interval
//! arithmetic (`ground::interval`) rather than sampled — the inverse Jacobian regular
//! over a box ([`regular`], [`free`]: singularity-free ranges about a pose).
//!
//! Linear legs: a leg's row of the inverse Jacobian is its vector and moment, both
//! polynomial in the pose's position and the sines and cosines of its angles, so interval
//! arithmetic bounds them over a box ([`pose_box`]). Rotary servos: the horn's angle in
//! closed form, bounded through the arcsine and arctangent, then the horn tip and the rod
//! ([`servos`]).

pub mod free;
pub mod pose_box;
pub mod regular;
pub mod servos;
pub mod workspace;

#[cfg(test)]
mod tests;
