//! What each setting reads and writes in a [`Scenario`].

use super::cueing::CueingKey;
use super::dynamics::DynamicsKey;
use crate::io::scenario::Scenario;
use crate::model::actuator::Actuator;
use crate::model::angle::Angle;
use crate::model::geometry::{Geometry, Plate, PlateJoints};
use crate::model::rotary::RotaryActuators;
use crate::model::trajectory::{Channel, Sampling, Trajectory};

/// Numbers of `[geometry]` and `[pivot]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GeometryKey {
    /// Base joint circle radius.
    BaseRadius,
    /// Platform joint circle radius.
    PlatformRadius,
    /// Home height.
    HomeHeight,
    /// Shortest leg.
    LegMin,
    /// Longest leg.
    LegMax,
    /// Angle of base joint `i` (0-based).
    BaseAngle(usize),
    /// Angle of platform joint `i` (0-based).
    PlatformAngle(usize),
    /// Coordinate `k` (x, y, z) of joint `i` (0-based) of a plate, metres.
    Joint(Plate, usize, usize),
    /// Component `i` (x, y, z) of the pivot offset.
    Pivot(usize),
}

/// The numbers of a rotary platform's `[actuator]` table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ActuatorKey {
    /// `horn_length_m`.
    HornLength,
    /// `rod_length_m`.
    RodLength,
    /// `horn_angles_deg[i]`.
    HornAngle(usize),
    /// `servo_min_deg` (with `servo_max_deg`, optional).
    ServoMin,
    /// `servo_max_deg`.
    ServoMax,
    /// `servo_trim_deg[i]`.
    Trim(usize),
    /// `servo_reversed[i]` (a switch).
    Reversed(usize),
}

/// How the trajectory is sampled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplingKey {
    /// First time.
    Start,
    /// Duration.
    Duration,
    /// Number of samples.
    Samples,
}

/// The numbers of one sinusoid channel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChannelKey {
    /// Peak deviation.
    Amplitude,
    /// Frequency.
    Frequency,
    /// Phase at t = 0.
    Phase,
    /// Centre value.
    Offset,
}

/// The numbers of the parametric shapes (each kind uses some).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShapeKey {
    /// Circle, helix and sway radius.
    Radius,
    /// Revolutions (or figure-eights) per second.
    Frequency,
    /// Height of level shapes.
    Z,
    /// Figure-eight half-width along x.
    AmplitudeX,
    /// Figure-eight half-width along y.
    AmplitudeY,
    /// Helix start height.
    ZStart,
    /// Helix end height.
    ZEnd,
    /// Sway lean.
    Tilt,
}

/// Optional actuator and joint limits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LimitKey {
    /// Leg speed.
    LegSpeed,
    /// Leg acceleration.
    LegAccel,
    /// Leg jerk.
    LegJerk,
    /// Base joint cone.
    BaseCone,
    /// Platform joint cone.
    PlatformCone,
    /// Leg cylinder radius.
    LegRadius,
    /// Servo speed (rotary platforms).
    ServoSpeed,
    /// Servo acceleration (rotary platforms).
    ServoAccel,
    /// Servo jerk (rotary platforms).
    ServoJerk,
}

pub use crate::model::actuator::ActuatorKind;

/// Thresholds of the checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckKey {
    /// Rigid-body tolerance.
    RigidTolerance,
    /// Jump ratio.
    JumpRatio,
    /// Jump floor.
    JumpFloor,
    /// Near-singular threshold.
    ConditionMax,
}

/// What a setting reads and writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SettingTarget {
    /// A platform number.
    Geometry(GeometryKey),
    /// A rotary platform's actuator number.
    Actuator(ActuatorKey),
    /// The sampling.
    Sampling(SamplingKey),
    /// Channel `i` (x, y, z, roll, pitch, yaw) of a sinusoid.
    Channel(usize, ChannelKey),
    /// A shape's number.
    Shape(ShapeKey),
    /// A limit.
    Limit(LimitKey),
    /// A check threshold.
    Check(CheckKey),
    /// A number or switch of `[cueing]`.
    Cueing(CueingKey),
    /// A number of `[dynamics]`.
    Dynamics(DynamicsKey),
}

impl SettingTarget {
    /// Whether it may be absent.
    pub(super) fn optional(self) -> bool {
        matches!(
            self,
            SettingTarget::Limit(_)
                | SettingTarget::Geometry(GeometryKey::LegMin | GeometryKey::LegMax)
                | SettingTarget::Actuator(ActuatorKey::ServoMin | ActuatorKey::ServoMax)
                | SettingTarget::Dynamics(DynamicsKey::Stiffness)
        )
    }

    /// The actuator kind it belongs to (`None`: both).
    pub fn actuator_kind(self) -> Option<ActuatorKind> {
        match self {
            SettingTarget::Actuator(_)
            | SettingTarget::Limit(
                LimitKey::ServoSpeed | LimitKey::ServoAccel | LimitKey::ServoJerk,
            ) => Some(ActuatorKind::Rotary),
            SettingTarget::Geometry(GeometryKey::LegMin | GeometryKey::LegMax)
            | SettingTarget::Limit(LimitKey::LegSpeed | LimitKey::LegAccel | LimitKey::LegJerk) => {
                Some(ActuatorKind::Linear)
            }
            SettingTarget::Dynamics(key) => key.kind(),
            _ => None,
        }
    }

    pub(super) fn applies(self, scenario: &Scenario) -> bool {
        let trajectory = &scenario.motion.trajectory;
        if self
            .actuator_kind()
            .is_some_and(|kind| kind != scenario.geometry.actuator().kind())
        {
            return false;
        }
        match self {
            SettingTarget::Channel(..) => matches!(trajectory, Trajectory::Sinusoid(_)),
            SettingTarget::Shape(key) => shape_value(trajectory, key).is_some(),
            SettingTarget::Geometry(key) => match key.circle_plate() {
                Some(plate) => scenario.geometry.params().plate(plate).circle().is_some(),
                None => true,
            },
            _ => true,
        }
    }

    pub(super) fn get(self, scenario: &Scenario) -> Option<f64> {
        match self {
            SettingTarget::Geometry(key) => geometry_value(scenario, key),
            SettingTarget::Actuator(key) => actuator_value(scenario, key),
            SettingTarget::Sampling(key) => {
                let s = &scenario.motion.sampling;
                Some(match key {
                    SamplingKey::Start => s.start(),
                    SamplingKey::Duration => s.duration(),
                    SamplingKey::Samples => s.len() as f64,
                })
            }
            SettingTarget::Channel(i, key) => match &scenario.motion.trajectory {
                Trajectory::Sinusoid(s) => s.channels().get(i).map(|(_, c)| match key {
                    ChannelKey::Amplitude => c.amplitude,
                    ChannelKey::Frequency => c.frequency_hz,
                    ChannelKey::Phase => c.phase.degrees(),
                    ChannelKey::Offset => c.offset,
                }),
                _ => None,
            },
            SettingTarget::Shape(key) => shape_value(&scenario.motion.trajectory, key),
            SettingTarget::Limit(key) => {
                let l = &scenario.limits;
                match key {
                    LimitKey::LegSpeed => l.leg_speed_max,
                    LimitKey::LegAccel => l.leg_accel_max,
                    LimitKey::LegJerk => l.leg_jerk_max,
                    LimitKey::BaseCone => l.base_cone.map(|a| a.degrees()),
                    LimitKey::PlatformCone => l.platform_cone.map(|a| a.degrees()),
                    LimitKey::LegRadius => l.leg_radius,
                    LimitKey::ServoSpeed => l.servo_speed_max,
                    LimitKey::ServoAccel => l.servo_accel_max,
                    LimitKey::ServoJerk => l.servo_jerk_max,
                }
            }
            SettingTarget::Check(key) => {
                let c = &scenario.checks;
                Some(match key {
                    CheckKey::RigidTolerance => c.rigid_tolerance,
                    CheckKey::JumpRatio => c.jump_ratio,
                    CheckKey::JumpFloor => c.jump_floor,
                    CheckKey::ConditionMax => c.condition_max,
                })
            }
            SettingTarget::Cueing(key) => super::cueing::get(&scenario.cueing, key),
            SettingTarget::Dynamics(key) => super::dynamics::get(&scenario.dynamics, key),
        }
    }

    /// Write a value already known to be finite (or `None` for an optional one).
    pub(super) fn set(self, scenario: &mut Scenario, value: Option<f64>) -> Result<(), String> {
        let v = value.unwrap_or(f64::NAN);
        match self {
            SettingTarget::Geometry(key) => set_geometry(scenario, key, value),
            SettingTarget::Actuator(key) => set_actuator(scenario, key, value),
            SettingTarget::Sampling(key) => set_sampling(scenario, key, v),
            SettingTarget::Channel(i, key) => {
                if let Trajectory::Sinusoid(s) = &mut scenario.motion.trajectory
                    && let Some(c) = s.channels_mut().into_iter().nth(i)
                {
                    set_channel(c, key, v);
                }
                Ok(())
            }
            SettingTarget::Shape(key) => {
                if let Some(field) = shape_field(&mut scenario.motion.trajectory, key) {
                    field.write(v);
                }
                Ok(())
            }
            SettingTarget::Limit(key) => set_limit(scenario, key, value),
            SettingTarget::Check(key) => {
                if v <= 0.0 {
                    return Err(format!("it must be positive, got {v}"));
                }
                let c = &mut scenario.checks;
                *match key {
                    CheckKey::RigidTolerance => &mut c.rigid_tolerance,
                    CheckKey::JumpRatio => &mut c.jump_ratio,
                    CheckKey::JumpFloor => &mut c.jump_floor,
                    CheckKey::ConditionMax => &mut c.condition_max,
                } = v;
                Ok(())
            }
            SettingTarget::Cueing(key) => super::cueing::set(&mut scenario.cueing, key, v),
            SettingTarget::Dynamics(key) => {
                super::dynamics::set(&mut scenario.dynamics, key, value)
            }
        }
    }
}

fn set_geometry(
    scenario: &mut Scenario,
    key: GeometryKey,
    value: Option<f64>,
) -> Result<(), String> {
    let mut p = scenario.geometry.params().clone();
    let v = value.unwrap_or(f64::NAN);
    let radius = |joints: &mut PlateJoints| {
        if let PlateJoints::Circle { radius, .. } = joints {
            *radius = v;
        }
    };
    let angle = |joints: &mut PlateJoints, i: usize| {
        if let PlateJoints::Circle { angles, .. } = joints
            && let Some(a) = angles.get_mut(i)
        {
            *a = Angle::from_degrees(v);
        }
    };
    match key {
        GeometryKey::BaseRadius => radius(&mut p.base),
        GeometryKey::PlatformRadius => radius(&mut p.platform),
        GeometryKey::HomeHeight => p.home_height = v,
        GeometryKey::LegMin => p.stroke.min = value,
        GeometryKey::LegMax => p.stroke.max = value,
        GeometryKey::BaseAngle(i) => angle(&mut p.base, i),
        GeometryKey::PlatformAngle(i) => angle(&mut p.platform, i),
        GeometryKey::Joint(plate, i, k) => {
            // A coordinate turns a plate on a circle into the coordinate form.
            let joints = p.plate_mut(plate);
            let mut points = joints.points();
            if let Some(c) = points.get_mut(i).and_then(|pt| pt.get_mut(k)) {
                *c = v;
            }
            *joints = PlateJoints::Points(points);
        }
        GeometryKey::Pivot(i) => {
            if let Some(c) = p.pivot.get_mut(i) {
                *c = v;
            }
        }
    }
    scenario.geometry = Geometry::new(p).map_err(|e| e.to_string())?;
    Ok(())
}

impl GeometryKey {
    /// The plate whose circle this key describes (radius and angles), if any: such keys
    /// apply only while that plate's joints are given on a circle.
    pub fn circle_plate(self) -> Option<Plate> {
        match self {
            GeometryKey::BaseRadius | GeometryKey::BaseAngle(_) => Some(Plate::Base),
            GeometryKey::PlatformRadius | GeometryKey::PlatformAngle(_) => Some(Plate::Platform),
            _ => None,
        }
    }
}

/// Rebuild the servos with one number changed. Setting one end of an absent servo range
/// makes the range symmetric (min = −max); `off` on either end removes the range.
fn set_actuator(
    scenario: &mut Scenario,
    key: ActuatorKey,
    value: Option<f64>,
) -> Result<(), String> {
    let Some(r) = scenario.geometry.rotary() else {
        return Err("the platform has linear legs".to_owned());
    };
    let v = value.unwrap_or(f64::NAN);
    let (mut horn, mut rod) = (r.horn_length(), r.rod_length());
    let mut angles = r.horn_angles().map(|a| a.degrees());
    let mut range = r.range().map(|(a, b)| (a.degrees(), b.degrees()));
    let mut reversed = *r.reversed();
    let mut trims = r.trims().map(|a| a.degrees());
    match key {
        ActuatorKey::HornLength => horn = v,
        ActuatorKey::RodLength => rod = v,
        ActuatorKey::HornAngle(i) => {
            if let Some(a) = angles.get_mut(i) {
                *a = v;
            }
        }
        ActuatorKey::ServoMin | ActuatorKey::ServoMax if value.is_none() => range = None,
        ActuatorKey::ServoMin => range = Some((v, range.map_or(-v, |(_, max)| max))),
        ActuatorKey::ServoMax => range = Some((range.map_or(-v, |(min, _)| min), v)),
        ActuatorKey::Trim(i) => {
            if let Some(t) = trims.get_mut(i) {
                *t = v;
            }
        }
        ActuatorKey::Reversed(i) => {
            if let Some(on) = reversed.get_mut(i) {
                *on = v == 1.0;
            }
        }
    }
    let servos = RotaryActuators::new(horn, rod, angles, range)
        .and_then(|r| r.with_mounting(reversed, trims))
        .map_err(|e| e.to_string())?;
    let mut p = scenario.geometry.params().clone();
    p.actuator = Actuator::Rotary(servos);
    scenario.geometry = Geometry::new(p).map_err(|e| e.to_string())?;
    Ok(())
}

fn set_sampling(scenario: &mut Scenario, key: SamplingKey, v: f64) -> Result<(), String> {
    let s = scenario.motion.sampling;
    let (mut start, mut duration, mut samples) = (s.start(), s.duration(), s.len() as f64);
    match key {
        SamplingKey::Start => start = v,
        SamplingKey::Duration => duration = v,
        SamplingKey::Samples => samples = v,
    }
    if samples < 2.0 {
        return Err(format!("at least 2 samples are needed, got {samples}"));
    }
    scenario.motion.sampling =
        Sampling::with_start(start, duration, samples as u64).map_err(|e| e.to_string())?;
    // A helix climbs over the whole sampled duration (as the file reader builds it).
    if let Trajectory::Helix(h) = &mut scenario.motion.trajectory {
        h.duration = duration;
    }
    Ok(())
}

fn set_channel(c: &mut Channel, key: ChannelKey, v: f64) {
    match key {
        ChannelKey::Amplitude => c.amplitude = v,
        ChannelKey::Frequency => c.frequency_hz = v,
        ChannelKey::Phase => c.phase = Angle::from_degrees(v),
        ChannelKey::Offset => c.offset = v,
    }
}

fn set_limit(scenario: &mut Scenario, key: LimitKey, value: Option<f64>) -> Result<(), String> {
    if let Some(v) = value {
        if v <= 0.0 {
            return Err(format!("it must be positive, got {v}"));
        }
        if matches!(key, LimitKey::BaseCone | LimitKey::PlatformCone) && v >= 180.0 {
            return Err(format!("a cone must be less than 180°, got {v}"));
        }
    }
    let l = &mut scenario.limits;
    let degrees = value.map(Angle::from_degrees);
    match key {
        LimitKey::LegSpeed => l.leg_speed_max = value,
        LimitKey::LegAccel => l.leg_accel_max = value,
        LimitKey::LegJerk => l.leg_jerk_max = value,
        LimitKey::BaseCone => l.base_cone = degrees,
        LimitKey::PlatformCone => l.platform_cone = degrees,
        LimitKey::LegRadius => l.leg_radius = value,
        LimitKey::ServoSpeed => l.servo_speed_max = value,
        LimitKey::ServoAccel => l.servo_accel_max = value,
        LimitKey::ServoJerk => l.servo_jerk_max = value,
    }
    Ok(())
}

/// A shape's number, read in the unit of its setting.
enum ShapeField<'a> {
    Plain(&'a mut f64),
    Degrees(&'a mut Angle),
}

impl ShapeField<'_> {
    fn read(&self) -> f64 {
        match self {
            ShapeField::Plain(v) => **v,
            ShapeField::Degrees(a) => a.degrees(),
        }
    }

    fn write(self, v: f64) {
        match self {
            ShapeField::Plain(x) => *x = v,
            ShapeField::Degrees(a) => *a = Angle::from_degrees(v),
        }
    }
}
/// A platform number of `scenario` (`None` where its layout has none: a circle's radius
/// of joints given as coordinates).
fn geometry_value(scenario: &Scenario, key: GeometryKey) -> Option<f64> {
    let params = scenario.geometry.params();
    match key {
        GeometryKey::BaseRadius => params.base.circle().map(|c| c.0),
        GeometryKey::PlatformRadius => params.platform.circle().map(|c| c.0),
        GeometryKey::HomeHeight => Some(params.home_height),
        GeometryKey::LegMin => params.stroke.min,
        GeometryKey::LegMax => params.stroke.max,
        GeometryKey::BaseAngle(i) => params
            .base
            .circle()
            .and_then(|c| c.1.get(i).map(|a| a.degrees())),
        GeometryKey::PlatformAngle(i) => params
            .platform
            .circle()
            .and_then(|c| c.1.get(i).map(|a| a.degrees())),
        GeometryKey::Joint(plate, i, k) => scenario
            .geometry
            .joints(plate)
            .get(i)
            .and_then(|p| p.get(k).copied()),
        GeometryKey::Pivot(i) => params.pivot.get(i).copied(),
    }
}

/// A rotary platform's actuator number (`None` for linear legs).
fn actuator_value(scenario: &Scenario, key: ActuatorKey) -> Option<f64> {
    let r = scenario.geometry.rotary()?;
    match key {
        ActuatorKey::HornLength => Some(r.horn_length()),
        ActuatorKey::RodLength => Some(r.rod_length()),
        ActuatorKey::HornAngle(i) => r.horn_angles().get(i).map(|a| a.degrees()),
        ActuatorKey::ServoMin => r.range().map(|(min, _)| min.degrees()),
        ActuatorKey::ServoMax => r.range().map(|(_, max)| max.degrees()),
        ActuatorKey::Trim(i) => r.trims().get(i).map(|a| a.degrees()),
        ActuatorKey::Reversed(i) => r.reversed().get(i).map(|&on| f64::from(u8::from(on))),
    }
}

/// The value of a shape key in this trajectory, if its kind has that key.
fn shape_value(trajectory: &Trajectory, key: ShapeKey) -> Option<f64> {
    if matches!(
        trajectory,
        Trajectory::Sinusoid(_) | Trajectory::Keyframes(_)
    ) {
        return None;
    }
    // A shape is a handful of numbers: reading through a copy keeps one table of fields.
    let mut copy = trajectory.clone();
    shape_field(&mut copy, key).map(|f| f.read())
}

/// The field a shape key names in this trajectory, if its kind has one.
fn shape_field(trajectory: &mut Trajectory, key: ShapeKey) -> Option<ShapeField<'_>> {
    use ShapeField::{Degrees, Plain};
    match (trajectory, key) {
        (Trajectory::Circle(c), ShapeKey::Radius) => Some(Plain(&mut c.radius)),
        (Trajectory::Circle(c), ShapeKey::Frequency) => Some(Plain(&mut c.frequency_hz)),
        (Trajectory::Circle(c), ShapeKey::Z) => Some(Plain(&mut c.z)),
        (Trajectory::FigureEight(f), ShapeKey::AmplitudeX) => Some(Plain(&mut f.amplitude_x)),
        (Trajectory::FigureEight(f), ShapeKey::AmplitudeY) => Some(Plain(&mut f.amplitude_y)),
        (Trajectory::FigureEight(f), ShapeKey::Frequency) => Some(Plain(&mut f.frequency_hz)),
        (Trajectory::FigureEight(f), ShapeKey::Z) => Some(Plain(&mut f.z)),
        (Trajectory::Helix(h), ShapeKey::Radius) => Some(Plain(&mut h.radius)),
        (Trajectory::Helix(h), ShapeKey::Frequency) => Some(Plain(&mut h.frequency_hz)),
        (Trajectory::Helix(h), ShapeKey::ZStart) => Some(Plain(&mut h.z_start)),
        (Trajectory::Helix(h), ShapeKey::ZEnd) => Some(Plain(&mut h.z_end)),
        (Trajectory::Sway(s), ShapeKey::Radius) => Some(Plain(&mut s.radius)),
        (Trajectory::Sway(s), ShapeKey::Frequency) => Some(Plain(&mut s.frequency_hz)),
        (Trajectory::Sway(s), ShapeKey::Tilt) => Some(Degrees(&mut s.tilt)),
        (Trajectory::Sway(s), ShapeKey::Z) => Some(Plain(&mut s.z)),
        _ => None,
    }
}
