//! The rig as a robot description needs it, whatever the format: its fixed frames, each
//! leg's chain at home (the bodies' reference frames) and at every exported sample, the
//! actuators' range, and where a CAD part sits in its body's frame.

use anyhow::{Result, bail};
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use stewart_kinematics::model::appearance::Part;
use stewart_kinematics::model::geometry::Plate;
use stewart_kinematics::model::scene::SceneFrame;
use stewart_kinematics::solve::chains::{LegChain, servo_axis};
use stewart_kinematics::{Geometry, Pose, Scenario};

use super::masses::Masses;

/// A servo's fixed dimensions and the horns' directions.
pub(crate) struct Servos {
    /// Horn length, metres.
    pub(crate) horn: f64,
    /// Rod length, metres.
    pub(crate) rod: f64,
    /// Each horn's direction at angle 0, `(cos β, sin β, 0)`.
    pub(crate) directions: [Vector3<f64>; 6],
    /// Each shaft's axis (a positive turn lifts the horn's tip).
    pub(crate) axes: [Vector3<f64>; 6],
}

/// The platform, its legs and its actuators at one time.
#[derive(Clone)]
pub(crate) struct Sample {
    /// Seconds.
    pub(crate) time: f64,
    /// The studio's pose.
    pub(crate) pose: Pose,
    /// The platform frame's origin in the base frame (the pose's position, moved by a
    /// pivot's offset when the scenario sets one).
    pub(crate) centre: Vector3<f64>,
    /// The platform frame's axes, `Rz(yaw)·Ry(pitch)·Rx(roll)`.
    pub(crate) rotation: UnitQuaternion<f64>,
    /// Each leg's open chain.
    pub(crate) chains: [LegChain; 6],
}

impl Sample {
    /// The actuators' values: leg lengths (m) or servo angles (rad, the studio's model
    /// angle).
    pub(crate) fn actuators(&self) -> [f64; 6] {
        self.chains.map(|c| match c {
            LegChain::Linear { length, .. } => length,
            LegChain::Rotary { servo, .. } => servo,
        })
    }

    /// Each leg's first joint's rotation: the universal joint at the base (linear legs) or
    /// the rod's at the horn's tip, in its parent's frame.
    pub(crate) fn swings(&self) -> [Rotation3<f64>; 6] {
        self.chains.map(|c| match c {
            LegChain::Linear { universal, .. } => universal.rotation(),
            LegChain::Rotary { rod, .. } => rod.rotation(),
        })
    }
}

/// Everything a robot description of the scenario says.
pub(crate) struct Rig {
    /// The scenario's name.
    pub(crate) name: String,
    /// Base joints (servo shafts' centres), base frame, metres.
    pub(crate) base_joints: [Vector3<f64>; 6],
    /// Platform joints in the platform frame, metres.
    pub(crate) platform_joints: [Vector3<f64>; 6],
    /// The pivot offset of the pose's rotation, platform frame.
    pub(crate) pivot: Vector3<f64>,
    /// The servos of a rotary rig.
    pub(crate) servos: Option<Servos>,
    /// Each actuator's range: the stroke (m; an end the scenario does not set is 0 or
    /// twice the longest leg sampled) or the servo range (rad; none when not set).
    pub(crate) range: Option<(f64, f64)>,
    /// The actuators' speed limit, m/s or rad/s, when the scenario sets one.
    pub(crate) speed_limit: Option<f64>,
    /// What the description assumed beyond the scenario, in sentences for its comment.
    pub(crate) notes: Vec<String>,
    /// Home: the bodies' reference frames.
    pub(crate) home: Sample,
    /// The exported samples.
    pub(crate) samples: Vec<Sample>,
    /// Masses and inertias of the moving bodies.
    pub(crate) masses: Masses,
    /// The platform's size (for the studio's shapes' proportions), metres.
    pub(crate) size: f64,
    /// The base and platform plates' radii, metres.
    pub(crate) radii: [f64; 2],
    /// Each moving part's placement in its body's frame, per leg (the studio's drawing
    /// frame of [`Part`] at home, expressed in the body's reference frame).
    pub(crate) part_frames: PartFrames,
}

/// Where a CAD part's frame lies in its body's frame: the leg's first part (cylinder or
/// horn) and its rod, per leg.
pub(crate) struct PartFrames {
    /// The cylinder's or horn's part frame in its body's frame.
    pub(crate) first: [UnitQuaternion<f64>; 6],
    /// The rod's part frame in its body's frame.
    pub(crate) rod: [UnitQuaternion<f64>; 6],
}

impl PartFrames {
    /// The part frame of `part` on leg `k`, in its body's frame (the base's and the
    /// platform's are their bodies' own).
    pub(crate) fn of(&self, part: Part, k: usize) -> UnitQuaternion<f64> {
        match part {
            Part::Cylinder | Part::Horn => self.first[k],
            Part::Rod => self.rod[k],
            Part::Base | Part::Platform => UnitQuaternion::identity(),
        }
    }
}

impl Rig {
    /// `scenario`'s rig at every `every`-th sample of its motion; `place(t)` words where a
    /// sample lies for an error (a pose no servo reaches, or one beyond the stroke or the
    /// servo range, which the description's joint limits would contradict).
    pub(crate) fn of(
        scenario: &Scenario,
        every: usize,
        place: impl Fn(f64) -> String,
    ) -> Result<Self> {
        let g = &scenario.geometry;
        let given = actuator_range(g);
        let motion = scenario.motion.sample();
        let mut samples = Vec::with_capacity(motion.times.len() / every.max(1) + 1);
        for (&time, &pose) in motion.times.iter().zip(&motion.poses).step_by(every.max(1)) {
            let s = sample(g, time, pose).map_err(|e| anyhow::anyhow!("{}: {e}", place(time)))?;
            check_range(g, given, &s, &place)?;
            samples.push(s);
        }
        let mut notes = Vec::new();
        // The bodies' reference configuration: home, unless home breaks the limits (then
        // the default configuration would), when the first sample stands for it.
        let home = match sample(g, 0.0, g.home_pose()) {
            Ok(h) if check_range(g, given, &h, &|_| String::new()).is_ok() => h,
            _ => {
                let Some(first) = samples.first() else {
                    anyhow::bail!("{}: the trajectory has no sample", place(f64::NAN));
                };
                notes.push(format!(
                    "The home pose lies beyond the actuators' limits or reach: the bodies' \
                     reference configuration is the first sample's (t = {} s).",
                    first.time
                ));
                first.clone()
            }
        };
        let range = filled_range(g, given, &samples, &home, &mut notes);
        let servos = g.rotary().map(|r| Servos {
            horn: r.horn_length(),
            rod: r.rod_length(),
            directions: r.horn_angles().map(|b| {
                let b = b.radians();
                Vector3::new(b.cos(), b.sin(), 0.0)
            }),
            axes: r
                .horn_angles()
                .map(|b| servo_axis(b.radians()).into_inner()),
        });
        let frame = g.scene_frame(&home.pose, Vec::new());
        let part_frames = part_frames(&frame, &home, servos.as_ref());
        Ok(Self {
            name: scenario.name.clone(),
            base_joints: *g.base_joints(),
            platform_joints: *g.platform_joints(),
            pivot: g.pivot(),
            masses: Masses::of(scenario, &home),
            servos,
            range,
            speed_limit: if g.rotary().is_some() {
                scenario.limits.servo_speed_max.map(f64::to_radians)
            } else {
                scenario.limits.leg_speed_max
            },
            notes,
            home,
            samples,
            size: g.characteristic_length(),
            radii: [g.plate_radius(Plate::Base), g.plate_radius(Plate::Platform)],
            part_frames,
        })
    }

    /// Whether the actuators are servos.
    pub(crate) fn rotary(&self) -> bool {
        self.servos.is_some()
    }

    /// The actuator's name for leg `k` (from 0): `leg{k}` or `servo{k}`, counted from 1.
    pub(crate) fn actuator_name(&self, k: usize) -> String {
        if self.rotary() {
            format!("servo{}", k + 1)
        } else {
            format!("leg{}", k + 1)
        }
    }

    /// Each leg's first joint's reference rotation (its body's frame at home) in its
    /// parent's frame.
    pub(crate) fn home_swings(&self) -> [Rotation3<f64>; 6] {
        self.home.swings()
    }

    /// The horn's frame of servo `k` turned by `angle` (radians) about its shaft.
    pub(crate) fn horn_rotation(&self, k: usize, angle: f64) -> Rotation3<f64> {
        match &self.servos {
            Some(s) => Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(s.axes[k]), angle),
            None => Rotation3::identity(),
        }
    }
}

/// The chains at `pose`.
fn sample(
    g: &Geometry,
    time: f64,
    pose: Pose,
) -> Result<Sample, stewart_kinematics::model::rotary::Unreachable> {
    let chains = g.leg_chains(&pose)?;
    let rotation =
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(pose.rotation()));
    Ok(Sample {
        time,
        pose,
        centre: g.platform_centre(&pose),
        rotation,
        chains,
    })
}

/// The range written for the actuators: the servo range as given, or the stroke with an
/// end it does not set filled (shortest: 0; longest: twice the longest leg of the samples
/// and the reference), each filled end said in `notes`.
fn filled_range(
    g: &Geometry,
    given: Option<(f64, f64)>,
    samples: &[Sample],
    home: &Sample,
    notes: &mut Vec<String>,
) -> Option<(f64, f64)> {
    if g.rotary().is_some() {
        if given.is_none() {
            notes.push("The scenario sets no servo range: the servos turn freely.".to_owned());
        }
        return given;
    }
    let stroke = g.stroke();
    let lo = stroke.min.unwrap_or_else(|| {
        notes.push("The scenario sets no shortest leg: the slides reach down to 0 m.".to_owned());
        0.0
    });
    let hi = stroke.max.unwrap_or_else(|| {
        let longest = samples
            .iter()
            .chain(std::iter::once(home))
            .flat_map(Sample::actuators)
            .fold(0.0, f64::max);
        notes.push(format!(
            "The scenario sets no longest leg: the slides reach up to twice the longest \
             sampled, {} m.",
            2.0 * longest
        ));
        2.0 * longest
    });
    Some((lo, hi))
}

/// The stroke (linear legs) or the servo range in radians, when both ends are set.
fn actuator_range(g: &Geometry) -> Option<(f64, f64)> {
    match g.rotary() {
        Some(r) => r.range().map(|(lo, hi)| (lo.radians(), hi.radians())),
        None => match g.stroke() {
            stewart_kinematics::model::geometry::StrokeLimits {
                min: Some(lo),
                max: Some(hi),
            } => Some((lo, hi)),
            _ => None,
        },
    }
}

/// Refuse a sample whose actuator lies beyond the stroke (either end that is set) or the
/// servo range: the description's limits would contradict its own keyframes.
fn check_range(
    g: &Geometry,
    range: Option<(f64, f64)>,
    s: &Sample,
    place: &impl Fn(f64) -> String,
) -> Result<()> {
    let values = s.actuators();
    for (k, &v) in values.iter().enumerate() {
        let leg = k + 1;
        if g.rotary().is_some() {
            if let Some((lo, hi)) = range
                && !(lo..=hi).contains(&v)
            {
                bail!(
                    "{}: servo {leg} turns to {:.3}°, outside its range {} … {}° \
                     (`stewart check` lists every such sample)",
                    place(s.time),
                    v.to_degrees(),
                    lo.to_degrees(),
                    hi.to_degrees()
                );
            }
        } else if let Some(by) = g.stroke().violation(v) {
            bail!(
                "{}: leg {leg} is {:.6} m long, {:.6} m {} its stroke \
                 (`stewart check` lists every such sample)",
                place(s.time),
                v,
                by.abs(),
                if by > 0.0 { "beyond" } else { "short of" }
            );
        }
    }
    Ok(())
}

/// Each moving part's drawing frame at home in its body's reference frame: the body's
/// rotation at home in the base frame, undone from the drawing's.
fn part_frames(frame: &SceneFrame, home: &Sample, servos: Option<&Servos>) -> PartFrames {
    let swings = home.swings();
    let mut first = [UnitQuaternion::identity(); 6];
    let mut rod = [UnitQuaternion::identity(); 6];
    for k in 0..6 {
        let swing = UnitQuaternion::from_rotation_matrix(&swings[k]);
        match (servos, home.chains[k], frame.horn_placement(k)) {
            (Some(s), LegChain::Rotary { servo, .. }, Some(horn)) => {
                let turned = UnitQuaternion::from_axis_angle(
                    &nalgebra::Unit::new_normalize(s.axes[k]),
                    servo,
                );
                first[k] = turned.inverse() * horn.rotation;
                rod[k] = (turned * swing).inverse() * frame.rod_placement(k).rotation;
            }
            _ => {
                first[k] = swing.inverse() * frame.leg_placements(k)[0].rotation;
                rod[k] = swing.inverse() * frame.rod_placement(k).rotation;
            }
        }
    }
    PartFrames { first, rod }
}
