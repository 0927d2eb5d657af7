//! Every WGSL file in the top-level `shaders/` is part of a module the renderer builds; each module
//! parses and validates with naga; and the Rust mirror of the shared uniforms has the
//! size naga's layout gives the WGSL struct.

use naga::Module;

fn parse(name: &str, source: &str) -> Module {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{name}: {e:?}"));
    module
}

#[test]
fn every_shader_validates() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shaders");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".wgsl"))
        .collect();
    files.sort();
    let mut used: Vec<&str> = stewart_render::shaders::MODULES
        .iter()
        .flat_map(|(_, parts, _)| parts.iter().copied())
        .collect();
    used.sort();
    used.dedup();
    assert_eq!(
        files, used,
        "every shader file must be compiled in, and only those"
    );
    for (name, _, source) in stewart_render::shaders::MODULES {
        let module = parse(name, source);
        for entry in ["vs_main", "fs_main"] {
            assert!(
                module.entry_points.iter().any(|e| e.name == entry),
                "{name}: no {entry}"
            );
        }
    }
}

/// Size and alignment naga's layouter gives the type of the global variable `name`.
fn uniform_layout(module: &Module, name: &str) -> (u32, u32) {
    let mut layouter = naga::proc::Layouter::default();
    layouter
        .update(module.to_ctx())
        .unwrap_or_else(|e| panic!("{e:?}"));
    let (_, var) = module
        .global_variables
        .iter()
        .find(|(_, v)| v.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no global `{name}`"));
    let layout = layouter[var.ty];
    (layout.size, layout.alignment.round_up(1))
}

#[test]
fn the_rust_globals_mirror_the_wgsl_struct() {
    use stewart_render::gpu_types::Globals;
    for (name, _, source) in stewart_render::shaders::MODULES {
        let module = parse(name, source);
        let (size, align) = uniform_layout(&module, "globals");
        assert_eq!(size as usize, size_of::<Globals>(), "{name}: size");
        // A uniform buffer's struct must be 16-byte aligned; the Rust struct is made of
        // vec4 and mat4 columns only, so its fields fall where WGSL puts them.
        assert_eq!(align, 16, "{name}: alignment");
    }
}
