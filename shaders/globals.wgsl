// The uniforms every pipeline shares: camera, lights, shading. Prepended to each shader
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
