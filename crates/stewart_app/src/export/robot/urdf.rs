//! URDF (ROS): a tree, so the loops stay open. A virtual chain carries the platform from
//! `base` — prismatic `x`, `y`, `z`, then revolute `yaw`, `pitch`, `roll` (about the
//! pivot when the scenario sets one), so that `R = Rz·Ry·Rx` as in the studio — with a
//! fixed link `platform_joint{k}` at each platform joint; each leg is its own chain from
//! `base` ending in a link `tip{k}` on its far end: `leg{k}_swing_x`, `leg{k}_swing_y`
//! (the universal joint) and the slide `leg{k}_slide` (its value the leg's length), or
//! the servo's `servo{k}` (its model angle) and the rod's `servo{k}_rod_x`,
//! `servo{k}_rod_y`. Set the joints to a row of the joint-state table and every `tip{k}`
//! lies on its `platform_joint{k}`.

use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use stewart_kinematics::model::appearance::{AppearanceSettings, Part};
use stewart_kinematics::solve::chains::LegChain;
use xmlwriter::{Options, XmlWriter};

use super::masses::Inertial;
use super::rig::Rig;
use super::{attribute_text, comment_safe, vector};

/// The movable joints' names, in the joint-state table's order.
pub(crate) fn joint_names(rig: &Rig) -> Vec<String> {
    let mut out: Vec<String> = ["x", "y", "z", "yaw", "pitch", "roll"]
        .map(str::to_owned)
        .to_vec();
    for n in 1..=6 {
        if rig.rotary() {
            out.extend([
                format!("servo{n}"),
                format!("servo{n}_rod_x"),
                format!("servo{n}_rod_y"),
            ]);
        } else {
            out.extend([
                format!("leg{n}_swing_x"),
                format!("leg{n}_swing_y"),
                format!("leg{n}_slide"),
            ]);
        }
    }
    out
}

/// The movable joints' values at sample `s`, in [`joint_names`]' order.
pub(crate) fn joint_values(s: &super::rig::Sample) -> Vec<f64> {
    // The virtual chain turns yaw first, then pitch, then roll.
    let [x, y, z, roll, pitch, yaw] = s.pose.to_coordinates();
    let mut out = vec![x, y, z, yaw, pitch, roll];
    for chain in &s.chains {
        match chain {
            LegChain::Linear { universal, length } => {
                out.extend([universal.about_x, universal.about_y, *length]);
            }
            LegChain::Rotary { servo, rod } => out.extend([*servo, rod.about_x, rod.about_y]),
        }
    }
    out
}

/// The joint-state table: `t` and one column per movable joint, one row per sample.
pub(crate) fn joint_states(rig: &Rig) -> String {
    let mut text = String::from("t");
    for name in joint_names(rig) {
        text.push(',');
        text.push_str(&name);
    }
    text.push('\n');
    let mut buffer = ryu::Buffer::new();
    for s in &rig.samples {
        text.push_str(buffer.format(s.time));
        for v in joint_values(s) {
            text.push(',');
            text.push_str(buffer.format(v));
        }
        text.push('\n');
    }
    text
}

/// The URDF document of `rig`; CAD parts named by the files of `meshes`.
pub(crate) fn write(rig: &Rig, meshes: &AppearanceSettings) -> String {
    let mut w = XmlWriter::new(Options::default());
    w.write_declaration();
    w.start_element("robot");
    w.write_attribute("name", &attribute_text(&rig.name));
    w.write_comment(&comment_safe(&header(rig)));
    let u = Urdf { rig, meshes };
    u.link(&mut w, "base", None, Part::Base, 0, |w| {
        cylinder(
            w,
            1.1 * rig.radii[0],
            0.03 * rig.size,
            &Vector3::new(0.0, 0.0, -0.015 * rig.size),
            "base",
        );
    });
    u.platform_chain(&mut w);
    for k in 0..6 {
        if rig.rotary() {
            u.servo_leg(&mut w, k);
        } else {
            u.linear_leg(&mut w, k);
        }
    }
    w.end_document()
}

fn header(rig: &Rig) -> String {
    let mut text = format!(
        " The Stewart platform `{}`, written by the studio's `stewart robot` as URDF.\n\
         Metres, radians, z up, the studio's base frame. URDF cannot close a loop: the\n\
         platform hangs on a virtual chain (x, y, z, yaw, pitch, roll) and each leg is an\n\
         open chain ending in tip{{k}}; its joint-state table gives every joint's value per\n\
         sample, at which each tip{{k}} lies on platform_joint{{k}}.\n",
        rig.name
    );
    text.push_str(&format!(
        " Joint limits: the stroke or servo range and the scenario's speed limit (else\n\
         {UNBOUNDED_SPEED}); effort {UNBOUNDED_EFFORT} everywhere, the scenario bounds none.\n"
    ));
    text.push_str(&super::assumptions(rig));
    text
}

/// The writer's context: the rig and the CAD parts' files.
struct Urdf<'a> {
    rig: &'a Rig,
    meshes: &'a AppearanceSettings,
}

/// The speed written where the scenario sets none, m/s or rad/s (URDF requires one; 0
/// would read as "cannot move").
const UNBOUNDED_SPEED: f64 = 1e3;
/// The effort written on every limited joint, N or N·m: the scenario bounds none.
const UNBOUNDED_EFFORT: f64 = 1e6;

/// A joint's kind and range.
enum Motion {
    Fixed,
    /// Turns without end.
    Continuous,
    /// Turns or slides within `(lower, upper)` (radians or metres), at most at a speed
    /// (rad/s or m/s).
    Limited(&'static str, f64, f64, f64),
}

impl Urdf<'_> {
    /// A link; its visual is the CAD part `part` of leg `k` when the scenario has one,
    /// else `shape`.
    fn link(
        &self,
        w: &mut XmlWriter,
        name: &str,
        mass: Option<&Inertial>,
        part: Part,
        k: usize,
        shape: impl FnOnce(&mut XmlWriter),
    ) {
        w.start_element("link");
        w.write_attribute("name", name);
        if let Some(i) = mass {
            inertial(w, i);
        }
        w.start_element("visual");
        match self.meshes.part(part) {
            Some(look) => {
                let frame = self.rig.part_frames.of(part, k);
                let [rx, ry, rz] = look.rotation_deg.map(f64::to_radians);
                let turn = Rotation3::from_euler_angles(rx, ry, rz);
                let placed = frame * UnitQuaternion::from_rotation_matrix(&turn);
                origin(w, &(frame * Vector3::from(look.offset_m)), &placed);
                w.start_element("geometry");
                w.start_element("mesh");
                w.write_attribute("filename", &attribute_text(&file_uri(&look.file)));
                let s = look.scale.metres();
                w.write_attribute("scale", &format!("{s} {s} {s}"));
                w.end_element();
                w.end_element();
            }
            None => shape(w),
        }
        w.end_element();
        w.end_element();
    }

    /// The virtual chain to the platform and the platform's joints.
    fn platform_chain(&self, w: &mut XmlWriter) {
        let rig = self.rig;
        let reach = 10.0 * rig.size + rig.home.centre.norm();
        let slides = [
            ("x", Vector3::x()),
            ("y", Vector3::y()),
            ("z", Vector3::z()),
        ];
        let mut parent = "base".to_owned();
        for (name, axis) in slides {
            let child = format!("platform_{name}");
            joint(
                w,
                name,
                &Motion::Limited("prismatic", -reach, reach, UNBOUNDED_SPEED),
                &parent,
                &child,
                &Vector3::zeros(),
                Some(&axis),
            );
            empty_link(w, &child);
            parent = child;
        }
        let pivot = rig.pivot;
        let turns = [
            ("yaw", Vector3::z(), pivot),
            ("pitch", Vector3::y(), Vector3::zeros()),
            ("roll", Vector3::x(), Vector3::zeros()),
        ];
        for (name, axis, at) in turns {
            let child = if name == "roll" && pivot == Vector3::zeros() {
                "platform".to_owned()
            } else {
                format!("platform_{name}")
            };
            joint(
                w,
                name,
                &Motion::Continuous,
                &parent,
                &child,
                &at,
                Some(&axis),
            );
            if child != "platform" {
                empty_link(w, &child);
            }
            parent = child;
        }
        if pivot != Vector3::zeros() {
            joint(
                w,
                "platform_pivot",
                &Motion::Fixed,
                &parent,
                "platform",
                &-pivot,
                None,
            );
        }
        self.link(
            w,
            "platform",
            Some(&rig.masses.platform),
            Part::Platform,
            0,
            |w| {
                cylinder(
                    w,
                    1.1 * rig.radii[1],
                    0.03 * rig.size,
                    &Vector3::new(0.0, 0.0, -0.015 * rig.size),
                    "platform",
                );
            },
        );
        for (k, at) in rig.platform_joints.iter().enumerate() {
            let name = format!("platform_joint{}", k + 1);
            joint(w, &name, &Motion::Fixed, "platform", &name, at, None);
            empty_link(w, &name);
        }
    }

    /// A linear leg: the universal joint at the base joint, the cylinder, the slide, the
    /// rod (its origin at the platform joint) and the tip.
    fn linear_leg(&self, w: &mut XmlWriter, k: usize) {
        let rig = self.rig;
        let n = k + 1;
        let length = rig.home.actuators()[k];
        let (lower, upper) = rig.range.unwrap_or((0.0, f64::MAX));
        let cylinder_link = format!("leg{n}_cylinder");
        let names = [format!("leg{n}_swing_x"), format!("leg{n}_swing_y")];
        universal(
            w,
            &names,
            "base",
            &format!("leg{n}_cross"),
            &cylinder_link,
            &rig.base_joints[k],
        );
        let radius = 0.025 * rig.size;
        let inertial = rig.masses.cylinder.inertial(&Vector3::z(), false);
        self.link(w, &cylinder_link, Some(&inertial), Part::Cylinder, k, |w| {
            cylinder(
                w,
                radius,
                0.55 * length,
                &Vector3::new(0.0, 0.0, 0.275 * length),
                "cylinder",
            );
        });
        let rod_link = format!("leg{n}_rod");
        let slide = Motion::Limited(
            "prismatic",
            lower,
            upper,
            rig.speed_limit.unwrap_or(UNBOUNDED_SPEED),
        );
        let z = Vector3::z();
        joint(
            w,
            &format!("leg{n}_slide"),
            &slide,
            &cylinder_link,
            &rod_link,
            &Vector3::zeros(),
            Some(&z),
        );
        // The rod reaches down the leg from the platform joint.
        self.rod(w, k, 0.6 * radius, -0.55 * length);
    }

    /// A servo: its revolute at the shaft's centre, the horn, the rod's universal joint
    /// at the horn's tip, the rod and the tip.
    fn servo_leg(&self, w: &mut XmlWriter, k: usize) {
        let rig = self.rig;
        let Some(servos) = &rig.servos else { return };
        let n = k + 1;
        let direction = servos.directions[k];
        let horn_link = format!("servo{n}_horn");
        let motion = match rig.range {
            Some((lo, hi)) => Motion::Limited(
                "revolute",
                lo,
                hi,
                rig.speed_limit.unwrap_or(UNBOUNDED_SPEED),
            ),
            None => Motion::Continuous,
        };
        let axis = servos.axes[k];
        joint(
            w,
            &format!("servo{n}"),
            &motion,
            "base",
            &horn_link,
            &rig.base_joints[k],
            Some(&axis),
        );
        let radius = 0.02 * rig.size;
        let inertial = rig.masses.horn.inertial(&direction, true);
        self.link(w, &horn_link, Some(&inertial), Part::Horn, k, |w| {
            let turn = UnitQuaternion::rotation_between(&Vector3::z(), &direction)
                .unwrap_or_else(UnitQuaternion::identity);
            origin(w, &(direction * servos.horn / 2.0), &turn);
            geometry_cylinder(w, radius, servos.horn);
            material(w, "horn");
        });
        let names = [format!("servo{n}_rod_x"), format!("servo{n}_rod_y")];
        let cross = format!("servo{n}_rod_cross");
        universal(
            w,
            &names,
            &horn_link,
            &cross,
            &format!("servo{n}_rod"),
            &(direction * servos.horn),
        );
        // The rod reaches up from the horn's tip to the platform joint.
        self.rod(w, k, 0.5 * radius, servos.rod);
    }

    /// Leg `k`'s rod link (`leg{k}_rod` or `servo{k}_rod`), drawn from its origin to
    /// `reach` along its z, with its tip: at its origin for a linear leg's (which sits on
    /// the platform joint), at its far end for a servo's.
    fn rod(&self, w: &mut XmlWriter, k: usize, radius: f64, reach: f64) {
        let rig = self.rig;
        let name = format!("{}_rod", rig.actuator_name(k));
        let inertial = rig.masses.rod.inertial(&Vector3::z(), false);
        self.link(w, &name, Some(&inertial), Part::Rod, k, |w| {
            cylinder(
                w,
                radius,
                reach.abs(),
                &Vector3::new(0.0, 0.0, reach / 2.0),
                "rod",
            );
        });
        let tip_at = if rig.rotary() { reach } else { 0.0 };
        tip(w, &name, k + 1, &Vector3::new(0.0, 0.0, tip_at));
    }
}

/// A universal joint at `at` in `parent`: a revolute about x (`names[0]`) to the link
/// `cross`, then one about the turned y (`names[1]`) to `child`.
fn universal(
    w: &mut XmlWriter,
    names: &[String; 2],
    parent: &str,
    cross: &str,
    child: &str,
    at: &Vector3<f64>,
) {
    joint(
        w,
        &names[0],
        &Motion::Continuous,
        parent,
        cross,
        at,
        Some(&Vector3::x()),
    );
    empty_link(w, cross);
    joint(
        w,
        &names[1],
        &Motion::Continuous,
        cross,
        child,
        &Vector3::zeros(),
        Some(&Vector3::y()),
    );
}

/// A mesh file's absolute path as the `file://` URI RViz and URDF libraries resolve.
fn file_uri(path: &str) -> String {
    format!("file://{path}")
}

/// The fixed link `tip{n}` at `at` in `parent`.
fn tip(w: &mut XmlWriter, parent: &str, n: usize, at: &Vector3<f64>) {
    let name = format!("tip{n}");
    joint(
        w,
        &format!("{name}_fixed"),
        &Motion::Fixed,
        parent,
        &name,
        at,
        None,
    );
    empty_link(w, &name);
}

fn joint(
    w: &mut XmlWriter,
    name: &str,
    motion: &Motion,
    parent: &str,
    child: &str,
    at: &Vector3<f64>,
    axis: Option<&Vector3<f64>>,
) {
    w.start_element("joint");
    w.write_attribute("name", name);
    w.write_attribute(
        "type",
        match motion {
            Motion::Fixed => "fixed",
            Motion::Continuous => "continuous",
            Motion::Limited(kind, ..) => kind,
        },
    );
    w.start_element("parent");
    w.write_attribute("link", parent);
    w.end_element();
    w.start_element("child");
    w.write_attribute("link", child);
    w.end_element();
    origin(w, at, &UnitQuaternion::identity());
    if let Some(axis) = axis {
        w.start_element("axis");
        w.write_attribute("xyz", &vector(axis));
        w.end_element();
    }
    if let Motion::Limited(_, lower, upper, speed) = motion {
        w.start_element("limit");
        w.write_attribute("lower", lower);
        w.write_attribute("upper", upper);
        // URDF requires an effort; a scenario bounds none (the file's comment says so).
        w.write_attribute("effort", &UNBOUNDED_EFFORT);
        w.write_attribute("velocity", speed);
        w.end_element();
    }
    w.end_element();
}

fn empty_link(w: &mut XmlWriter, name: &str) {
    w.start_element("link");
    w.write_attribute("name", name);
    w.end_element();
}

fn origin(w: &mut XmlWriter, xyz: &Vector3<f64>, turn: &UnitQuaternion<f64>) {
    w.start_element("origin");
    w.write_attribute("xyz", &vector(xyz));
    w.write_attribute("rpy", &rpy(turn));
    w.end_element();
}

/// URDF's `rpy`: `R = Rz(y)·Ry(p)·Rx(r)`.
fn rpy(turn: &UnitQuaternion<f64>) -> String {
    let (r, p, y) = turn.euler_angles();
    format!("{r} {p} {y}")
}

fn inertial(w: &mut XmlWriter, i: &Inertial) {
    let m = &i.inertia;
    w.start_element("inertial");
    origin(w, &i.centre, &UnitQuaternion::identity());
    w.start_element("mass");
    w.write_attribute("value", &i.mass);
    w.end_element();
    w.start_element("inertia");
    for (key, (r, c)) in [
        ("ixx", (0, 0)),
        ("ixy", (0, 1)),
        ("ixz", (0, 2)),
        ("iyy", (1, 1)),
        ("iyz", (1, 2)),
        ("izz", (2, 2)),
    ] {
        w.write_attribute(key, &m[(r, c)]);
    }
    w.end_element();
    w.end_element();
}

/// A cylinder along the link's z, centred at `at`.
fn cylinder(w: &mut XmlWriter, radius: f64, length: f64, at: &Vector3<f64>, colour: &str) {
    origin(w, at, &UnitQuaternion::identity());
    geometry_cylinder(w, radius, length);
    material(w, colour);
}

fn geometry_cylinder(w: &mut XmlWriter, radius: f64, length: f64) {
    w.start_element("geometry");
    w.start_element("cylinder");
    w.write_attribute("radius", &radius);
    w.write_attribute("length", &length);
    w.end_element();
    w.end_element();
}

/// The studio's colour of a part, by its name.
fn material(w: &mut XmlWriter, name: &str) {
    let rgba = match name {
        "base" => "0.45 0.47 0.5 1",
        "platform" => "0.3 0.5 0.75 1",
        "rod" => "0.8 0.82 0.85 1",
        _ => "0.25 0.27 0.3 1",
    };
    w.start_element("material");
    w.write_attribute("name", name);
    w.start_element("color");
    w.write_attribute("rgba", rgba);
    w.end_element();
    w.end_element();
}
