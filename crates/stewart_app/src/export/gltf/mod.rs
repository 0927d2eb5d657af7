//! The trajectory as an animated glTF 2.0 scene (`stewart render --out FILE.glb` or
//! `FILE.gltf` with its `.bin` beside it; the viewer's *Export → 3-D animation*).
//!
//! A root node `stewart` turns the studio's z-up frame into glTF's y-up (−90° about x, no
//! scale); below it every node is in the studio's frame, in metres: `base` (still),
//! `platform` (the platform frame at each sample), per actuator k `leg{k}_cylinder` (at
//! base joint k) and `leg{k}_rod` (at platform joint k), or `servo{k}_horn` (at the shaft,
//! turned by the servo angle) and `servo{k}_rod` (at the horn tip) — each part's frame as
//! [`stewart_kinematics::model::appearance::Part`] defines it. One animation, named after
//! the scenario, has a key per trajectory sample: translation and rotation (LINEAR, the
//! shorter way between neighbouring quaternions) of every moving node. Meshes are the
//! studio's drawing (plates, tubes, balls, horns) or the scenario's CAD parts, in the
//! theme's colours as metallic-roughness base colours.

mod document;
mod meshes;

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context as _, Result};
use glam::{Quat, Vec3};
use gltf_json as json;
use json::validation::Checked::Valid;
use stewart_kinematics::Scenario;
use stewart_kinematics::model::scene::{Placement, SceneFrame};
use stewart_render::Theme;
use stewart_render::appearance::parts::PartSet;

use document::Document;

/// What to export.
#[derive(Clone, Debug)]
pub(crate) struct GltfRequest {
    /// `.glb`, or `.gltf` (its buffer in a `.bin` of the same name beside it).
    pub(crate) out: PathBuf,
    /// Colours.
    pub(crate) theme: Theme,
    /// Each actuator in its own colour (the plot's).
    pub(crate) coloured_legs: bool,
    /// The CAD parts drawn in place of the usual ones.
    pub(crate) parts: PartSet,
}

/// What an export wrote.
pub(crate) struct GltfReport {
    /// Keyframes per moving node.
    pub(crate) samples: usize,
    /// Moving nodes.
    pub(crate) moving: usize,
    /// Bytes written (both files of a `.gltf`).
    pub(crate) bytes: u64,
    /// How long it took, seconds.
    pub(crate) seconds: f64,
}

/// Whether `path` names a glTF file (`.glb`, `.gltf`, any case).
pub(crate) fn is_gltf(path: &Path) -> bool {
    matches!(
        crate::output::extension(path).as_deref(),
        Some("glb" | "gltf")
    )
}

/// One animated node: its name, mesh and keys.
struct Track {
    name: String,
    translations: Vec<f32>,
    rotations: Vec<f32>,
    last: Option<Quat>,
}

impl Track {
    fn new(name: String, samples: usize) -> Self {
        Self {
            name,
            translations: Vec::with_capacity(3 * samples),
            rotations: Vec::with_capacity(4 * samples),
            last: None,
        }
    }

    /// Add the key at `p`, its quaternion on the side of the previous one.
    fn key(&mut self, p: &Placement) {
        let mut q = stewart_render::draw_list::frame_rotation(p);
        if self.last.is_some_and(|last| last.dot(q) < 0.0) {
            q = -q;
        }
        self.last = Some(q);
        self.translations
            .extend([p.origin.x as f32, p.origin.y as f32, p.origin.z as f32]);
        self.rotations.extend(q.to_array());
    }
}

/// The moving nodes of a scene: the platform, then per actuator its two parts.
fn placements(frame: &SceneFrame) -> Vec<Placement> {
    let mut out = vec![frame.platform_placement()];
    for k in 0..6 {
        match frame.horn_placement(k) {
            Some(horn) => out.push(horn),
            None => out.push(frame.leg_placements(k)[0]),
        }
        out.push(frame.rod_placement(k));
    }
    out
}

/// The moving nodes' names, in [`placements`]' order.
fn names(rotary: bool) -> Vec<String> {
    let mut out = vec!["platform".to_owned()];
    for k in 1..=6 {
        if rotary {
            out.push(format!("servo{k}_horn"));
            out.push(format!("servo{k}_rod"));
        } else {
            out.push(format!("leg{k}_cylinder"));
            out.push(format!("leg{k}_rod"));
        }
    }
    out
}

/// Write `scenario`'s trajectory as `request` says; `inputs` are the files the command
/// reads (never overwritten).
pub(crate) fn export_gltf(
    scenario: &Scenario,
    request: &GltfRequest,
    inputs: &[(&str, impl AsRef<Path>)],
) -> Result<GltfReport> {
    let started = Instant::now();
    let glb = crate::output::extension(&request.out).as_deref() == Some("glb");
    let destination = crate::output::Destination::new(&request.out, inputs)?;
    destination.require_file()?;
    let bin_path = request.out.with_extension("bin");
    let bin_destination = if glb {
        None
    } else {
        Some(crate::output::Destination::new(&bin_path, inputs)?)
    };

    let sampled = Sampled::of(scenario);
    let mut doc = Document::default();
    let g = &scenario.geometry;
    let home = g.scene_frame(&g.home_pose(), Vec::new());
    let looks = meshes::Looks {
        theme: &request.theme,
        coloured: request.coloured_legs,
        parts: &request.parts,
    };
    let meshes = meshes::build(&mut doc, &home, &looks, sampled.longest as f32);
    let animated = animate(&mut doc, &sampled, &meshes);
    close_document(&mut doc, &scenario.name, animated);

    let bytes = match bin_destination {
        None => {
            let (glb, _) = doc.finish(None);
            destination.write_bytes(&glb)?;
            glb.len() as u64
        }
        Some(bin_destination) => {
            let uri = uri_of(&bin_path)?;
            let (text, bin) = doc.finish(Some(&uri));
            bin_destination.write_bytes(&bin)?;
            destination.write_bytes(&text)?;
            (text.len() + bin.len()) as u64
        }
    };
    Ok(GltfReport {
        samples: sampled.times.len(),
        moving: sampled.tracks.len(),
        bytes,
        seconds: started.elapsed().as_secs_f64(),
    })
}

/// The trajectory sampled for the animation: its times, each moving part's track, and the
/// longest leg reached (the rods' meshes are made that long).
struct Sampled {
    times: Vec<f64>,
    tracks: Vec<Track>,
    longest: f64,
}

impl Sampled {
    /// Every moving part of `scenario`'s rig placed at each time of its motion.
    fn of(scenario: &Scenario) -> Self {
        let g = &scenario.geometry;
        let times: Vec<f64> = scenario.motion.times().collect();
        let rotary = g.rotary().is_some();
        let mut tracks: Vec<Track> = names(rotary)
            .into_iter()
            .map(|n| Track::new(n, times.len()))
            .collect();
        let mut longest = 0.0f64;
        for &t in &times {
            let frame = g.scene_frame(&scenario.motion.trajectory.pose_at(t), Vec::new());
            for (track, p) in tracks.iter_mut().zip(placements(&frame)) {
                track.key(&p);
            }
            longest = frame.legs.iter().map(|l| l.length).fold(longest, f64::max);
        }
        Self {
            times,
            tracks,
            longest,
        }
    }
}

/// The scene's nodes under its root (the base, then the moving parts at their first key)
/// and the animation's channels and samplers.
struct Animated {
    children: Vec<json::Index<json::Node>>,
    channels: Vec<json::animation::Channel>,
    samplers: Vec<json::animation::Sampler>,
}

/// The base and each moving part as nodes of `doc`, every track a translation and a
/// rotation channel sampled linearly at the motion's times (from its first).
fn animate(doc: &mut Document, sampled: &Sampled, meshes: &meshes::Meshes) -> Animated {
    let times = &sampled.times;
    let start = times.first().copied().unwrap_or(0.0);
    let seconds: Vec<f32> = times.iter().map(|t| (t - start) as f32).collect();
    let input = doc.floats(&seconds, 1, true, None);
    let base = doc.root.push(json::Node {
        name: Some("base".to_owned()),
        mesh: Some(meshes.base),
        ..Default::default()
    });
    let mut children = vec![base];
    let mut channels = Vec::new();
    let mut samplers = Vec::new();
    for (k, track) in sampled.tracks.iter().enumerate() {
        let translation = doc.floats(&track.translations, 3, true, None);
        let rotation = doc.floats(&track.rotations, 4, false, None);
        let node = doc.root.push(json::Node {
            name: Some(track.name.clone()),
            mesh: Some(meshes.moving[k]),
            translation: track.translations.get(..3).and_then(|s| s.try_into().ok()),
            rotation: track
                .rotations
                .get(..4)
                .and_then(|s| s.try_into().ok())
                .map(json::scene::UnitQuaternion),
            ..Default::default()
        });
        children.push(node);
        for (output, path) in [
            (translation, json::animation::Property::Translation),
            (rotation, json::animation::Property::Rotation),
        ] {
            let sampler = json::Index::push(
                &mut samplers,
                json::animation::Sampler {
                    extensions: None,
                    extras: Default::default(),
                    input,
                    interpolation: Valid(json::animation::Interpolation::Linear),
                    output,
                },
            );
            channels.push(json::animation::Channel {
                sampler,
                target: json::animation::Target {
                    extensions: None,
                    extras: Default::default(),
                    node,
                    path: Valid(path),
                },
                extensions: None,
                extras: Default::default(),
            });
        }
    }
    Animated {
        children,
        channels,
        samplers,
    }
}

/// The document's root node (turned so that the studio's z, up, is glTF's y), its scene
/// and animation, both named `name`, and its asset.
fn close_document(doc: &mut Document, name: &str, animated: Animated) {
    // −90° about x: the studio's z (up) becomes glTF's y (up).
    let half = std::f32::consts::FRAC_1_SQRT_2;
    let root = doc.root.push(json::Node {
        name: Some("stewart".to_owned()),
        rotation: Some(json::scene::UnitQuaternion([-half, 0.0, 0.0, half])),
        children: Some(animated.children),
        ..Default::default()
    });
    let scene = doc.root.push(json::Scene {
        extensions: None,
        extras: Default::default(),
        name: Some(name.to_owned()),
        nodes: vec![root],
    });
    doc.root.scene = Some(scene);
    doc.root.push(json::Animation {
        extensions: None,
        extras: Default::default(),
        channels: animated.channels,
        name: Some(name.to_owned()),
        samplers: animated.samplers,
    });
    doc.root.asset = json::Asset {
        generator: Some(format!(
            "Stewart platform studio {}",
            env!("CARGO_PKG_VERSION")
        )),
        version: "2.0".to_owned(),
        ..Default::default()
    };
}

/// The relative URI of the buffer file beside the `.gltf` (its name, percent-encoded).
fn uri_of(bin: &Path) -> Result<String> {
    let name = bin
        .file_name()
        .and_then(|n| n.to_str())
        .context("the output file's name is not text")?;
    Ok(name
        .bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => {
                (b as char).to_string()
            }
            _ => format!("%{b:02X}"),
        })
        .collect())
}

/// A point of the studio frame in single precision, for meshes.
pub(super) fn v3(v: &nalgebra::Vector3<f64>) -> Vec3 {
    Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

#[cfg(test)]
mod tests;
