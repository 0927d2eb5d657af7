// The uniforms every pipeline shares (camera, lights, shading) and the sRGB encoding. Prepended to each shader
// module by `stewart_render::shaders`; the renderer's `gpu_types::Globals` mirrors it
// (a test compares their sizes through naga's layout).

struct Globals {
    view_proj: mat4x4<f32>,
    // xyz: camera position (world, metres); w unused.
    eye: vec4<f32>,
    // xyz: direction *towards* the key light (world); w: key light strength.
    key_light: vec4<f32>,
    // xyz: direction towards the fill light; w: fill strength.
    fill_light: vec4<f32>,
    // x: ambient, y: specular strength, z: shininess, w: 1 to encode the output as sRGB
    // (for targets that are not sRGB formats, such as egui's), 0 to output linear.
    shading: vec4<f32>,
};

@group(0) @binding(0) var<uniform> globals: Globals;

// Linear to sRGB when the target does not do it (see `Globals::shading.w`).
fn encode(linear: vec3<f32>) -> vec3<f32> {
    if globals.shading.w < 0.5 {
        return linear;
    }
    let c = clamp(linear, vec3<f32>(0.0), vec3<f32>(1.0));
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}
