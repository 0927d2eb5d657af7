//! CAD parts: mesh files read into triangle meshes the renderer draws in place of a
//! body's usual drawing (`[appearance]` in a scenario file).
//!
//! - [`load`]: one file — STL (binary or ASCII, read here: see `stl.rs`), OBJ with its MTL colours
//!   (`tobj`), glTF 2.0 / GLB (`gltf`: meshes under the default scene with their node
//!   transforms, base-colour materials) — into a [`PartMesh`], its pieces one colour each;
//! - [`parts`]: the scenario's table read into a [`parts::PartSet`] (paths relative to the
//!   scenario file, each part's scale checked against the platform's size);
//! - [`simplify`]: a lighter stand-in for a heavy part, for views a software rasteriser
//!   draws.
//!
//! Files without normals get flat ones (each triangle its own), as glTF prescribes. Every
//! fault is a [`PartFileError`] naming the file and, where the format has them, the line,
//! facet or byte.

mod gltf_file;
mod normals;
mod obj;
pub mod parts;
pub mod simplify;
mod stl;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::Vec3;
use stewart_kinematics::io::file::{FileError, FileKind};
use thiserror::Error;

use crate::mesh::Mesh;

/// One colour's share of a part: a mesh in the file's units and its colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// Its triangles, in the file's units and axes (node transforms applied).
    pub mesh: Arc<Mesh>,
    /// The file's colour for it (sRGB, alpha), when the file gives one.
    pub colour: Option<[f32; 4]>,
}

/// A mesh file read: its pieces and their extent.
#[derive(Clone, Debug, PartialEq)]
pub struct PartMesh {
    /// The pieces, in file order.
    pub pieces: Vec<Piece>,
    /// How many triangles in all.
    pub triangles: usize,
    /// The smallest and largest corner of its bounding box, file units.
    pub bounds: [Vec3; 2],
    /// The other files its reading opened or tried (an OBJ's material files, a glTF's
    /// buffer files): inputs a command may not write over.
    pub sidecars: Vec<PathBuf>,
}

impl PartMesh {
    /// The bounding box's diagonal, file units.
    pub fn size(&self) -> f32 {
        (self.bounds[1] - self.bounds[0]).length()
    }

    /// Gather `pieces` (none empty) and check that there is something finite to draw.
    fn new(path: &Path, pieces: Vec<Piece>) -> Result<PartMesh, PartFileError> {
        let pieces: Vec<Piece> = pieces
            .into_iter()
            .filter(|p| !p.mesh.indices.is_empty())
            .collect();
        let triangles = pieces.iter().map(|p| p.mesh.indices.len() / 3).sum();
        if triangles == 0 {
            return Err(PartFileError::Empty {
                path: path.to_owned(),
            });
        }
        let mut bounds = [Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)];
        for v in pieces.iter().flat_map(|p| &p.mesh.vertices) {
            let p = Vec3::from_array(v.position);
            bounds = [bounds[0].min(p), bounds[1].max(p)];
        }
        Ok(PartMesh {
            pieces,
            triangles,
            bounds,
            sidecars: Vec::new(),
        })
    }
}

/// Where in a file a fault is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// A line, from 1.
    Line(usize),
    /// A byte offset from the file's start.
    Byte(u64),
    /// A place in a glTF document: `meshes[2].primitives[0]`, `accessors[5]`.
    Item(String),
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Location::Line(n) => write!(f, "line {n}"),
            Location::Byte(b) => write!(f, "byte {b}"),
            Location::Item(s) => f.write_str(s),
        }
    }
}

/// Why a mesh file could not be read.
#[derive(Debug, Error)]
pub enum PartFileError {
    /// The file could not be opened or read.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        source: std::io::Error,
    },
    /// Not read: not a regular file (a folder, FIFO, device), or larger than a part may be.
    #[error("{reason}")]
    Refused {
        /// The file.
        path: PathBuf,
        /// Why, naming the file.
        reason: String,
    },
    /// Neither its name nor its first bytes say STL, OBJ or glTF.
    #[error("{}: not a mesh file this studio reads (STL, OBJ, glTF or GLB, told by the name's ending)", path.display())]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// The file breaks its format.
    #[error("{}{}: {reason}", path.display(), at.as_ref().map(|a| format!(", {a}")).unwrap_or_default())]
    Malformed {
        /// The file.
        path: PathBuf,
        /// Where, when the format says.
        at: Option<Location>,
        /// What is wrong.
        reason: String,
    },
    /// A vertex coordinate that is NaN or infinite.
    #[error("{}{}: a vertex coordinate is not a finite number ({value})", path.display(), at.as_ref().map(|a| format!(", {a}")).unwrap_or_default())]
    NotFinite {
        /// The file.
        path: PathBuf,
        /// Where.
        at: Option<Location>,
        /// The value.
        value: f32,
    },
    /// The file holds no triangles.
    #[error("{}: holds no triangles to draw", path.display())]
    Empty {
        /// The file.
        path: PathBuf,
    },
}

/// The formats read, told by the file name's ending.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// STL, binary or ASCII.
    Stl,
    /// Wavefront OBJ (with an MTL file for colours).
    Obj,
    /// glTF 2.0: `.gltf` (JSON, buffers beside it or inline) or `.glb`.
    Gltf,
}

impl MeshFormat {
    /// The format of `path`, by its ending (any case).
    pub fn of(path: &Path) -> Option<MeshFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "stl" => Some(MeshFormat::Stl),
            "obj" => Some(MeshFormat::Obj),
            "gltf" | "glb" => Some(MeshFormat::Gltf),
            _ => None,
        }
    }
}

/// Read the mesh file at `path`.
pub fn load(path: &Path) -> Result<PartMesh, PartFileError> {
    let format = MeshFormat::of(path).ok_or_else(|| PartFileError::UnknownFormat {
        path: path.to_owned(),
    })?;
    let bytes =
        stewart_kinematics::io::file::read_file(path, FileKind::Mesh).map_err(|e| match e {
            FileError::Io { cause: source, .. } => PartFileError::Io {
                path: path.to_owned(),
                source,
            },
            refused => PartFileError::Refused {
                path: path.to_owned(),
                reason: refused.to_string(),
            },
        })?;
    let mut sidecars = Vec::new();
    let pieces = match format {
        MeshFormat::Stl => stl::read(path, &bytes)?,
        MeshFormat::Obj => obj::read(path, &bytes, &mut sidecars)?,
        MeshFormat::Gltf => gltf_file::read(path, &bytes, &mut sidecars)?,
    };
    let mut mesh = PartMesh::new(path, pieces)?;
    mesh.sidecars = sidecars;
    Ok(mesh)
}

/// `Err(NotFinite)` at `at` for the first coordinate of `p` that is not finite.
fn finite(
    path: &Path,
    p: [f32; 3],
    at: impl FnOnce() -> Option<Location>,
) -> Result<(), PartFileError> {
    match p.into_iter().find(|v| !v.is_finite()) {
        None => Ok(()),
        Some(value) => Err(PartFileError::NotFinite {
            path: path.to_owned(),
            at: at(),
            value,
        }),
    }
}

#[cfg(test)]
mod tests;
