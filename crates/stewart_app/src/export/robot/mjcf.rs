//! MJCF (MuJoCo): the base welded to the world, each leg a chain of bodies from it —
//! `leg{k}_cylinder` on a ball joint and `leg{k}_rod` on the slide `leg{k}_slide`, or
//! `servo{k}_horn` on the hinge `servo{k}` and `servo{k}_rod` on a ball joint — and the
//! platform on a free joint; each rod's far end tied to its platform joint by a `connect`
//! equality; one position actuator per leg whose control is the leg's length (m) or the
//! servo's model angle (rad); one keyframe per sample.
//!
//! The slide's and hinge's `ref` is their home value, so a joint's position *is* the
//! length or the angle, and the default configuration (`qpos0`) is home with every loop
//! closed: `connect` takes its second body's anchor from there.

use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use stewart_kinematics::model::appearance::Part;
use stewart_render::appearance::parts::PartSet;
use xmlwriter::{Options, XmlWriter};

use super::masses::Inertial;
use super::rig::{Rig, Sample};
use super::{attribute_text, comment_safe, quat_of, quaternion, vector};

/// The simulation step, seconds: a tenth of the actuators' period and below the
/// equality constraints' time constant's half.
const TIMESTEP: f64 = 0.001;
/// The actuators' natural frequency, rad/s (25 Hz), critically damped.
const ACTUATOR_OMEGA: f64 = 2.0 * std::f64::consts::PI * 25.0;
/// The passive joints' friction, as a frequency: together the six ball joints damp the
/// platform's motion across its legs as a critical damping of its mass at this frequency
/// would (`c = 2·M·ω`, shared by six joints at the leg's lever `l`: `d = c·l²/6`). Without
/// it, a platform near a singularity, where the actuators barely hold one direction, rings
/// for many seconds after a move.
const PASSIVE_OMEGA: f64 = ACTUATOR_OMEGA / 30.0;

/// The MJCF document of `rig`, its CAD parts from `parts`.
pub(crate) fn write(rig: &Rig, parts: &PartSet) -> String {
    let mut w = XmlWriter::new(Options::default());
    w.start_element("mujoco");
    w.write_attribute("model", &attribute_text(&rig.name));
    w.write_comment(&comment_safe(&header(rig)));
    w.start_element("compiler");
    w.write_attribute("angle", "radian");
    w.write_attribute("inertiafromgeom", "false");
    w.write_attribute("autolimits", "true");
    w.end_element();
    w.start_element("option");
    w.write_attribute("timestep", &TIMESTEP);
    w.write_attribute("integrator", "implicitfast");
    w.end_element();
    defaults(&mut w, rig);
    w.start_element("visual");
    // Offscreen pictures up to full HD (slides, papers).
    w.start_element("global");
    w.write_attribute("offwidth", "1920");
    w.write_attribute("offheight", "1080");
    w.end_element();
    w.start_element("headlight");
    w.write_attribute("ambient", "0.3 0.3 0.3");
    w.end_element();
    w.end_element();
    assets(&mut w, parts);
    w.start_element("worldbody");
    w.start_element("light");
    w.write_attribute("pos", &vector(&Vector3::new(0.0, 0.0, 4.0 * rig.size)));
    w.write_attribute("dir", "0 0 -1");
    w.write_attribute("directional", "true");
    w.end_element();
    overview_camera(&mut w, rig);
    base(&mut w, rig, parts);
    platform(&mut w, rig, parts);
    w.end_element();
    equalities(&mut w, rig);
    actuators(&mut w, rig);
    keyframes(&mut w, rig);
    w.end_document()
}

/// A camera named `overview` from the studio's default direction (135° round, 25° up),
/// aimed at the middle of the rig at home.
fn overview_camera(w: &mut XmlWriter, rig: &Rig) {
    let (azimuth, elevation) = (135f64.to_radians(), 25f64.to_radians());
    let target = rig.home.centre * 0.5;
    let back = Vector3::new(
        azimuth.cos() * elevation.cos(),
        azimuth.sin() * elevation.cos(),
        elevation.sin(),
    );
    let distance = 2.6 * rig.size.max(rig.home.centre.norm()) + rig.radii[0];
    // Its x axis level, its y axis up the picture (the camera looks along −z).
    let x = Vector3::z().cross(&back).normalize();
    let y = back.cross(&x);
    w.start_element("camera");
    w.write_attribute("name", "overview");
    w.write_attribute("pos", &vector(&(target + back * distance)));
    w.write_attribute("xyaxes", &format!("{} {}", vector(&x), vector(&y)));
    w.end_element();
}

/// What the file is and what it assumed.
fn header(rig: &Rig) -> String {
    let mut text = format!(
        " The Stewart platform `{}`, written by the studio's `stewart robot` as MJCF.\n\
         Metres, radians, z up, the studio's base frame. Controls: leg lengths (m) or servo\n\
         model angles (rad, positive lifts the horn's tip). Keyframes: the studio's samples.\n",
        rig.name
    );
    text.push_str(
        " MuJoCo starts every control at 0, which pulls the legs in: load a keyframe\n\
         (mj_resetDataKeyframe, or the viewer's Load key) or set the controls first.\n",
    );
    text.push_str(&super::assumptions(rig));
    text
}

/// Parts do not collide (they overlap at every joint); the loops close stiffly.
fn defaults(w: &mut XmlWriter, rig: &Rig) {
    w.start_element("default");
    w.start_element("geom");
    w.write_attribute("contype", "0");
    w.write_attribute("conaffinity", "0");
    w.end_element();
    w.start_element("site");
    w.write_attribute("size", &(0.02 * rig.size));
    w.write_attribute("rgba", "0.9 0.6 0.2 1");
    w.end_element();
    w.start_element("equality");
    w.write_attribute("solref", &format!("{} 1", 4.0 * TIMESTEP));
    w.end_element();
    w.end_element();
}

/// The CAD parts' meshes, inline (every format the studio reads, in the part's frame).
fn assets(w: &mut XmlWriter, parts: &PartSet) {
    if parts.is_empty() {
        return;
    }
    w.start_element("asset");
    for part in Part::ALL {
        let Some(loaded) = parts.get(part) else {
            continue;
        };
        for (i, piece) in loaded.mesh.pieces.iter().enumerate() {
            let vertices: Vec<String> = piece
                .mesh
                .vertices
                .iter()
                .map(|v| {
                    let p = loaded
                        .transform
                        .transform_point3(glam::Vec3::from_array(v.position));
                    format!("{} {} {}", p.x, p.y, p.z)
                })
                .collect();
            let faces: Vec<String> = piece.mesh.indices.iter().map(u32::to_string).collect();
            w.start_element("mesh");
            w.write_attribute("name", &mesh_name(part, i));
            w.write_attribute("inertia", "shell");
            w.write_attribute("vertex", &vertices.join(" "));
            w.write_attribute("face", &faces.join(" "));
            w.end_element();
        }
    }
    w.end_element();
}

fn mesh_name(part: Part, piece: usize) -> String {
    format!("{}_mesh{piece}", part.word())
}

/// The CAD part's geoms in a body whose frame is `frame` from the part's, or `fallback`
/// (the studio's shape) when the scenario has none.
fn part_geoms(
    w: &mut XmlWriter,
    parts: &PartSet,
    part: Part,
    frame: &UnitQuaternion<f64>,
    fallback: impl FnOnce(&mut XmlWriter),
) {
    let Some(loaded) = parts.get(part) else {
        fallback(w);
        return;
    };
    for (i, piece) in loaded.mesh.pieces.iter().enumerate() {
        let [r, g, b, a] = loaded
            .colour
            .or(piece.colour)
            .unwrap_or([0.7, 0.7, 0.72, 1.0]);
        w.start_element("geom");
        w.write_attribute("type", "mesh");
        w.write_attribute("mesh", &mesh_name(part, i));
        w.write_attribute("quat", &quaternion(frame));
        w.write_attribute("rgba", &format!("{r} {g} {b} {a}"));
        w.end_element();
    }
}

/// A capsule from the body's origin to `to`.
fn capsule(w: &mut XmlWriter, to: &Vector3<f64>, radius: f64, rgba: &str) {
    w.start_element("geom");
    w.write_attribute("type", "capsule");
    w.write_attribute("fromto", &format!("0 0 0 {}", vector(to)));
    w.write_attribute("size", &radius);
    w.write_attribute("rgba", rgba);
    w.end_element();
}

/// A plate of `radius` just below the body's origin.
fn plate(w: &mut XmlWriter, radius: f64, half: f64, rgba: &str) {
    w.start_element("geom");
    w.write_attribute("type", "cylinder");
    w.write_attribute("size", &format!("{radius} {half}"));
    w.write_attribute("pos", &format!("0 0 {}", -half));
    w.write_attribute("rgba", rgba);
    w.end_element();
}

fn inertial(w: &mut XmlWriter, i: &Inertial) {
    let m = &i.inertia;
    w.start_element("inertial");
    w.write_attribute("pos", &vector(&i.centre));
    w.write_attribute("mass", &i.mass);
    w.write_attribute(
        "fullinertia",
        &format!(
            "{} {} {} {} {} {}",
            m[(0, 0)],
            m[(1, 1)],
            m[(2, 2)],
            m[(0, 1)],
            m[(0, 2)],
            m[(1, 2)]
        ),
    );
    w.end_element();
}

/// The base, welded to the world, with each leg's chain.
fn base(w: &mut XmlWriter, rig: &Rig, parts: &PartSet) {
    w.start_element("body");
    w.write_attribute("name", "base");
    let half = 0.015 * rig.size;
    part_geoms(w, parts, Part::Base, &UnitQuaternion::identity(), |w| {
        plate(w, 1.1 * rig.radii[0], half, "0.45 0.47 0.5 1");
    });
    for (k, swing) in rig.home_swings().iter().enumerate() {
        match &rig.servos {
            None => linear_leg(w, rig, parts, k, swing),
            Some(s) => servo_leg(w, rig, parts, k, swing, s.horn, s.rod),
        }
    }
    w.end_element();
}

/// Leg `k` of a linear rig: the cylinder on a ball joint at the base joint, the rod on
/// the slide, its origin at the platform joint.
fn linear_leg(w: &mut XmlWriter, rig: &Rig, parts: &PartSet, k: usize, swing: &Rotation3<f64>) {
    let n = k + 1;
    let length = rig.home.actuators()[k];
    let radius = 0.025 * rig.size;
    let m = &rig.masses;
    w.start_element("body");
    w.write_attribute("name", &format!("leg{n}_cylinder"));
    w.write_attribute("pos", &vector(&rig.base_joints[k]));
    w.write_attribute("quat", &quaternion(&quat_of(swing)));
    ball(w, &format!("leg{n}_ball"), m.platform.mass, length);
    inertial(w, &m.cylinder.inertial(&Vector3::z(), false));
    part_geoms(w, parts, Part::Cylinder, &rig.part_frames.first[k], |w| {
        capsule(
            w,
            &Vector3::new(0.0, 0.0, 0.55 * length),
            radius,
            "0.25 0.27 0.3 1",
        );
    });
    w.start_element("body");
    w.write_attribute("name", &format!("leg{n}_rod"));
    w.write_attribute("pos", &format!("0 0 {length}"));
    w.start_element("joint");
    w.write_attribute("name", &format!("leg{n}_slide"));
    w.write_attribute("type", "slide");
    w.write_attribute("axis", "0 0 1");
    w.write_attribute("ref", &length);
    if let Some((lo, hi)) = rig.range {
        w.write_attribute("range", &format!("{lo} {hi}"));
    }
    w.end_element();
    inertial(w, &m.rod.inertial(&Vector3::z(), false));
    part_geoms(w, parts, Part::Rod, &rig.part_frames.rod[k], |w| {
        capsule(
            w,
            &Vector3::new(0.0, 0.0, -0.55 * length),
            0.6 * radius,
            "0.8 0.82 0.85 1",
        );
    });
    site(w, &format!("leg{n}_tip"), &Vector3::zeros());
    w.end_element();
    w.end_element();
}

/// Servo `k`: the horn on its hinge at the shaft's centre, the rod on a ball joint at the
/// horn's tip.
fn servo_leg(
    w: &mut XmlWriter,
    rig: &Rig,
    parts: &PartSet,
    k: usize,
    swing: &Rotation3<f64>,
    horn: f64,
    rod: f64,
) {
    let n = k + 1;
    let Some(servos) = &rig.servos else { return };
    let angle = rig.home.actuators()[k];
    let direction = servos.directions[k];
    let m = &rig.masses;
    let radius = 0.02 * rig.size;
    w.start_element("body");
    w.write_attribute("name", &format!("servo{n}_horn"));
    w.write_attribute("pos", &vector(&rig.base_joints[k]));
    w.write_attribute("quat", &quaternion(&quat_of(&rig.horn_rotation(k, angle))));
    w.start_element("joint");
    w.write_attribute("name", &format!("servo{n}"));
    w.write_attribute("type", "hinge");
    w.write_attribute("axis", &vector(&servos.axes[k]));
    w.write_attribute("ref", &angle);
    if let Some((lo, hi)) = rig.range {
        w.write_attribute("range", &format!("{lo} {hi}"));
    }
    w.end_element();
    inertial(w, &m.horn.inertial(&direction, true));
    part_geoms(w, parts, Part::Horn, &rig.part_frames.first[k], |w| {
        capsule(w, &(direction * horn), radius, "0.25 0.27 0.3 1");
    });
    w.start_element("body");
    w.write_attribute("name", &format!("servo{n}_rod"));
    w.write_attribute("pos", &vector(&(direction * horn)));
    w.write_attribute("quat", &quaternion(&quat_of(swing)));
    ball(w, &format!("servo{n}_ball"), m.platform.mass, rod);
    inertial(w, &m.rod.inertial(&Vector3::z(), false));
    part_geoms(w, parts, Part::Rod, &rig.part_frames.rod[k], |w| {
        capsule(
            w,
            &Vector3::new(0.0, 0.0, rod),
            0.5 * radius,
            "0.8 0.82 0.85 1",
        );
    });
    site(w, &format!("servo{n}_tip"), &Vector3::new(0.0, 0.0, rod));
    w.end_element();
    w.end_element();
}

/// A ball joint with the passive joints' friction ([`PASSIVE_OMEGA`]) for a platform of
/// `mass` at the lever `lever` (the leg's or the rod's length).
fn ball(w: &mut XmlWriter, name: &str, mass: f64, lever: f64) {
    w.start_element("joint");
    w.write_attribute("name", name);
    w.write_attribute("type", "ball");
    w.write_attribute("damping", &(mass * PASSIVE_OMEGA * lever * lever / 3.0));
    w.end_element();
}

fn site(w: &mut XmlWriter, name: &str, pos: &Vector3<f64>) {
    w.start_element("site");
    w.write_attribute("name", name);
    w.write_attribute("pos", &vector(pos));
    w.end_element();
}

/// The platform on its free joint at home, with a site at each platform joint.
fn platform(w: &mut XmlWriter, rig: &Rig, parts: &PartSet) {
    w.start_element("body");
    w.write_attribute("name", "platform");
    w.write_attribute("pos", &vector(&rig.home.centre));
    w.write_attribute("quat", &quaternion(&rig.home.rotation));
    w.start_element("freejoint");
    w.write_attribute("name", "platform");
    w.end_element();
    inertial(w, &rig.masses.platform);
    part_geoms(w, parts, Part::Platform, &UnitQuaternion::identity(), |w| {
        plate(w, 1.1 * rig.radii[1], 0.015 * rig.size, "0.3 0.5 0.75 1");
    });
    for (k, joint) in rig.platform_joints.iter().enumerate() {
        site(w, &format!("platform_joint{}", k + 1), joint);
    }
    w.end_element();
}

/// Each rod's far end tied to its platform joint.
fn equalities(w: &mut XmlWriter, rig: &Rig) {
    w.start_element("equality");
    for k in 0..6 {
        let n = k + 1;
        let (body, anchor) = match &rig.servos {
            None => (format!("leg{n}_rod"), Vector3::zeros()),
            Some(s) => (format!("servo{n}_rod"), Vector3::new(0.0, 0.0, s.rod)),
        };
        w.start_element("connect");
        w.write_attribute("name", &format!("{}_closure", rig.actuator_name(k)));
        w.write_attribute("body1", &body);
        w.write_attribute("body2", "platform");
        w.write_attribute("anchor", &vector(&anchor));
        w.end_element();
    }
    w.end_element();
}

/// One position actuator per leg, critically damped at [`ACTUATOR_OMEGA`] for the mass
/// it moves (a sixth of the platform's, the rod's, and a servo's horn).
fn actuators(w: &mut XmlWriter, rig: &Rig) {
    let m = &rig.masses;
    let moved = m.platform.mass / 6.0 + m.rod.mass;
    let effective = match &rig.servos {
        None => moved,
        Some(s) => {
            moved * s.horn * s.horn + m.horn.across + m.horn.mass * m.horn.along * m.horn.along
        }
    };
    let kp = effective * ACTUATOR_OMEGA * ACTUATOR_OMEGA;
    let kv = 2.0 * effective * ACTUATOR_OMEGA;
    w.start_element("actuator");
    for k in 0..6 {
        let name = rig.actuator_name(k);
        let joint = match rig.servos {
            None => format!("leg{}_slide", k + 1),
            Some(_) => name.clone(),
        };
        w.start_element("position");
        w.write_attribute("name", &name);
        w.write_attribute("joint", &joint);
        w.write_attribute("kp", &kp);
        w.write_attribute("kv", &kv);
        if let Some((lo, hi)) = rig.range {
            w.write_attribute("ctrlrange", &format!("{lo} {hi}"));
        }
        w.end_element();
    }
    w.end_element();
}

/// One keyframe per sample: every joint's position and the actuators' controls.
fn keyframes(w: &mut XmlWriter, rig: &Rig) {
    w.start_element("keyframe");
    for s in &rig.samples {
        w.start_element("key");
        w.write_attribute("name", &format!("t={}", s.time));
        w.write_attribute("time", &s.time);
        w.write_attribute("qpos", &qpos(rig, s).join(" "));
        let ctrl: Vec<String> = s.actuators().iter().map(f64::to_string).collect();
        w.write_attribute("ctrl", &ctrl.join(" "));
        w.end_element();
    }
    w.end_element();
}

/// The joints' positions at `s`, in the order MuJoCo numbers them (the bodies' order).
pub(crate) fn qpos(rig: &Rig, s: &Sample) -> Vec<String> {
    let mut out = Vec::with_capacity(37);
    let home = rig.home_swings();
    let swings = s.swings();
    for (k, value) in s.actuators().iter().enumerate() {
        let ball = quaternion(&quat_of(&(home[k].inverse() * swings[k])));
        if rig.rotary() {
            out.extend([value.to_string(), ball]);
        } else {
            out.extend([ball, value.to_string()]);
        }
    }
    out.push(vector(&s.centre));
    out.push(quaternion(&s.rotation));
    out
}
