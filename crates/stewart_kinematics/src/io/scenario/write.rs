//! Writing a [`Scenario`] back to TOML.

use toml::Spanned;

use super::Scenario;
use super::file::{
    ActuatorFile, ActuatorKind, AngularChannelFile, ChecksFile, GeometryFile, KeyFile, LimitsFile,
    LinearChannelFile, PayloadFile, PivotFile, PointsFile, ScenarioFile, TrajectoryFile,
    TrajectoryKind,
};
use crate::model::actuator::Actuator;
use crate::model::geometry::PlateJoints;
use crate::model::trajectory::{Channel, Motion, Trajectory};

fn s<T>(v: T) -> Spanned<T> {
    Spanned::new(0..0, v)
}

/// A plate's keys: `(radius, angles_deg, joints_m)`, one form or the other.
type PlateKeys = (
    Option<Spanned<f64>>,
    Option<Spanned<Vec<f64>>>,
    Option<PointsFile>,
);

fn plate_keys(joints: &PlateJoints) -> PlateKeys {
    match joints {
        PlateJoints::Circle { radius, angles } => (
            Some(s(*radius)),
            Some(s(angles.iter().map(|a| a.degrees()).collect())),
            None,
        ),
        PlateJoints::Points(points) => (
            None,
            None,
            Some(s(points
                .iter()
                .map(|p| s(p.iter().map(|&c| s(c)).collect()))
                .collect())),
        ),
    }
}

fn linear(c: &Channel) -> Option<Spanned<LinearChannelFile>> {
    Some(s(LinearChannelFile {
        amplitude_m: c.amplitude,
        frequency_hz: c.frequency_hz,
        phase_deg: c.phase.degrees(),
        offset_m: Some(c.offset),
        wave: c.wave,
    }))
}

fn angular(c: &Channel) -> Option<Spanned<AngularChannelFile>> {
    Some(s(AngularChannelFile {
        amplitude_deg: c.amplitude,
        frequency_hz: c.frequency_hz,
        phase_deg: c.phase.degrees(),
        offset_deg: c.offset,
        wave: c.wave,
    }))
}

/// The `[actuator]` table: none for linear legs (the default kind).
fn actuator_table(actuator: &Actuator) -> Option<Spanned<ActuatorFile>> {
    match actuator {
        Actuator::Linear => None,
        Actuator::Rotary(r) => Some(s(ActuatorFile {
            kind: s(ActuatorKind::Rotary),
            horn_length_m: Some(s(r.horn_length())),
            rod_length_m: Some(s(r.rod_length())),
            horn_angles_deg: Some(s(r.horn_angles().iter().map(|a| a.degrees()).collect())),
            servo_min_deg: r.range().map(|(min, _)| s(min.degrees())),
            servo_max_deg: r.range().map(|(_, max)| s(max.degrees())),
            servo_reversed: r
                .reversed()
                .iter()
                .any(|&b| b)
                .then(|| s(r.reversed().to_vec())),
            servo_trim_deg: r
                .trims()
                .iter()
                .any(|t| t.radians() != 0.0)
                .then(|| s(r.trims().iter().map(|t| t.degrees()).collect())),
        })),
    }
}

/// The `[trajectory]` table: the sampling and the kind's own keys.
fn trajectory_table(motion: &Motion) -> TrajectoryFile {
    let sampling = motion.sampling;
    let mut t = match sampling.is_at_keys() {
        true => TrajectoryFile {
            at_keys: Some(s(true)),
            ..TrajectoryFile::default()
        },
        false => TrajectoryFile {
            start_s: (sampling.start() != 0.0).then(|| s(sampling.start())),
            duration_s: Some(s(sampling.duration())),
            samples: Some(s(sampling.len() as i64)),
            ..TrajectoryFile::default()
        },
    };
    let kind = match &motion.trajectory {
        Trajectory::Sinusoid(c) => {
            t.x = linear(&c.x);
            t.y = linear(&c.y);
            t.z = linear(&c.z);
            t.roll = angular(&c.roll_deg);
            t.pitch = angular(&c.pitch_deg);
            t.yaw = angular(&c.yaw_deg);
            TrajectoryKind::Sinusoid
        }
        Trajectory::Circle(c) => {
            t.radius_m = Some(s(c.radius));
            t.frequency_hz = Some(s(c.frequency_hz));
            t.z_m = Some(s(c.z));
            TrajectoryKind::Circle
        }
        Trajectory::FigureEight(c) => {
            t.amplitude_x_m = Some(s(c.amplitude_x));
            t.amplitude_y_m = Some(s(c.amplitude_y));
            t.frequency_hz = Some(s(c.frequency_hz));
            t.z_m = Some(s(c.z));
            TrajectoryKind::FigureEight
        }
        Trajectory::Helix(c) => {
            t.radius_m = Some(s(c.radius));
            t.frequency_hz = Some(s(c.frequency_hz));
            t.z_start_m = Some(s(c.z_start));
            t.z_end_m = Some(s(c.z_end));
            TrajectoryKind::Helix
        }
        Trajectory::Sway(c) => {
            t.radius_m = Some(s(c.radius));
            t.frequency_hz = Some(s(c.frequency_hz));
            t.tilt_deg = Some(s(c.tilt.degrees()));
            t.z_m = Some(s(c.z));
            TrajectoryKind::Sway
        }
        Trajectory::Keyframes(k) => {
            t.interpolation = Some(s(k.interpolation()));
            t.keys = Some(s(k
                .keys()
                .iter()
                .map(|key| {
                    let [roll_deg, pitch_deg, yaw_deg] = key.pose.rpy_degrees();
                    s(KeyFile {
                        t_s: key.t,
                        x_m: key.pose.position.x,
                        y_m: key.pose.position.y,
                        z_m: key.pose.position.z,
                        roll_deg,
                        pitch_deg,
                        yaw_deg,
                    })
                })
                .collect()));
            TrajectoryKind::Keyframes
        }
    };
    t.kind = Some(s(kind));
    t
}

pub(super) fn to_toml(scenario: &Scenario) -> String {
    let g = scenario.geometry.params();
    let (base_radius, base_angles_deg, base_joints_m) = plate_keys(&g.base);
    let (platform_radius, platform_angles_deg, platform_joints_m) = plate_keys(&g.platform);
    let geometry = s(GeometryFile {
        base_radius,
        platform_radius,
        home_height: s(g.home_height),
        base_angles_deg,
        platform_angles_deg,
        base_joints_m,
        platform_joints_m,
        leg_min: g.stroke.min.map(s),
        leg_max: g.stroke.max.map(s),
    });
    let actuator = actuator_table(scenario.geometry.actuator());
    let pivot = (g.pivot != nalgebra::Vector3::zeros()).then(|| PivotFile {
        offset_m: s([g.pivot.x, g.pivot.y, g.pivot.z]),
    });
    let t = trajectory_table(&scenario.motion);
    let l = &scenario.limits;
    let limits = LimitsFile {
        leg_speed_max_m_s: l.leg_speed_max.map(s),
        leg_accel_max_m_s2: l.leg_accel_max.map(s),
        servo_speed_max_deg_s: l.servo_speed_max.map(s),
        servo_accel_max_deg_s2: l.servo_accel_max.map(s),
        leg_jerk_max_m_s3: l.leg_jerk_max.map(s),
        servo_jerk_max_deg_s3: l.servo_jerk_max.map(s),
        base_cone_deg: l.base_cone.map(|a| s(a.degrees())),
        platform_cone_deg: l.platform_cone.map(|a| s(a.degrees())),
        leg_radius_m: l.leg_radius.map(s),
    };
    let c = &scenario.checks;
    let file = ScenarioFile {
        name: Some(scenario.name.clone()),
        description: (!scenario.description.is_empty()).then(|| scenario.description.clone()),
        geometry,
        actuator,
        pivot,
        trajectory: Some(s(t)),
        limits: (*l != crate::model::limits::Limits::default()).then_some(limits),
        payload: scenario.payload.map(|p| {
            s(PayloadFile {
                mass_kg: p.mass,
                com_m: [p.centre_of_mass.x, p.centre_of_mass.y, p.centre_of_mass.z],
                inertia_kg_m2: inertia_values(&p.inertia),
            })
        }),
        checks: Some(ChecksFile {
            rigid_tolerance_m: Some(s(c.rigid_tolerance)),
            jump_ratio: Some(s(c.jump_ratio)),
            jump_floor_m: Some(s(c.jump_floor)),
            condition_max: Some(s(c.condition_max)),
        }),
        link: (scenario.link != crate::model::link_settings::LinkSettings::default())
            .then(|| s(scenario.link.clone())),
        cueing: (scenario.cueing != crate::model::cueing_settings::CueingSettings::default())
            .then(|| s(scenario.cueing.clone())),
        dynamics: (scenario.dynamics
            != crate::model::dynamics_settings::DynamicsSettings::default())
        .then(|| s(scenario.dynamics.clone())),
        appearance: (scenario.appearance
            != crate::model::appearance::AppearanceSettings::default())
        .then(|| s(scenario.appearance.clone())),
    };
    // Serialising plain numbers, strings and tables cannot fail.
    let text =
        toml::to_string(&file).unwrap_or_else(|e| unreachable!("scenario serialisation: {e}"));
    one_point_per_line(&text)
}

/// `[payload] inertia_kg_m2`: the three principal moments when the tensor is diagonal,
/// else its six entries (Ixx, Iyy, Izz, Ixy, Ixz, Iyz).
fn inertia_values(i: &nalgebra::Matrix3<f64>) -> Vec<f64> {
    let diagonal = vec![i[(0, 0)], i[(1, 1)], i[(2, 2)]];
    if i[(0, 1)] == 0.0 && i[(0, 2)] == 0.0 && i[(1, 2)] == 0.0 {
        diagonal
    } else {
        [diagonal, vec![i[(0, 1)], i[(0, 2)], i[(1, 2)]]].concat()
    }
}

/// `key = [[x, y, z], [x, y, z], …]` written one point per line, as people write them.
fn one_point_per_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 64);
    for line in text.lines() {
        match line.split_once(" = [[") {
            Some((key, rest)) if key.ends_with("_joints_m") && rest.ends_with("]]") => {
                out.push_str(key);
                out.push_str(" = [\n");
                for point in rest.trim_end_matches("]]").split("], [") {
                    out.push_str("  [");
                    out.push_str(point);
                    out.push_str("],\n");
                }
                out.push_str("]\n");
            }
            _ => {
                out.push_str(line);
                out.push('\n');
            }
        }
    }
    out
}
