//! Findings in words.

use std::fmt;

use super::{Finding, FindingKind};

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let legs: Vec<String> = self.legs.iter().map(|l| format!("L{l}")).collect();
        let leg = match legs.len() {
            0 => String::new(),
            1 => format!("leg {}", legs[0]),
            _ => format!("legs {}", legs.join(" and ")),
        };
        let number = |k: usize| self.legs.get(k).copied().unwrap_or(0);
        let servo = format!("servo S{}", number(0));
        let rod = format!("rod R{}", number(0));
        let span = if self.count > 1 {
            format!(
                "from t = {:.3} s to t = {:.3} s ({} samples)",
                self.first_time, self.last_time, self.count
            )
        } else {
            format!("at t = {:.3} s", self.first_time)
        };
        let over = -self.margin;
        let (worst, when, limit) = (self.worst_value, self.worst_time, self.limit);
        match self.kind {
            FindingKind::StrokeMax => write!(
                f,
                "{leg} is longer than its maximum {limit:.4} m {span}; worst {worst:.4} m at t = {when:.3} s, {:.1} mm over",
                over * 1e3
            ),
            FindingKind::StrokeMin => write!(
                f,
                "{leg} is shorter than its minimum {limit:.4} m {span}; worst {worst:.4} m at t = {when:.3} s, {:.1} mm under",
                over * 1e3
            ),
            FindingKind::LegSpeed => write!(
                f,
                "{leg} moves faster than {limit} m/s {span}; worst {worst:.3} m/s at t = {when:.3} s, {over:.3} m/s over"
            ),
            FindingKind::LegAccel => write!(
                f,
                "{leg} accelerates beyond {limit} m/s² {span}; worst {worst:.2} m/s² at t = {when:.3} s, {over:.2} m/s² over"
            ),
            FindingKind::LegJerk => write!(
                f,
                "{leg} jerks beyond {limit} m/s³ {span}; worst {worst:.2} m/s³ at t = {when:.3} s, {over:.2} m/s³ over"
            ),
            FindingKind::BaseCone => write!(
                f,
                "{leg} leans more than {limit}° from the base normal at its base joint {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° over"
            ),
            FindingKind::PlatformCone => write!(
                f,
                "{leg} leans more than {limit}° from the platform normal at its platform joint {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° over"
            ),
            FindingKind::LegCollision => write!(
                f,
                "{leg} come closer than {:.1} mm (twice the leg radius) {span}; closest {:.1} mm at t = {when:.3} s, {:.1} mm of overlap",
                limit * 1e3,
                worst * 1e3,
                over * 1e3
            ),
            FindingKind::NearSingular => {
                let value = if worst.is_finite() {
                    format!("{worst:.1}")
                } else {
                    "singular".to_owned()
                };
                write!(
                    f,
                    "the platform is near a singular pose {span} (normalised condition number above {limit}); worst {value} at t = {when:.3} s"
                )
            }
            FindingKind::ArchitectureSingular => write!(
                f,
                "the geometry is architecturally singular: every pose of the motion is singular, so the legs cannot hold or steer the platform in one direction"
            ),
            FindingKind::Jump => write!(
                f,
                "{leg} length jumps {span}; worst step {:.2} mm at t = {when:.3} s, where the steps around it allow at most {:.3} mm",
                worst * 1e3,
                limit * 1e3
            ),
            FindingKind::Unreachable => write!(
                f,
                "{servo} cannot reach its platform joint {span}: no horn angle closes its rod; at worst {} % beyond its reach, at t = {when:.3} s",
                percent(over * 100.0)
            ),
            FindingKind::ServoMax => write!(
                f,
                "{servo} turns past its maximum {limit}° {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° over"
            ),
            FindingKind::ServoMin => write!(
                f,
                "{servo} turns past its minimum {limit}° {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° under"
            ),
            FindingKind::ServoSpeed => write!(
                f,
                "{servo} turns faster than {limit}°/s {span}; worst {worst:.1}°/s at t = {when:.3} s, {over:.1}°/s over"
            ),
            FindingKind::ServoAccel => write!(
                f,
                "{servo} accelerates beyond {limit}°/s² {span}; worst {worst:.0}°/s² at t = {when:.3} s, {over:.0}°/s² over"
            ),
            FindingKind::ServoJerk => write!(
                f,
                "{servo} jerks beyond {limit}°/s³ {span}; worst {worst:.0}°/s³ at t = {when:.3} s, {over:.0}°/s³ over"
            ),
            FindingKind::HornCone => write!(
                f,
                "{rod} leans more than {limit}° from the base normal at its horn joint {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° over"
            ),
            FindingKind::RodPlatformCone => write!(
                f,
                "{rod} leans more than {limit}° from the platform normal at its platform joint {span}; worst {worst:.2}° at t = {when:.3} s, {over:.2}° over"
            ),
            FindingKind::RodCollision => write!(
                f,
                "rods R{} and R{} come closer than {:.1} mm (twice the rod radius) {span}; closest {:.1} mm at t = {when:.3} s, {:.1} mm of overlap",
                number(0),
                number(1),
                limit * 1e3,
                worst * 1e3,
                over * 1e3
            ),
            FindingKind::RodHornCollision => write!(
                f,
                "rod R{} comes closer than {:.1} mm (twice the rod radius) to the horn of servo S{} {span}; closest {:.1} mm at t = {when:.3} s, {:.1} mm of overlap",
                number(0),
                limit * 1e3,
                number(1),
                worst * 1e3,
                over * 1e3
            ),
            FindingKind::ServoJump => write!(
                f,
                "{servo} angle jumps {span}; worst step {worst:.2}° at t = {when:.3} s, where the steps around it allow at most {limit:.3}°"
            ),
            FindingKind::RigidBody => write!(
                f,
                "the platform does not move rigidly {span}: a distance between platform joints changed by {worst:.3e} m (tolerance {limit:.1e} m) at t = {when:.3} s"
            ),
        }
    }
}

/// A percentage with two decimals, in scientific notation when it is out of all proportion
/// (a joint far out of reach).
fn percent(p: f64) -> String {
    if p.is_finite() && p.abs() < 1e6 {
        format!("{p:.2}")
    } else {
        format!("{p:.3e}")
    }
}
