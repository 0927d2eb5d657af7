//! Every WGSL file in `shaders/` parses and validates with naga, and the renderer uses them all.

#[test]
fn every_shader_validates() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".wgsl"))
        .collect();
    files.sort();
    let mut known: Vec<&str> = stewart_render::shaders::ALL
        .iter()
        .map(|(n, _)| *n)
        .collect();
    known.sort();
    assert_eq!(
        files, known,
        "every shader file must be compiled in, and only those"
    );
    for (name, source) in stewart_render::shaders::ALL {
        let module = naga::front::wgsl::parse_str(source)
            .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(source)));
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        assert!(
            module.entry_points.iter().any(|e| e.name == "vs_main"),
            "{name}"
        );
        assert!(
            module.entry_points.iter().any(|e| e.name == "fs_main"),
            "{name}"
        );
    }
}
