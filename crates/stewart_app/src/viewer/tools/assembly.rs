//! Stepping through the assembly modes of the legs shown: every other pose the platform
//! can take with the same six leg lengths (or, for servos, the same six servo angles),
//! found by the core's homotopy solver.

use stewart_kinematics::analysis::architecture;
use stewart_kinematics::model::rotary::Unreachable;
use stewart_kinematics::solve::forward::ForwardError;
use stewart_kinematics::solve::forward::assembly::same_placement;
use stewart_kinematics::{Geometry, Pose};

/// What the modes were computed for: the geometry and the legs (or servo angles).
#[derive(Clone, Debug, PartialEq)]
struct Key {
    geometry: Geometry,
    actuation: [f64; 6],
}

/// The modes of the last legs asked about, and which one is shown.
#[derive(Clone, Debug, Default)]
pub(crate) struct AssemblyBrowser {
    key: Option<Key>,
    modes: Vec<Pose>,
    /// Index of the mode shown and how many there are, after a step.
    pub(crate) shown: Option<(usize, usize)>,
}

/// Why no other mode can be shown.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum NoMode {
    /// The geometry is architecturally singular: the legs do not determine the pose.
    Singular,
    /// A servo cannot reach its joint at the pose shown.
    Unreachable(Unreachable),
    /// The solver failed.
    Solver(ForwardError),
    /// The solver found no real pose.
    NoRealPose,
}

/// Two actuations closer than this (metres or degrees) are the same legs.
const SAME_ACTUATION: f64 = 1e-9;

impl AssemblyBrowser {
    /// The mode after the one at `pose`, among the modes of the legs (or servo angles)
    /// that hold `pose` on `geometry`: the pose to show, or why there is none.
    pub(crate) fn next(&mut self, geometry: &Geometry, pose: &Pose) -> Result<Pose, NoMode> {
        let actuation = geometry
            .actuator_values_at(pose)
            .map_err(NoMode::Unreachable)?;
        let same = self.key.as_ref().is_some_and(|k| {
            k.geometry == *geometry
                && k.actuation
                    .iter()
                    .zip(&actuation)
                    .all(|(a, b)| (a - b).abs() < SAME_ACTUATION)
        });
        if !same {
            // Checked once per geometry and legs, like the modes themselves.
            if architecture::architecture(geometry).singular {
                return Err(NoMode::Singular);
            }
            let solved = geometry.actuator_assembly_modes(&actuation);
            self.modes = solved
                .map_err(NoMode::Solver)?
                .iter()
                .map(|m| m.pose)
                .collect();
            self.key = Some(Key {
                geometry: geometry.clone(),
                actuation,
            });
        }
        let n = self.modes.len();
        let here = self.modes.iter().position(|m| same_placement(m, pose));
        let next = here.map_or(0, |i| (i + 1) % n.max(1));
        let pose = *self.modes.get(next).ok_or(NoMode::NoRealPose)?;
        self.shown = Some((next, n));
        Ok(pose)
    }
}
