//! The WGSL sources, from the repository's top-level `shaders/` folder (the one place every
//! WGSL file lives; this module is the only reader). `globals.wgsl` (the uniforms
//! every pipeline reads) is written once and prepended to each pipeline's module.

/// Lit instanced meshes (the opaque and the translucent pipelines), globals included.
pub const MESH: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/mesh.wgsl")
);
/// Unlit lines, globals included.
pub const LINES: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/lines.wgsl")
);

/// Screen-space text and boxes from the glyph atlas, globals included.
pub const TEXT: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/text.wgsl")
);

/// Translucent analysis meshes with a colour per vertex (workspace surface, conditioning
/// slice), globals included.
pub const ANALYSIS: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/analysis.wgsl")
);

/// The view's background as one flat triangle, globals included.
pub const BACKGROUND: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/background.wgsl")
);

/// A picture rendered off screen drawn over the viewport, globals included (bound, not
/// read).
pub const BLIT: &str = concat!(
    include_str!("../../../shaders/globals.wgsl"),
    include_str!("../../../shaders/blit.wgsl")
);

/// Every pipeline's module with the shader files it is made of, for validation.
pub const MODULES: [(&str, &[&str], &str); 6] = [
    (
        "background",
        &["globals.wgsl", "background.wgsl"],
        BACKGROUND,
    ),
    ("blit", &["globals.wgsl", "blit.wgsl"], BLIT),
    ("mesh", &["globals.wgsl", "mesh.wgsl"], MESH),
    ("analysis", &["globals.wgsl", "analysis.wgsl"], ANALYSIS),
    ("lines", &["globals.wgsl", "lines.wgsl"], LINES),
    ("text", &["globals.wgsl", "text.wgsl"], TEXT),
];
