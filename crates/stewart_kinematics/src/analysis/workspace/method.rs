//! How a workspace's columns were decided, in words, for reports: each actuator kind has
//! its own method (closed-form shells for legs, servo reach for servos) and its own limits.

use crate::model::actuator::Actuator;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;

use super::ConstantOrientationWorkspace;

impl ConstantOrientationWorkspace {
    /// How the columns of this workspace (of `geometry` under `limits`) were decided.
    pub fn method_words(&self, geometry: &Geometry, limits: &Limits) -> String {
        match geometry.actuator() {
            Actuator::Rotary(_) => {
                let cones = if limits.base_cone.is_some() || limits.platform_cone.is_some() {
                    ", rod cones"
                } else {
                    ""
                };
                let clearance = if limits.leg_radius.is_some() {
                    format!(
                        "; rod clearance by branch and bound (pieces settled by how far rods and horns can move, sampled below {:.2} mm), edges bisected to 1e-12 m",
                        self.cell * 1e3
                    )
                } else {
                    String::new()
                };
                format!("servo reach, range{cones} exact per column{clearance}")
            }
            Actuator::Linear if limits.has_pose_limits() => {
                "stroke and cone limits exact per column, leg clearance by a certified scan with edges bisected to 1e-12 m".to_owned()
            }
            Actuator::Linear => "reachable heights exact per column".to_owned(),
        }
    }
}
