//! A scenario's `[appearance]` table read: each part's mesh file loaded (paths relative to
//! the scenario file's folder) and placed in its part's frame by the table's scale,
//! rotation and offset.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{EulerRot, Mat4, Quat, Vec3};
use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::model::appearance::{AppearanceSettings, MeshScale, Part, PartLook};
use thiserror::Error;

use super::{PartFileError, PartMesh};

/// One part's mesh, ready to place.
#[derive(Clone, Debug)]
pub struct LoadedPart {
    /// The file as read.
    pub mesh: Arc<PartMesh>,
    /// A stand-in of at most [`super::simplify::PREVIEW_TRIANGLES`] triangles (the same
    /// mesh when it has no more), for views a software rasteriser draws.
    pub preview: Arc<PartMesh>,
    /// A lighter one, at most [`super::simplify::MOVING_TRIANGLES`] (the preview when it
    /// has no more), for such views while they move.
    pub moving: Arc<PartMesh>,
    /// From the file's units and axes into the part's frame: offset · rotation · scale.
    pub transform: Mat4,
    /// The table's colour (sRGB, alpha), which wins over the file's.
    pub colour: Option<[f32; 4]>,
    /// The file's path as read.
    pub path: PathBuf,
}

/// The meshes of every part that has one.
#[derive(Clone, Debug, Default)]
pub struct PartSet {
    parts: [Option<LoadedPart>; 5],
}

/// Why a part's mesh was refused: the table key and file at fault, and the reason.
#[derive(Debug, Error)]
#[error("`appearance.{part}.{key}` ({file}): {fault}")]
pub struct PartError {
    /// The part.
    pub part: Part,
    /// The key at fault: `file` or `scale`.
    pub key: &'static str,
    /// The file as the table names it.
    pub file: String,
    /// What is wrong.
    pub fault: PartFault,
}

/// What is wrong with a part's mesh.
#[derive(Debug, Error)]
pub enum PartFault {
    /// The file could not be read as a mesh.
    #[error(transparent)]
    Cad(#[from] PartFileError),
    /// At its scale the part is absurdly large or small against the platform.
    #[error(
        "at scale `{scale}` the part is {size_m:.3e} m across, against a platform of {platform_m:.3} m: {hint}"
    )]
    Scale {
        /// The scale as written.
        scale: String,
        /// The part's size at that scale, metres.
        size_m: f64,
        /// The platform's size, metres.
        platform_m: f64,
        /// What scale would fit.
        hint: String,
    },
}

/// The largest and smallest part against the platform's size.
const SIZE_RATIO: (f64, f64) = (1e-3, 50.0);

fn slot(part: Part) -> usize {
    Part::ALL.iter().position(|&p| p == part).unwrap_or(0)
}

impl PartSet {
    /// No part has a mesh.
    pub fn none() -> Self {
        Self::default()
    }

    /// Read the meshes `appearance` names for a platform of actuator `kind` and size
    /// `platform_m` (the larger plate radius), files relative to `folder`; the first part
    /// that fails is the error. Meshes of `previous` read from the same path are kept
    /// rather than read again (a slider moving a part's offset does not reread its
    /// file); with `previews`, heavy parts get their stand-ins for software rasterisers.
    pub fn load(
        appearance: &AppearanceSettings,
        folder: &Path,
        kind: ActuatorKind,
        platform_m: f64,
        previous: Option<&PartSet>,
        previews: bool,
    ) -> Result<PartSet, PartError> {
        let (set, mut errors) =
            Self::read(appearance, folder, kind, platform_m, previous, previews);
        match errors.is_empty() {
            true => Ok(set),
            false => Err(errors.swap_remove(0)),
        }
    }

    /// [`PartSet::load`] part by part: the parts that read, and why each other failed.
    pub fn read(
        appearance: &AppearanceSettings,
        folder: &Path,
        kind: ActuatorKind,
        platform_m: f64,
        previous: Option<&PartSet>,
        previews: bool,
    ) -> (PartSet, Vec<PartError>) {
        let mut set = PartSet::default();
        let mut errors = Vec::new();
        for (part, look) in appearance.parts().filter(|(p, _)| p.applies_to(kind)) {
            match read_part(part, look, folder, platform_m, previous, previews) {
                Ok(loaded) => set.parts[slot(part)] = Some(loaded),
                Err(e) => errors.push(e),
            }
        }
        (set, errors)
    }

    /// The mesh of `part`, if it has one.
    pub fn get(&self, part: Part) -> Option<&LoadedPart> {
        self.parts[slot(part)].as_ref()
    }

    /// Every file the parts were read from: each part's, and the files its reading opened
    /// beside it (material and buffer files).
    pub fn files(&self) -> Vec<PathBuf> {
        self.parts
            .iter()
            .flatten()
            .flat_map(|p| std::iter::once(p.path.clone()).chain(p.mesh.sidecars.iter().cloned()))
            .collect()
    }

    /// Whether no part has a mesh.
    pub fn is_empty(&self) -> bool {
        self.parts.iter().all(Option::is_none)
    }

    /// How many triangles the parts hold (each counted once, however often drawn).
    pub fn triangles(&self) -> usize {
        self.parts.iter().flatten().map(|p| p.mesh.triangles).sum()
    }
}

/// A platform's size for judging parts: the farthest joint from the z axis, metres.
pub fn platform_size(g: &stewart_kinematics::model::geometry::Geometry) -> f64 {
    g.base_joints()
        .iter()
        .chain(g.platform_joints())
        .map(|p| p.xy().norm())
        .fold(0.0, f64::max)
}

/// One part's mesh read (or kept from `previous`) and judged against the platform.
fn read_part(
    part: Part,
    look: &PartLook,
    folder: &Path,
    platform_m: f64,
    previous: Option<&PartSet>,
    previews: bool,
) -> Result<LoadedPart, PartError> {
    let path = folder.join(&look.file);
    let error = |key, fault| PartError {
        part,
        key,
        file: look.file.clone(),
        fault,
    };
    let kept = previous
        .and_then(|p| p.get(part))
        .filter(|p| p.path == path)
        .map(|p| {
            (
                Arc::clone(&p.mesh),
                Arc::clone(&p.preview),
                Arc::clone(&p.moving),
            )
        });
    let (mesh, preview, moving) = match kept {
        Some(all) => all,
        None => {
            let mesh = Arc::new(super::load(&path).map_err(|e| error("file", e.into()))?);
            let lighter = |from: &Arc<PartMesh>, budget| {
                previews
                    .then(|| super::simplify::simplified(from, budget))
                    .flatten()
                    .map_or_else(|| Arc::clone(from), Arc::new)
            };
            let preview = lighter(&mesh, super::simplify::PREVIEW_TRIANGLES);
            let moving = lighter(&preview, super::simplify::MOVING_TRIANGLES);
            (mesh, preview, moving)
        }
    };
    check_size(&mesh, look.scale, platform_m).map_err(|f| error("scale", f))?;
    Ok(LoadedPart {
        transform: transform(look),
        colour: look.colour.map(|c| c.rgba()),
        mesh,
        preview,
        moving,
        path,
    })
}

impl LoadedPart {
    /// The colour `piece` of this part is drawn in: the table's, else the file's, else
    /// `studio`'s.
    pub fn colour_of(&self, piece: &super::Piece, studio: [f32; 4]) -> [f32; 4] {
        self.colour.or(piece.colour).unwrap_or(studio)
    }
}

/// The table's placement of a file in its part's frame: offset · Rz · Ry · Rx · scale.
pub fn transform(look: &PartLook) -> Mat4 {
    let [rx, ry, rz] = look.rotation_deg.map(|d| (d as f32).to_radians());
    Mat4::from_scale_rotation_translation(
        Vec3::splat(look.scale.metres() as f32),
        Quat::from_euler(EulerRot::ZYX, rz, ry, rx),
        Vec3::from_array(look.offset_m.map(|v| v as f32)),
    )
}

/// The unit (mm, cm, m, in) that makes `mesh` nearest the platform's size `platform_m`
/// (for a file whose unit nobody said).
pub fn likely_unit(mesh: &PartMesh, platform_m: f64) -> MeshScale {
    let size = f64::from(mesh.size());
    [
        MeshScale::Millimetre,
        MeshScale::Centimetre,
        MeshScale::Metre,
        MeshScale::Inch,
    ]
    .into_iter()
    .min_by(|a, b| {
        let off = |s: &MeshScale| (size * s.metres() / platform_m).ln().abs();
        off(a).total_cmp(&off(b))
    })
    .unwrap_or(MeshScale::Metre)
}

/// Refuse a scale that makes the part more than 50 times the platform's size or less
/// than a thousandth of it, naming the unit that would fit.
fn check_size(mesh: &PartMesh, scale: MeshScale, platform_m: f64) -> Result<(), PartFault> {
    let size = f64::from(mesh.size());
    let size_m = size * scale.metres();
    let ratio = size_m / platform_m;
    if !platform_m.is_finite()
        || platform_m <= 0.0
        || (SIZE_RATIO.0..=SIZE_RATIO.1).contains(&ratio)
    {
        return Ok(());
    }
    let best = likely_unit(mesh, platform_m);
    let hint = if (SIZE_RATIO.0..=SIZE_RATIO.1).contains(&(size * best.metres() / platform_m)) {
        format!(
            "is the file in {}? (`scale = \"{}\"`)",
            match best {
                MeshScale::Millimetre => "millimetres",
                MeshScale::Centimetre => "centimetres",
                MeshScale::Inch => "inches",
                _ => "metres",
            },
            best.word()
        )
    } else {
        "give the metres per file unit as the scale".to_owned()
    };
    Err(PartFault::Scale {
        scale: scale.word(),
        size_m,
        platform_m,
        hint,
    })
}
