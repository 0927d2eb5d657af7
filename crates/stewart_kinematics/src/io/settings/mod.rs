//! Every adjustable number of a scenario, declared once as data: its key (the dotted path
//! of the scenario file), label, unit, slider range and default. The viewer draws its
//! sliders from this list, the command line's `--set KEY=VALUE` looks keys up in it,
//! and `stewart settings` prints it, so the three always agree with the file format.
//!
//! Reading and writing go through [`Setting::get`] and [`Setting::set`]; a write is
//! validated by the same constructors the file reader uses ([`crate::model::geometry::Geometry::new`],
//! [`crate::model::trajectory::Sampling::with_start`]), so a refused value leaves the scenario as it was.

mod actuator_kind;
mod catalogue;
mod cueing;
mod dynamics;
mod kinds;
mod target;

use std::ops::RangeInclusive;
use std::sync::LazyLock;

use thiserror::Error;

use crate::io::scenario::Scenario;
pub use actuator_kind::{SwitchError, switch_actuator};
pub use cueing::{AXES, CueingKey};
pub use dynamics::DynamicsKey;
pub use kinds::{TrajectoryChoice, default_trajectory, switch_trajectory};
pub use target::{
    ActuatorKey, ActuatorKind, ChannelKey, CheckKey, GeometryKey, LimitKey, SamplingKey,
    SettingTarget, ShapeKey,
};

/// The unit a setting is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Metres.
    Metre,
    /// Degrees.
    Degree,
    /// Hertz.
    Hertz,
    /// Seconds.
    Second,
    /// Metres per second.
    MetrePerSecond,
    /// Metres per second squared.
    MetrePerSecondSquared,
    /// Metres per second cubed.
    MetrePerSecondCubed,
    /// Degrees per second.
    DegreePerSecond,
    /// Degrees per second squared.
    DegreePerSecondSquared,
    /// Degrees per second cubed.
    DegreePerSecondCubed,
    /// A whole number of things (samples).
    Count,
    /// A pure number (ratios, condition numbers).
    Ratio,
    /// Radians per second (filter frequencies).
    RadianPerSecond,
    /// A switch: 1 on (`true`), 0 off (`false`).
    Switch,
    /// Kilograms.
    Kilogram,
    /// Kilogram square metres (moments of inertia).
    KilogramSquareMetre,
    /// An actuator's stiffness: N/m for linear legs, N·m/rad for servos.
    Stiffness,
    /// An actuator's viscous friction: N·s/m for linear legs, N·m·s/rad for servos.
    Friction,
}

impl Unit {
    /// The symbol shown after values and in labels (empty for pure numbers).
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::Metre => "m",
            Unit::Degree => "°",
            Unit::Hertz => "Hz",
            Unit::Second => "s",
            Unit::MetrePerSecond => "m/s",
            Unit::MetrePerSecondSquared => "m/s²",
            Unit::DegreePerSecond => "°/s",
            Unit::DegreePerSecondSquared => "°/s²",
            Unit::MetrePerSecondCubed => "m/s³",
            Unit::DegreePerSecondCubed => "°/s³",
            Unit::RadianPerSecond => "rad/s",
            Unit::Count | Unit::Ratio | Unit::Switch => "",
            Unit::Kilogram => "kg",
            Unit::KilogramSquareMetre => "kg·m²",
            Unit::Stiffness => "N/m or N·m/rad",
            Unit::Friction => "N·s/m or N·m·s/rad",
        }
    }

    /// The symbol for a platform whose actuators are of `kind` (stiffness and friction
    /// differ between legs and servos; every other unit is [`Unit::symbol`]).
    pub fn symbol_for(self, kind: ActuatorKind) -> &'static str {
        match (self, kind) {
            (Unit::Stiffness, ActuatorKind::Linear) => "N/m",
            (Unit::Stiffness, ActuatorKind::Rotary) => "N·m/rad",
            (Unit::Friction, ActuatorKind::Linear) => "N·s/m",
            (Unit::Friction, ActuatorKind::Rotary) => "N·m·s/rad",
            _ => self.symbol(),
        }
    }

    /// The values a number of this unit may take anywhere (file, `--set`, slider): see
    /// [`crate::ground::bounds`]. Whether a particular value makes sense (a positive radius) is
    /// then up to the model's constructors.
    pub fn accepted(self) -> RangeInclusive<f64> {
        use crate::ground::bounds::{self, symmetric};
        match self {
            Unit::Metre => symmetric(bounds::LENGTH_M),
            Unit::Degree => symmetric(bounds::ANGLE_DEG),
            Unit::Hertz => symmetric(bounds::FREQUENCY_HZ),
            Unit::Second => symmetric(bounds::TIME_S),
            Unit::MetrePerSecond => symmetric(bounds::SPEED_M_S),
            Unit::MetrePerSecondSquared => symmetric(bounds::ACCEL_M_S2),
            Unit::DegreePerSecond => symmetric(bounds::ANGULAR_SPEED_DEG_S),
            Unit::DegreePerSecondSquared => symmetric(bounds::ANGULAR_ACCEL_DEG_S2),
            Unit::MetrePerSecondCubed => symmetric(bounds::JERK_M_S3),
            Unit::DegreePerSecondCubed => symmetric(bounds::ANGULAR_JERK_DEG_S3),
            Unit::Count => 2.0..=crate::model::trajectory::MAX_SAMPLES as f64,
            Unit::Ratio => symmetric(bounds::RATIO),
            Unit::RadianPerSecond => symmetric(crate::model::cueing_settings::MAX_OMEGA),
            Unit::Switch => 0.0..=1.0,
            Unit::Kilogram => symmetric(bounds::MASS_KG),
            Unit::KilogramSquareMetre => symmetric(bounds::INERTIA_KG_M2),
            Unit::Stiffness => symmetric(crate::model::dynamics_settings::MAX_STIFFNESS),
            Unit::Friction => symmetric(crate::model::dynamics_settings::MAX_FRICTION),
        }
    }
}

/// What a setting is when nobody says otherwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DefaultValue {
    /// A fixed number.
    Value(f64),
    /// The platform's home height plus this many metres.
    AboveHome(f64),
    /// Absent: the limit or check is not applied.
    Off,
}

impl DefaultValue {
    /// The number for a platform whose home height is `home_height` (`None` when off).
    pub fn resolve(self, home_height: f64) -> Option<f64> {
        match self {
            DefaultValue::Value(v) => Some(v),
            DefaultValue::AboveHome(dz) => Some(home_height + dz),
            DefaultValue::Off => None,
        }
    }
}

/// One adjustable number of a scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    /// Dotted path in the scenario file, such as `geometry.base_radius` or
    /// `trajectory.pitch.phase_deg`; what `--set` takes.
    pub key: String,
    /// Short words for people, such as `base radius`.
    pub label: String,
    /// The unit of the value.
    pub unit: Unit,
    /// The range a slider offers (typed values may go beyond where the model allows).
    pub range: RangeInclusive<f64>,
    /// The values accepted at all: the unit's range ([`Unit::accepted`]) narrowed by the
    /// model's own rule on the setting's sign and size (a radius is positive, a cue scale
    /// at most 10). A value inside may still conflict with another setting (a stroke
    /// minimum above its maximum).
    pub accepted: RangeInclusive<f64>,
    /// Whether the accepted range's lower end is itself refused (a length must be
    /// positive: above 0, not 0).
    pub min_excluded: bool,
    /// Whether its upper end is itself refused (a joint cone is below 180°).
    pub max_excluded: bool,
    /// The value when none is given.
    pub default: DefaultValue,
    /// The section of the file (and the panel of the viewer) it belongs to.
    pub group: Group,
    /// What it reads and writes.
    pub target: SettingTarget,
}

/// The sections settings are grouped in, as in the scenario file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// `[geometry]` and `[pivot]`.
    Geometry,
    /// `[trajectory]`.
    Trajectory,
    /// `[limits]`.
    Limits,
    /// `[checks]`.
    Checks,
    /// `[cueing]`.
    Cueing,
    /// `[dynamics]`.
    Dynamics,
    /// `[appearance]` (CAD parts: files and words, no numbers of the catalogue).
    Appearance,
}

/// Why a setting could not be read or written.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SettingError {
    /// No setting has this key.
    #[error("unknown setting `{0}` (`stewart settings` lists every key)")]
    Unknown(String),
    /// `KEY=VALUE` was not of that form or the value not a number.
    #[error("`{text}` is not KEY=VALUE with a number (or `off`) as the value")]
    Syntax {
        /// What was given.
        text: String,
    },
    /// The key belongs to another trajectory kind.
    #[error("`{key}` does not apply to a `{kind}` trajectory")]
    NotApplicable {
        /// The key.
        key: String,
        /// The scenario's trajectory kind.
        kind: &'static str,
    },
    /// A circle key (radius, angle) for a plate whose joints are given as coordinates.
    #[error(
        "`{key}` does not apply: the {plate} joints are given as coordinates (`geometry.{plate}_joints_m`); set those instead"
    )]
    PlateGivenAsPoints {
        /// The key.
        key: String,
        /// The plate.
        plate: crate::model::geometry::Plate,
    },
    /// An actuator key on a platform with linear legs.
    #[error("`{key}` applies to rotary platforms only (`[actuator] kind = \"rotary\"`)")]
    NotRotary {
        /// The key.
        key: String,
    },
    /// A linear-leg key (stroke, leg speed) on a rotary platform.
    #[error("`{key}` applies to linear legs only; a rotary platform has servo limits instead")]
    NotLinear {
        /// The key.
        key: String,
    },
    /// The value was refused; the scenario is unchanged.
    #[error("`{key}` = {value} refused: {reason}")]
    Invalid {
        /// The key.
        key: String,
        /// The value given (`off` for none).
        value: String,
        /// Why.
        reason: String,
    },
}

impl Setting {
    /// The label with its unit, as sliders show it: `base radius (m)`.
    pub fn label_with_unit(&self) -> String {
        match self.unit.symbol() {
            "" => self.label.clone(),
            unit => format!("{} ({unit})", self.label),
        }
    }

    /// The accepted range in words, such as `-1000 … 1000 m`, or `above 0 … 1000 m` when
    /// its lower end is refused.
    pub fn accepted_words(&self) -> String {
        self.accepted_words_in(self.unit.symbol())
    }

    /// [`Setting::accepted_words`] in the unit of a platform whose actuators are of
    /// `kind` (a stiffness in N/m or N·m/rad).
    pub fn accepted_words_for(&self, kind: ActuatorKind) -> String {
        self.accepted_words_in(self.unit.symbol_for(kind))
    }

    fn accepted_words_in(&self, unit: &str) -> String {
        let words = crate::ground::bounds::range_words(&self.accepted, unit);
        match (self.min_excluded, self.max_excluded) {
            (false, false) => words,
            (true, false) => format!("above {words}"),
            (min, true) => {
                let above = if min { "above" } else { "from" };
                format!(
                    "{above} {} and below {} {unit}",
                    crate::ground::bounds::short(*self.accepted.start()),
                    crate::ground::bounds::short(*self.accepted.end())
                )
                .trim_end()
                .to_owned()
            }
        }
    }

    /// Whether `v` lies in the accepted range (its excluded ends refused); the refusal
    /// names this setting's own rule, as `stewart settings` prints it.
    pub fn check_accepted(&self, v: f64, kind: ActuatorKind) -> Result<(), String> {
        if !v.is_finite() {
            return Err("it must be a finite number".to_owned());
        }
        let (lo, hi) = (*self.accepted.start(), *self.accepted.end());
        let inside = self.accepted.contains(&v)
            && !(self.min_excluded && v == lo)
            && !(self.max_excluded && v == hi);
        if inside {
            return Ok(());
        }
        Err(format!(
            "{} is outside the accepted range {}",
            crate::ground::bounds::short(v),
            self.accepted_words_for(kind)
        ))
    }

    /// Whether the setting may be absent (`off`).
    pub fn optional(&self) -> bool {
        self.target.optional()
    }

    /// Whether the setting means something for this scenario (trajectory keys belong to
    /// some trajectory kinds only).
    pub fn applies(&self, scenario: &Scenario) -> bool {
        self.target.applies(scenario)
    }

    /// The current value; `None` when the setting is off or does not apply.
    pub fn get(&self, scenario: &Scenario) -> Option<f64> {
        self.target.get(scenario)
    }

    /// The range a slider offers for this scenario's platform: a length follows the
    /// platform's size (the declared range is for the seed's, 0.6 m platform radius: a
    /// 6 cm desk platform gets a tenth of it), a stroke limit spans half to twice the
    /// home leg length, a servo's stiffness spans servos' (N·m/rad), and the range always
    /// holds the present value.
    pub fn range_for(&self, scenario: &Scenario) -> RangeInclusive<f64> {
        let (mut lo, mut hi) = (*self.range.start(), *self.range.end());
        let g = &scenario.geometry;
        let stroke = matches!(
            self.target,
            SettingTarget::Geometry(GeometryKey::LegMin | GeometryKey::LegMax)
        );
        let servo_part = matches!(self.target, SettingTarget::Actuator(_));
        if stroke {
            let home = g.leg_lengths(&g.home_pose());
            let mean = home.iter().sum::<f64>() / 6.0;
            if mean.is_finite() && mean > 0.0 {
                (lo, hi) = (0.5 * mean, 2.0 * mean);
            }
        } else if self.unit == Unit::Stiffness && g.actuator().kind() == ActuatorKind::Rotary {
            (lo, hi) = crate::model::dynamics_settings::ROTARY_STIFFNESS_RANGE;
        } else if self.unit == Unit::Metre && !servo_part {
            let seed = crate::model::geometry::Geometry::seed().characteristic_length();
            let scale = (g.characteristic_length() / seed).clamp(1e-3, 1e3);
            if scale.is_finite() {
                (lo, hi) = (lo * scale, hi * scale);
            }
        }
        if let Some(v) = self.get(scenario).filter(|v| v.is_finite()) {
            (lo, hi) = (lo.min(v), hi.max(v));
        }
        lo..=hi
    }

    /// The default for this scenario's platform.
    pub fn default_for(&self, scenario: &Scenario) -> Option<f64> {
        self.default.resolve(scenario.geometry.home_height())
    }

    /// The value an optional setting takes when switched on: its default, else a typical
    /// value (an actuator stiffness of the platform's kind), else the top of its declared
    /// range.
    pub fn value_when_switched_on(&self, scenario: &Scenario) -> f64 {
        if let Some(v) = self.default_for(scenario) {
            return v;
        }
        if self.unit == Unit::Stiffness {
            return crate::model::dynamics_settings::typical_stiffness(
                scenario.geometry.actuator().kind(),
            );
        }
        *self.range.end()
    }

    /// Write `value` (`None`: switch off). Validated as the file reader validates; a
    /// refused value leaves the scenario unchanged.
    pub fn set(&self, scenario: &mut Scenario, value: Option<f64>) -> Result<(), SettingError> {
        let shown = value.map_or_else(|| "off".to_owned(), crate::ground::bounds::short);
        let invalid = |reason: String| SettingError::Invalid {
            key: self.key.clone(),
            value: shown.clone(),
            reason,
        };
        match self.target.actuator_kind() {
            Some(kind) if kind != scenario.geometry.actuator().kind() => {
                let key = self.key.clone();
                return Err(match kind {
                    ActuatorKind::Rotary => SettingError::NotRotary { key },
                    ActuatorKind::Linear => SettingError::NotLinear { key },
                });
            }
            _ => {}
        }
        if let SettingTarget::Geometry(key) = self.target
            && let Some(plate) = key.circle_plate()
            && scenario.geometry.params().plate(plate).circle().is_none()
        {
            return Err(SettingError::PlateGivenAsPoints {
                key: self.key.clone(),
                plate,
            });
        }
        if !self.applies(scenario) {
            return Err(SettingError::NotApplicable {
                key: self.key.clone(),
                kind: scenario.motion.trajectory.kind_name(),
            });
        }
        match value {
            None if !self.optional() => {
                return Err(invalid("it cannot be switched off".to_owned()));
            }
            // A switch first: NaN is no more a switch than 2 is.
            Some(v) if self.unit == Unit::Switch && v != 0.0 && v != 1.0 => {
                return Err(invalid(
                    "it is a switch: true or false (on or off, 1 or 0)".to_owned(),
                ));
            }
            Some(v) if !v.is_finite() => {
                return Err(invalid("it must be a finite number".to_owned()));
            }
            Some(v) if self.unit == Unit::Count && v.fract() != 0.0 => {
                return Err(invalid(format!(
                    "it must be a whole number from {}",
                    self.accepted_words()
                )));
            }
            // The setting's own accepted range, as printed; within it the model refuses
            // only what depends on other settings (a stroke minimum above its maximum).
            Some(v) => self
                .check_accepted(v, scenario.geometry.actuator().kind())
                .map_err(invalid)?,
            _ => {}
        }
        self.target.set(scenario, value).map_err(|reason| {
            // A rule named with its key is this setting's own when the key is its own.
            let own = format!("`{}` ", self.key);
            invalid(
                reason
                    .strip_prefix(&own)
                    .map_or(reason.clone(), str::to_owned),
            )
        })
    }
}

static ALL: LazyLock<Vec<Setting>> = LazyLock::new(catalogue::build);

/// Every setting, in file order.
pub fn all() -> &'static [Setting] {
    &ALL
}

/// The setting with this key.
pub fn find(key: &str) -> Result<&'static Setting, SettingError> {
    all()
        .iter()
        .find(|s| s.key == key)
        .ok_or_else(|| SettingError::Unknown(key.to_owned()))
}

/// The setting for a target.
pub fn of(target: SettingTarget) -> &'static Setting {
    all()
        .iter()
        .find(|s| s.target == target)
        .unwrap_or_else(|| unreachable!("the catalogue declares every target ({target:?})"))
}

/// Parse `KEY=VALUE` (a number, or `off` for optional settings; a switch also takes
/// `true`, `false`, `on` and `off`).
pub fn parse_assignment(text: &str) -> Result<(&'static Setting, Option<f64>), SettingError> {
    let syntax = || SettingError::Syntax {
        text: text.to_owned(),
    };
    let (key, value) = text.split_once('=').ok_or_else(syntax)?;
    let setting = find(key.trim())?;
    let value = value.trim();
    let value = if setting.unit == Unit::Switch {
        // One rule for every switch (the link's too): words, or a number equal to 1 or 0.
        let on = crate::model::switch::read(value).ok_or_else(|| SettingError::Invalid {
            key: setting.key.clone(),
            value: value.to_owned(),
            reason: format!("it is a switch: {}", crate::model::switch::ACCEPTS),
        })?;
        Some(f64::from(u8::from(on)))
    } else if value.eq_ignore_ascii_case("off") {
        None
    } else {
        let reason = if setting.optional() {
            "it must be a number, or `off`"
        } else {
            "it must be a number"
        };
        let refused = |reason: &str| SettingError::Invalid {
            key: setting.key.clone(),
            value: value.to_owned(),
            reason: reason.to_owned(),
        };
        let number = value.parse::<f64>().map_err(|_| refused(reason))?;
        // Refused as typed (`1e400`, not the `inf` it reads as).
        if !number.is_finite() {
            return Err(refused("it must be a finite number"));
        }
        Some(number)
    };
    Ok((setting, value))
}

/// The settings that bound the actuator quantity of `kind`, lower end first: the stroke
/// (`geometry.leg_min`, `leg_max`) or the servo range (`actuator.servo_min_deg`, `…max…`).
pub fn quantity_limit_targets(kind: ActuatorKind) -> [SettingTarget; 2] {
    match kind {
        ActuatorKind::Linear => [
            SettingTarget::Geometry(GeometryKey::LegMin),
            SettingTarget::Geometry(GeometryKey::LegMax),
        ],
        ActuatorKind::Rotary => [
            SettingTarget::Actuator(ActuatorKey::ServoMin),
            SettingTarget::Actuator(ActuatorKey::ServoMax),
        ],
    }
}

/// The first setting of `scenario` whose value lies outside its accepted range (a file
/// may hold values no slider offers), with the reason.
pub fn out_of_range(scenario: &Scenario) -> Option<(&'static Setting, String)> {
    all().iter().find_map(|s| {
        let v = s.get(scenario)?;
        s.check_accepted(v, scenario.geometry.actuator().kind())
            .err()
            .map(|reason| (s, reason))
    })
}

/// Apply `KEY=VALUE` assignments in order (`link.*` and `appearance.*` keys take words,
/// see [`crate::model::link_settings::LinkSettings::set_text`] and
/// [`crate::model::appearance::AppearanceSettings::set_text`]); the first refusal stops and is returned, and
/// the scenario is then left as it was before any of them.
pub fn apply_all<'a>(
    scenario: &mut Scenario,
    assignments: impl IntoIterator<Item = &'a str>,
) -> Result<(), SettingError> {
    let mut edited = scenario.clone();
    for text in assignments {
        // The tables that take words: (key, reason) of a refusal.
        if let Some((key, value)) = text.split_once('=') {
            let key = key.trim();
            let worded = if let Some(k) = key.strip_prefix("link.") {
                Some(
                    edited
                        .link
                        .set_text(k, value)
                        .map_err(|p| (p.key, p.reason)),
                )
            } else if key == "cueing.algorithm" {
                Some(
                    crate::model::cueing_settings::CueingAlgorithm::from_word(value)
                        .map(|a| edited.cueing.algorithm = a)
                        .ok_or_else(|| (key.to_owned(), "must be `washout` or `mpc`".to_owned())),
                )
            } else {
                key.strip_prefix("appearance.").map(|k| {
                    edited
                        .appearance
                        .set_text(k, value)
                        .map_err(|p| (p.key, p.reason))
                })
            };
            if let Some(done) = worded {
                // As typed; between backticks when spaces at an end are part of it (a
                // template keeps its end), else they would not show.
                let typed = if value.trim() == value {
                    value.to_owned()
                } else {
                    format!("`{value}`")
                };
                done.map_err(|(key, reason)| SettingError::Invalid {
                    key,
                    value: typed,
                    reason,
                })?;
                continue;
            }
        }
        let (setting, value) = parse_assignment(text)?;
        // A refusal quotes the value as typed (`2e3`, not the 2000 it reads as).
        setting.set(&mut edited, value).map_err(|e| match e {
            SettingError::Invalid { key, reason, .. } => SettingError::Invalid {
                key,
                value: text
                    .split_once('=')
                    .map_or("", |(_, v)| v.trim())
                    .to_owned(),
                reason,
            },
            other => other,
        })?;
    }
    *scenario = edited;
    Ok(())
}

#[cfg(test)]
mod tests;
