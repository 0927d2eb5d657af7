//! Forward kinematics along a sequence of leg lengths (a sensor read-back, a recorded run).
//!
//! Each sample starts from the previous sample's pose (the first from home), which is
//! fast and follows one assembly branch. Moving from one assembly branch to another
//! requires passing through a singular pose, where `det J` changes sign; a sign change
//! between consecutive solutions is therefore reported as a branch change.

use serde::{Deserialize, Serialize};

use super::{ForwardError, ForwardOptions, ForwardSolution};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// A change of assembly branch between two consecutive samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BranchChange {
    /// Index of the sample after the change (0-based).
    pub index: usize,
    /// `det J` at the sample before.
    pub det_before: f64,
    /// `det J` at the sample after.
    pub det_after: f64,
}

/// The poses of a sequence and where the branch changed.
#[derive(Clone, Debug, PartialEq)]
pub struct SequenceSolution {
    /// One solution per sample.
    pub solutions: Vec<ForwardSolution>,
    /// Branch changes found.
    pub branch_changes: Vec<BranchChange>,
}

/// A sample that could not be solved, with its index (0-based).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("sample {}: {error}", index + 1)]
pub struct SequenceError {
    /// Index of the sample (0-based).
    pub index: usize,
    /// Why it failed.
    pub error: ForwardError,
}

/// See [`Geometry::forward_sequence`].
pub(crate) fn forward_sequence(
    geometry: &Geometry,
    lengths: &[[f64; 6]],
    cold: bool,
    options: &ForwardOptions,
) -> Result<SequenceSolution, SequenceError> {
    geometry.forward_sequence_from(lengths, &geometry.home_pose(), cold, options)
}

/// See [`Geometry::forward_sequence_from`].
pub(crate) fn forward_sequence_from(
    geometry: &Geometry,
    lengths: &[[f64; 6]],
    home: &Pose,
    cold: bool,
    options: &ForwardOptions,
) -> Result<SequenceSolution, SequenceError> {
    let home = *home;
    let mut solutions: Vec<ForwardSolution> = Vec::with_capacity(lengths.len());
    for (index, row) in lengths.iter().enumerate() {
        let start = match solutions.last() {
            Some(s) if !cold => s.pose,
            _ => home,
        };
        let solution = geometry
            .forward(row, &start, options)
            .map_err(|error| SequenceError { index, error })?;
        solutions.push(solution);
    }
    let branch_changes = geometry.branch_changes(&solutions);
    Ok(SequenceSolution {
        solutions,
        branch_changes,
    })
}

/// See [`Geometry::branch_changes`].
pub(crate) fn branch_changes(
    geometry: &Geometry,
    solutions: &[ForwardSolution],
) -> Vec<BranchChange> {
    let dets: Vec<f64> = solutions
        .iter()
        .map(|s| geometry.jacobian(&s.pose).determinant())
        .collect();
    dets.windows(2)
        .enumerate()
        .filter(|(_, d)| d[0] * d[1] < 0.0)
        .map(|(k, d)| BranchChange {
            index: k + 1,
            det_before: d[0],
            det_after: d[1],
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_smooth_sequence_is_followed_warm_and_cold() {
        let g = crate::test_support::paired_geometry();
        let truth: Vec<Pose> = (0..200)
            .map(|k| {
                let t = k as f64 * 0.05;
                Pose::from_xyz_rpy_deg(
                    [0.1 * t.sin(), 0.1 * t.cos(), 0.8 + 0.05 * (0.5 * t).sin()],
                    [5.0 * t.sin(), 3.0 * t.cos(), 10.0 * (0.3 * t).sin()],
                )
            })
            .collect();
        let lengths: Vec<[f64; 6]> = truth.iter().map(|p| g.leg_lengths(p)).collect();
        for cold in [false, true] {
            let seq = g
                .forward_sequence(&lengths, cold, &ForwardOptions::default())
                .unwrap_or_else(|e| panic!("{e}"));
            assert!(seq.branch_changes.is_empty());
            for (s, t) in seq.solutions.iter().zip(&truth) {
                assert!((s.pose.position - t.position).norm() < 1e-9);
            }
            let iterations: usize = seq.solutions.iter().map(|s| s.iterations).sum();
            if cold {
                assert!(
                    iterations > 3 * 200,
                    "cold starts need more iterations: {iterations}"
                );
            } else {
                assert!(
                    iterations <= 4 * 200,
                    "warm starts converge in a few steps: {iterations}"
                );
            }
        }
    }

    #[test]
    fn a_jump_to_the_mirror_branch_is_flagged_and_a_bad_row_is_located() {
        let g = crate::test_support::paired_geometry();
        let p = Pose::from_xyz_rpy_deg([0.02, 0.0, 0.8], [0.0, 0.0, 5.0]);
        // The mirror image of p through the base plane has the same lengths.
        let mirror = Pose::from_xyz_rpy_deg([0.02, 0.0, -0.8], [0.0, 0.0, 5.0]);
        let rows = vec![g.leg_lengths(&p); 3];
        // Warm: starting on the mirror branch, the solver stays there: no change.
        let seq = g
            .forward_sequence_from(&rows, &mirror, false, &ForwardOptions::default())
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(seq.branch_changes.is_empty());
        assert!(seq.solutions.iter().all(|s| s.pose.position.z < 0.0));
        // Row 0 on the mirror branch, row 1 on the upper one: det J changes sign there.
        let below = g
            .forward_sequence_from(&rows[..1], &mirror, false, &ForwardOptions::default())
            .unwrap_or_else(|e| panic!("{e}"));
        let above = g
            .forward_sequence(&rows[1..2], false, &ForwardOptions::default())
            .unwrap_or_else(|e| panic!("{e}"));
        let mixed = [below.solutions[0], above.solutions[0]];
        let changes = g.branch_changes(&mixed);
        assert_eq!(changes.len(), 1);
        assert_eq!(changes[0].index, 1);
        assert!(changes[0].det_before * changes[0].det_after < 0.0);
        // Followed warm from home, the same rows never change branch.
        let warm = g
            .forward_sequence(&rows, false, &ForwardOptions::default())
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(warm.branch_changes.is_empty());
        let bad = vec![g.leg_lengths(&p), [0.1; 6]];
        let err = g
            .forward_sequence(&bad, false, &ForwardOptions::default())
            .unwrap_err();
        assert_eq!(err.index, 1);
        assert!(err.to_string().starts_with("sample 2: "));
    }
}
