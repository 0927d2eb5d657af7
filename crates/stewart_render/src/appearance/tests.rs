//! The CAD readers against the shipped example parts (made by
//! `scripts/make-cad-examples.py`, whose numbers these check) and against broken files.

use std::path::{Path, PathBuf};

use glam::Vec3;
use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::model::appearance::{AppearanceSettings, MeshScale, Part, PartLook};

use super::parts::{PartFault, PartSet};
use super::{Location, PartFileError, load};

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/cad")
        .join(name)
}

fn near(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).abs().max_element() <= tol
}

#[test]
fn the_example_parts_read_with_their_sizes_colours_and_frames() {
    // Binary STL in millimetres: the hexagon's corners at 1100 mm, top face at z = 0.
    let base = load(&example("base.stl")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(base.triangles, 1608);
    assert!(
        near(
            base.bounds[1],
            Vec3::new(1100.0 * 0.866_025_4, 1100.0, 0.0),
            0.1
        ),
        "{:?}",
        base.bounds
    );
    assert!((base.bounds[0].z + 40.0).abs() < 1e-3);
    assert_eq!(base.pieces[0].colour, None);
    // ASCII STL: the rod reaches down along -y to -760 mm.
    let rod = load(&example("rod.stl")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(rod.triangles, 512);
    assert!((rod.bounds[0].y + 760.0).abs() < 1e-3 && rod.bounds[1].y.abs() < 1e-3);
    // OBJ with two MTL colours.
    let platform = load(&example("platform.obj")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(platform.triangles, 280);
    let colours: Vec<_> = platform.pieces.iter().map(|p| p.colour).collect();
    assert!(
        colours.contains(&Some([0.85, 0.45, 0.12, 1.0])),
        "{colours:?}"
    );
    assert!(
        colours.contains(&Some([0.2, 0.2, 0.22, 1.0])),
        "{colours:?}"
    );
    // GLB in metres, its base colour turned from linear to sRGB.
    let cylinder = load(&example("cylinder.glb")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(cylinder.triangles, 512);
    assert!((cylinder.bounds[1].y - 0.5).abs() < 1e-6 && cylinder.bounds[0].y.abs() < 1e-6);
    let [r, ..] = cylinder.pieces[0]
        .colour
        .unwrap_or_else(|| panic!("a material"));
    assert!((r - 0.7681).abs() < 2e-3, "{r}"); // linear 0.55 → sRGB 0.768
    // GLB modelled in millimetres under a node scaled by 0.001: metres after the node.
    let horn = load(&example("horn.glb")).unwrap_or_else(|e| panic!("{e}"));
    assert!((horn.bounds[1].x - 0.025).abs() < 1e-6, "{:?}", horn.bounds);
    assert!(
        (horn.bounds[1].z - 0.0025).abs() < 1e-6,
        "{:?}",
        horn.bounds
    );
    // Every normal is unit length (the file's, or a flat one from the winding).
    for part in [&base, &rod, &platform, &cylinder, &horn] {
        for v in part.pieces.iter().flat_map(|p| &p.mesh.vertices) {
            assert!((Vec3::from(v.normal).length() - 1.0).abs() < 1e-3);
        }
    }
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap_or_else(|e| panic!("{e}"));
    path
}

fn binary_stl(header: &[u8], triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut out = vec![b' '; 80];
    out[..header.len()].copy_from_slice(header);
    out.extend((triangles.len() as u32).to_le_bytes());
    for t in triangles {
        out.extend([0u8; 12]);
        for p in t {
            for c in p {
                out.extend(c.to_le_bytes());
            }
        }
        out.extend([0u8; 2]);
    }
    out
}

fn error(path: &Path) -> String {
    match load(path) {
        Ok(m) => panic!("{} read as {} triangles", path.display(), m.triangles),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_binary_stl_whose_header_says_solid_is_still_binary() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let path = write(
        dir.path(),
        "sw.stl",
        &binary_stl(b"solid SolidWorks export", &[t, t]),
    );
    let mesh = load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(mesh.triangles, 2);
    assert_eq!(mesh.pieces[0].mesh.vertices[0].normal, [0.0, 0.0, 1.0]);
}

#[test]
fn broken_stl_files_are_refused_at_their_byte_or_line() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    // Cut short: the header promises 3 facets.
    let mut cut = binary_stl(b"part", &[t, t, t]);
    cut.truncate(84 + 50 * 2 + 7);
    let e = error(&write(dir.path(), "cut.stl", &cut));
    assert!(
        e.contains("promises 3 facets, 234 bytes in all, but the file has 191"),
        "{e}"
    );
    // NaN in the second facet's third vertex, x: byte 84 + 50 + 12 + 24.
    let mut nan = t;
    nan[2][0] = f32::NAN;
    let e = error(&write(
        dir.path(),
        "nan.stl",
        &binary_stl(b"part", &[t, nan]),
    ));
    assert!(
        e.ends_with("nan.stl, byte 170: a vertex coordinate is not a finite number (NaN)"),
        "{e}"
    );
    // ASCII: a vertex with two numbers, and a file that stops inside a facet.
    let ascii = "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0\n  vertex 0 1 0\n endloop\nendfacet\nendsolid x\n";
    let e = error(&write(dir.path(), "a.stl", ascii.as_bytes()));
    assert!(
        e.contains("a.stl, line 5: expected `vertex x y z` with three numbers, found `vertex 1 0`"),
        "{e}"
    );
    let cut = ascii.find("  vertex 1").unwrap_or(0);
    let e = error(&write(dir.path(), "b.stl", &ascii.as_bytes()[..cut]));
    assert!(
        e.contains("b.stl, line 4: the file ends where `vertex x y z` should follow"),
        "{e}"
    );
    let e = error(&write(
        dir.path(),
        "c.stl",
        b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 inf\n",
    ));
    assert!(
        e.contains("c.stl, line 4: a vertex coordinate is not a finite number (inf)"),
        "{e}"
    );
    // No triangles: an empty solid, and a binary file of no facets.
    let e = error(&write(dir.path(), "empty.stl", b"solid x\nendsolid x\n"));
    assert!(e.ends_with("empty.stl: holds no triangles to draw"), "{e}");
    let e = error(&write(dir.path(), "none.stl", &binary_stl(b"", &[])));
    assert!(e.ends_with("holds no triangles to draw"), "{e}");
    assert!(error(&write(dir.path(), "tiny.stl", b"abc")).contains("3 bytes: too short"));
}

#[test]
fn broken_obj_and_gltf_files_are_refused_with_their_place() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let e = error(&write(
        dir.path(),
        "f.obj",
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n",
    ));
    assert!(
        e.contains("f.obj, line 5: `9` refers to vertex 9, but 3 are given before this line"),
        "{e}"
    );
    let e = error(&write(
        dir.path(),
        "n.obj",
        b"v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n",
    ));
    assert!(
        e.contains("n.obj, line 2: a vertex coordinate is not a finite number"),
        "{e}"
    );
    let e = error(&write(
        dir.path(),
        "v.obj",
        b"v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n",
    ));
    assert!(
        e.contains("v.obj, line 2: a vertex needs three numbers: `v 1 x 0`"),
        "{e}"
    );
    let e = error(&write(dir.path(), "e.obj", b"# nothing\nv 0 0 0\n"));
    assert!(e.ends_with("e.obj: holds no triangles to draw"), "{e}");
    // A GLB cut in its binary chunk, and a glTF whose JSON breaks.
    let glb = std::fs::read(example("cylinder.glb")).unwrap_or_else(|e| panic!("{e}"));
    let e = error(&write(dir.path(), "cut.glb", &glb[..glb.len() / 2]));
    assert!(
        e.starts_with(&format!(
            "{}: not a valid glTF 2.0 file",
            dir.path().join("cut.glb").display()
        )),
        "{e}"
    );
    let e = error(&write(
        dir.path(),
        "j.gltf",
        b"{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [\n",
    ));
    assert!(
        e.contains("j.gltf: not a valid glTF 2.0 file") && e.contains("line 2"),
        "{e}"
    );
    let e = error(&write(dir.path(), "x.ply", b"ply\n"));
    assert!(e.contains("not a mesh file this studio reads"), "{e}");
    assert!(matches!(
        load(&dir.path().join("missing.stl")),
        Err(PartFileError::Io { .. })
    ));
    assert_eq!(Location::Byte(3).to_string(), "byte 3");
}

#[test]
fn a_part_set_reads_the_table_names_the_key_at_fault_and_keeps_unchanged_files() {
    let folder = example("");
    let mut a = AppearanceSettings {
        base: Some(PartLook {
            scale: MeshScale::Millimetre,
            ..PartLook::new("base.stl")
        }),
        horn: Some(PartLook::new("horn.glb")),
        ..AppearanceSettings::default()
    };
    let set = PartSet::load(&a, &folder, ActuatorKind::Linear, 1.0, None, true)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(set.get(Part::Base).is_some());
    assert!(
        set.get(Part::Horn).is_none(),
        "a linear platform has no horns"
    );
    // Unchanged file: the same mesh, not read again.
    if let Some(b) = a.base.as_mut() {
        b.offset_m = [0.0, 0.0, 0.1];
    }
    let again = PartSet::load(&a, &folder, ActuatorKind::Linear, 1.0, Some(&set), true)
        .unwrap_or_else(|e| panic!("{e}"));
    let mesh = |s: &PartSet| s.get(Part::Base).map(|p| std::sync::Arc::as_ptr(&p.mesh));
    assert_eq!(mesh(&set), mesh(&again));
    // The millimetre file at the default scale (metres): 2.2 km across.
    if let Some(b) = a.base.as_mut() {
        b.scale = MeshScale::Metre;
    }
    let e = PartSet::load(&a, &folder, ActuatorKind::Linear, 1.0, None, true)
        .err()
        .unwrap_or_else(|| panic!("accepted"));
    assert!(matches!(e.fault, PartFault::Scale { .. }));
    let words = e.to_string();
    assert!(
        words.starts_with("`appearance.base.scale` (base.stl): at scale `m` the part is 2."),
        "{words}"
    );
    assert!(
        words.ends_with("is the file in millimetres? (`scale = \"mm\"`)"),
        "{words}"
    );
    if let Some(b) = a.base.as_mut() {
        b.file = "nowhere.stl".into();
    }
    let e = PartSet::load(&a, &folder, ActuatorKind::Linear, 1.0, None, true)
        .err()
        .unwrap_or_else(|| panic!("accepted"));
    assert!(
        e.to_string()
            .starts_with("`appearance.base.file` (nowhere.stl): "),
        "{e}"
    );
}

/// A one-triangle glTF with its buffer inline, `accessors` and `nodes` as given.
fn tiny_gltf(accessors: &str, nodes: &str, scene_nodes: &str) -> String {
    use base64::Engine as _;
    let mut bin = Vec::new();
    for v in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bin.extend(v.to_le_bytes());
    }
    let data = base64::engine::general_purpose::STANDARD.encode(&bin);
    format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":{scene_nodes}}}],"nodes":{nodes},"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],"buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{data}"}}],"bufferViews":[{{"buffer":0,"byteLength":36}}],"accessors":{accessors}}}"#
    )
}

#[test]
fn hostile_gltf_accessors_and_node_trees_are_refused_not_read() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let good = r#"[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]"#;
    let one = r#"[{"mesh":0}]"#;
    let ok = write(
        dir.path(),
        "ok.gltf",
        tiny_gltf(good, one, "[0]").as_bytes(),
    );
    assert_eq!(load(&ok).map(|m| m.triangles).ok(), Some(1));
    for (name, accessors, nodes, roots, says) in [
        (
            "many.gltf",
            r#"[{"bufferView":0,"componentType":5126,"count":4000000000,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]"#,
            one,
            "[0]",
            "accessors[0]: reaches past its buffer view",
        ),
        (
            "vec2.gltf",
            r#"[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC2","min":[0,0],"max":[1,1]}]"#,
            one,
            "[0]",
            "attributes[\"POSITION\"]",
        ),
        (
            "twice.gltf",
            good,
            r#"[{"children":[1]},{"mesh":0}]"#,
            "[0,1]",
            "is reached twice in the scene",
        ),
    ] {
        let e = error(&write(
            dir.path(),
            name,
            tiny_gltf(accessors, nodes, roots).as_bytes(),
        ));
        assert!(e.contains(says), "{name}: {e}");
    }
}

#[test]
fn a_heavy_part_whose_small_piece_vanishes_keeps_no_empty_piece() {
    use crate::appearance::simplify::simplified;
    use crate::mesh::Mesh;
    // A big sphere and a tiny one (a screw) far from it: at the coarse grid the screw
    // falls into one cell.
    let big = Mesh::sphere();
    let mut tiny = Mesh::sphere();
    for v in &mut tiny.vertices {
        v.position = (Vec3::from(v.position) * 1e-4 + Vec3::new(3.0, 0.0, 0.0)).to_array();
    }
    let part = crate::appearance::PartMesh::new(
        Path::new("x"),
        vec![
            crate::appearance::Piece {
                mesh: std::sync::Arc::new(big),
                colour: None,
            },
            crate::appearance::Piece {
                mesh: std::sync::Arc::new(tiny),
                colour: Some([1.0; 4]),
            },
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let light = simplified(&part, 200).unwrap_or_else(|| panic!("not simplified"));
    assert!(light.pieces.iter().all(|p| !p.mesh.indices.is_empty()));
    assert!(light.triangles <= 200);
}

#[test]
fn a_stride_that_cannot_hold_its_elements_and_files_that_are_not_files_are_refused() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let good = r#"[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]"#;
    let one = r#"[{"mesh":0}]"#;
    // byteStride 5 (and 8, too small for a VEC3 of floats): refused at the view, not a
    // panic inside the reader.
    for stride in [5, 8, 13] {
        let text = tiny_gltf(good, one, "[0]").replace(
            r#""bufferViews":[{"buffer":0,"byteLength":36}]"#,
            &format!(r#""bufferViews":[{{"buffer":0,"byteLength":36,"byteStride":{stride}}}]"#),
        );
        let e = error(&write(
            dir.path(),
            &format!("s{stride}.gltf"),
            text.as_bytes(),
        ));
        assert!(
            e.contains("bufferViews[0]") && e.contains("byteStride"),
            "{stride}: {e}"
        );
    }
    // A view reaching past its buffer.
    let text = tiny_gltf(good, one, "[0]").replace(
        r#""bufferViews":[{"buffer":0,"byteLength":36}]"#,
        r#""bufferViews":[{"buffer":0,"byteOffset":8,"byteLength":36}]"#,
    );
    let e = error(&write(dir.path(), "past.gltf", text.as_bytes()));
    assert!(e.contains("bufferViews[0]"), "{e}");
    #[cfg(unix)]
    {
        // `mtllib /dev/zero`: the material file is refused (the part takes the studio's
        // colours), never read until memory runs out.
        let obj = write(
            dir.path(),
            "zero.obj",
            b"mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        );
        let part = load(&obj).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(part.triangles, 1);
        // A folder or a FIFO named as a part: refused at once, by name.
        let folder = dir.path().join("folder.stl");
        std::fs::create_dir(&folder).unwrap_or_else(|e| panic!("{e}"));
        assert!(error(&folder).contains("is a folder"), "{}", error(&folder));
        let fifo = dir.path().join("pipe.glb");
        if std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|s| s.success())
        {
            assert!(error(&fifo).contains("FIFO"), "{}", error(&fifo));
        }
    }
}

#[test]
fn a_heavy_part_has_a_preview_and_a_lighter_stand_in_for_a_moving_view() {
    use crate::draw_list::PartDetail;
    // A binary STL of 100 000 triangles: a wavy plate of 224 × 224 cells, top and bottom.
    let n = 224usize;
    let mut triangles: Vec<[Vec3; 3]> = Vec::new();
    let at = |i: usize, j: usize, top: bool| {
        let (x, y) = (i as f32 * 4.0 - 448.0, j as f32 * 4.0 - 448.0);
        let z = if top {
            20.0 + 5.0 * (x / 30.0).sin() * (y / 40.0).cos()
        } else {
            0.0
        };
        Vec3::new(x, y, z)
    };
    for top in [true, false] {
        for i in 0..n {
            for j in 0..n {
                let [a, b, c, d] = [
                    at(i, j, top),
                    at(i + 1, j, top),
                    at(i + 1, j + 1, top),
                    at(i, j + 1, top),
                ];
                if top {
                    triangles.extend([[a, b, c], [a, c, d]]);
                } else {
                    triangles.extend([[a, c, b], [a, d, c]]);
                }
            }
        }
    }
    let mut bytes = vec![0u8; 80];
    bytes.extend((triangles.len() as u32).to_le_bytes());
    for t in &triangles {
        let normal = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        for v in std::iter::once(normal).chain(t.iter().copied()) {
            for c in v.to_array() {
                bytes.extend(c.to_le_bytes());
            }
        }
        bytes.extend([0, 0]);
    }
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(dir.path().join("plate.stl"), &bytes).unwrap_or_else(|e| panic!("{e}"));
    let looks = AppearanceSettings {
        platform: Some(PartLook {
            scale: MeshScale::Millimetre,
            ..PartLook::new("plate.stl")
        }),
        ..AppearanceSettings::default()
    };
    let set = PartSet::load(&looks, dir.path(), ActuatorKind::Linear, 1.0, None, true)
        .unwrap_or_else(|e| panic!("{e}"));
    let part = set
        .get(Part::Platform)
        .unwrap_or_else(|| panic!("no platform"));
    assert_eq!(part.mesh.triangles, 2 * 2 * n * n);
    let (preview, moving) = (part.preview.triangles, part.moving.triangles);
    assert!(
        preview <= crate::appearance::simplify::PREVIEW_TRIANGLES,
        "{preview}"
    );
    assert!(
        moving <= crate::appearance::simplify::MOVING_TRIANGLES,
        "{moving}"
    );
    assert!(moving > 1000, "{moving}: nothing left to see");
    // The draw list places the meshes of the detail asked for.
    let scenario = stewart_kinematics::Scenario::seed();
    let frame = scenario
        .geometry
        .scene_frame(&scenario.geometry.home_pose(), Vec::new());
    for (detail, mesh) in [
        (PartDetail::File, &part.mesh),
        (PartDetail::Preview, &part.preview),
        (PartDetail::Moving, &part.moving),
    ] {
        let overlays = crate::Overlays {
            part_detail: detail,
            ..crate::Overlays::default()
        };
        let list = crate::DrawList::build_with_parts(&frame, &crate::Theme::DARK, &overlays, &set);
        let drawn: Vec<_> = list
            .parts
            .iter()
            .map(|p| std::sync::Arc::as_ptr(&p.mesh))
            .collect();
        let wanted: Vec<_> = mesh
            .pieces
            .iter()
            .map(|p| std::sync::Arc::as_ptr(&p.mesh))
            .collect();
        assert_eq!(drawn, wanted, "{detail:?}");
    }
}
