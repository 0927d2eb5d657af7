//! Reading a 2-million-triangle CAD part (the issue's bar: under 2 s): a binary STL (the
//! format big CAD exports come in) and the same surface as GLB, from files in a temporary
//! folder, through `stewart_render::appearance::load` (parse, check, flat normals, bounds); and
//! the lighter stand-in made of it for views a software rasteriser draws.

use std::io::Write as _;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};

/// A closed surface (a torus) of `2 · n · m` triangles: grid point (i, j).
fn torus(n: usize, m: usize) -> impl Fn(usize, usize) -> [f32; 3] {
    move |i, j| {
        let (u, v) = (
            (i % n) as f32 / n as f32 * std::f32::consts::TAU,
            (j % m) as f32 / m as f32 * std::f32::consts::TAU,
        );
        let r = 300.0 + 80.0 * v.cos();
        [r * u.cos(), r * u.sin(), 80.0 * v.sin()]
    }
}

fn write_stl(path: &Path, n: usize, m: usize) {
    let p = torus(n, m);
    let mut out =
        std::io::BufWriter::new(std::fs::File::create(path).unwrap_or_else(|e| panic!("{e}")));
    let mut header = [b' '; 80];
    header[..10].copy_from_slice(b"torus 2M t");
    let count = (2 * n * m) as u32;
    let mut bytes = header.to_vec();
    bytes.extend(count.to_le_bytes());
    out.write_all(&bytes).unwrap_or_else(|e| panic!("{e}"));
    for i in 0..n {
        for j in 0..m {
            for t in [
                [p(i, j), p(i + 1, j), p(i + 1, j + 1)],
                [p(i, j), p(i + 1, j + 1), p(i, j + 1)],
            ] {
                let mut facet = [0u8; 50];
                for (k, c) in t.iter().flatten().enumerate() {
                    facet[12 + 4 * k..16 + 4 * k].copy_from_slice(&c.to_le_bytes());
                }
                out.write_all(&facet).unwrap_or_else(|e| panic!("{e}"));
            }
        }
    }
}

fn write_glb(path: &Path, n: usize, m: usize) {
    let p = torus(n, m);
    let mut positions: Vec<u8> = Vec::with_capacity(12 * n * m);
    for i in 0..n {
        for j in 0..m {
            positions.extend(p(i, j).iter().flat_map(|c| c.to_le_bytes()));
        }
    }
    let mut indices: Vec<u8> = Vec::with_capacity(24 * n * m);
    let at = |i: usize, j: usize| ((i % n) * m + (j % m)) as u32;
    for i in 0..n {
        for j in 0..m {
            for k in [
                at(i, j),
                at(i + 1, j),
                at(i + 1, j + 1),
                at(i, j),
                at(i + 1, j + 1),
                at(i, j + 1),
            ] {
                indices.extend(k.to_le_bytes());
            }
        }
    }
    let bin_len = positions.len() + indices.len();
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],"buffers":[{{"byteLength":{bin_len}}}],"bufferViews":[{{"buffer":0,"byteLength":{}}},{{"buffer":0,"byteOffset":{},"byteLength":{}}}],"accessors":[{{"bufferView":0,"componentType":5126,"count":{},"type":"VEC3","min":[-380,-380,-80],"max":[380,380,80]}},{{"bufferView":1,"componentType":5125,"count":{},"type":"SCALAR"}}]}}"#,
        positions.len(),
        positions.len(),
        indices.len(),
        n * m,
        6 * n * m
    );
    let mut json = json.into_bytes();
    while json.len() % 4 != 0 {
        json.push(b' ');
    }
    let total = 12 + 8 + json.len() + 8 + bin_len;
    let mut out = Vec::with_capacity(total);
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(&json);
    out.extend((bin_len as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(&positions);
    out.extend(&indices);
    std::fs::write(path, out).unwrap_or_else(|e| panic!("{e}"));
}

fn bench(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    // 1000 × 1000 grid cells, two triangles each.
    let (n, m) = (1000, 1000);
    let stl = dir.path().join("torus.stl");
    let glb = dir.path().join("torus.glb");
    write_stl(&stl, n, m);
    write_glb(&glb, n, m);
    let mut group = c.benchmark_group("cad_load_2M_triangles");
    group.sample_size(10);
    for (name, path) in [("binary_stl", &stl), ("glb", &glb)] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let part = stewart_render::appearance::load(path).unwrap_or_else(|e| panic!("{e}"));
                assert_eq!(part.triangles, 2 * n * m);
                part
            });
        });
    }
    // The stand-in a software rasteriser draws instead.
    let part = stewart_render::appearance::load(&stl).unwrap_or_else(|e| panic!("{e}"));
    group.bench_function("preview_of_binary_stl", |b| {
        b.iter(|| {
            let preview = stewart_render::appearance::simplify::simplified(
                &part,
                stewart_render::appearance::simplify::PREVIEW_TRIANGLES,
            )
            .unwrap_or_else(|| panic!("not simplified"));
            assert!(preview.triangles <= stewart_render::appearance::simplify::PREVIEW_TRIANGLES);
            preview
        });
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
