//! The meshes of the glTF scene, each in its node's frame: the studio's drawing (plates
//! with their posts and joint balls, actuator bodies, rods, horns, servo bodies) at the
//! sizes the renderer draws them, or the scenario's CAD parts.

use std::sync::Arc;

use glam::{Mat3, Mat4, Quat, Vec3};
use gltf_json as json;
use stewart_kinematics::model::appearance::Part;
use stewart_kinematics::model::scene::SceneFrame;
use stewart_render::Theme;
use stewart_render::appearance::parts::{LoadedPart, PartSet};
use stewart_render::draw_list::{
    BODY_RADIUS, JOINT_RADIUS, PLATE_THICKNESS, ROD_RADIUS, along, body_length,
};
use stewart_render::mesh::Mesh;
use stewart_render::plate_shape::plate_shape;
use stewart_render::theme::{Srgba, linear, series};

use super::document::{Document, Geometry};
use super::v3;

/// How the parts look.
pub(super) struct Looks<'a> {
    /// The theme's colours.
    pub(super) theme: &'a Theme,
    /// Each actuator in its own colour.
    pub(super) coloured: bool,
    /// CAD parts in place of the studio's.
    pub(super) parts: &'a PartSet,
}

/// The meshes made: the base's and one per moving node (in `super::placements`' order).
pub(super) struct Meshes {
    /// The base's (plate, joints, servo bodies).
    pub(super) base: json::Index<json::Mesh>,
    /// The platform's, then each actuator's two parts'.
    pub(super) moving: Vec<json::Index<json::Mesh>>,
}

/// What every mesh of the scene is built from: the home scene, the looks, the unit shapes,
/// the platform's size `s` and the longest leg.
#[derive(Clone, Copy)]
struct Home<'a> {
    home: &'a SceneFrame,
    looks: &'a Looks<'a>,
    shapes: &'a Shapes,
    s: f32,
    longest: f32,
}

type Pieces = Vec<(Geometry, json::Index<json::Material>)>;

/// The shared shapes, written once.
struct Shapes {
    cylinder: Arc<Mesh>,
    sphere: Arc<Mesh>,
    cuboid: Arc<Mesh>,
}

/// Every mesh of the scene of the platform at `home`, rods long enough for legs of
/// `longest` metres.
pub(super) fn build(doc: &mut Document, home: &SceneFrame, looks: &Looks, longest: f32) -> Meshes {
    let shapes = Shapes {
        cylinder: Arc::new(Mesh::cylinder()),
        sphere: Arc::new(Mesh::sphere()),
        cuboid: Arc::new(Mesh::cuboid()),
    };
    let s = home.base_radius.max(home.platform_radius) as f32;
    let at = Home {
        home,
        looks,
        shapes: &shapes,
        s,
        longest,
    };
    let base = base_mesh(doc, &at);
    let (platform, joint) = platform_pieces(doc, &at);
    let mut moving = vec![doc.mesh("platform", &platform)];
    leg_meshes(doc, &at, joint, &mut moving);
    Meshes { base, moving }
}

/// The base's mesh: its plate (or CAD part), its joints, and the servo bodies standing
/// still where the renderer puts them.
fn base_mesh(doc: &mut Document, at: &Home<'_>) -> json::Index<json::Mesh> {
    let (home, looks, shapes, s) = (at.home, at.looks, at.shapes, at.s);
    let theme = looks.theme;
    let mut base: Pieces = Vec::new();
    match looks.parts.get(Part::Base) {
        Some(part) => base.extend(part_pieces(doc, part, theme.base_plate)),
        None => {
            let joints: Vec<Vec3> = home.base_joints.iter().map(v3).collect();
            base.extend(plate(doc, shapes, &joints, s, theme.base_plate));
        }
    }
    if home.servos.is_none() {
        let joint = doc.material(doc_colour(theme.joint));
        for p in &home.base_joints {
            let g = doc.geometry(&shapes.sphere, ball(v3(p), JOINT_RADIUS * s));
            base.push((g, joint));
        }
    }
    // Servo bodies stand still: the home scene's boxes, where the renderer puts them.
    let home_list = stewart_render::DrawList::build(
        home,
        theme,
        &stewart_render::Overlays {
            grid: false,
            base_axes: false,
            path: false,
            labels: false,
            coloured_legs: looks.coloured,
            ..stewart_render::Overlays::default()
        },
    );
    for body in &home_list.boxes {
        let g = doc.geometry(&shapes.cuboid, Mat4::from_cols_array_2d(&body.model));
        let m = doc.material(body.color);
        base.push((g, m));
    }
    doc.mesh("base", &base)
}

/// The platform's pieces in its own frame (its plate or CAD part, its joints where the
/// platform frame holds them), and the joints' material.
fn platform_pieces(doc: &mut Document, at: &Home<'_>) -> (Pieces, json::Index<json::Material>) {
    let (home, looks, shapes, s) = (at.home, at.looks, at.shapes, at.s);
    let theme = looks.theme;
    // The platform in its own frame: its joints where the platform frame holds them.
    let mut platform: Pieces = match looks.parts.get(Part::Platform) {
        Some(part) => part_pieces(doc, part, theme.platform),
        None => {
            let p = home.platform_placement();
            let to_local = p.rotation.inverse();
            let joints: Vec<Vec3> = home
                .platform_joints
                .iter()
                .map(|q| v3(&(to_local * (q - p.origin))))
                .collect();
            plate(doc, shapes, &joints, s, theme.platform)
        }
    };
    let joint = doc.material(doc_colour(theme.joint));
    let p = home.platform_placement();
    for q in &home.platform_joints {
        let local = v3(&(p.rotation.inverse() * (q - p.origin)));
        let g = doc.geometry(&shapes.sphere, ball(local, JOINT_RADIUS * s));
        platform.push((g, joint));
    }
    (platform, joint)
}

/// Each leg's meshes pushed to `moving`: a linear leg's cylinder and rod (the rod reaching
/// into the body at the `longest` leg), or a servo's horn and rod.
fn leg_meshes(
    doc: &mut Document,
    at: &Home<'_>,
    joint: json::Index<json::Material>,
    moving: &mut Vec<json::Index<json::Mesh>>,
) {
    let (home, looks, shapes, s) = (at.home, at.looks, at.shapes, at.s);
    let longest = at.longest;
    let theme = looks.theme;
    match &home.servos {
        None => {
            let home_length = home.legs[0].length as f32;
            let body = body_length(home.legs[0].min_length, home_length);
            // Written only when drawn (once: the geometry is shared by the six).
            let body_shape =
                along(Vec3::ZERO, Vec3::Y * body, BODY_RADIUS * s, [0.0; 4]).model_matrix();
            // The rod reaches into the body at the longest leg.
            let rod_length = longest.max(home_length) - body + 0.02 * s;
            let rod = rod_pieces(doc, shapes, looks, Vec3::NEG_Y * rod_length, Vec3::ZERO, s);
            let rod = doc.mesh("rod", &rod);
            for k in 0..6 {
                let studio = if looks.coloured {
                    series(k)
                } else {
                    theme.leg_body
                };
                let pieces = match looks.parts.get(Part::Cylinder) {
                    Some(part) => part_pieces(doc, part, studio),
                    None => vec![(
                        doc.geometry(&shapes.cylinder, body_shape),
                        doc.material(doc_colour(studio)),
                    )],
                };
                moving.push(doc.mesh(&format!("leg{}_cylinder", k + 1), &pieces));
                moving.push(rod);
            }
        }
        Some(servos) => {
            let rod_length = (home.legs[0].top - home.legs[0].base).norm() as f32;
            let rod = rod_pieces(doc, shapes, looks, Vec3::ZERO, Vec3::Y * rod_length, s);
            let rod = doc.mesh("rod", &rod);
            let horn = (servos[0].horn_tip - servos[0].shaft).norm() as f32;
            let arm = along(Vec3::ZERO, Vec3::X * horn, 0.13 * horn, [0.0; 4]).model_matrix();
            let tip = ball(Vec3::X * horn, 0.16 * horn);
            for k in 0..6 {
                let studio = if looks.coloured {
                    series(k)
                } else {
                    theme.horn
                };
                let pieces = match looks.parts.get(Part::Horn) {
                    Some(part) => part_pieces(doc, part, studio),
                    None => vec![
                        (
                            doc.geometry(&shapes.cylinder, arm),
                            doc.material(doc_colour(studio)),
                        ),
                        (doc.geometry(&shapes.sphere, tip), joint),
                    ],
                };
                moving.push(doc.mesh(&format!("servo{}_horn", k + 1), &pieces));
                moving.push(rod);
            }
        }
    }
}

/// The rod's pieces: its CAD part, or a tube from `from` to `to` in its frame (`s`: the
/// larger plate's radius), in the theme's rod colour.
fn rod_pieces(
    doc: &mut Document,
    shapes: &Shapes,
    looks: &Looks,
    from: Vec3,
    to: Vec3,
    s: f32,
) -> Pieces {
    let colour = looks.theme.leg_rod;
    match looks.parts.get(Part::Rod) {
        Some(part) => part_pieces(doc, part, colour),
        None => {
            let tube = along(from, to, ROD_RADIUS * s, [0.0; 4]).model_matrix();
            let g = doc.geometry(&shapes.cylinder, tube);
            vec![(g, doc.material(doc_colour(colour)))]
        }
    }
}

/// An sRGB colour as glTF's linear base colour.
fn doc_colour(c: Srgba) -> [f32; 4] {
    linear(c)
}

/// A ball of `radius` at `at`.
fn ball(at: Vec3, radius: f32) -> Mat4 {
    Mat4::from_scale_rotation_translation(Vec3::splat(radius), Quat::IDENTITY, at)
}

/// A plate through `joints` (in its frame's z = 0 plane) and its posts, in `colour`.
fn plate(doc: &mut Document, shapes: &Shapes, joints: &[Vec3], s: f32, colour: Srgba) -> Pieces {
    let thickness = PLATE_THICKNESS * s;
    let shape = plate_shape(Vec3::ZERO, Mat3::IDENTITY, joints, thickness);
    let material = doc.material(doc_colour(colour));
    let mesh = Mesh::plate(shape.centre, shape.normal, &shape.corners, thickness);
    let mut pieces = vec![(doc.write_geometry(&mesh, Mat4::IDENTITY), material)];
    for (foot, joint) in shape.posts {
        let post = along(foot, joint, 0.6 * ROD_RADIUS * s, [0.0; 4]).model_matrix();
        pieces.push((doc.geometry(&shapes.cylinder, post), material));
    }
    pieces
}

/// A CAD part's pieces in its frame, coloured as the renderer colours them (the table's
/// colour, else the file's, else `studio`).
fn part_pieces(doc: &mut Document, part: &LoadedPart, studio: Srgba) -> Pieces {
    part.mesh
        .pieces
        .iter()
        .map(|piece| {
            let chosen = part.colour_of(piece, studio);
            let g = doc.geometry(&piece.mesh, part.transform);
            (g, doc.material(doc_colour(chosen)))
        })
        .collect()
}

/// An instance's model matrix.
trait ModelMatrix {
    fn model_matrix(&self) -> Mat4;
}

impl ModelMatrix for stewart_render::gpu_types::MeshInstance {
    fn model_matrix(&self) -> Mat4 {
        Mat4::from_cols_array_2d(&self.model)
    }
}
