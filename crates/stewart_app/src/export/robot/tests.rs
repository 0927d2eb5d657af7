//! The descriptions read back as MuJoCo and a URDF library read them — bodies, joints and
//! their values composed here from the XML alone — must put each leg's far end on its
//! platform joint and the platform at the studio's pose, on every kind of rig.

use std::collections::HashMap;

use nalgebra::{Isometry3, Quaternion, Translation3, Unit, UnitQuaternion, Vector3};
use stewart_kinematics::model::appearance::AppearanceSettings;
use stewart_kinematics::{Pose, Scenario};
use stewart_render::appearance::parts::PartSet;

use super::{RobotFormat, describe};

const RIGS: [&str; 5] = ["seed", "paired", "servo-desk", "crank-rig", "dietmaier"];
const EVERY: usize = 37;

fn preset(name: &str) -> Scenario {
    Scenario::preset(name).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|v| v.parse().unwrap_or_else(|_| panic!("not a number: {v}")))
        .collect()
}

fn vector(text: &str) -> Vector3<f64> {
    let v = numbers(text);
    Vector3::new(v[0], v[1], v[2])
}

fn quat(v: &[f64]) -> UnitQuaternion<f64> {
    UnitQuaternion::from_quaternion(Quaternion::new(v[0], v[1], v[2], v[3]))
}

fn attr<'a>(node: roxmltree::Node<'a, 'a>, name: &str) -> Option<&'a str> {
    node.attribute(name)
}

/// The studio's platform frame at `pose`.
fn studio_frame(s: &Scenario, pose: &Pose) -> Isometry3<f64> {
    let g = &s.geometry;
    let r = nalgebra::Rotation3::from_matrix_unchecked(pose.rotation());
    Isometry3::from_parts(
        Translation3::from(g.platform_centre(pose)),
        UnitQuaternion::from_rotation_matrix(&r),
    )
}

/// MuJoCo's forward kinematics of an MJCF file at one keyframe's `qpos`: every body's and
/// site's world frame. Joints: a ball turns by its quaternion, a slide moves by
/// `q − ref` along its axis, a hinge turns by `q − ref` about its axis, a free joint
/// places its body in the world.
struct Mjcf<'a> {
    doc: &'a roxmltree::Document<'a>,
}

impl Mjcf<'_> {
    fn sites(
        &self,
        qpos: &[f64],
    ) -> (
        HashMap<String, Vector3<f64>>,
        HashMap<String, Isometry3<f64>>,
    ) {
        let world = self
            .doc
            .descendants()
            .find(|n| n.has_tag_name("worldbody"))
            .expect("worldbody");
        let mut sites = HashMap::new();
        let mut bodies = HashMap::new();
        let mut at = 0;
        for body in world.children().filter(|n| n.has_tag_name("body")) {
            walk(
                body,
                Isometry3::identity(),
                qpos,
                &mut at,
                &mut sites,
                &mut bodies,
            );
        }
        assert_eq!(
            at,
            qpos.len(),
            "qpos has as many numbers as the joints take"
        );
        (sites, bodies)
    }
}

fn walk(
    body: roxmltree::Node,
    parent: Isometry3<f64>,
    qpos: &[f64],
    at: &mut usize,
    sites: &mut HashMap<String, Vector3<f64>>,
    bodies: &mut HashMap<String, Isometry3<f64>>,
) {
    let pos = attr(body, "pos").map_or_else(Vector3::zeros, vector);
    let q = attr(body, "quat").map_or_else(UnitQuaternion::identity, |t| quat(&numbers(t)));
    let mut frame = parent * Isometry3::from_parts(Translation3::from(pos), q);
    for joint in body.children().filter(|n| n.is_element()) {
        let kind = match joint.tag_name().name() {
            "freejoint" => "free",
            "joint" => attr(joint, "type").unwrap_or("hinge"),
            _ => continue,
        };
        let axis = attr(joint, "axis").map_or_else(Vector3::z, vector);
        let reference = attr(joint, "ref").map_or(0.0, |t| t.parse().expect("ref"));
        match kind {
            "free" => {
                let v = &qpos[*at..*at + 7];
                frame = Isometry3::from_parts(Translation3::new(v[0], v[1], v[2]), quat(&v[3..]));
                *at += 7;
            }
            "ball" => {
                frame *= Isometry3::from_parts(Translation3::identity(), quat(&qpos[*at..*at + 4]));
                *at += 4;
            }
            "slide" => {
                frame *= Translation3::from(axis * (qpos[*at] - reference));
                *at += 1;
            }
            "hinge" => {
                let turn = UnitQuaternion::from_axis_angle(
                    &Unit::new_normalize(axis),
                    qpos[*at] - reference,
                );
                frame *= Isometry3::from_parts(Translation3::identity(), turn);
                *at += 1;
            }
            other => panic!("joint type {other}"),
        }
    }
    if let Some(name) = attr(body, "name") {
        bodies.insert(name.to_owned(), frame);
    }
    for child in body.children().filter(|n| n.is_element()) {
        match child.tag_name().name() {
            "site" => {
                let p = attr(child, "pos").map_or_else(Vector3::zeros, vector);
                sites.insert(
                    attr(child, "name").expect("site name").to_owned(),
                    (frame * nalgebra::Point3::from(p)).coords,
                );
            }
            "body" => walk(child, frame, qpos, at, sites, bodies),
            _ => {}
        }
    }
}

fn export(s: &Scenario, format: RobotFormat) -> super::RobotFiles {
    describe(
        s,
        format,
        EVERY,
        &PartSet::none(),
        &AppearanceSettings::default(),
        |t| format!("at {t}"),
    )
    .unwrap_or_else(|e| panic!("{}: {e}", s.name))
}

#[test]
fn every_mjcf_keyframe_closes_the_loops_at_the_studios_pose_on_every_rig() {
    for name in RIGS {
        let s = preset(name);
        let g = &s.geometry;
        let size = g.characteristic_length();
        let text = export(&s, RobotFormat::Mjcf).description;
        let doc = roxmltree::Document::parse(&text).expect("MJCF is XML");
        let samples = s.motion.sample();
        let keys: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("key"))
            .collect();
        assert_eq!(keys.len(), samples.times.len().div_ceil(EVERY), "{name}");
        let rotary = g.rotary().is_some();
        let leg = if rotary { "servo" } else { "leg" };
        for (key, (&t, pose)) in keys
            .iter()
            .zip(samples.times.iter().zip(&samples.poses).step_by(EVERY))
        {
            assert_eq!(attr(*key, "time"), Some(t.to_string().as_str()));
            let (sites, bodies) =
                Mjcf { doc: &doc }.sites(&numbers(attr(*key, "qpos").expect("qpos")));
            let joints = g.inverse(pose).platform_joints;
            for k in 1..=6 {
                let tip = sites[&format!("{leg}{k}_tip")];
                let on = sites[&format!("platform_joint{k}")];
                assert!(
                    (tip - on).norm() < 1e-12 * size,
                    "{name} t={t} leg {k}: {:e}",
                    (tip - on).norm()
                );
                assert!(
                    (on - joints[k - 1]).norm() < 1e-12 * size,
                    "{name} t={t} joint {k}"
                );
            }
            let platform = bodies["platform"];
            let studio = studio_frame(&s, pose);
            assert!(
                (platform.translation.vector - studio.translation.vector).norm() < 1e-12 * size
            );
            assert!(
                platform.rotation.angle_to(&studio.rotation) < 1e-12,
                "{name} t={t}"
            );
            // The controls are the studio's leg lengths or servo angles.
            let values = g.actuator_values_batch(&[*pose]).expect("solved")[0];
            let ctrl = numbers(attr(*key, "ctrl").expect("ctrl"));
            for k in 0..6 {
                let want = if rotary {
                    values[k].to_radians()
                } else {
                    values[k]
                };
                assert!(
                    (ctrl[k] - want).abs() < 1e-12,
                    "{name} t={t} ctrl {k}: {} vs {want}",
                    ctrl[k]
                );
            }
        }
    }
}

#[test]
fn the_mjcf_default_configuration_is_home_with_its_loops_closed() {
    for name in RIGS {
        let s = preset(name);
        let text = export(&s, RobotFormat::Mjcf).description;
        let doc = roxmltree::Document::parse(&text).expect("MJCF is XML");
        // qpos0: every ball at identity, every slide and hinge at its ref, the free joint
        // at its body's frame.
        let mut qpos0 = Vec::new();
        for joint in doc
            .descendants()
            .filter(|n| n.has_tag_name("joint") || n.has_tag_name("freejoint"))
        {
            match attr(joint, "type") {
                Some("ball") => qpos0.extend([1.0, 0.0, 0.0, 0.0]),
                Some("slide" | "hinge") => {
                    qpos0.push(attr(joint, "ref").expect("ref").parse().expect("ref"))
                }
                _ => {
                    let body = joint.parent().expect("body");
                    qpos0.extend(numbers(attr(body, "pos").expect("pos")));
                    qpos0.extend(numbers(attr(body, "quat").expect("quat")));
                }
            }
        }
        let (sites, bodies) = Mjcf { doc: &doc }.sites(&qpos0);
        let leg = if s.geometry.rotary().is_some() {
            "servo"
        } else {
            "leg"
        };
        for k in 1..=6 {
            let gap =
                (sites[&format!("{leg}{k}_tip")] - sites[&format!("platform_joint{k}")]).norm();
            assert!(
                gap < 1e-12 * s.geometry.characteristic_length(),
                "{name} leg {k}: {gap:e}"
            );
        }
        let home = studio_frame(&s, &s.geometry.home_pose());
        assert!((bodies["platform"].translation.vector - home.translation.vector).norm() < 1e-12);
        // One actuator per leg, on its slide or servo, its range the stroke or servo range.
        let actuators: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("position"))
            .collect();
        assert_eq!(actuators.len(), 6);
        for (k, a) in actuators.iter().enumerate() {
            let n = k + 1;
            let (name_, joint) = if leg == "servo" {
                (format!("servo{n}"), format!("servo{n}"))
            } else {
                (format!("leg{n}"), format!("leg{n}_slide"))
            };
            assert_eq!(attr(*a, "name"), Some(name_.as_str()));
            assert_eq!(attr(*a, "joint"), Some(joint.as_str()));
        }
    }
}

/// A URDF library's forward kinematics: each link's frame from `base` through the joints'
/// origins (`xyz`, `rpy` with `R = Rz·Ry·Rx`) and motions about or along their axes.
fn urdf_frames(
    doc: &roxmltree::Document,
    cfg: &HashMap<String, f64>,
) -> HashMap<String, Isometry3<f64>> {
    let joints: Vec<_> = doc
        .root_element()
        .children()
        .filter(|n| n.has_tag_name("joint"))
        .collect();
    let mut frames = HashMap::from([("base".to_owned(), Isometry3::identity())]);
    let mut left = joints.len();
    while left > 0 {
        let before = left;
        for j in &joints {
            let child = j
                .children()
                .find(|n| n.has_tag_name("child"))
                .and_then(|n| attr(n, "link"))
                .expect("child");
            let parent = j
                .children()
                .find(|n| n.has_tag_name("parent"))
                .and_then(|n| attr(n, "link"))
                .expect("parent");
            if frames.contains_key(child) || !frames.contains_key(parent) {
                continue;
            }
            let origin = j
                .children()
                .find(|n| n.has_tag_name("origin"))
                .expect("origin");
            let xyz = vector(attr(origin, "xyz").expect("xyz"));
            let rpy = numbers(attr(origin, "rpy").expect("rpy"));
            let mut frame = frames[parent]
                * Isometry3::from_parts(
                    Translation3::from(xyz),
                    UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]),
                );
            let name = attr(*j, "name").expect("joint name");
            let axis = j
                .children()
                .find(|n| n.has_tag_name("axis"))
                .map(|n| vector(attr(n, "xyz").expect("axis")));
            match attr(*j, "type") {
                Some("fixed") => {}
                Some("prismatic") => frame *= Translation3::from(axis.expect("axis") * cfg[name]),
                Some("revolute" | "continuous") => {
                    frame *= UnitQuaternion::from_axis_angle(
                        &Unit::new_normalize(axis.expect("axis")),
                        cfg[name],
                    );
                }
                other => panic!("joint type {other:?}"),
            }
            frames.insert(child.to_owned(), frame);
            left -= 1;
        }
        assert!(left < before, "every link hangs from base");
    }
    frames
}

#[test]
fn every_urdf_joint_state_puts_each_tip_on_its_platform_joint_on_every_rig() {
    for name in RIGS {
        let s = preset(name);
        let size = s.geometry.characteristic_length();
        let files = export(&s, RobotFormat::Urdf);
        let doc = roxmltree::Document::parse(&files.description).expect("URDF is XML");
        let states = files.joint_states.expect("joint states");
        let mut lines = states.lines();
        let header: Vec<&str> = lines.next().expect("header").split(',').collect();
        assert_eq!(header[0], "t");
        let samples = s.motion.sample();
        let mut rows = 0;
        for (line, pose) in lines.zip(samples.poses.iter().step_by(EVERY)) {
            rows += 1;
            let cfg: HashMap<String, f64> = header
                .iter()
                .zip(line.split(','))
                .map(|(h, v)| ((*h).to_owned(), v.parse().expect("number")))
                .collect();
            let frames = urdf_frames(&doc, &cfg);
            for k in 1..=6 {
                let tip = frames[&format!("tip{k}")].translation.vector;
                let joint = frames[&format!("platform_joint{k}")].translation.vector;
                assert!(
                    (tip - joint).norm() < 1e-12 * size,
                    "{name} leg {k}: {:e}",
                    (tip - joint).norm()
                );
            }
            let studio = studio_frame(&s, pose);
            let platform = frames["platform"];
            assert!(
                (platform.translation.vector - studio.translation.vector).norm() < 1e-12 * size,
                "{name}"
            );
            assert!(
                platform.rotation.angle_to(&studio.rotation) < 1e-12,
                "{name}"
            );
        }
        assert_eq!(rows, samples.times.len().div_ceil(EVERY), "{name}");
    }
}

/// Why `s` cannot be described in `format`.
fn refusal(s: &Scenario, format: RobotFormat) -> String {
    let e = describe(
        s,
        format,
        1,
        &PartSet::none(),
        &AppearanceSettings::default(),
        |t| format!("the trajectory at t = {t} s"),
    );
    e.err().expect("refused").to_string()
}

#[test]
fn a_pose_beyond_the_stroke_or_a_servos_reach_is_refused_with_its_time() {
    let mut s = preset("paired");
    let g = s.geometry.clone();
    let longest = (0..=200)
        .map(|k| s.motion.trajectory.pose_at(f64::from(k) * 0.05))
        .flat_map(|p| g.leg_lengths(&p))
        .fold(0.0, f64::max);
    let mut params = g.params().clone();
    params.stroke.max = Some(longest - 1e-3);
    s.geometry = stewart_kinematics::Geometry::new(params).expect("geometry");
    let words = refusal(&s, RobotFormat::Mjcf);
    assert!(
        words.contains("the trajectory at t = ") && words.contains("beyond its stroke"),
        "{words}"
    );

    let mut s = preset("servo-desk");
    stewart_kinematics::io::settings::apply_all(&mut s, ["trajectory.z.offset_m=1"]).expect("set");
    let words = refusal(&s, RobotFormat::Urdf);
    assert!(
        words.contains("the trajectory at t = 0 s") && words.contains("cannot reach"),
        "{words}"
    );
}

#[test]
fn a_horn_part_turns_with_its_servo_and_a_legs_part_stays_along_its_leg() {
    use stewart_kinematics::solve::chains::LegChain;
    for name in ["paired", "servo-desk"] {
        let s = preset(name);
        let g = &s.geometry;
        let rig = super::Rig::of(&s, 1, |t| t.to_string()).expect("rig");
        for sample in rig.samples.iter().step_by(97) {
            let frame = g.scene_frame(&sample.pose, Vec::new());
            for k in 0..6 {
                match sample.chains[k] {
                    LegChain::Rotary { servo, .. } => {
                        // The horn's body turned by the servo carries the part exactly as
                        // the studio draws it at this pose.
                        let body = super::quat_of(&rig.horn_rotation(k, servo));
                        let drawn = frame.horn_placement(k).expect("horn").rotation;
                        assert!(
                            (body * rig.part_frames.first[k]).angle_to(&drawn) < 1e-12,
                            "{name} servo {k}"
                        );
                    }
                    LegChain::Linear { universal, .. } => {
                        // The cylinder's drawing axis (+y) lies along the leg.
                        let body = super::quat_of(&universal.rotation());
                        let along = body * rig.part_frames.first[k] * Vector3::y();
                        let leg = frame.leg_placements(k)[0].rotation * Vector3::y();
                        assert!((along - leg).norm() < 1e-12, "{name} leg {k}");
                    }
                }
            }
        }
    }
}

#[test]
fn masses_come_from_payload_and_dynamics_and_each_default_is_said() {
    let mut s = preset("paired");
    stewart_kinematics::io::settings::apply_all(
        &mut s,
        [
            "dynamics.rod_mass_kg=0.6",
            "dynamics.rod_com_m=0.2",
            "dynamics.rod_inertia_kg_m2=0.005",
        ],
    )
    .expect("set");
    let payload = s.payload.expect("paired has a payload");
    let text = export(&s, RobotFormat::Mjcf).description;
    let doc = roxmltree::Document::parse(&text).expect("MJCF is XML");
    let inertial_of = |body: &str| {
        let b = doc
            .descendants()
            .find(|n| n.has_tag_name("body") && attr(*n, "name") == Some(body))
            .expect("body");
        b.children()
            .find(|n| n.has_tag_name("inertial"))
            .expect("inertial")
    };
    let platform = inertial_of("platform");
    assert_eq!(
        attr(platform, "mass"),
        Some(payload.mass.to_string().as_str())
    );
    assert!((vector(attr(platform, "pos").expect("pos")) - payload.centre_of_mass).norm() < 1e-15);
    let full = numbers(attr(platform, "fullinertia").expect("fullinertia"));
    let i = payload.inertia;
    assert_eq!(
        full,
        vec![
            i[(0, 0)],
            i[(1, 1)],
            i[(2, 2)],
            i[(0, 1)],
            i[(0, 2)],
            i[(1, 2)]
        ]
    );
    // The rod hangs 0.2 m below its platform joint, across 0.005 kg·m².
    let rod = inertial_of("leg3_rod");
    assert_eq!(attr(rod, "mass"), Some("0.6"));
    assert_eq!(
        numbers(attr(rod, "pos").expect("pos")),
        vec![0.0, 0.0, -0.2]
    );
    let full = numbers(attr(rod, "fullinertia").expect("fullinertia"));
    assert!(
        (full[0] - 0.005).abs() < 1e-15 && (full[1] - 0.005).abs() < 1e-15,
        "{full:?}"
    );
    // The cylinder has no mass in the scenario: its default is said, the rod's is not.
    let comment = doc
        .descendants()
        .find(|n| n.is_comment())
        .and_then(|n| n.text())
        .expect("comment");
    assert!(comment.contains("Light default: cylinder"), "{comment}");
    assert!(!comment.contains("Light default: rod"), "{comment}");
    assert!(!comment.contains("Light default: platform"), "{comment}");
}

#[test]
fn any_scenario_name_makes_well_formed_xml() {
    let mut s = preset("servo-desk");
    s.name = "a&b <c> \"d\" 'e' \u{1} --f-".to_owned();
    for format in [RobotFormat::Mjcf, RobotFormat::Urdf] {
        let text = export(&s, format).description;
        let doc = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{format:?}: {e}"));
        let name = attr(
            doc.root_element(),
            if format == RobotFormat::Mjcf {
                "model"
            } else {
                "name"
            },
        );
        assert_eq!(name, Some("a&b <c> \"d\" 'e' \u{FFFD} --f-"), "{format:?}");
    }
}

#[test]
fn a_flat_payload_a_one_sided_stroke_and_home_beyond_it_still_make_a_model_mujoco_takes() {
    // A point-mass payload: MuJoCo needs every principal moment above 0.
    let mut s = preset("paired");
    if let Some(p) = s.payload.as_mut() {
        p.inertia = nalgebra::Matrix3::zeros();
    }
    let text = export(&s, RobotFormat::Mjcf).description;
    let doc = roxmltree::Document::parse(&text).expect("MJCF is XML");
    let platform = doc
        .descendants()
        .find(|n| n.has_tag_name("body") && attr(*n, "name") == Some("platform"))
        .and_then(|b| b.children().find(|n| n.has_tag_name("inertial")))
        .expect("inertial");
    let full = numbers(attr(platform, "fullinertia").expect("fullinertia"));
    assert!(full[..3].iter().all(|&m| m > 0.0), "{full:?}");
    assert!(text.contains("principal moment below"));

    // Only the shortest leg set: the longest is filled, and said.
    let mut s = preset("seed");
    set(&mut s, &["geometry.leg_max=off"]);
    let text = export(&s, RobotFormat::Mjcf).description;
    let doc = roxmltree::Document::parse(&text).expect("MJCF is XML");
    let slide = doc
        .descendants()
        .find(|n| attr(*n, "name") == Some("leg1_slide"))
        .expect("slide");
    let range = numbers(attr(slide, "range").expect("range"));
    assert_eq!(range[0], 0.55);
    assert!(range[1] > 2.0, "{range:?}");
    assert!(text.contains("no longest leg"));

    // Home beyond the stroke: the reference is the first sample, inside it.
    let mut s = preset("seed");
    set(
        &mut s,
        &[
            "trajectory.z.offset_m=1",
            "geometry.leg_min=0.99",
            "geometry.leg_max=1.4",
        ],
    );
    let files = export(&s, RobotFormat::Mjcf).description;
    let doc = roxmltree::Document::parse(&files).expect("MJCF is XML");
    for k in 1..=6 {
        let slide = doc
            .descendants()
            .find(|n| attr(*n, "name") == Some(format!("leg{k}_slide").as_str()))
            .expect("slide");
        let reference: f64 = attr(slide, "ref").expect("ref").parse().expect("ref");
        assert!((0.99..=1.4).contains(&reference), "leg {k}: {reference}");
    }
    assert!(files.contains("reference configuration is the first sample"));
}

fn set(s: &mut Scenario, assignments: &[&str]) {
    stewart_kinematics::io::settings::apply_all(s, assignments.iter().copied()).expect("set");
}
