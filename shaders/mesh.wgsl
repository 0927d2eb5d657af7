// Lit, instanced meshes: legs (cylinders), joints (spheres), axes, and the plates.
// Self-contained: the renderer's `Globals` and `MeshInstance` mirror these structs.

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

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

struct InstanceIn {
    @location(2) model_0: vec4<f32>,
    @location(3) model_1: vec4<f32>,
    @location(4) model_2: vec4<f32>,
    @location(5) model_3: vec4<f32>,
    // Linear RGB and alpha.
    @location(6) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn, i: InstanceIn) -> VertexOut {
    let model = mat4x4<f32>(i.model_0, i.model_1, i.model_2, i.model_3);
    let world = model * vec4<f32>(v.position, 1.0);
    var out: VertexOut;
    out.clip = globals.view_proj * world;
    out.world = world.xyz;
    // Meshes are only scaled equally across their round axes, so the model matrix keeps
    // normals' directions (see the renderer's mesh docs).
    out.normal = (model * vec4<f32>(v.normal, 0.0)).xyz;
    out.color = i.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let to_eye = normalize(globals.eye.xyz - in.world);
    var n = normalize(in.normal);
    // Two-sided: light the face that looks at the camera (plates are seen from below too).
    if dot(n, to_eye) < 0.0 {
        n = -n;
    }
    let key = normalize(globals.key_light.xyz);
    let fill = normalize(globals.fill_light.xyz);
    let diffuse = globals.key_light.w * max(dot(n, key), 0.0) + globals.fill_light.w * max(dot(n, fill), 0.0);
    let half_vector = normalize(key + to_eye);
    let specular = globals.shading.y * pow(max(dot(n, half_vector), 0.0), globals.shading.z);
    let lit = in.color.rgb * (globals.shading.x + diffuse) + vec3<f32>(specular);
    return vec4<f32>(encode(lit), in.color.a);
}

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
