// The view's background, one triangle over the whole viewport in the theme's colour
// (`Globals::background`): inside a UI's render pass, where the view cannot be cleared on
// its own, this is what a clear would be (no texture read, no blending).

@vertex
fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    // (-1,-1), (3,-1), (-1,3): covers the viewport.
    let x = f32((i << 1u) & 2u) * 2.0 - 1.0;
    let y = f32(i & 2u) * 2.0 - 1.0;
    return vec4<f32>(x, y, 1.0, 1.0);
}

@fragment
fn fs_main() -> @location(0) vec4<f32> {
    return vec4<f32>(encode(globals.background.rgb), globals.background.a);
}
