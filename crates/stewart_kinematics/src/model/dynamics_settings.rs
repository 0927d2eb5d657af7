//! The `[dynamics]` table of a scenario: what the actuators add to the moving mass of
//! `[payload]` — their stiffness, viscous friction and the bodies of each leg. Plain
//! data, checked here; `analysis::dynamics` computes with it.
//!
//! ```toml
//! [dynamics]
//! actuator_stiffness = 2.0e7     # N/m (linear legs) or N·m/rad (servos); needed by `modes`
//! actuator_friction = 50.0       # viscous: N·s/m or N·m·s/rad
//! # linear legs: the cylinder hangs from the base joint, the rod from the platform joint
//! cylinder_mass_kg = 1.2
//! cylinder_com_m = 0.15          # from the base joint along the leg
//! cylinder_inertia_kg_m2 = 0.01  # about its centre of mass, across the leg
//! rod_mass_kg = 0.6
//! rod_com_m = 0.2                # from the platform joint back along the leg (servos: from the horn tip)
//! rod_inertia_kg_m2 = 0.005      # about its centre of mass, across the rod
//! # servos: the horn turns with the shaft
//! horn_mass_kg = 0.02
//! horn_com_m = 0.01              # from the shaft's axis along the horn
//! horn_inertia_kg_m2 = 2.0e-6    # about its centre of mass, around the shaft's direction
//! ```
//!
//! Every value defaults to zero (massless legs, no friction) except the stiffness, which
//! is absent until given. Leg parts are slender bodies: their spin about their own axis is
//! not modelled (a ball or universal joint lets it free or holds it still; either way it
//! carries no actuator force).

use serde::{Deserialize, Serialize};

use crate::model::actuator::ActuatorKind;

/// One moving part of a leg: mass, where its centre of mass is along the part, and its
/// moment of inertia about that centre.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LegPart {
    /// Mass, kg.
    pub mass: f64,
    /// Distance of the centre of mass from the part's reference end, m.
    pub com: f64,
    /// Moment of inertia about the centre of mass, kg·m² (across a cylinder or rod; about
    /// the shaft's direction for a horn).
    pub inertia: f64,
}

impl LegPart {
    /// Whether the part has neither mass nor inertia (it then adds nothing).
    pub fn is_massless(&self) -> bool {
        self.mass == 0.0 && self.inertia == 0.0
    }
}

/// The `[dynamics]` table.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct DynamicsSettings {
    /// Axial stiffness of each actuator: N/m for linear legs, N·m/rad for servos (absent:
    /// not given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub actuator_stiffness: Option<f64>,
    /// Viscous friction of each actuator: N·s/m, or N·m·s/rad for servos.
    pub actuator_friction: f64,
    /// Cylinder mass (linear legs), kg.
    pub cylinder_mass_kg: f64,
    /// Cylinder centre of mass from the base joint along the leg, m.
    pub cylinder_com_m: f64,
    /// Cylinder moment of inertia about its centre of mass across the leg, kg·m².
    pub cylinder_inertia_kg_m2: f64,
    /// Rod mass, kg.
    pub rod_mass_kg: f64,
    /// Rod centre of mass: from the platform joint back along a linear leg, or from the
    /// horn tip along a servo's rod, m.
    pub rod_com_m: f64,
    /// Rod moment of inertia about its centre of mass across the rod, kg·m².
    pub rod_inertia_kg_m2: f64,
    /// Horn mass (servos), kg.
    pub horn_mass_kg: f64,
    /// Horn centre of mass from the shaft's axis along the horn, m.
    pub horn_com_m: f64,
    /// Horn moment of inertia about its centre of mass around the shaft's direction, kg·m².
    pub horn_inertia_kg_m2: f64,
}

/// A `[dynamics]` value refused: the key (`dynamics.rod_mass_kg`) and why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{key}` {reason}")]
pub struct DynamicsProblem {
    /// The key, as `--set` names it.
    pub key: String,
    /// Why.
    pub reason: String,
}

/// A typical actuator stiffness of a linear leg, N/m: an electric or hydraulic actuator of
/// a motion platform (ball screw, cylinder) is of the order of 10⁷ N/m along its axis.
pub const TYPICAL_LINEAR_STIFFNESS: f64 = 2.0e7;

/// A typical stiffness of a servo, N·m/rad: a geared hobby or desk servo holds about
/// 50 N·m per radian of deflection.
pub const TYPICAL_ROTARY_STIFFNESS: f64 = 50.0;

/// The slider range of the actuator stiffness for servos, N·m/rad (linear legs: the
/// declared 10³ … 10⁸ N/m).
pub const ROTARY_STIFFNESS_RANGE: (f64, f64) = (1.0, 1.0e5);

/// A typical actuator stiffness for actuators of `kind` (what the stiffness is when first
/// switched on): N/m for linear legs, N·m/rad for servos.
pub fn typical_stiffness(kind: ActuatorKind) -> f64 {
    match kind {
        ActuatorKind::Linear => TYPICAL_LINEAR_STIFFNESS,
        ActuatorKind::Rotary => TYPICAL_ROTARY_STIFFNESS,
    }
}

/// The largest stiffness accepted (N/m or N·m/rad).
pub const MAX_STIFFNESS: f64 = 1e12;
/// The largest viscous friction accepted (N·s/m or N·m·s/rad).
pub const MAX_FRICTION: f64 = 1e9;

impl DynamicsSettings {
    /// The cylinder of a linear leg (from the base joint).
    pub fn cylinder(&self) -> LegPart {
        LegPart {
            mass: self.cylinder_mass_kg,
            com: self.cylinder_com_m,
            inertia: self.cylinder_inertia_kg_m2,
        }
    }

    /// The rod (from the platform joint on a linear leg, from the horn tip on a servo).
    pub fn rod(&self) -> LegPart {
        LegPart {
            mass: self.rod_mass_kg,
            com: self.rod_com_m,
            inertia: self.rod_inertia_kg_m2,
        }
    }

    /// A servo's horn (from the shaft's axis).
    pub fn horn(&self) -> LegPart {
        LegPart {
            mass: self.horn_mass_kg,
            com: self.horn_com_m,
            inertia: self.horn_inertia_kg_m2,
        }
    }

    /// The parts that move with an actuator of `kind`: cylinder and rod, or horn and rod.
    pub fn parts(&self, kind: ActuatorKind) -> [LegPart; 2] {
        match kind {
            ActuatorKind::Linear => [self.cylinder(), self.rod()],
            ActuatorKind::Rotary => [self.horn(), self.rod()],
        }
    }

    /// Every number with its key (in the table), in file order; the stiffness only when
    /// given.
    pub fn values(&self) -> Vec<(&'static str, f64)> {
        let mut out = Vec::with_capacity(11);
        if let Some(k) = self.actuator_stiffness {
            out.push(("actuator_stiffness", k));
        }
        out.extend([
            ("actuator_friction", self.actuator_friction),
            ("cylinder_mass_kg", self.cylinder_mass_kg),
            ("cylinder_com_m", self.cylinder_com_m),
            ("cylinder_inertia_kg_m2", self.cylinder_inertia_kg_m2),
            ("rod_mass_kg", self.rod_mass_kg),
            ("rod_com_m", self.rod_com_m),
            ("rod_inertia_kg_m2", self.rod_inertia_kg_m2),
            ("horn_mass_kg", self.horn_mass_kg),
            ("horn_com_m", self.horn_com_m),
            ("horn_inertia_kg_m2", self.horn_inertia_kg_m2),
        ]);
        out
    }

    /// The first value that cannot work, if any: a stiffness that is not positive, a
    /// negative friction, mass, distance or inertia, or one beyond the accepted bounds;
    /// NaN and infinity never.
    pub fn problem(&self) -> Option<DynamicsProblem> {
        use crate::ground::bounds::{INERTIA_KG_M2, LENGTH_M, MASS_KG};
        let bad = |key: &str, reason: String| {
            Some(DynamicsProblem {
                key: format!("dynamics.{key}"),
                reason,
            })
        };
        if let Some(k) = self.actuator_stiffness
            && !(k > 0.0 && k <= MAX_STIFFNESS)
        {
            return bad(
                "actuator_stiffness",
                format!("must be a positive stiffness of at most {MAX_STIFFNESS:e}, got {k}"),
            );
        }
        for (key, v) in self.values() {
            let (max, what) = match key {
                "actuator_stiffness" => continue,
                "actuator_friction" => (MAX_FRICTION, "a friction coefficient"),
                k if k.ends_with("_mass_kg") => (MASS_KG, "a mass in kg"),
                k if k.ends_with("_com_m") => (LENGTH_M, "a distance in metres"),
                _ => (INERTIA_KG_M2, "a moment of inertia in kg·m²"),
            };
            if !(v >= 0.0 && v <= max) {
                return bad(key, format!("must be {what} from 0 to {max:e}, got {v}"));
            }
        }
        None
    }
}
