//! Scenario files: geometry, pivot, trajectory and check settings in readable TOML.
//!
//! ```toml
//! name = "seed"
//! [geometry]                       # required; exactly these keys
//! base_radius = 1.0                # m
//! platform_radius = 0.6            # m
//! home_height = 0.8                # m
//! base_angles_deg = [0, 60, 120, 180, 240, 300]
//! platform_angles_deg = [30, 90, 150, 210, 270, 330]
//! # or, for either plate, its six joints as points (base frame / platform frame), m:
//! # base_joints_m = [[1.0, 0.0, 0.0], [0.5, 0.866, 0.05], …]   (instead of radius and angles)
//! leg_min = 0.55                   # m, optional
//! leg_max = 1.30                   # m, optional
//! [pivot]                          # optional: rotation centre in the platform frame
//! offset_m = [0.0, 0.0, 0.0]
//! [trajectory]                     # optional: the seed's motion when absent
//! kind = "sinusoid"                # sinusoid | circle | figure8 | helix | sway | keyframes | pose_table
//! duration_s = 10.0
//! samples = 1001
//! [limits]                         # optional: speed, acceleration, joint cones, leg size
//! leg_speed_max_m_s = 0.5
//! [payload]                        # optional: moving mass for `forces`
//! mass_kg = 60.0
//! com_m = [0.0, 0.0, 0.1]          # platform frame
//! inertia_kg_m2 = [3.0, 3.0, 5.0]  # about the centre of mass, platform axes: Ixx, Iyy, Izz
//!                                  # (or six: Ixx, Iyy, Izz, Ixy, Ixz, Iyz)
//! [dynamics]                       # optional: stiffness, friction and leg parts
//! actuator_stiffness = 2.0e7       # see crate::model::dynamics_settings for every key
//! [checks]                         # optional thresholds
//! jump_ratio = 5.0
//! [link]                           # optional: sending set-points to hardware
//! transport = "udp"                # see crate::model::link_settings for every key
//! address = "192.168.1.20:9000"
//! [appearance.base]                # optional: a CAD part drawn for a body
//! file = "parts/base.stl"          # see crate::model::appearance for every key
//! scale = "mm"
//! ```
//!
//! See `assets/presets/` (top level) for a file of every trajectory kind and docs/guide/file-format.md for every key.

pub(crate) mod build;
mod error;
mod file;
mod locate;
pub mod presets;
mod write;

pub use error::{ScenarioError, ScenarioProblem};

use crate::analysis::checks::CheckSettings;
use crate::analysis::forces::Payload;
use crate::model::appearance::AppearanceSettings;
use crate::model::cueing_settings::CueingSettings;
use crate::model::dynamics_settings::DynamicsSettings;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::link_settings::LinkSettings;
use crate::model::trajectory::Motion;

/// A platform, its motion and the check thresholds: everything a run needs.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// Short name (a preset's name, or the file's).
    pub name: String,
    /// One line about it.
    pub description: String,
    /// The platform.
    pub geometry: Geometry,
    /// The motion and its sampling.
    pub motion: Motion,
    /// Actuator and joint limits beyond the stroke.
    pub limits: Limits,
    /// The moving mass, when given.
    pub payload: Option<Payload>,
    /// Thresholds of the checks.
    pub checks: CheckSettings,
    /// How set-points reach real hardware (`[link]`).
    pub link: LinkSettings,
    /// How vehicle motion becomes platform motion (`[cueing]`).
    pub cueing: CueingSettings,
    /// What the actuators add to the moving mass: stiffness, friction, leg parts
    /// (`[dynamics]`).
    pub dynamics: DynamicsSettings,
    /// Mesh files drawn for the base, the platform and the actuators' parts
    /// (`[appearance]`).
    pub appearance: AppearanceSettings,
    /// The other files its text named and its loader read (its pose table), as opened:
    /// a command may never write one of them.
    pub files_read: Vec<std::path::PathBuf>,
}

impl Scenario {
    /// The seed article's scenario, built in code (the `seed` preset file says the same).
    pub fn seed() -> Self {
        let geometry = Geometry::seed();
        Self {
            name: "seed".to_owned(),
            description: "The seed article's platform and motion.".to_owned(),
            motion: Motion::seed(geometry.home_height()),
            limits: Limits::default(),
            payload: None,
            geometry,
            checks: CheckSettings::default(),
            link: LinkSettings::default(),
            cueing: CueingSettings::default(),
            dynamics: DynamicsSettings::default(),
            appearance: AppearanceSettings::default(),
            files_read: Vec::new(),
        }
    }

    /// The scenario as TOML text that [`Scenario::from_toml_str`] reads back to an equal
    /// scenario. A pose table is written out as inline keyframes.
    pub fn to_toml(&self) -> String {
        write::to_toml(self)
    }

    /// The same scenario with both plates' joints given as coordinates
    /// (`base_joints_m`, `platform_joints_m`): the same platform, so the same legs.
    pub fn as_coordinates(&self) -> Scenario {
        let mut params = self.geometry.params().clone();
        params.base = params.base.as_points();
        params.platform = params.platform.as_points();
        let geometry = Geometry::new(params)
            .unwrap_or_else(|e| unreachable!("the same joints validate again: {e}"));
        Scenario {
            geometry,
            ..self.clone()
        }
    }
}

#[cfg(test)]
mod tests;
