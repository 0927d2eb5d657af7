//! From parsed file structs to a validated [`Scenario`], locating every refusal.

use std::ops::Range;
use std::path::Path;

use nalgebra::Vector3;
use toml::Spanned;

use super::Scenario;
use super::error::{ScenarioError, ScenarioProblem};
use super::file::{
    ActuatorFile, ActuatorKind, AngularChannelFile, ChecksFile, GeometryFile, KeyFile, LimitsFile,
    LinearChannelFile, PivotFile, PointsFile, ScenarioFile, TrajectoryFile, TrajectoryKind,
};
use crate::analysis::checks::CheckSettings;
use crate::analysis::forces::Payload;
use crate::model::actuator::Actuator;
use crate::model::angle::Angle;
use crate::model::geometry::{
    Geometry, GeometryError, GeometryParams, Plate, PlateJoints, StrokeLimits,
};
use crate::model::limits::Limits;
use crate::model::pose::Pose;
use crate::model::rotary::{RotaryActuators, RotaryError};
use crate::model::trajectory::{
    Channel, Circle, FigureEight, Helix, Interpolation, Keyframe, Keyframes, Motion, PoseTable,
    Sampling, Sinusoid, Sway, Trajectory,
};

/// Samples of a motion when the file does not say (the seed's count, as the
/// `trajectory.samples` setting declares).
const DEFAULT_SAMPLES: i64 = Sampling::SEED.len() as i64;
/// Duration of a motion when the file does not say (the seed's), seconds.
const DEFAULT_DURATION: f64 = Sampling::SEED.duration();

/// The source text and name, to turn byte spans into located errors.
struct Source<'a> {
    text: &'a str,
    file: &'a str,
}

impl Source<'_> {
    fn err(
        &self,
        span: Option<Range<usize>>,
        problem: impl Into<ScenarioProblem>,
    ) -> ScenarioError {
        ScenarioError::at(self.file, self.text, span, problem)
    }

    fn invalid(
        &self,
        span: Option<Range<usize>>,
        field: &str,
        reason: impl Into<String>,
    ) -> ScenarioError {
        self.err(
            span,
            ScenarioProblem::Invalid {
                field: field.to_owned(),
                reason: reason.into(),
            },
        )
    }

    /// A number that must be finite.
    fn finite(&self, field: &str, v: &Spanned<f64>) -> Result<f64, ScenarioError> {
        self.finite_at(field, *v.get_ref(), v.span())
    }

    fn finite_at(&self, field: &str, v: f64, span: Range<usize>) -> Result<f64, ScenarioError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.invalid(
                Some(span),
                field,
                format!("must be a finite number, got {v}"),
            ))
        }
    }
}

pub(crate) fn parse(
    text: &str,
    file: &str,
    base_dir: Option<&Path>,
) -> Result<Scenario, ScenarioError> {
    let src = Source { text, file };
    let parsed: ScenarioFile = toml::from_str(text).map_err(|e| {
        src.err(
            e.span(),
            ScenarioProblem::Syntax(e.message().trim_end().to_owned()),
        )
    })?;
    let actuator = build_actuator(&src, parsed.actuator.as_ref())?;
    let geometry = build_geometry(&src, &parsed.geometry, parsed.pivot.as_ref(), actuator)?;
    let motion = match &parsed.trajectory {
        Some(t) => build_motion(&src, t, &geometry, base_dir)?,
        None => Motion::seed(geometry.home_height()),
    };
    let checks = build_checks(&src, parsed.checks.as_ref())?;
    let limits = build_limits(&src, parsed.limits.as_ref(), geometry.actuator().kind())?;
    let payload = parsed
        .payload
        .as_ref()
        .map(|p| {
            let f = p.get_ref();
            let inertia = crate::analysis::forces::inertia_tensor(&f.inertia_kg_m2).ok_or_else(|| {
                let span = super::locate::span_of(text, "payload.inertia_kg_m2")
                    .or_else(|| Some(p.span()));
                src.invalid(
                    span,
                    "payload.inertia_kg_m2",
                    format!(
                        "takes 3 principal moments (Ixx, Iyy, Izz) or 6 values (Ixx, Iyy, Izz, Ixy, Ixz, Iyz), got {}",
                        f.inertia_kg_m2.len()
                    ),
                )
            })?;
            Payload::new(f.mass_kg, Vector3::from(f.com_m), inertia)
                .map_err(|e| src.invalid(Some(p.span()), "payload", e.to_string()))
        })
        .transpose()?;
    let mut link = checked_table(&src, text, parsed.link.as_ref(), |l| {
        l.problem().map(|p| (p.key, p.reason))
    })?;
    // A template reads the same wherever it is written: its leading spaces dropped.
    link.template =
        (link.template).map(|t| crate::model::link_settings::template_text(&t).to_owned());
    let cueing = checked_table(&src, text, parsed.cueing.as_ref(), |c| {
        c.problem().map(|p| (p.key, p.reason))
    })?;
    let dynamics = checked_table(&src, text, parsed.dynamics.as_ref(), |d| {
        d.problem().map(|p| (p.key, p.reason))
    })?;
    let appearance = checked_table(&src, text, parsed.appearance.as_ref(), |a| {
        a.problem().map(|p| (p.key, p.reason))
    })?;
    let name = parsed.name.unwrap_or_else(|| {
        Path::new(file)
            .file_stem()
            .map_or_else(|| file.to_owned(), |s| s.to_string_lossy().into_owned())
    });
    let scenario = Scenario {
        name,
        description: parsed.description.unwrap_or_default(),
        geometry,
        motion,
        limits,
        payload,
        checks,
        link,
        cueing,
        dynamics,
        appearance,
        files_read: pose_table_path(parsed.trajectory.as_ref().map(Spanned::get_ref), base_dir)
            .into_iter()
            .collect(),
    };
    Ok(scenario)
}

/// A table that checks itself (`[link]`, `[cueing]`): its first problem (key, reason) is
/// the error, located at the key when the text has it; no table is the defaults.
fn checked_table<T: Clone + Default>(
    src: &Source,
    text: &str,
    table: Option<&Spanned<T>>,
    problem: impl Fn(&T) -> Option<(String, String)>,
) -> Result<T, ScenarioError> {
    let Some(table) = table else {
        return Ok(T::default());
    };
    if let Some((key, reason)) = problem(table.get_ref()) {
        let span = super::locate::span_of(text, &key).or_else(|| Some(table.span()));
        return Err(src.invalid(span, &key, reason));
    }
    Ok(table.get_ref().clone())
}

/// The error for the value of `key` in `text` (the file `file`), refused for `reason`,
/// located at the key when the text has it, else at its table (`link.template` written
/// as `link.format = "template:…"` is found at `[link]`).
pub(crate) fn invalid_key(text: &str, file: &str, key: &str, reason: String) -> ScenarioError {
    let span = super::locate::span_of(text, key).or_else(|| {
        let (table, _) = key.rsplit_once('.')?;
        super::locate::span_of(text, table)
    });
    Source { text, file }.invalid(span, key, reason)
}

fn angles(src: &Source, field: &str, v: &Spanned<Vec<f64>>) -> Result<[Angle; 6], ScenarioError> {
    let list = v.get_ref();
    let array: [f64; 6] = list.as_slice().try_into().map_err(|_| {
        src.invalid(
            Some(v.span()),
            field,
            format!("must list 6 angles (one per leg), got {}", list.len()),
        )
    })?;
    Ok(array.map(Angle::from_degrees))
}

/// `[actuator]`: linear legs when absent; for `rotary`, the horn, rod, horn directions
/// and the optional servo range, each checked against its accepted range.
fn build_actuator(
    src: &Source,
    file: Option<&Spanned<ActuatorFile>>,
) -> Result<Actuator, ScenarioError> {
    let Some(file) = file else {
        return Ok(Actuator::Linear);
    };
    match file.get_ref().kind.get_ref() {
        ActuatorKind::Linear => {
            no_servo_keys(src, file.get_ref())?;
            Ok(Actuator::Linear)
        }
        ActuatorKind::Rotary => build_servos(src, file),
    }
}

/// Linear legs take none of the servos' keys.
fn no_servo_keys(src: &Source, a: &ActuatorFile) -> Result<(), ScenarioError> {
    let rotary_keys = [
        ("horn_length_m", a.horn_length_m.as_ref().map(Spanned::span)),
        ("rod_length_m", a.rod_length_m.as_ref().map(Spanned::span)),
        (
            "horn_angles_deg",
            a.horn_angles_deg.as_ref().map(Spanned::span),
        ),
        ("servo_min_deg", a.servo_min_deg.as_ref().map(Spanned::span)),
        ("servo_max_deg", a.servo_max_deg.as_ref().map(Spanned::span)),
        (
            "servo_reversed",
            a.servo_reversed.as_ref().map(Spanned::span),
        ),
        (
            "servo_trim_deg",
            a.servo_trim_deg.as_ref().map(Spanned::span),
        ),
    ];
    match rotary_keys.iter().find(|(_, span)| span.is_some()) {
        Some((key, span)) => Err(src.invalid(
            span.clone(),
            &format!("actuator.{key}"),
            "belongs to rotary servos, not to `kind = \"linear\"`",
        )),
        None => Ok(()),
    }
}

/// The servos of an `[actuator]` table with `kind = "rotary"`: horns, rods, directions,
/// range and mounting, each error at its key.
fn build_servos(src: &Source, file: &Spanned<ActuatorFile>) -> Result<Actuator, ScenarioError> {
    use crate::ground::bounds::{ANGLE_DEG, LENGTH_M, check, symmetric};
    let a = file.get_ref();
    let missing = |key: &str| {
        src.invalid(
            Some(file.span()),
            &format!("actuator.{key}"),
            "is required by `kind = \"rotary\"` but missing",
        )
    };
    let length = |key: &str, v: &Option<Spanned<f64>>| -> Result<f64, ScenarioError> {
        let v = v.as_ref().ok_or_else(|| missing(key))?;
        check(*v.get_ref(), &symmetric(LENGTH_M), "m")
            .map_err(|reason| src.invalid(Some(v.span()), &format!("actuator.{key}"), reason))
    };
    let horn = length("horn_length_m", &a.horn_length_m)?;
    let rod = length("rod_length_m", &a.rod_length_m)?;
    let angles = a
        .horn_angles_deg
        .as_ref()
        .ok_or_else(|| missing("horn_angles_deg"))?;
    let list: [f64; 6] = angles.get_ref().as_slice().try_into().map_err(|_| {
        src.invalid(
            Some(angles.span()),
            "actuator.horn_angles_deg",
            format!(
                "must list 6 angles (one per servo), got {}",
                angles.get_ref().len()
            ),
        )
    })?;
    for (i, v) in list.iter().enumerate() {
        check(*v, &symmetric(ANGLE_DEG), "°").map_err(|reason| {
            src.invalid(
                Some(angles.span()),
                &format!("actuator.horn_angles_deg[{i}]"),
                reason,
            )
        })?;
    }
    let range = match (&a.servo_min_deg, &a.servo_max_deg) {
        (None, None) => None,
        (Some(min), Some(max)) => Some((*min.get_ref(), *max.get_ref())),
        (Some(v), None) | (None, Some(v)) => {
            return Err(src.invalid(
                Some(v.span()),
                "actuator.servo_min_deg",
                "and `servo_max_deg` go together: give both ends of the servo range, or neither",
            ));
        }
    };
    let (reversed, trims) = servo_mounting(src, a)?;
    RotaryActuators::new(horn, rod, list, range)
        .and_then(|r| r.with_mounting(reversed, trims))
        .map(Actuator::Rotary)
        .map_err(|e| {
            let span = match &e {
                RotaryError::Length {
                    key: "rod_length_m",
                    ..
                } => a.rod_length_m.as_ref().map(Spanned::span),
                RotaryError::Length { .. } | RotaryError::HornNotShorter { .. } => {
                    a.horn_length_m.as_ref().map(Spanned::span)
                }
                RotaryError::HornAngle { .. } => Some(angles.span()),
                RotaryError::Range { .. } => a.servo_min_deg.as_ref().map(Spanned::span),
                RotaryError::Trim { .. } => a.servo_trim_deg.as_ref().map(Spanned::span),
            };
            src.err(span, e)
        })
}

/// The servos' mounting: which are reversed and their trims (degrees), six each when
/// given (none reversed, no trims when not).
fn servo_mounting(src: &Source, a: &ActuatorFile) -> Result<([bool; 6], [f64; 6]), ScenarioError> {
    let six = |key: &str, len: usize, span: Range<usize>| {
        src.invalid(
            Some(span),
            &format!("actuator.{key}"),
            format!("must list 6 values (one per servo), got {len}"),
        )
    };
    let reversed: [bool; 6] = match &a.servo_reversed {
        None => [false; 6],
        Some(v) => v
            .get_ref()
            .as_slice()
            .try_into()
            .map_err(|_| six("servo_reversed", v.get_ref().len(), v.span()))?,
    };
    let trims: [f64; 6] = match &a.servo_trim_deg {
        None => [0.0; 6],
        Some(v) => v
            .get_ref()
            .as_slice()
            .try_into()
            .map_err(|_| six("servo_trim_deg", v.get_ref().len(), v.span()))?,
    };
    Ok((reversed, trims))
}

/// Six points `[[x, y, z], …]` in metres, each coordinate finite.
fn points(src: &Source, field: &str, v: &PointsFile) -> Result<[Vector3<f64>; 6], ScenarioError> {
    let list = v.get_ref();
    if list.len() != 6 {
        return Err(src.invalid(
            Some(v.span()),
            field,
            format!(
                "must list 6 points [x, y, z] (one per leg), got {}",
                list.len()
            ),
        ));
    }
    let mut out = [Vector3::zeros(); 6];
    for (i, point) in list.iter().enumerate() {
        let xyz = point.get_ref();
        if xyz.len() != 3 {
            return Err(src.invalid(
                Some(point.span()),
                &format!("{field}[{i}]"),
                format!(
                    "must be a point [x, y, z] in metres, got {} numbers",
                    xyz.len()
                ),
            ));
        }
        for (k, c) in xyz.iter().enumerate() {
            out[i][k] = src.finite(&format!("{field}[{i}][{k}]"), c)?;
        }
    }
    Ok(out)
}

/// One plate's joints from its keys in `[geometry]`: on a circle (`{plate}_radius` and
/// `{plate}_angles_deg`) or as coordinates (`{plate}_joints_m`), never both.
fn plate_joints(
    src: &Source,
    table: &Range<usize>,
    plate: Plate,
    radius: Option<&Spanned<f64>>,
    angle_list: Option<&Spanned<Vec<f64>>>,
    point_list: Option<&PointsFile>,
) -> Result<PlateJoints, ScenarioError> {
    let key = |suffix: &str| format!("{plate}_{suffix}");
    if let Some(p) = point_list {
        let circle_key = radius
            .map(|r| ("radius", r.span()))
            .or_else(|| angle_list.map(|a| ("angles_deg", a.span())));
        if let Some((suffix, span)) = circle_key {
            return Err(src.invalid(
                Some(span),
                &key(suffix),
                format!(
                    "and `{}` both describe the {plate} joints: give either their coordinates or a radius and angles, not both",
                    key("joints_m")
                ),
            ));
        }
        return Ok(PlateJoints::Points(points(src, &key("joints_m"), p)?));
    }
    match (radius, angle_list) {
        (Some(r), Some(a)) => Ok(PlateJoints::Circle {
            radius: *r.get_ref(),
            angles: angles(src, &key("angles_deg"), a)?,
        }),
        (Some(r), None) => Err(src.invalid(
            Some(r.span()),
            &key("angles_deg"),
            format!("is missing: `{}` needs the six joint angles", key("radius")),
        )),
        (None, Some(a)) => Err(src.invalid(
            Some(a.span()),
            &key("radius"),
            format!("is missing: `{}` needs the circle's radius", key("angles_deg")),
        )),
        (None, None) => Err(src.invalid(
            Some(table.clone()),
            &key("joints_m"),
            format!(
                "is missing: give the {plate} joints as `{}` (six points [x, y, z] in metres) or as `{}` and `{}`",
                key("joints_m"),
                key("radius"),
                key("angles_deg")
            ),
        )),
    }
}

fn build_geometry(
    src: &Source,
    table: &Spanned<GeometryFile>,
    pivot: Option<&PivotFile>,
    actuator: Actuator,
) -> Result<Geometry, ScenarioError> {
    let g = table.get_ref();
    let params = GeometryParams {
        base: plate_joints(
            src,
            &table.span(),
            Plate::Base,
            g.base_radius.as_ref(),
            g.base_angles_deg.as_ref(),
            g.base_joints_m.as_ref(),
        )?,
        platform: plate_joints(
            src,
            &table.span(),
            Plate::Platform,
            g.platform_radius.as_ref(),
            g.platform_angles_deg.as_ref(),
            g.platform_joints_m.as_ref(),
        )?,
        home_height: *g.home_height.get_ref(),
        stroke: StrokeLimits {
            min: g.leg_min.as_ref().map(|v| *v.get_ref()),
            max: g.leg_max.as_ref().map(|v| *v.get_ref()),
        },
        pivot: pivot.map_or_else(Vector3::zeros, |p| Vector3::from(*p.offset_m.get_ref())),
        actuator,
    };
    Geometry::new(params).map_err(|e| {
        let span = geometry_error_span(g, pivot, &e);
        src.err(span, e)
    })
}

/// Where in the file the value a geometry error is about was written.
fn geometry_error_span(
    g: &GeometryFile,
    pivot: Option<&PivotFile>,
    e: &GeometryError,
) -> Option<Range<usize>> {
    let field = match e {
        GeometryError::NotFinite { field, .. } | GeometryError::NotPositive { field, .. } => {
            field.as_str()
        }
        GeometryError::DuplicateJoint {
            plate: Plate::Base, ..
        } => "base_angles_deg",
        GeometryError::DuplicateJoint {
            plate: Plate::Platform,
            ..
        } => "platform_angles_deg",
        GeometryError::CoincidentJoints { plate, second, .. } => {
            let list = match plate {
                Plate::Base => &g.base_joints_m,
                Plate::Platform => &g.platform_joints_m,
            };
            return list
                .as_ref()
                .and_then(|l| l.get_ref().get(second - 1).map(Spanned::span));
        }
        GeometryError::StrokeOrder { .. } => "leg_max",
        GeometryError::StrokeOnRotary { key } => key,
    };
    let optional = |v: &Option<Spanned<f64>>| v.as_ref().map(Spanned::span);
    match field {
        "base_radius" => optional(&g.base_radius),
        "platform_radius" => optional(&g.platform_radius),
        "home_height" => Some(g.home_height.span()),
        "leg_min" => optional(&g.leg_min),
        "leg_max" => optional(&g.leg_max),
        f if f.starts_with("base_angles_deg") => g.base_angles_deg.as_ref().map(Spanned::span),
        f if f.starts_with("platform_angles_deg") => {
            g.platform_angles_deg.as_ref().map(Spanned::span)
        }
        f if f.starts_with("pivot") => pivot.map(|p| p.offset_m.span()),
        _ => None,
    }
}

fn build_checks(src: &Source, c: Option<&ChecksFile>) -> Result<CheckSettings, ScenarioError> {
    let mut settings = CheckSettings::default();
    let Some(c) = c else { return Ok(settings) };
    let positive =
        |field: &str, v: &Option<Spanned<f64>>, target: &mut f64| -> Result<(), ScenarioError> {
            if let Some(v) = v {
                let x = src.finite(field, v)?;
                if x <= 0.0 {
                    return Err(src.invalid(
                        Some(v.span()),
                        field,
                        format!("must be positive, got {x}"),
                    ));
                }
                *target = x;
            }
            Ok(())
        };
    positive(
        "checks.rigid_tolerance_m",
        &c.rigid_tolerance_m,
        &mut settings.rigid_tolerance,
    )?;
    positive("checks.jump_ratio", &c.jump_ratio, &mut settings.jump_ratio)?;
    positive(
        "checks.jump_floor_m",
        &c.jump_floor_m,
        &mut settings.jump_floor,
    )?;
    positive(
        "checks.condition_max",
        &c.condition_max,
        &mut settings.condition_max,
    )?;
    Ok(settings)
}

fn build_limits(
    src: &Source,
    l: Option<&LimitsFile>,
    kind: ActuatorKind,
) -> Result<Limits, ScenarioError> {
    let Some(l) = l else {
        return Ok(Limits::default());
    };
    // Leg rates belong to linear legs, servo rates to servos.
    let (misplaced, why) = match kind {
        ActuatorKind::Rotary => (
            [
                ("limits.leg_speed_max_m_s", &l.leg_speed_max_m_s),
                ("limits.leg_accel_max_m_s2", &l.leg_accel_max_m_s2),
                ("limits.leg_jerk_max_m_s3", &l.leg_jerk_max_m_s3),
            ],
            "applies to linear legs only; a rotary platform takes `servo_speed_max_deg_s`, `servo_accel_max_deg_s2` and `servo_jerk_max_deg_s3`",
        ),
        ActuatorKind::Linear => (
            [
                ("limits.servo_speed_max_deg_s", &l.servo_speed_max_deg_s),
                ("limits.servo_accel_max_deg_s2", &l.servo_accel_max_deg_s2),
                ("limits.servo_jerk_max_deg_s3", &l.servo_jerk_max_deg_s3),
            ],
            "applies to rotary platforms only (`[actuator] kind = \"rotary\"`)",
        ),
    };
    if let Some((field, Some(v))) = misplaced.iter().find(|(_, v)| v.is_some()) {
        return Err(src.invalid(Some(v.span()), field, why.to_owned()));
    }
    let positive = |field: &str, v: &Option<Spanned<f64>>| -> Result<Option<f64>, ScenarioError> {
        let Some(v) = v else { return Ok(None) };
        let x = src.finite(field, v)?;
        if x <= 0.0 {
            return Err(src.invalid(Some(v.span()), field, format!("must be positive, got {x}")));
        }
        Ok(Some(x))
    };
    let cone = |field: &str, v: &Option<Spanned<f64>>| -> Result<Option<Angle>, ScenarioError> {
        let Some(deg) = positive(field, v)? else {
            return Ok(None);
        };
        if deg >= 180.0 {
            let span = v.as_ref().map(Spanned::span);
            return Err(src.invalid(span, field, format!("must be less than 180°, got {deg}")));
        }
        Ok(Some(Angle::from_degrees(deg)))
    };
    Ok(Limits {
        leg_speed_max: positive("limits.leg_speed_max_m_s", &l.leg_speed_max_m_s)?,
        leg_accel_max: positive("limits.leg_accel_max_m_s2", &l.leg_accel_max_m_s2)?,
        servo_speed_max: positive("limits.servo_speed_max_deg_s", &l.servo_speed_max_deg_s)?,
        servo_accel_max: positive("limits.servo_accel_max_deg_s2", &l.servo_accel_max_deg_s2)?,
        leg_jerk_max: positive("limits.leg_jerk_max_m_s3", &l.leg_jerk_max_m_s3)?,
        servo_jerk_max: positive("limits.servo_jerk_max_deg_s3", &l.servo_jerk_max_deg_s3)?,
        base_cone: cone("limits.base_cone_deg", &l.base_cone_deg)?,
        platform_cone: cone("limits.platform_cone_deg", &l.platform_cone_deg)?,
        leg_radius: positive("limits.leg_radius_m", &l.leg_radius_m)?,
    })
}

/// The keys each trajectory kind uses, beyond `kind`, `start_s`, `duration_s` and `samples`.
fn keys_used_by(kind: TrajectoryKind) -> &'static [&'static str] {
    match kind {
        TrajectoryKind::Sinusoid => &["x", "y", "z", "roll", "pitch", "yaw"],
        TrajectoryKind::Circle => &["radius_m", "frequency_hz", "z_m"],
        TrajectoryKind::FigureEight => &["amplitude_x_m", "amplitude_y_m", "frequency_hz", "z_m"],
        TrajectoryKind::Helix => &["radius_m", "frequency_hz", "z_start_m", "z_end_m"],
        TrajectoryKind::Sway => &["radius_m", "frequency_hz", "tilt_deg", "z_m"],
        TrajectoryKind::Keyframes => &["interpolation", "keys"],
        TrajectoryKind::PoseTable => &["interpolation", "file"],
    }
}

/// Every kind-specific key of the table that is present, with its span.
fn present_keys(t: &TrajectoryFile) -> Vec<(&'static str, Range<usize>)> {
    fn s<T>(v: &Option<Spanned<T>>) -> Option<Range<usize>> {
        v.as_ref().map(Spanned::span)
    }
    [
        ("x", s(&t.x)),
        ("y", s(&t.y)),
        ("z", s(&t.z)),
        ("roll", s(&t.roll)),
        ("pitch", s(&t.pitch)),
        ("yaw", s(&t.yaw)),
        ("radius_m", s(&t.radius_m)),
        ("frequency_hz", s(&t.frequency_hz)),
        ("z_m", s(&t.z_m)),
        ("amplitude_x_m", s(&t.amplitude_x_m)),
        ("amplitude_y_m", s(&t.amplitude_y_m)),
        ("z_start_m", s(&t.z_start_m)),
        ("z_end_m", s(&t.z_end_m)),
        ("tilt_deg", s(&t.tilt_deg)),
        ("interpolation", s(&t.interpolation)),
        ("keys", s(&t.keys)),
        ("file", s(&t.file)),
    ]
    .into_iter()
    .filter_map(|(k, span)| span.map(|span| (k, span)))
    .collect()
}

fn build_motion(
    src: &Source,
    table: &Spanned<TrajectoryFile>,
    geometry: &Geometry,
    base_dir: Option<&Path>,
) -> Result<Motion, ScenarioError> {
    let t = table.get_ref();
    let Some(kind) = &t.kind else {
        return Err(src.invalid(
            Some(table.span()),
            "trajectory.kind",
            "is missing: say one of sinusoid, circle, figure8, helix, sway, keyframes, pose_table",
        ));
    };
    let kind_span = kind.span();
    let kind = *kind.get_ref();
    for (key, span) in present_keys(t) {
        if !keys_used_by(kind).contains(&key) {
            return Err(src.invalid(
                Some(span),
                &format!("trajectory.{key}"),
                format!(
                    "is not used by trajectory kind `{}` (it uses: {})",
                    kind.name(),
                    keys_used_by(kind).join(", ")
                ),
            ));
        }
    }
    let shapes = ShapeReader {
        src,
        t,
        kind,
        kind_span,
    };
    let h0 = geometry.home_height();
    let trajectory = match kind {
        TrajectoryKind::Sinusoid => Trajectory::Sinusoid(Sinusoid {
            x: linear_channel(src, "x", t.x.as_ref(), 0.0)?,
            y: linear_channel(src, "y", t.y.as_ref(), 0.0)?,
            z: linear_channel(src, "z", t.z.as_ref(), h0)?,
            roll_deg: angular_channel(src, "roll", t.roll.as_ref())?,
            pitch_deg: angular_channel(src, "pitch", t.pitch.as_ref())?,
            yaw_deg: angular_channel(src, "yaw", t.yaw.as_ref())?,
        }),
        TrajectoryKind::Circle => Trajectory::Circle(Circle {
            radius: shapes.required("radius_m", &t.radius_m)?,
            frequency_hz: shapes.required("frequency_hz", &t.frequency_hz)?,
            z: shapes.optional("z_m", &t.z_m)?.unwrap_or(h0),
        }),
        TrajectoryKind::FigureEight => Trajectory::FigureEight(FigureEight {
            amplitude_x: shapes.required("amplitude_x_m", &t.amplitude_x_m)?,
            amplitude_y: shapes.required("amplitude_y_m", &t.amplitude_y_m)?,
            frequency_hz: shapes.required("frequency_hz", &t.frequency_hz)?,
            z: shapes.optional("z_m", &t.z_m)?.unwrap_or(h0),
        }),
        TrajectoryKind::Helix => Trajectory::Helix(Helix {
            radius: shapes.required("radius_m", &t.radius_m)?,
            frequency_hz: shapes.required("frequency_hz", &t.frequency_hz)?,
            z_start: shapes.required("z_start_m", &t.z_start_m)?,
            z_end: shapes.required("z_end_m", &t.z_end_m)?,
            duration: t
                .duration_s
                .as_ref()
                .map_or(DEFAULT_DURATION, |d| *d.get_ref()),
        }),
        TrajectoryKind::Sway => Trajectory::Sway(Sway {
            radius: shapes.required("radius_m", &t.radius_m)?,
            frequency_hz: shapes.required("frequency_hz", &t.frequency_hz)?,
            tilt: Angle::from_degrees(shapes.required("tilt_deg", &t.tilt_deg)?),
            z: shapes.optional("z_m", &t.z_m)?.unwrap_or(h0),
        }),
        TrajectoryKind::Keyframes => {
            let Some(keys) = &t.keys else {
                return Err(shapes.missing("keys"));
            };
            Trajectory::Keyframes(build_keyframes(src, keys, interpolation(t))?)
        }
        TrajectoryKind::PoseTable => {
            let Some(path) = &t.file else {
                return Err(shapes.missing("file"));
            };
            Trajectory::Keyframes(read_pose_table(src, path, base_dir, interpolation(t))?)
        }
    };
    let sampling = build_sampling(src, t, &trajectory)?;
    Ok(Motion {
        trajectory,
        sampling,
    })
}

fn interpolation(t: &TrajectoryFile) -> Interpolation {
    t.interpolation.as_ref().map_or(
        if t.file.is_some() {
            Interpolation::Linear
        } else {
            Interpolation::Cubic
        },
        |i| *i.get_ref(),
    )
}

/// Reads the numeric keys of a shape, naming the kind when one is missing.
struct ShapeReader<'a> {
    src: &'a Source<'a>,
    t: &'a TrajectoryFile,
    kind: TrajectoryKind,
    kind_span: Range<usize>,
}

impl ShapeReader<'_> {
    fn missing(&self, key: &str) -> ScenarioError {
        self.src.invalid(
            Some(self.kind_span.clone()),
            &format!("trajectory.{key}"),
            format!(
                "is required by trajectory kind `{}` but missing",
                self.kind.name()
            ),
        )
    }

    fn optional(&self, key: &str, v: &Option<Spanned<f64>>) -> Result<Option<f64>, ScenarioError> {
        let _ = self.t;
        v.as_ref()
            .map(|v| self.src.finite(&format!("trajectory.{key}"), v))
            .transpose()
    }

    fn required(&self, key: &str, v: &Option<Spanned<f64>>) -> Result<f64, ScenarioError> {
        self.optional(key, v)?.ok_or_else(|| self.missing(key))
    }
}

fn check_channel(
    src: &Source,
    name: &str,
    span: Range<usize>,
    values: [(&str, f64); 4],
) -> Result<(), ScenarioError> {
    for (key, v) in values {
        src.finite_at(&format!("trajectory.{name}.{key}"), v, span.clone())?;
    }
    Ok(())
}

fn linear_channel(
    src: &Source,
    name: &str,
    c: Option<&Spanned<LinearChannelFile>>,
    default_offset: f64,
) -> Result<Channel, ScenarioError> {
    let Some(c) = c else {
        return Ok(Channel::default().with_offset(default_offset));
    };
    let f = c.get_ref();
    let offset = f.offset_m.unwrap_or(default_offset);
    check_channel(
        src,
        name,
        c.span(),
        [
            ("amplitude_m", f.amplitude_m),
            ("frequency_hz", f.frequency_hz),
            ("phase_deg", f.phase_deg),
            ("offset_m", offset),
        ],
    )?;
    Ok(Channel {
        amplitude: f.amplitude_m,
        frequency_hz: f.frequency_hz,
        phase: Angle::from_degrees(f.phase_deg),
        offset,
        wave: f.wave,
    })
}

fn angular_channel(
    src: &Source,
    name: &str,
    c: Option<&Spanned<AngularChannelFile>>,
) -> Result<Channel, ScenarioError> {
    let Some(c) = c else {
        return Ok(Channel::default());
    };
    let f = c.get_ref();
    check_channel(
        src,
        name,
        c.span(),
        [
            ("amplitude_deg", f.amplitude_deg),
            ("frequency_hz", f.frequency_hz),
            ("phase_deg", f.phase_deg),
            ("offset_deg", f.offset_deg),
        ],
    )?;
    Ok(Channel {
        amplitude: f.amplitude_deg,
        frequency_hz: f.frequency_hz,
        phase: Angle::from_degrees(f.phase_deg),
        offset: f.offset_deg,
        wave: f.wave,
    })
}

fn build_keyframes(
    src: &Source,
    keys: &Spanned<Vec<Spanned<KeyFile>>>,
    interpolation: Interpolation,
) -> Result<Keyframes, ScenarioError> {
    let mut frames = Vec::with_capacity(keys.get_ref().len());
    for (i, k) in keys.get_ref().iter().enumerate() {
        let f = k.get_ref();
        let values = [
            ("t_s", f.t_s),
            ("x_m", f.x_m),
            ("y_m", f.y_m),
            ("z_m", f.z_m),
            ("roll_deg", f.roll_deg),
            ("pitch_deg", f.pitch_deg),
            ("yaw_deg", f.yaw_deg),
        ];
        for (key, v) in values {
            src.finite_at(&format!("trajectory.keys[{i}].{key}"), v, k.span())?;
        }
        frames.push(Keyframe {
            t: f.t_s,
            pose: Pose::from_xyz_rpy_deg(
                [f.x_m, f.y_m, f.z_m],
                [f.roll_deg, f.pitch_deg, f.yaw_deg],
            ),
        });
    }
    Keyframes::new(frames, interpolation).map_err(|e| {
        // Point at the key the error names, or at the list.
        let span = match &e {
            crate::model::trajectory::KeyframeError::NotIncreasing { index, .. }
            | crate::model::trajectory::KeyframeError::NotFinite { index }
            | crate::model::trajectory::KeyframeError::OutOfRange { index, .. }
            | crate::model::trajectory::KeyframeError::TooClose { index, .. } => {
                keys.get_ref().get(index - 1).map(Spanned::span)
            }
            crate::model::trajectory::KeyframeError::Empty => None,
        };
        src.err(Some(span.unwrap_or_else(|| keys.span())), e)
    })
}

/// The path of the pose table `[trajectory] file` names, as it is opened (relative to the
/// scenario's folder).
fn table_path(path: &str, base_dir: Option<&Path>) -> std::path::PathBuf {
    let relative = Path::new(path);
    match base_dir {
        Some(dir) if relative.is_relative() => dir.join(relative),
        _ => relative.to_path_buf(),
    }
}

/// The pose table a `[trajectory]` table reads, if it reads one.
fn pose_table_path(
    t: Option<&TrajectoryFile>,
    base_dir: Option<&Path>,
) -> Option<std::path::PathBuf> {
    let file = t?.file.as_ref()?;
    Some(table_path(file.get_ref(), base_dir))
}

fn read_pose_table(
    src: &Source,
    path: &Spanned<String>,
    base_dir: Option<&Path>,
    interpolation: Interpolation,
) -> Result<Keyframes, ScenarioError> {
    let full = table_path(path.get_ref(), base_dir);
    let name = full.display().to_string();
    let bytes =
        crate::io::file::read_file(&full, crate::io::file::FileKind::Table).map_err(|e| {
            src.invalid(
                Some(path.span()),
                "trajectory.file",
                match e {
                    crate::io::file::FileError::Io { cause: source, .. } => {
                        format!("names `{name}`, which cannot be opened ({source})")
                    }
                    other => format!("names a file that cannot be read: {other}"),
                },
            )
        })?;
    let table =
        PoseTable::read(bytes.as_slice(), &name).map_err(|e| src.err(Some(path.span()), e))?;
    table
        .to_keyframes(&name, interpolation)
        .map_err(|e| src.err(Some(path.span()), e))
}

/// Sampled at the keys' own times; a table of one moment is refused as evenly sampled ones are.
fn keys_sampling(
    src: &Source,
    t: &TrajectoryFile,
    keys: &Keyframes,
) -> Result<Sampling, ScenarioError> {
    Sampling::at_keys(keys).map_err(|e| {
        if let crate::model::trajectory::SamplingError::TooFine { step, at } = e {
            let (span, key) = match &t.file {
                Some(file) => (Some(file.span()), "trajectory.file"),
                None => (t.keys.as_ref().map(Spanned::span), "trajectory.keys"),
            };
            return src.invalid(
                span,
                key,
                format!(
                    "has times {step:.3e} s apart on average, too fine to tell apart at {at} s (fewer than 1e10 steps per unit of time from zero): start the times nearer 0, or space them more"
                ),
            );
        }
        let (span, key, what) = match &t.file {
            Some(file) if t.at_keys.is_some() => (Some(file.span()), "trajectory.file", "holds a single moment in time (one row, or every row at the same time): add a row at another time (or, without `at_keys`, give `duration_s` to hold the pose that long)"),
            Some(file) => (Some(file.span()), "trajectory.file", "holds a single moment in time (one row, or every row at the same time): add a row at another time, or give `duration_s` to hold the pose that long"),
            None => (t.keys.as_ref().map(Spanned::span), "trajectory.keys", "hold a single moment in time: add a key at another time, or give `duration_s` to hold the pose that long"),
        };
        src.invalid(span, key, what)
    })
}

fn build_sampling(
    src: &Source,
    t: &TrajectoryFile,
    trajectory: &Trajectory,
) -> Result<Sampling, ScenarioError> {
    // Keyframed motions may be sampled at their keys' own times: a table is by default
    // (every row judged and played as it is), keys when `at_keys = true` says so.
    let given = t.start_s.is_some() || t.duration_s.is_some() || t.samples.is_some();
    let at_keys = t.at_keys.as_ref().map(|v| (*v.get_ref(), v.span()));
    match (trajectory, at_keys) {
        (Trajectory::Keyframes(keys), Some((true, span))) => {
            if given {
                return Err(src.invalid(
                    Some(span),
                    "trajectory.at_keys",
                    "samples at the keys' own times: leave out start_s, duration_s and samples (or set at_keys = false)",
                ));
            }
            return keys_sampling(src, t, keys);
        }
        (Trajectory::Keyframes(keys), None) if t.file.is_some() && !given => {
            return keys_sampling(src, t, keys);
        }
        (Trajectory::Keyframes(_), _) | (_, None | Some((false, _))) => {}
        (_, Some((true, span))) => {
            return Err(src.invalid(
                Some(span),
                "trajectory.at_keys",
                "applies to keyframes and pose tables only",
            ));
        }
    }
    // Keyframed motions default to their own time span and, for tables, their row count.
    let (default_start, default_duration, default_samples) = match trajectory {
        Trajectory::Keyframes(k) => {
            let (first, last) = k.time_span();
            let rows = if t.file.is_some() {
                k.keys().len() as i64
            } else {
                DEFAULT_SAMPLES
            };
            (first, last - first, rows.max(2))
        }
        _ => (0.0, DEFAULT_DURATION, DEFAULT_SAMPLES),
    };
    let start = match &t.start_s {
        Some(v) => src.finite("trajectory.start_s", v)?,
        None => default_start,
    };
    let duration = match &t.duration_s {
        Some(v) => src.finite("trajectory.duration_s", v)?,
        None if default_duration <= 0.0 => {
            // Named as the file says it: a table (`file`, as `stewart cue` writes for a
            // one-sample recording) or keys.
            return Err(match &t.file {
                Some(file) => src.invalid(
                    Some(file.span()),
                    "trajectory.file",
                    "holds a single moment in time (one row, or every row at the same time): add a row at another time, or give `duration_s` to hold the pose that long",
                ),
                None => src.invalid(
                    t.keys.as_ref().map(Spanned::span),
                    "trajectory.keys",
                    "hold a single moment in time: add a key at another time, or give `duration_s` to hold the pose that long",
                ),
            });
        }
        None => default_duration,
    };
    let samples = t.samples.as_ref().map_or(default_samples, |s| *s.get_ref());
    let samples_span = t.samples.as_ref().map(Spanned::span);
    if !(2..=crate::model::trajectory::MAX_SAMPLES as i64).contains(&samples) {
        return Err(src.invalid(
            samples_span,
            "trajectory.samples",
            format!(
                "must be a whole number from 2 to {}, got {samples}",
                crate::model::trajectory::MAX_SAMPLES
            ),
        ));
    }
    Sampling::with_start(start, duration, samples as u64).map_err(|e| {
        let span = match e {
            crate::model::trajectory::SamplingError::Duration(_) => {
                t.duration_s.as_ref().map(Spanned::span)
            }
            crate::model::trajectory::SamplingError::TooFewSamples(_)
            | crate::model::trajectory::SamplingError::TooFine { .. } => samples_span.clone(),
            crate::model::trajectory::SamplingError::Start(_) => {
                t.start_s.as_ref().map(Spanned::span)
            }
        };
        src.err(span, e)
    })
}
