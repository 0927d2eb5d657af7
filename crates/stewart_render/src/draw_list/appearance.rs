//! CAD parts in the draw list: each part's pieces placed in its part's frame (see
//! [`stewart_kinematics::model::appearance::Part`]) by the `[appearance]` table's scale,
//! rotation and offset, coloured by the table, else the file, else the studio (the leg's
//! colour, the theme's plates); a rod, body or horn near or past its limit takes the
//! warning colour whatever its file says, as the usual drawing does.

use std::sync::Arc;

use glam::{Mat4, Quat, Vec3};
use stewart_kinematics::model::appearance::Part;
use stewart_kinematics::model::scene::{LegStatus, Placement, SceneFrame};

use super::{DrawList, LegColours};
use crate::appearance::parts::{LoadedPart, PartSet};
use crate::gpu_types::MeshInstance;
use crate::mesh::Mesh;
use crate::theme::{Srgba, linear};

/// One piece of a placed part.
#[derive(Clone, Debug, PartialEq)]
pub struct PartInstance {
    /// The piece's triangles, in the file's units.
    pub mesh: Arc<Mesh>,
    /// Where (file units → world) and in what linear colour.
    pub instance: MeshInstance,
    /// The part's bounding box corners, file units.
    pub bounds: [Vec3; 2],
}

/// A part frame's orientation in single precision (f64 → f32 here, where kinematics data
/// enters the renderer).
pub fn frame_rotation(p: &Placement) -> Quat {
    let q = p.rotation.quaternion();
    Quat::from_xyzw(q.i as f32, q.j as f32, q.k as f32, q.w as f32).normalize()
}

/// A part's frame as a matrix.
pub fn frame_matrix(p: &Placement) -> Mat4 {
    Mat4::from_rotation_translation(
        frame_rotation(p),
        Vec3::new(p.origin.x as f32, p.origin.y as f32, p.origin.z as f32),
    )
}

/// Which of a CAD part's meshes a view draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PartDetail {
    /// The file as read (exports, screenshots, a GPU).
    #[default]
    File,
    /// Its stand-in of at most [`crate::appearance::simplify::PREVIEW_TRIANGLES`] (a view on a
    /// software rasteriser).
    Preview,
    /// Its lighter stand-in of at most [`crate::appearance::simplify::MOVING_TRIANGLES`] (such a
    /// view while it moves).
    Moving,
}

impl DrawList {
    /// Place every part `parts` has a mesh for.
    pub(crate) fn appearance_parts(
        &mut self,
        frame: &SceneFrame,
        colours: &LegColours,
        parts: &PartSet,
        detail: PartDetail,
    ) {
        if parts.is_empty() {
            return;
        }
        let theme = colours.theme;
        if let Some(p) = parts.get(Part::Base) {
            self.place(p, detail, Mat4::IDENTITY, theme.base_plate, false);
        }
        if let Some(p) = parts.get(Part::Platform) {
            self.place(
                p,
                detail,
                frame_matrix(&frame.platform_placement()),
                theme.platform,
                false,
            );
        }
        for (k, leg) in frame.legs.iter().enumerate() {
            let (body, rod) = colours.of(k, leg.status);
            let warn = leg.status != LegStatus::Normal;
            if frame.servos.is_none()
                && let Some(p) = parts.get(Part::Cylinder)
            {
                let [at, _] = frame.leg_placements(k);
                self.place(
                    p,
                    detail,
                    frame_matrix(&at),
                    body,
                    warn && !colours.coloured,
                );
            }
            if let Some(p) = parts.get(Part::Rod) {
                self.place(p, detail, frame_matrix(&frame.rod_placement(k)), rod, warn);
            }
            if let (Some(p), Some(at)) = (parts.get(Part::Horn), frame.horn_placement(k)) {
                self.place(
                    p,
                    detail,
                    frame_matrix(&at),
                    colours.horn(k, leg.status),
                    warn,
                );
            }
        }
    }

    /// Each piece of `part` (its mesh of `detail`) at `frame`: in `studio` when `warning`,
    /// else in the table's colour, the file's, or `studio`; always opaque.
    fn place(
        &mut self,
        part: &LoadedPart,
        detail: PartDetail,
        frame: Mat4,
        studio: Srgba,
        warning: bool,
    ) {
        let model = (frame * part.transform).to_cols_array_2d();
        let mesh = match detail {
            PartDetail::File => &part.mesh,
            PartDetail::Preview => &part.preview,
            PartDetail::Moving => &part.moving,
        };
        for piece in mesh.pieces.iter().filter(|p| !p.mesh.indices.is_empty()) {
            let chosen = if warning {
                studio
            } else {
                part.colour_of(piece, studio)
            };
            let [r, g, b, _] = linear(chosen);
            self.parts.push(PartInstance {
                mesh: Arc::clone(&piece.mesh),
                instance: MeshInstance {
                    model,
                    color: [r, g, b, 1.0],
                },
                bounds: part.mesh.bounds,
            });
        }
    }
}
