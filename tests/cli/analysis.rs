//! `stewart workspace` and `stewart forces`.

use crate::{parse_csv, stderr, stdout, stewart, tempdir};

/// The number after `label` in `text`.
fn number_after(text: &str, label: &str) -> f64 {
    let rest = text
        .split(label)
        .nth(1)
        .unwrap_or_else(|| panic!("no `{label}` in {text}"));
    rest.split_whitespace()
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("no number after `{label}`"))
}

#[test]
fn workspace_reports_volume_extent_ranges_and_writes_points() {
    let dir = tempdir();
    let ply = dir.path().join("ws.ply");
    let o = stewart(&[
        "workspace",
        "--preset",
        "circle",
        "--resolution",
        "100",
        "--out",
        &ply.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let volume = number_after(&text, "volume ");
    let error = number_after(&text, "± ");
    assert!(volume > 0.3 && volume < 0.45, "{text}");
    assert!(error < 0.01 * volume, "{text}");
    assert!(text.contains("extent x "), "{text}");
    for axis in ["roll ", "pitch", "yaw  "] {
        assert!(text.contains(&format!("  {axis} -")), "{text}");
    }
    let ply_text = std::fs::read_to_string(&ply).unwrap_or_default();
    let count: usize = ply_text
        .lines()
        .find_map(|l| l.strip_prefix("element vertex "))
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let body: Vec<&str> = ply_text
        .split("end_header\n")
        .nth(1)
        .unwrap_or("")
        .lines()
        .collect();
    assert!(
        count > 1000 && body.len() == count,
        "{count} vs {}",
        body.len()
    );
    // CSV too, and a tilted orientation shrinks the volume.
    let csv = dir.path().join("ws.csv");
    let o = stewart(&[
        "workspace",
        "--preset",
        "circle",
        "--resolution",
        "100",
        "--orientation",
        "10,-5,20",
        "--out",
        &csv.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(number_after(&stdout(&o), "volume ") < volume);
    let (header, rows) = parse_csv(&std::fs::read_to_string(&csv).unwrap_or_default());
    assert_eq!(header, ["x", "y", "z"]);
    assert!(rows.iter().all(|r| r[2] > 0.0));
}

#[test]
fn workspace_refuses_what_it_cannot_compute() {
    let dir = tempdir();
    let o = stewart(&["workspace", "--preset", "circle", "--orientation", "1,2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("not three comma-separated numbers"),
        "{}",
        stderr(&o)
    );
    let o = stewart(&[
        "workspace",
        "--preset",
        "circle",
        "--orientation",
        "1,nan,2",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let o = stewart(&[
        "workspace",
        "--preset",
        "circle",
        "--out",
        &dir.path().join("ws.txt").display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("must end in .csv or .ply"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.path().join("ws.txt").exists());
    let s = dir.path().join("nostroke.toml");
    std::fs::write(&s, "[geometry]\nbase_radius = 1.0\nplatform_radius = 0.6\nhome_height = 0.8\nbase_angles_deg = [10, 110, 130, 230, 250, 350]\nplatform_angles_deg = [50, 70, 170, 190, 290, 310]\n").unwrap_or_default();
    let o = stewart(&["workspace", "--scenario", &s.display().to_string()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("needs both stroke limits"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn forces_carry_the_payload() {
    let o = stewart(&["forces", "--preset", "paired"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(header.len(), 13);
    assert_eq!(header[1], "F1_static");
    assert_eq!(header[12], "F6");
    assert_eq!(rows.len(), 1001);
    // 60 kg on legs leaning ~45°: every leg in compression, each well under the full weight·2.
    for r in &rows {
        assert!(
            r[1..].iter().all(|&f| f > 0.0 && f < 2.0 * 60.0 * 9.81),
            "{r:?}"
        );
    }
    // A heavier payload from the command line scales the static forces exactly.
    let heavy = stewart(&["forces", "--preset", "paired", "--mass", "120"]);
    let (_, heavy) = parse_csv(&stdout(&heavy));
    for (a, b) in rows.iter().zip(&heavy) {
        for c in 1..7 {
            assert!((b[c] - 2.0 * a[c]).abs() < 1e-9 * b[c].abs().max(1.0));
        }
    }
    let o = stewart(&["forces", "--preset", "circle"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no [payload] table"), "{}", stderr(&o));
    let o = stewart(&["forces", "--preset", "seed", "--mass", "10"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("architecturally singular"),
        "{}",
        stderr(&o)
    );
    let o = stewart(&["forces", "--preset", "paired", "--mass", "-3"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("the mass must be more than 0 and at most 1e6 kg, got -3"),
        "{}",
        stderr(&o)
    );
    // Moments no rigid body has (5 > 1 + 1) are refused, and said why.
    let o = stewart(&[
        "forces",
        "--preset",
        "paired",
        "--mass",
        "10",
        "--inertia",
        "1,1,5",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("each principal moment at most the sum of the other two"),
        "{}",
        stderr(&o)
    );
    assert!(o.stdout.is_empty());
}

#[test]
fn workspace_plot_draws_two_slices_coloured_by_conditioning() {
    let dir = tempdir();
    let svg = dir.path().join("ws.svg");
    let o = stewart(&[
        "workspace",
        "--preset",
        "paired",
        "--resolution",
        "100",
        "--plot",
        &svg.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    assert_eq!(text.matches(r#"class="boundary""#).count(), 2, "two slices");
    assert_eq!(text.matches(r#"class="centre""#).count(), 2);
    assert!(text.contains("Horizontal slice at z = 0.800 m"));
    assert!(text.contains("Vertical slice at y = 0.000 m"));
    assert!(text.contains("condition number") && text.contains("x (m)"));
    assert!(!text.contains("<image"), "cells are vector rectangles");
    assert!(text.matches("<rect").count() > 100, "coloured cells");
    // In Chinese, as a PDF that renders.
    let pdf = dir.path().join("ws.pdf");
    let o = stewart(&[
        "workspace",
        "--preset",
        "paired",
        "--resolution",
        "100",
        "--lang",
        "zh",
        "--plot",
        &pdf.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r = std::process::Command::new("pdftotext")
        .args(["-q"])
        .arg(&pdf)
        .arg("-")
        .output()
        .unwrap_or_else(|e| panic!("pdftotext: {e}"));
    let words = String::from_utf8_lossy(&r.stdout).replace(char::is_whitespace, "");
    assert!(
        words.contains("水平截面") && words.contains("条件数"),
        "{words}"
    );
}

#[test]
fn workspace_plot_refuses_a_bad_file_before_computing() {
    let dir = tempdir();
    let bad = dir.path().join("ws.txt");
    let o = stewart(&["workspace", "--plot", &bad.display().to_string()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("must end in .svg, .pdf or .png"));
    assert!(!bad.exists());
    refuses_an_empty_workspace("--plot", &dir.path().join("empty.svg"), "nothing to plot");
}

/// Nothing reachable (the paired platform rolled 80°): one error naming it, exit 2,
/// nothing written to `file` given with `flag`.
fn refuses_an_empty_workspace(flag: &str, file: &std::path::Path, message: &str) {
    let o = stewart(&[
        "workspace",
        "--preset",
        "paired",
        "--orientation",
        "80,0,0",
        "--resolution",
        "50",
        flag,
        &file.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains(message), "{}", stderr(&o));
    assert!(!file.exists());
}

#[test]
fn workspace_surface_is_a_closed_ply_mesh_enclosing_the_volume() {
    let dir = tempdir();
    let ply = dir.path().join("ws.ply");
    let o = stewart(&[
        "workspace",
        "--preset",
        "seed",
        "--resolution",
        "120",
        "--surface",
        &ply.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let volume = number_after(&out, "volume");
    let bound = number_after(&out, "m³ ±");
    let enclosing = number_after(&out, "enclosing");
    // The mesh's enclosed volume agrees with the column sum within twice its bound (its
    // own bound, from the half-resolution mesh, is of the same size).
    assert!((enclosing - volume).abs() <= 2.0 * bound + 1e-6, "{out}");
    let bytes = std::fs::read(&ply).unwrap_or_default();
    let end = b"\nend_header\n";
    let at = bytes
        .windows(end.len())
        .position(|w| w == end)
        .unwrap_or_else(|| panic!("no header end"))
        + end.len();
    let header = String::from_utf8_lossy(&bytes[..at]).into_owned();
    assert!(header.starts_with("ply\nformat binary_little_endian 1.0\n"));
    let count = |what: &str| -> usize {
        header
            .lines()
            .find_map(|l| l.strip_prefix(&format!("element {what} ")))
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("no {what} count in {header}"))
    };
    let (vertices, faces) = (count("vertex"), count("face"));
    assert!(out.contains(&format!("Wrote the surface ({faces} triangles")));
    // float x, y, z per vertex; a count byte and three ints per face; nothing more.
    assert_eq!(bytes.len() - at, 12 * vertices + 13 * faces);
    // Every face is a triangle of valid indices.
    for f in bytes[at + 12 * vertices..].chunks(13) {
        assert_eq!(f[0], 3);
        for k in 0..3 {
            let i = i32::from_le_bytes([f[1 + 4 * k], f[2 + 4 * k], f[3 + 4 * k], f[4 + 4 * k]]);
            assert!(i >= 0 && (i as usize) < vertices);
        }
    }
}

#[test]
fn workspace_surface_refuses_a_bad_file_and_an_empty_workspace() {
    let dir = tempdir();
    let stl = dir.path().join("ws.stl");
    let o = stewart(&["workspace", "--surface", &stl.display().to_string()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("must end in .ply"), "{}", stderr(&o));
    assert!(!stl.exists());
    refuses_an_empty_workspace(
        "--surface",
        &dir.path().join("empty.ply"),
        "no surface to write",
    );
}
