//! The workspace surface as a PLY file (binary, little-endian): vertices as `float x, y,
//! z` in metres, faces as triangles (`uchar` count, `int` indices), with the platform
//! name, orientation and enclosed volume in comments. MeshLab, Blender and ParaView read it.

use std::fmt::Write as _;

use stewart_kinematics::analysis::workspace::WorkspaceSurface;

/// What the file says about where the surface comes from.
pub(crate) struct PlyHeader<'a> {
    /// The scenario's name.
    pub(crate) name: &'a str,
    /// Roll, pitch, yaw, degrees.
    pub(crate) orientation_deg: [f64; 3],
    /// The workspace's volume and its error bound, m³.
    pub(crate) volume: [f64; 2],
    /// Columns a side.
    pub(crate) resolution: usize,
}

/// The file's bytes.
pub(crate) fn ply(surface: &WorkspaceSurface, header: &PlyHeader) -> Vec<u8> {
    let mut text = String::from("ply\nformat binary_little_endian 1.0\n");
    let [r, p, y] = header.orientation_deg;
    // Writing to a String cannot fail. Comments stay on one line each.
    let name: String = header.name.chars().filter(|c| !c.is_control()).collect();
    let _ = writeln!(text, "comment stewart workspace surface of {name}");
    let _ = writeln!(
        text,
        "comment orientation roll {r} pitch {p} yaw {y} degrees; metres"
    );
    let _ = writeln!(
        text,
        "comment volume {:.9} m3 +- {:.9} m3 on {} x {} columns; enclosed by this mesh {:.9} m3",
        header.volume[0],
        header.volume[1],
        header.resolution,
        header.resolution,
        surface.enclosed_volume()
    );
    let _ = writeln!(text, "element vertex {}", surface.positions.len());
    text.push_str("property float x\nproperty float y\nproperty float z\n");
    let _ = writeln!(text, "element face {}", surface.triangles.len());
    text.push_str("property list uchar int vertex_indices\nend_header\n");
    let mut bytes = text.into_bytes();
    bytes.reserve(surface.positions.len() * 12 + surface.triangles.len() * 13);
    for p in &surface.positions {
        for v in p {
            bytes.extend_from_slice(&(*v as f32).to_le_bytes());
        }
    }
    for t in &surface.triangles {
        bytes.push(3);
        for &i in t {
            // Indices fit: a surface has at most a few million vertices.
            bytes.extend_from_slice(&(i as i32).to_le_bytes());
        }
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::analysis::workspace;
    use stewart_kinematics::{Angle, Scenario, model::limits::Limits};

    /// Read back what [`ply`] writes: header lines, vertices, triangles.
    fn read(bytes: &[u8]) -> (Vec<String>, Vec<[f32; 3]>, Vec<[i32; 3]>) {
        // The header ends at the line `end_header` (a comment may mention the words).
        let end = b"\nend_header\n";
        let at = bytes
            .windows(end.len())
            .position(|w| w == end)
            .unwrap_or_else(|| panic!("no end_header"))
            + end.len();
        let header: Vec<String> = String::from_utf8_lossy(&bytes[..at])
            .lines()
            .map(str::to_owned)
            .collect();
        let count = |what: &str| -> usize {
            header
                .iter()
                .find_map(|l| l.strip_prefix(&format!("element {what} ")))
                .and_then(|n| n.parse().ok())
                .unwrap_or_else(|| panic!("no {what} count"))
        };
        let (nv, nf) = (count("vertex"), count("face"));
        let mut body = &bytes[at..];
        let mut f32s = |n: usize| -> Vec<f32> {
            let v = body[..4 * n]
                .chunks(4)
                .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect();
            body = &body[4 * n..];
            v
        };
        let vertices: Vec<[f32; 3]> = f32s(3 * nv).chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        let mut faces = Vec::new();
        for _ in 0..nf {
            assert_eq!(body[0], 3);
            let i = |k: usize| {
                i32::from_le_bytes([
                    body[1 + 4 * k],
                    body[2 + 4 * k],
                    body[3 + 4 * k],
                    body[4 + 4 * k],
                ])
            };
            faces.push([i(0), i(1), i(2)]);
            body = &body[13..];
        }
        assert!(body.is_empty(), "{} bytes left over", body.len());
        (header, vertices, faces)
    }

    #[test]
    fn the_file_reads_back_to_the_same_mesh_and_volume() {
        let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let ws = workspace::constant_orientation_workspace(
            &s.geometry,
            &Limits::default(),
            [Angle::ZERO; 3],
            48,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let surface = WorkspaceSurface::from_workspace(&ws);
        let bytes = ply(
            &surface,
            &PlyHeader {
                name: "paired\nend_header",
                orientation_deg: [0.0; 3],
                volume: [ws.volume, ws.volume_error],
                resolution: 48,
            },
        );
        let (header, vertices, faces) = read(&bytes);
        assert_eq!(header[0], "ply");
        assert_eq!(header[1], "format binary_little_endian 1.0");
        // A name cannot end the header early: it stays on its comment line.
        assert_eq!(
            header.iter().filter(|l| l.as_str() == "end_header").count(),
            1
        );
        assert!(
            header
                .iter()
                .any(|l| l == "comment stewart workspace surface of pairedend_header")
        );
        assert_eq!(vertices.len(), surface.positions.len());
        assert_eq!(faces.len(), surface.triangles.len());
        for (v, p) in vertices.iter().zip(&surface.positions) {
            for k in 0..3 {
                assert!((f64::from(v[k]) - p[k]).abs() < 1e-6);
            }
        }
        // The volume the file's own mesh encloses (f32 coordinates) is the surface's.
        let p = |i: i32| nalgebra::Vector3::from(vertices[i as usize].map(f64::from));
        let v: f64 = faces
            .iter()
            .map(|f| p(f[0]).dot(&p(f[1]).cross(&p(f[2]))))
            .sum::<f64>()
            / 6.0;
        assert!(
            (v - surface.enclosed_volume()).abs() < 1e-6 * ws.volume,
            "{v}"
        );
        assert!(header.iter().any(|l| l.starts_with("comment volume ")));
    }
}
