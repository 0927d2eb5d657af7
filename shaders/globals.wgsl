// The uniforms every pipeline shares (camera, lights, shading), the sRGB encoding and the
// lighting of lit surfaces. Prepended to each shader
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
    // The view's background, linear RGB and alpha (drawn by background.wgsl).
    background: vec4<f32>,
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

// Lit colour of a surface point: ambient, key and fill diffuse, a specular highlight.
// Two-sided: the face that looks at the camera is lit (plates and the workspace surface
// are seen from both sides).
fn shade(color: vec3<f32>, world: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    let to_eye = normalize(globals.eye.xyz - world);
    var n = normalize(normal);
    if dot(n, to_eye) < 0.0 {
        n = -n;
    }
    let key = normalize(globals.key_light.xyz);
    let fill = normalize(globals.fill_light.xyz);
    let diffuse = globals.key_light.w * max(dot(n, key), 0.0) + globals.fill_light.w * max(dot(n, fill), 0.0);
    let half_vector = normalize(key + to_eye);
    let specular = globals.shading.y * pow(max(dot(n, half_vector), 0.0), globals.shading.z);
    return color * (globals.shading.x + diffuse) + vec3<f32>(specular);
}

// What a lit triangle's vertex stage hands its fragment stage (mesh.wgsl, analysis.wgsl).
struct LitOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // Linear RGB and alpha.
    @location(2) color: vec4<f32>,
};

// The lit, encoded colour of a fragment of a lit triangle.
fn lit(in: LitOut) -> vec4<f32> {
    return vec4<f32>(encode(shade(in.color.rgb, in.world, in.normal)), in.color.a);
}
