//! Rigid-body self-consistency: the distances between platform joints, computed in the
//! base frame from the solved joint positions, must equal those on the platform itself.

use crate::analysis::checks::{Finding, FindingKind};
use crate::model::geometry::Geometry;
use crate::model::leg_solution::LegSolution;

/// Worst distance change over all samples, and a finding if it exceeds `tolerance` (metres).
pub fn check(
    geometry: &Geometry,
    times: &[f64],
    solutions: &[LegSolution],
    tolerance: f64,
) -> (f64, Vec<Finding>) {
    let a = geometry.platform_joints();
    let mut reference = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in i + 1..6 {
            reference[i][j] = (a[i] - a[j]).norm();
        }
    }
    let mut worst = 0.0f64;
    let mut worst_k = 0;
    let mut bad: Vec<usize> = Vec::new();
    for (k, s) in solutions.iter().enumerate() {
        let q = &s.platform_joints;
        let mut sample_worst = 0.0f64;
        for i in 0..6 {
            for j in i + 1..6 {
                sample_worst = sample_worst.max(((q[i] - q[j]).norm() - reference[i][j]).abs());
            }
        }
        if sample_worst > worst {
            worst = sample_worst;
            worst_k = k;
        }
        if sample_worst > tolerance {
            bad.push(k);
        }
    }
    let findings = match (bad.first(), bad.last()) {
        (Some(&first), Some(&last)) => vec![Finding {
            kind: FindingKind::RigidBody,
            legs: Vec::new(),
            first_time: times[first],
            last_time: times[last],
            count: bad.len(),
            worst_time: times[worst_k],
            worst_value: worst,
            limit: tolerance,
            margin: tolerance - worst,
            unit: "m".to_owned(),
        }],
        _ => Vec::new(),
    };
    (worst, findings)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::pose::Pose;
    use nalgebra::Vector3;

    #[test]
    fn correct_solutions_pass_and_a_corrupted_joint_is_caught() {
        let g = Geometry::seed();
        let times = [0.0, 0.1, 0.2];
        let mut sols: Vec<_> = times
            .iter()
            .map(|&t| {
                g.inverse(&Pose::from_xyz_rpy_deg(
                    [t, 0.0, 0.8],
                    [10.0 * t, 5.0, -3.0],
                ))
            })
            .collect();
        let (worst, findings) = check(&g, &times, &sols, 1e-9);
        assert!(worst < 1e-14 && findings.is_empty());
        // Move one joint by 1 mm at t = 0.1 s, as a wrong formula would.
        sols[1].platform_joints[2] += Vector3::new(1e-3, 1e-3, 0.0);
        let (_, findings) = check(&g, &times, &sols, 1e-9);
        assert_eq!(findings.len(), 1);
        assert_eq!(findings[0].first_time, 0.1);
        assert!(findings[0].worst_value > 5e-4);
    }
}
