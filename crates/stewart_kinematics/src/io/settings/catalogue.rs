//! The list of settings: keys, labels, units, slider ranges and defaults.
//!
//! Defaults are the seed's platform and motion; shape defaults are those of the shipped
//! presets. Slider ranges cover sensible laboratory platforms; typed values may go
//! beyond them wherever the model accepts them.

use super::cueing::{AXES, CueingKey};
use super::dynamics::DynamicsKey;
use super::target::{
    ActuatorKey, ChannelKey, CheckKey, GeometryKey, LimitKey, SamplingKey, SettingTarget, ShapeKey,
};
use super::{DefaultValue, Group, Setting, Unit};
use crate::analysis::checks::CheckSettings;
use crate::model::cueing_settings::CueingSettings;
use crate::model::geometry::{GeometryParams, Plate};
use crate::model::trajectory::{Sampling, Sinusoid};

use DefaultValue::{AboveHome, Off, Value};
use Unit::{
    Count, Degree, DegreePerSecond, DegreePerSecondCubed, DegreePerSecondSquared, Hertz, Metre,
    MetrePerSecond, MetrePerSecondCubed, MetrePerSecondSquared, RadianPerSecond, Ratio, Second,
    Switch,
};

struct Declare {
    list: Vec<Setting>,
    group: Group,
}

impl Declare {
    fn add(
        &mut self,
        key: impl Into<String>,
        label: impl Into<String>,
        unit: Unit,
        range: (f64, f64),
        default: DefaultValue,
        target: SettingTarget,
    ) {
        self.list.push(Setting {
            key: key.into(),
            label: label.into(),
            unit,
            range: range.0..=range.1,
            accepted: unit.accepted(),
            min_excluded: false,
            max_excluded: false,
            default,
            group: self.group,
            target,
        });
    }
}

pub(super) fn build() -> Vec<Setting> {
    let mut d = Declare {
        list: Vec::new(),
        group: Group::Geometry,
    };
    geometry(&mut d);
    actuator(&mut d);
    d.group = Group::Trajectory;
    trajectory(&mut d);
    d.group = Group::Limits;
    limits(&mut d);
    d.group = Group::Checks;
    checks(&mut d);
    d.group = Group::Cueing;
    cueing(&mut d);
    d.group = Group::Dynamics;
    dynamics(&mut d);
    for setting in &mut d.list {
        if let Some(rule) = model_rule(&setting.key) {
            let unit = setting.accepted.clone();
            let max = rule.max.unwrap_or(*unit.end()).min(*unit.end());
            setting.accepted = rule.min.max(*unit.start())..=max;
            setting.min_excluded = rule.min_excluded;
            setting.max_excluded = rule.max_excluded;
        }
    }
    d.list
}

/// The model's own rule on one setting's sign and size (what its constructor or `[…]`
/// table check refuses whatever else the scenario says).
struct ModelRule {
    min: f64,
    min_excluded: bool,
    max: Option<f64>,
    max_excluded: bool,
}

/// A positive number (above 0), at most `max` when given.
const fn positive(max: Option<f64>) -> Option<ModelRule> {
    Some(ModelRule {
        min: 0.0,
        min_excluded: true,
        max,
        max_excluded: false,
    })
}

/// Zero or more, at most `max` when given.
const fn not_negative(max: Option<f64>) -> Option<ModelRule> {
    Some(ModelRule {
        min: 0.0,
        min_excluded: false,
        max,
        max_excluded: false,
    })
}

/// The rule for `key` (`None`: the unit's range is the rule).
fn model_rule(key: &str) -> Option<ModelRule> {
    use crate::model::cueing_settings::{MAX_OMEGA, MAX_SCALE, MAX_ZETA};
    let (section, name) = key.split_once('.')?;
    match (section, name) {
        ("geometry", "base_radius" | "platform_radius" | "home_height" | "leg_min" | "leg_max")
        | ("actuator", "horn_length_m" | "rod_length_m")
        | ("trajectory", "duration_s")
        | ("checks", _)
        | ("dynamics", "actuator_stiffness") => positive(None),
        ("limits", "base_cone_deg" | "platform_cone_deg") => Some(ModelRule {
            min: 0.0,
            min_excluded: true,
            max: Some(180.0),
            max_excluded: true,
        }),
        ("limits", "leg_radius_m") => positive(None),
        // A servo range end in (−180°, 180°]; a trim within ±180° (`model::rotary`).
        ("actuator", "servo_min_deg" | "servo_max_deg") => Some(ModelRule {
            min: -180.0,
            min_excluded: true,
            max: Some(180.0),
            max_excluded: false,
        }),
        ("actuator", n) if n.starts_with("servo_trim_deg") => Some(ModelRule {
            min: -180.0,
            min_excluded: false,
            max: Some(180.0),
            max_excluded: false,
        }),
        ("limits", n) if n.contains("_max_") => positive(None),
        ("cueing", "translation_scale" | "rotation_scale") => not_negative(Some(MAX_SCALE)),
        ("cueing", "translation_hp_wb") => not_negative(Some(MAX_OMEGA)),
        ("cueing", "translation_hp_wn" | "tilt_lp_wn" | "rotation_hp_wn") => {
            positive(Some(MAX_OMEGA))
        }
        ("cueing", n) if n.ends_with("_zeta") => positive(Some(MAX_ZETA)),
        ("cueing", "tilt_rate_max_deg_s") => positive(Some(360.0)),
        ("cueing", "limiter_recovery_s" | "stall_s" | "fade_s") => positive(Some(3600.0)),
        ("cueing", "input_prediction_s") => not_negative(Some(0.5)),
        ("dynamics", n)
            if n == "actuator_friction"
                || n.ends_with("_mass_kg")
                || n.ends_with("_com_m")
                || n.ends_with("_inertia_kg_m2") =>
        {
            not_negative(None)
        }
        _ => None,
    }
}

fn geometry(d: &mut Declare) {
    use GeometryKey::*;
    let seed = GeometryParams::seed();
    let g = |k| SettingTarget::Geometry(k);
    let m = (0.05, 3.0);
    d.add(
        "geometry.base_radius",
        "base radius",
        Metre,
        m,
        Value(1.0),
        g(BaseRadius),
    );
    d.add(
        "geometry.platform_radius",
        "platform radius",
        Metre,
        m,
        Value(0.6),
        g(PlatformRadius),
    );
    d.add(
        "geometry.home_height",
        "home height",
        Metre,
        m,
        Value(seed.home_height),
        g(HomeHeight),
    );
    d.add(
        "geometry.leg_min",
        "leg min",
        Metre,
        (0.05, 3.0),
        Off,
        g(LegMin),
    );
    d.add(
        "geometry.leg_max",
        "leg max",
        Metre,
        (0.05, 4.0),
        Off,
        g(LegMax),
    );
    joints(d);
}

/// Each plate's joints: their angles on the circle, or their coordinates; the pivot.
fn joints(d: &mut Declare) {
    use GeometryKey::*;
    let seed = GeometryParams::seed();
    let g = |k| SettingTarget::Geometry(k);
    let (base_angles, platform_angles) = crate::model::layout::Layout::seed().angles();
    for (plate, angles, key) in [
        ("base", base_angles, BaseAngle as fn(usize) -> GeometryKey),
        ("platform", platform_angles, PlatformAngle),
    ] {
        for (i, angle) in angles.iter().enumerate() {
            d.add(
                format!("geometry.{plate}_angles_deg[{i}]"),
                format!("{plate} joint {}", i + 1),
                Degree,
                (-180.0, 360.0),
                Value(angle.degrees()),
                g(key(i)),
            );
        }
    }
    for (plate, joints) in [
        (Plate::Base, seed.base.points()),
        (Plate::Platform, seed.platform.points()),
    ] {
        for (i, point) in joints.iter().enumerate() {
            for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
                d.add(
                    format!("geometry.{plate}_joints_m[{i}][{k}]"),
                    format!("{plate} joint {} {axis}", i + 1),
                    Metre,
                    (-3.0, 3.0),
                    Value(point[k]),
                    g(Joint(plate, i, k)),
                );
            }
        }
    }
    for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
        d.add(
            format!("pivot.offset_m[{i}]"),
            format!("pivot {axis}"),
            Metre,
            (-1.0, 1.0),
            Value(0.0),
            g(Pivot(i)),
        );
    }
}

/// A rotary platform's servos (they apply to rotary scenarios only). Defaults: hobby
/// servos with 25 mm horns and 120 mm rods.
fn actuator(d: &mut Declare) {
    use ActuatorKey::*;
    let a = |k| SettingTarget::Actuator(k);
    d.add(
        "actuator.horn_length_m",
        "horn length",
        Metre,
        (0.005, 0.3),
        Value(0.025),
        a(HornLength),
    );
    d.add(
        "actuator.rod_length_m",
        "rod length",
        Metre,
        (0.02, 1.5),
        Value(0.12),
        a(RodLength),
    );
    for (i, default) in [255.0, 105.0, 15.0, 225.0, 135.0, 345.0]
        .into_iter()
        .enumerate()
    {
        d.add(
            format!("actuator.horn_angles_deg[{i}]"),
            format!("horn {} direction", i + 1),
            Degree,
            (0.0, 360.0),
            Value(default),
            a(HornAngle(i)),
        );
    }
    d.add(
        "actuator.servo_min_deg",
        "servo minimum",
        Degree,
        (-179.0, 0.0),
        Off,
        a(ServoMin),
    );
    d.add(
        "actuator.servo_max_deg",
        "servo maximum",
        Degree,
        (0.0, 180.0),
        Off,
        a(ServoMax),
    );
    for i in 0..6 {
        d.add(
            format!("actuator.servo_trim_deg[{i}]"),
            format!("servo {} trim", i + 1),
            Degree,
            (-30.0, 30.0),
            Value(0.0),
            a(Trim(i)),
        );
    }
    for i in 0..6 {
        d.add(
            format!("actuator.servo_reversed[{i}]"),
            format!("servo {} reversed", i + 1),
            Switch,
            (0.0, 1.0),
            Value(0.0),
            a(Reversed(i)),
        );
    }
}

fn trajectory(d: &mut Declare) {
    sampling(d);
    sinusoid_channels(d);
    shapes(d);
}

/// The trajectory's sampling: start, duration, samples.
fn sampling(d: &mut Declare) {
    let seed = Sampling::SEED;
    let sampling = |k| SettingTarget::Sampling(k);
    d.add(
        "trajectory.start_s",
        "start",
        Second,
        (-60.0, 60.0),
        Value(seed.start()),
        sampling(SamplingKey::Start),
    );
    d.add(
        "trajectory.duration_s",
        "duration",
        Second,
        (0.5, 120.0),
        Value(seed.duration()),
        sampling(SamplingKey::Duration),
    );
    d.add(
        "trajectory.samples",
        "samples",
        Count,
        (2.0, 20_000.0),
        Value(seed.len() as f64),
        sampling(SamplingKey::Samples),
    );
}

/// Each of the sinusoid's six channels: amplitude, frequency, phase, offset.
fn sinusoid_channels(d: &mut Declare) {
    use ChannelKey::{Amplitude, Offset, Phase};
    let channels = Sinusoid::seed(0.0);
    for (i, (name, c)) in channels.channels().into_iter().enumerate() {
        // x, y, z are lengths; roll, pitch, yaw angles.
        let (unit, suffix, amplitude, offset) = if i >= 3 {
            (Degree, "deg", (0.0, 45.0), (-45.0, 45.0))
        } else {
            (Metre, "m", (0.0, 0.5), (-0.5, 0.5))
        };
        let key = |part: &str, unit_suffix: &str| format!("trajectory.{name}.{part}_{unit_suffix}");
        let label = |part: &str| format!("{name} {part}");
        let t = |k| SettingTarget::Channel(i, k);
        d.add(
            key("amplitude", suffix),
            label("amplitude"),
            unit,
            amplitude,
            Value(c.amplitude),
            t(Amplitude),
        );
        d.add(
            key("frequency", "hz"),
            label("frequency"),
            Hertz,
            (0.0, 2.0),
            Value(c.frequency_hz),
            t(ChannelKey::Frequency),
        );
        d.add(
            key("phase", "deg"),
            label("phase"),
            Degree,
            (-180.0, 180.0),
            Value(c.phase.degrees()),
            t(Phase),
        );
        // The z channel oscillates about the home height unless told otherwise.
        let (offset_range, offset_default) = if name == "z" {
            ((0.1, 3.0), AboveHome(0.0))
        } else {
            (offset, Value(c.offset))
        };
        d.add(
            key("offset", suffix),
            label("offset"),
            unit,
            offset_range,
            offset_default,
            t(Offset),
        );
    }
}

/// The shapes' numbers (circle, figure eight, helix, sway): radius, frequency, heights,
/// half-widths, tilt.
fn shapes(d: &mut Declare) {
    use ShapeKey::{AmplitudeX, AmplitudeY, Radius, Tilt, Z, ZEnd, ZStart};
    let s = |k| SettingTarget::Shape(k);
    let height = (0.1, 3.0);
    d.add(
        "trajectory.radius_m",
        "radius",
        Metre,
        (0.0, 0.5),
        Value(0.15),
        s(Radius),
    );
    d.add(
        "trajectory.frequency_hz",
        "frequency",
        Hertz,
        (0.0, 2.0),
        Value(0.2),
        s(ShapeKey::Frequency),
    );
    d.add(
        "trajectory.z_m",
        "height",
        Metre,
        height,
        AboveHome(0.0),
        s(Z),
    );
    d.add(
        "trajectory.amplitude_x_m",
        "x half-width",
        Metre,
        (0.0, 0.5),
        Value(0.2),
        s(AmplitudeX),
    );
    d.add(
        "trajectory.amplitude_y_m",
        "y half-width",
        Metre,
        (0.0, 0.5),
        Value(0.1),
        s(AmplitudeY),
    );
    d.add(
        "trajectory.z_start_m",
        "start height",
        Metre,
        height,
        AboveHome(-0.1),
        s(ZStart),
    );
    d.add(
        "trajectory.z_end_m",
        "end height",
        Metre,
        height,
        AboveHome(0.1),
        s(ZEnd),
    );
    d.add(
        "trajectory.tilt_deg",
        "tilt",
        Degree,
        (0.0, 30.0),
        Value(5.0),
        s(Tilt),
    );
}

fn limits(d: &mut Declare) {
    use LimitKey::*;
    let l = |k| SettingTarget::Limit(k);
    d.add(
        "limits.leg_speed_max_m_s",
        "max leg speed",
        MetrePerSecond,
        (0.01, 2.0),
        Off,
        l(LegSpeed),
    );
    d.add(
        "limits.leg_accel_max_m_s2",
        "max leg acceleration",
        MetrePerSecondSquared,
        (0.01, 20.0),
        Off,
        l(LegAccel),
    );
    d.add(
        "limits.leg_jerk_max_m_s3",
        "max leg jerk",
        MetrePerSecondCubed,
        (0.1, 1000.0),
        Off,
        l(LegJerk),
    );
    d.add(
        "limits.servo_speed_max_deg_s",
        "max servo speed",
        DegreePerSecond,
        (10.0, 2000.0),
        Off,
        l(ServoSpeed),
    );
    d.add(
        "limits.servo_accel_max_deg_s2",
        "max servo acceleration",
        DegreePerSecondSquared,
        (100.0, 100_000.0),
        Off,
        l(ServoAccel),
    );
    d.add(
        "limits.servo_jerk_max_deg_s3",
        "max servo jerk",
        DegreePerSecondCubed,
        (1000.0, 10_000_000.0),
        Off,
        l(ServoJerk),
    );
    d.add(
        "limits.base_cone_deg",
        "base joint cone",
        Degree,
        (1.0, 90.0),
        Off,
        l(BaseCone),
    );
    d.add(
        "limits.platform_cone_deg",
        "platform joint cone",
        Degree,
        (1.0, 90.0),
        Off,
        l(PlatformCone),
    );
    d.add(
        "limits.leg_radius_m",
        "leg / rod radius",
        Metre,
        (0.001, 0.1),
        Off,
        l(LegRadius),
    );
}

fn checks(d: &mut Declare) {
    use CheckKey::*;
    let c = |k| SettingTarget::Check(k);
    let seed = CheckSettings::default();
    d.add(
        "checks.rigid_tolerance_m",
        "rigid-body tolerance",
        Metre,
        (1e-12, 1e-3),
        Value(seed.rigid_tolerance),
        c(RigidTolerance),
    );
    d.add(
        "checks.jump_ratio",
        "jump ratio",
        Ratio,
        (1.5, 50.0),
        Value(seed.jump_ratio),
        c(JumpRatio),
    );
    d.add(
        "checks.jump_floor_m",
        "jump floor",
        Metre,
        (1e-6, 0.05),
        Value(seed.jump_floor),
        c(JumpFloor),
    );
    d.add(
        "checks.condition_max",
        "near-singular condition number",
        Ratio,
        (2.0, 1000.0),
        Value(seed.condition_max),
        c(ConditionMax),
    );
}

/// A setting declared by key (in its table), label, unit, slider range and target.
type Row<K> = (&'static str, &'static str, Unit, (f64, f64), K);

/// The `[cueing]` table's settings; each default is the table's own.
const CUEING: [Row<CueingKey>; 28] = {
    use CueingKey::*;
    let (scale, omega, zeta) = ((0.0, 2.0), (0.05, 20.0), (0.1, 2.0));
    let switch = (0.0, 1.0);
    [
        (
            "translation_scale",
            "translation scale",
            Ratio,
            scale,
            TranslationScale,
        ),
        (
            "translation_hp_wn",
            "translation high-pass ω",
            RadianPerSecond,
            omega,
            TranslationHpWn,
        ),
        (
            "translation_hp_zeta",
            "translation high-pass ζ",
            Ratio,
            zeta,
            TranslationHpZeta,
        ),
        (
            "translation_hp_wb",
            "return to neutral ω_b",
            RadianPerSecond,
            (0.0, 5.0),
            TranslationHpWb,
        ),
        ("tilt", "tilt coordination", Switch, switch, Tilt),
        (
            "tilt_lp_wn",
            "tilt low-pass ω",
            RadianPerSecond,
            omega,
            TiltLpWn,
        ),
        ("tilt_lp_zeta", "tilt low-pass ζ", Ratio, zeta, TiltLpZeta),
        (
            "tilt_rate_max_deg_s",
            "max tilt rate",
            DegreePerSecond,
            (0.5, 30.0),
            TiltRateMax,
        ),
        (
            "rotation_scale",
            "rotation scale",
            Ratio,
            scale,
            RotationScale,
        ),
        (
            "rotation_hp_wn",
            "rotation high-pass ω",
            RadianPerSecond,
            omega,
            RotationHpWn,
        ),
        (
            "rotation_hp_zeta",
            "rotation high-pass ζ",
            Ratio,
            zeta,
            RotationHpZeta,
        ),
        (
            "workspace_limiter",
            "workspace limiter",
            Switch,
            switch,
            Limiter,
        ),
        (
            "limiter_recovery_s",
            "limiter recovery",
            Second,
            (0.1, 10.0),
            LimiterRecovery,
        ),
        ("stall_s", "input stall time", Second, (0.05, 5.0), Stall),
        ("fade_s", "fade to neutral", Second, (0.1, 10.0), Fade),
        (
            "input_prediction_s",
            "input prediction",
            Second,
            (0.0, 0.2),
            Prediction,
        ),
        (
            "mpc_horizon_steps",
            "MPC horizon steps",
            Count,
            (2.0, 30.0),
            HorizonSteps,
        ),
        ("mpc_step_s", "MPC step", Second, (0.02, 0.3), Step),
        (
            "mpc_solve_interval_s",
            "MPC solve interval",
            Second,
            (0.005, 0.05),
            SolveInterval,
        ),
        (
            "mpc_force_weight",
            "MPC force weight",
            Ratio,
            (0.0, 10.0),
            ForceWeight,
        ),
        (
            "mpc_rate_weight",
            "MPC rate weight",
            Ratio,
            (0.0, 100.0),
            RateWeight,
        ),
        (
            "mpc_displacement_weight",
            "MPC displacement weight",
            Ratio,
            (0.0, 10.0),
            DisplacementWeight,
        ),
        (
            "mpc_velocity_weight",
            "MPC velocity weight",
            Ratio,
            (0.0, 10.0),
            VelocityWeight,
        ),
        (
            "mpc_tilt_weight",
            "MPC tilt weight",
            Ratio,
            (0.0, 100.0),
            TiltWeight,
        ),
        (
            "mpc_input_weight",
            "MPC acceleration weight",
            Ratio,
            (0.0001, 0.1),
            InputWeight,
        ),
        ("mpc_margin", "MPC margin", Ratio, (0.0, 0.1), Margin),
        ("mpc_preview", "MPC look-ahead", Switch, switch, Preview),
        (
            "vestibular",
            "MPC vestibular model",
            Switch,
            switch,
            Vestibular,
        ),
    ]
};

fn cueing(d: &mut Declare) {
    let defaults = CueingSettings::default();
    let mut add = |key: String, label: String, unit, range, target| {
        let default = super::cueing::get(&defaults, target).map_or(Off, Value);
        d.add(
            key,
            label,
            unit,
            range,
            default,
            SettingTarget::Cueing(target),
        );
    };
    for (key, label, unit, range, target) in CUEING {
        add(
            format!("cueing.{key}"),
            label.to_owned(),
            unit,
            range,
            target,
        );
    }
    for (i, axis) in AXES.iter().enumerate() {
        let label = format!("cue {axis}");
        add(
            format!("cueing.{axis}"),
            label,
            Switch,
            (0.0, 1.0),
            CueingKey::Axis(i),
        );
    }
    for (i, axis) in ["x", "y", "z"].iter().enumerate() {
        let (key, label) = (
            format!("cueing.reference_m[{i}]"),
            format!("reference {axis}"),
        );
        add(key, label, Metre, (-1.0, 1.0), CueingKey::Reference(i));
    }
    // The planner's own ranges (`CueingSettings::problem`).
    use crate::model::cueing_settings::{MAX_HORIZON_STEPS, MAX_WEIGHT};
    let weight = 0.0..=MAX_WEIGHT;
    for (key, accepted) in [
        ("mpc_horizon_steps", 2.0..=f64::from(MAX_HORIZON_STEPS)),
        ("mpc_step_s", 0.005..=1.0),
        ("mpc_solve_interval_s", 0.001..=1.0),
        ("mpc_force_weight", weight.clone()),
        ("mpc_rate_weight", weight.clone()),
        ("mpc_displacement_weight", weight.clone()),
        ("mpc_velocity_weight", weight.clone()),
        ("mpc_tilt_weight", weight),
        ("mpc_input_weight", 1e-9..=MAX_WEIGHT),
        ("mpc_margin", 0.0..=0.4),
    ] {
        if let Some(s) = d.list.iter_mut().find(|s| s.key == format!("cueing.{key}")) {
            s.accepted = accepted;
        }
    }
}

/// The `[dynamics]` table's settings: key (in its table), label, unit and slider range;
/// every default is zero but the stiffness's, which is absent until given.
fn dynamics(d: &mut Declare) {
    use DynamicsKey::*;
    use Unit::{Kilogram, KilogramSquareMetre};
    let rows: [Row<DynamicsKey>; 11] = [
        (
            "actuator_stiffness",
            "actuator stiffness",
            Unit::Stiffness,
            (1e3, 1e8),
            Stiffness,
        ),
        (
            "actuator_friction",
            "actuator friction",
            Unit::Friction,
            (0.0, 1e4),
            Friction,
        ),
        (
            "cylinder_mass_kg",
            "cylinder mass",
            Kilogram,
            (0.0, 20.0),
            CylinderMass,
        ),
        (
            "cylinder_com_m",
            "cylinder centre of mass",
            Metre,
            (0.0, 1.0),
            CylinderCom,
        ),
        (
            "cylinder_inertia_kg_m2",
            "cylinder inertia",
            KilogramSquareMetre,
            (0.0, 1.0),
            CylinderInertia,
        ),
        ("rod_mass_kg", "rod mass", Kilogram, (0.0, 20.0), RodMass),
        ("rod_com_m", "rod centre of mass", Metre, (0.0, 1.0), RodCom),
        (
            "rod_inertia_kg_m2",
            "rod inertia",
            KilogramSquareMetre,
            (0.0, 1.0),
            RodInertia,
        ),
        ("horn_mass_kg", "horn mass", Kilogram, (0.0, 0.5), HornMass),
        (
            "horn_com_m",
            "horn centre of mass",
            Metre,
            (0.0, 0.05),
            HornCom,
        ),
        (
            "horn_inertia_kg_m2",
            "horn inertia",
            KilogramSquareMetre,
            (0.0, 1e-3),
            HornInertia,
        ),
    ];
    for (key, label, unit, range, target) in rows {
        let default = if target == Stiffness { Off } else { Value(0.0) };
        d.add(
            format!("dynamics.{key}"),
            label,
            unit,
            range,
            default,
            SettingTarget::Dynamics(target),
        );
    }
}
