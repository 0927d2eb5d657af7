//! Steering a replacement pose: slopes cut back along their own direction (every actuator
//! together, so the values stay those of a pose) or each clamped alone, and, where no pose
//! has the values wanted (on a rig whose leg lengths reach only some values together, as
//! an architecturally singular one's), a pose on the way between two poses.

use super::{ActuatorGuard, Given};
use crate::model::pose::Pose;

/// Each actuator's range of slopes.
type Ranges = [(f64, f64); 6];

/// Halvings of the share tried on the way between two poses before giving up.
const HALVINGS: usize = 8;

/// `slope` with each actuator's clamped into its range in `allowed`.
pub(super) fn clamped(slope: &[f64; 6], allowed: &[(f64, f64); 6]) -> [f64; 6] {
    std::array::from_fn(|i| slope[i].clamp(allowed[i].0, allowed[i].1))
}

/// The slopes on the way from `from` (clamped into `allowed`) towards `to`, as far along
/// as every actuator's range in `allowed` lets all of them go together.
pub(super) fn along(from: &[f64; 6], to: &[f64; 6], allowed: &[(f64, f64); 6]) -> [f64; 6] {
    let base = clamped(from, allowed);
    let share = share_along(&base, to, allowed);
    std::array::from_fn(|i| (base[i] + share * (to[i] - base[i])).clamp(allowed[i].0, allowed[i].1))
}

/// How far (a share, 0 to 1) from `base` (within `allowed`) towards `to` every actuator
/// stays within its range in `allowed`.
fn share_along(base: &[f64; 6], to: &[f64; 6], allowed: &[(f64, f64); 6]) -> f64 {
    (0..6).fold(1.0f64, |share, i| {
        let way = to[i] - base[i];
        let (lo, hi) = allowed[i];
        let room = if way > 0.0 {
            (hi - base[i]) / way
        } else if way < 0.0 {
            (lo - base[i]) / way
        } else {
            1.0
        };
        share.min(room.max(0.0))
    })
}

impl ActuatorGuard {
    /// The pose at `t`, `dt` after the last (actuator values `q1`), on the way from `from`
    /// towards `to` as far as every actuator's slope stays in `aim` (and is found, as
    /// read back, in `allowed`), when the way from `from` starts within them.
    pub(super) fn between(
        &self,
        t: f64,
        (dt, q1): (f64, &[f64; 6]),
        from: &Pose,
        to: &Pose,
        (allowed, aim): (&Ranges, &Ranges),
    ) -> Option<Given> {
        let slope_to = |p: &Pose| -> Option<[f64; 6]> {
            let read = self.read_back(p)?;
            Some(std::array::from_fn(|i| (read[i] - q1[i]) / dt))
        };
        let (start, end) = (slope_to(from)?, slope_to(to)?);
        if (0..6).any(|i| start[i] < aim[i].0 || start[i] > aim[i].1) {
            return None;
        }
        let mut share = share_along(&start, &end, aim);
        let (a, b) = (from.to_coordinates(), to.to_coordinates());
        for _ in 0..HALVINGS {
            let pose =
                Pose::from_coordinates(std::array::from_fn(|j| a[j] + share * (b[j] - a[j])));
            if let Some(read) = self.read_back(&pose)
                && (0..6).all(|i| {
                    let s = (read[i] - q1[i]) / dt;
                    s >= allowed[i].0 && s <= allowed[i].1
                })
                && self.keeps_the_other_limits(&pose)
            {
                return Some((t, read, pose));
            }
            if share == 0.0 {
                break;
            }
            share *= 0.5;
        }
        None
    }
}
