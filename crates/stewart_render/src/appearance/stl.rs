//! STL, binary and ASCII. Read here rather than with `stl_io`: that crate takes any file
//! whose 80-byte header begins with `solid ` for ASCII (SolidWorks writes such binary
//! files) and its errors carry no place; this reader tells the two by the binary layout's
//! exact size and names the byte or line of a fault. Facet normals in the file are not
//! used: each triangle's normal comes from its winding (many exporters write zeros).

use std::path::Path;

use glam::Vec3;

use super::normals::FlatMesh;
use super::{Location, PartFileError, Piece, finite};

/// Bytes of a binary STL's header and of one facet.
const HEADER: usize = 84;
const FACET: usize = 50;

/// The pieces of an STL file (one, uncoloured).
pub(super) fn read(path: &Path, bytes: &[u8]) -> Result<Vec<Piece>, PartFileError> {
    let mesh = if is_binary(bytes) {
        binary(path, bytes)?
    } else if bytes.trim_ascii_start().starts_with(b"solid") {
        ascii(path, bytes)?
    } else {
        return Err(malformed(
            path,
            None,
            match bytes.len() {
                n if n < HEADER => {
                    format!(
                        "{n} bytes: too short for a binary STL (84-byte header) and not ASCII STL (`solid …`)"
                    )
                }
                n => format!(
                    "neither ASCII STL (`solid …`) nor binary STL: its header promises {} facets, {} bytes in all, but the file has {n}",
                    facets(bytes),
                    HEADER as u64 + FACET as u64 * facets(bytes) as u64
                ),
            },
        ));
    };
    Ok(vec![Piece {
        mesh: std::sync::Arc::new(mesh),
        colour: None,
    }])
}

/// The facet count a binary header gives.
fn facets(bytes: &[u8]) -> u32 {
    bytes
        .get(80..84)
        .and_then(|b| b.try_into().ok())
        .map_or(0, u32::from_le_bytes)
}

/// Whether `bytes` have the binary layout: a header and exactly as many facets as it
/// says (a binary file whose header begins `solid` is still binary).
fn is_binary(bytes: &[u8]) -> bool {
    bytes.len() >= HEADER
        && bytes.len() as u64 == HEADER as u64 + FACET as u64 * u64::from(facets(bytes))
        && !(bytes.trim_ascii_start().starts_with(b"solid")
            && std::str::from_utf8(bytes).is_ok_and(|t| t.contains("facet")))
}

fn malformed(path: &Path, at: Option<Location>, reason: String) -> PartFileError {
    PartFileError::Malformed {
        path: path.to_owned(),
        at,
        reason,
    }
}

fn binary(path: &Path, bytes: &[u8]) -> Result<crate::mesh::Mesh, PartFileError> {
    let count = facets(bytes) as usize;
    let mut mesh = FlatMesh::with_capacity(count);
    for (k, facet) in bytes[HEADER..].chunks_exact(FACET).enumerate() {
        let mut corners = [Vec3::ZERO; 3];
        for (j, corner) in corners.iter_mut().enumerate() {
            // After the normal's 12 bytes, 12 a vertex.
            let at = 12 + 12 * j;
            let p: [f32; 3] = std::array::from_fn(|c| {
                let o = at + 4 * c;
                f32::from_le_bytes([facet[o], facet[o + 1], facet[o + 2], facet[o + 3]])
            });
            finite(path, p, || {
                Some(Location::Byte((HEADER + k * FACET + at) as u64))
            })?;
            *corner = Vec3::from_array(p);
        }
        mesh.push(corners[0], corners[1], corners[2]);
    }
    Ok(mesh.finish())
}

fn ascii(path: &Path, bytes: &[u8]) -> Result<crate::mesh::Mesh, PartFileError> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        malformed(
            path,
            Some(Location::Byte(e.valid_up_to() as u64)),
            "ASCII STL that is not UTF-8 text (or a binary STL whose size does not match its facet count)".into(),
        )
    })?;
    let mut lines = Lines {
        lines: text
            .lines()
            .enumerate()
            .map(|(n, l)| (n + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty()),
        last: 1,
        path,
    };
    let mut mesh = FlatMesh::default();
    let mut next = |expect: &str| lines.next(expect);
    let (_, first) = next("solid")?;
    debug_assert!(first.starts_with("solid"));
    loop {
        let (n, line) = next("facet or endsolid")?;
        if line.starts_with("endsolid") {
            break;
        }
        let expect = |n: usize, line: &str, word: &str| {
            if line.split_whitespace().collect::<Vec<_>>().join(" ") == word {
                Ok(())
            } else {
                Err(malformed(
                    path,
                    Some(Location::Line(n)),
                    format!("expected `{word}`, found `{line}`"),
                ))
            }
        };
        if !line.starts_with("facet") {
            return Err(malformed(
                path,
                Some(Location::Line(n)),
                format!("expected `facet normal …` or `endsolid`, found `{line}`"),
            ));
        }
        let (n, line) = next("outer loop")?;
        expect(n, line, "outer loop")?;
        let mut corners = [Vec3::ZERO; 3];
        for corner in &mut corners {
            let (n, line) = next("vertex x y z")?;
            let fields: Vec<&str> = line.split_whitespace().collect();
            let numbers: Option<Vec<f32>> = match fields.as_slice() {
                ["vertex", x, y, z] => [x, y, z].iter().map(|t| t.parse().ok()).collect(),
                _ => None,
            };
            let Some(p) = numbers.and_then(|v| <[f32; 3]>::try_from(v).ok()) else {
                return Err(malformed(
                    path,
                    Some(Location::Line(n)),
                    format!("expected `vertex x y z` with three numbers, found `{line}`"),
                ));
            };
            finite(path, p, || Some(Location::Line(n)))?;
            *corner = Vec3::from_array(p);
        }
        let (n, line) = next("endloop")?;
        expect(n, line, "endloop")?;
        let (n, line) = next("endfacet")?;
        expect(n, line, "endfacet")?;
        mesh.push(corners[0], corners[1], corners[2]);
    }
    Ok(mesh.finish())
}

/// An ASCII STL's non-empty lines with their numbers, remembering the last one read.
struct Lines<'a, I> {
    lines: I,
    last: usize,
    path: &'a Path,
}

impl<'a, I: Iterator<Item = (usize, &'a str)>> Lines<'a, I> {
    /// The next line, or an error saying the file ends where `expect` should follow.
    fn next(&mut self, expect: &str) -> Result<(usize, &'a str), PartFileError> {
        match self.lines.next() {
            Some((n, line)) => {
                self.last = n;
                Ok((n, line))
            }
            None => Err(malformed(
                self.path,
                Some(Location::Line(self.last)),
                format!("the file ends where `{expect}` should follow (cut short?)"),
            )),
        }
    }
}
