//! The exported scene read back with the `gltf` crate (not our writer): at every sample
//! the platform node against inverse kinematics, each leg's two nodes as far apart as
//! the leg is long, each horn turned by its servo's angle.

use std::path::Path;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use stewart_kinematics::Scenario;
use stewart_render::Theme;
use stewart_render::appearance::parts::PartSet;

use super::{GltfRequest, export_gltf};

/// The file's document and its buffers (the GLB's chunk, or the `.bin` beside a `.gltf`).
fn read(path: &Path) -> (gltf::Document, Vec<Vec<u8>>) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{e}"));
    let gltf = gltf::Gltf::from_slice(&bytes).unwrap_or_else(|e| panic!("{e}"));
    let buffers = gltf
        .document
        .buffers()
        .map(|b| match b.source() {
            gltf::buffer::Source::Bin => gltf.blob.clone().unwrap_or_default(),
            gltf::buffer::Source::Uri(uri) => {
                std::fs::read(path.with_file_name(uri.replace("%20", " ")))
                    .unwrap_or_else(|e| panic!("{e}"))
            }
        })
        .collect();
    (gltf.document, buffers)
}

/// Each animated node's keys: name → (times, translations, rotations).
type Keys = std::collections::HashMap<String, (Vec<f32>, Vec<[f32; 3]>, Vec<[f32; 4]>)>;

fn keys(doc: &gltf::Document, buffers: &[Vec<u8>]) -> Keys {
    let mut out = Keys::new();
    let animation = doc
        .animations()
        .next()
        .unwrap_or_else(|| panic!("no animation"));
    for channel in animation.channels() {
        let reader = channel.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
        let name = channel
            .target()
            .node()
            .name()
            .unwrap_or_default()
            .to_owned();
        let entry = out.entry(name).or_default();
        entry.0 = reader
            .read_inputs()
            .unwrap_or_else(|| panic!("inputs"))
            .collect();
        match reader.read_outputs().unwrap_or_else(|| panic!("outputs")) {
            gltf::animation::util::ReadOutputs::Translations(t) => entry.1 = t.collect(),
            gltf::animation::util::ReadOutputs::Rotations(r) => entry.2 = r.into_f32().collect(),
            _ => panic!("only translations and rotations are animated"),
        }
    }
    out
}

fn rotation(q: [f32; 4]) -> UnitQuaternion<f64> {
    let [x, y, z, w] = q.map(f64::from);
    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z))
}

fn vector(t: [f32; 3]) -> Vector3<f64> {
    Vector3::new(t[0].into(), t[1].into(), t[2].into())
}

fn export(scenario: &Scenario, out: &Path) -> super::GltfReport {
    let request = GltfRequest {
        out: out.to_owned(),
        theme: Theme::LIGHT,
        coloured_legs: true,
        parts: PartSet::none(),
    };
    export_gltf(scenario, &request, crate::output::NO_INPUTS).unwrap_or_else(|e| panic!("{e:#}"))
}

#[test]
fn the_seed_read_back_has_the_platform_and_legs_of_inverse_kinematics_at_every_sample() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let s = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("seed.glb");
    let report = export(&s, &path);
    assert_eq!((report.samples, report.moving), (1001, 13));
    assert!(report.bytes < 5_000_000, "{} bytes", report.bytes);
    let (doc, buffers) = read(&path);
    // The root turns z up into y up, with no scale; its children are the parts.
    let root = doc
        .scenes()
        .next()
        .and_then(|s| s.nodes().next())
        .unwrap_or_else(|| panic!("root"));
    assert_eq!(root.name(), Some("stewart"));
    let (_, turn, scale) = root.transform().decomposed();
    assert_eq!(scale, [1.0; 3]);
    let up = rotation(turn) * Vector3::z();
    assert!((up - Vector3::y()).norm() < 1e-7, "{up}");
    let names: Vec<&str> = root.children().filter_map(|n| n.name()).collect();
    assert_eq!(
        names[..4],
        ["base", "platform", "leg1_cylinder", "leg1_rod"]
    );
    assert_eq!(names.len(), 14);
    assert_eq!(
        doc.animations()
            .next()
            .and_then(|a| a.name().map(str::to_owned)),
        Some("seed".into())
    );
    let keys = keys(&doc, &buffers);
    let times: Vec<f64> = s.motion.sampling.times().collect();
    let (t, platform_at, platform_turn) = &keys["platform"];
    assert_eq!(t.len(), times.len());
    let g = &s.geometry;
    let mut worst = [0.0f64; 3];
    for (i, &time) in times.iter().enumerate() {
        assert!((f64::from(t[i]) - time).abs() < 1e-6);
        let pose = s.motion.trajectory.pose_at(time);
        // The platform frame: its origin and axes as inverse kinematics places them.
        let centre = g.platform_centre(&pose);
        worst[0] = worst[0].max((vector(platform_at[i]) - centre).norm());
        let turn = rotation(platform_turn[i]).to_rotation_matrix();
        worst[1] = worst[1].max((turn.matrix() - pose.rotation()).abs().max());
        // Each leg: the distance between its two nodes is its length.
        let lengths = g.leg_lengths(&pose);
        for (k, length) in lengths.iter().enumerate() {
            let base = vector(keys[&format!("leg{}_cylinder", k + 1)].1[i]);
            let top = vector(keys[&format!("leg{}_rod", k + 1)].1[i]);
            // At base joint k and platform joint k.
            worst[0] = worst[0].max((base - g.base_joints()[k]).norm());
            let joint = centre + pose.rotation() * g.platform_joints()[k];
            worst[0] = worst[0].max((top - joint).norm());
            worst[2] = worst[2].max(((top - base).norm() - length).abs());
            // And the cylinder's +y points along it.
            let along = rotation(keys[&format!("leg{}_cylinder", k + 1)].2[i]) * Vector3::y();
            assert!((along - (top - base).normalize()).norm() < 1e-5);
        }
    }
    assert!(worst.iter().all(|&w| w < 1e-6), "{worst:?}");
    // Neighbouring quaternions take the shorter way.
    assert!(
        platform_turn
            .windows(2)
            .all(|w| { w[0].iter().zip(&w[1]).map(|(a, b)| a * b).sum::<f32>() >= 0.0 })
    );
}

#[test]
fn servo_horns_turn_by_their_servo_angles_and_a_gltf_keeps_its_buffer_beside_it() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let s = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("servo desk.gltf");
    export(&s, &path);
    assert!(dir.path().join("servo desk.bin").is_file());
    let (doc, buffers) = read(&path);
    assert_eq!(
        doc.buffers()
            .next()
            .map(|b| matches!(b.source(), gltf::buffer::Source::Uri("servo%20desk.bin"))),
        Some(true)
    );
    let keys = keys(&doc, &buffers);
    let g = &s.geometry;
    let rotary = g.rotary().unwrap_or_else(|| panic!("servos"));
    let mut worst = 0.0f64;
    for (i, time) in s.motion.sampling.times().enumerate().step_by(7) {
        let frame = g.scene_frame(&s.motion.trajectory.pose_at(time), Vec::new());
        let servos = frame.servos.unwrap_or_else(|| panic!("servos"));
        for (k, servo) in servos.iter().enumerate() {
            let (_, at, turn) = &keys[&format!("servo{}_horn", k + 1)];
            assert!((vector(at[i]) - servo.shaft).norm() < 1e-6);
            let x = rotation(turn[i]) * Vector3::x();
            let beta = rotary.horn_angles()[k].radians();
            let angle = x.z.atan2(x.x * beta.cos() + x.y * beta.sin());
            let theta = servo
                .angle_deg
                .unwrap_or_else(|| panic!("reachable"))
                .to_radians();
            worst = worst.max((angle - theta).abs());
            let rod = vector(keys[&format!("servo{}_rod", k + 1)].1[i]);
            assert!((rod - servo.horn_tip).norm() < 1e-6);
        }
    }
    assert!(worst < 1e-6, "{worst} rad");
}
