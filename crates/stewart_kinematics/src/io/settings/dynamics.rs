//! The `[dynamics]` table's settings: each number read and written by key, a written
//! value checked as the file reader checks it.

use crate::model::actuator::ActuatorKind;
use crate::model::dynamics_settings::DynamicsSettings;

/// A number of `[dynamics]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DynamicsKey {
    /// `actuator_stiffness` (optional).
    Stiffness,
    /// `actuator_friction`.
    Friction,
    /// `cylinder_mass_kg` (linear legs).
    CylinderMass,
    /// `cylinder_com_m` (linear legs).
    CylinderCom,
    /// `cylinder_inertia_kg_m2` (linear legs).
    CylinderInertia,
    /// `rod_mass_kg`.
    RodMass,
    /// `rod_com_m`.
    RodCom,
    /// `rod_inertia_kg_m2`.
    RodInertia,
    /// `horn_mass_kg` (servos).
    HornMass,
    /// `horn_com_m` (servos).
    HornCom,
    /// `horn_inertia_kg_m2` (servos).
    HornInertia,
}

impl DynamicsKey {
    /// Every key, in file order.
    pub const ALL: [DynamicsKey; 11] = {
        use DynamicsKey::*;
        [
            Stiffness,
            Friction,
            CylinderMass,
            CylinderCom,
            CylinderInertia,
            RodMass,
            RodCom,
            RodInertia,
            HornMass,
            HornCom,
            HornInertia,
        ]
    };

    /// The actuator kind whose parts it describes (`None`: both).
    pub fn kind(self) -> Option<ActuatorKind> {
        use DynamicsKey::*;
        match self {
            CylinderMass | CylinderCom | CylinderInertia => Some(ActuatorKind::Linear),
            HornMass | HornCom | HornInertia => Some(ActuatorKind::Rotary),
            _ => None,
        }
    }
}

fn field(d: &mut DynamicsSettings, key: DynamicsKey) -> &mut f64 {
    use DynamicsKey::*;
    match key {
        Stiffness => d.actuator_stiffness.get_or_insert(f64::NAN),
        Friction => &mut d.actuator_friction,
        CylinderMass => &mut d.cylinder_mass_kg,
        CylinderCom => &mut d.cylinder_com_m,
        CylinderInertia => &mut d.cylinder_inertia_kg_m2,
        RodMass => &mut d.rod_mass_kg,
        RodCom => &mut d.rod_com_m,
        RodInertia => &mut d.rod_inertia_kg_m2,
        HornMass => &mut d.horn_mass_kg,
        HornCom => &mut d.horn_com_m,
        HornInertia => &mut d.horn_inertia_kg_m2,
    }
}

/// The value of `key` (`None`: the stiffness is not given).
pub(super) fn get(d: &DynamicsSettings, key: DynamicsKey) -> Option<f64> {
    if key == DynamicsKey::Stiffness {
        return d.actuator_stiffness;
    }
    Some(*field(&mut d.clone(), key))
}

/// Write `value` at `key` (`None` removes the stiffness), refused with the reason when
/// the table would not work (left unchanged then).
pub(super) fn set(
    d: &mut DynamicsSettings,
    key: DynamicsKey,
    value: Option<f64>,
) -> Result<(), String> {
    let mut edited = d.clone();
    match value {
        None => edited.actuator_stiffness = None,
        Some(v) => *field(&mut edited, key) = v,
    }
    if let Some(p) = edited.problem() {
        return Err(p.reason);
    }
    *d = edited;
    Ok(())
}
