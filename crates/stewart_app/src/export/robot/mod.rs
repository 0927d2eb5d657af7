//! The rig as a robot description (`stewart robot`): MJCF for MuJoCo, its loops closed by
//! equality constraints and its keyframes the studio's samples; or URDF for ROS, a tree
//! with a virtual six-joint chain to the platform and each leg an open chain ending on
//! its platform joint, with the joints' values per sample as CSV.
//!
//! Metres, radians, z up, the studio's base frame. Every body's reference frame is its
//! frame at the studio's home pose, so that a simulator's default configuration is the
//! home pose with its loops closed.

mod masses;
mod mjcf;
mod rig;
mod urdf;

#[cfg(test)]
mod tests;

use std::path::Path;

use anyhow::Result;
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use stewart_kinematics::Scenario;
use stewart_render::appearance::parts::PartSet;

pub(crate) use rig::Rig;

/// Which description.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RobotFormat {
    /// MuJoCo's MJCF.
    Mjcf,
    /// ROS's URDF.
    Urdf,
}

/// What `stewart robot` writes: the description's text and, for URDF, the joint states.
pub(crate) struct RobotFiles {
    /// The MJCF or URDF document.
    pub(crate) description: String,
    /// `t` and one column per movable joint, one row per sample (URDF only).
    pub(crate) joint_states: Option<String>,
    /// How many samples (keyframes, rows).
    pub(crate) samples: usize,
}

/// `scenario`'s rig in `format`, every `every`-th sample; CAD meshes from `parts` (MJCF:
/// inline), or named by their files from `mesh_folder` (URDF: the scenario's table's
/// paths as `folder` makes them). `place(t)` words where a sample lies for an error.
pub(crate) fn describe(
    scenario: &Scenario,
    format: RobotFormat,
    every: usize,
    parts: &PartSet,
    mesh_files: &stewart_kinematics::model::appearance::AppearanceSettings,
    place: impl Fn(f64) -> String,
) -> Result<RobotFiles> {
    let rig = Rig::of(scenario, every, place)?;
    let samples = rig.samples.len();
    Ok(match format {
        RobotFormat::Mjcf => RobotFiles {
            description: mjcf::write(&rig, parts),
            joint_states: None,
            samples,
        },
        RobotFormat::Urdf => RobotFiles {
            description: urdf::write(&rig, mesh_files),
            joint_states: Some(urdf::joint_states(&rig)),
            samples,
        },
    })
}

/// What the description assumed beyond the scenario, a line each, for its comment.
fn assumptions(rig: &Rig) -> String {
    let mut text = String::new();
    for note in &rig.notes {
        text.push_str(&format!(" {note}\n"));
    }
    for d in &rig.masses.defaults {
        text.push_str(&format!(" Light default: {d}.\n"));
    }
    text
}

/// `x y z`, each number as Rust writes it back exactly.
fn vector(v: &Vector3<f64>) -> String {
    format!("{} {} {}", v.x, v.y, v.z)
}

/// `w x y z`.
fn quaternion(q: &UnitQuaternion<f64>) -> String {
    format!("{} {} {} {}", q.w, q.i, q.j, q.k)
}

/// A rotation as a unit quaternion.
fn quat_of(r: &Rotation3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(r)
}

/// Characters XML 1.0 cannot hold at all (control characters but tab, line feed and
/// carriage return) made U+FFFD.
fn printable(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() && !matches!(c, '\t' | '\n' | '\r') {
                '\u{FFFD}'
            } else {
                c
            }
        })
        .collect()
}

/// Text from the scenario (its name, a file's path) as an attribute's value: `&`, `<` and
/// `>` escaped (the writer escapes only the quote) and unprintable characters replaced.
fn attribute_text(text: &str) -> String {
    printable(text)
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A comment's text with no `--` (XML forbids it inside a comment) and nothing
/// unprintable.
fn comment_safe(text: &str) -> String {
    let mut out = printable(text).replace("--", "- -");
    while out.contains("--") {
        out = out.replace("--", "- -");
    }
    if out.ends_with('-') {
        out.push(' ');
    }
    out
}

/// Whether a path has a description's extension the format expects, for a note.
pub(crate) fn expected_extension(format: RobotFormat, path: &Path) -> bool {
    let ext = crate::output::extension(path);
    match format {
        RobotFormat::Mjcf => matches!(ext.as_deref(), Some("xml" | "mjcf")),
        RobotFormat::Urdf => ext.as_deref() == Some("urdf"),
    }
}
