// Lit, instanced meshes: legs (cylinders), joints (spheres), axes, and the plates.
// `globals.wgsl` is prepended; the renderer's `MeshInstance` mirrors `InstanceIn`.

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

@vertex
fn vs_main(v: VertexIn, i: InstanceIn) -> LitOut {
    let model = mat4x4<f32>(i.model_0, i.model_1, i.model_2, i.model_3);
    let world = model * vec4<f32>(v.position, 1.0);
    var out: LitOut;
    out.clip = globals.view_proj * world;
    out.world = world.xyz;
    // Normals go through the inverse transpose of the model's linear part. Instance
    // matrices are a rotation times a scale along the mesh's own axes (orthogonal
    // columns), whose inverse transpose is each column divided by its squared length:
    // right for a cone scaled to any radius and length. `gpu_types::normal_to_world`
    // is the same formula, tested on the CPU.
    let c0 = model[0].xyz;
    let c1 = model[1].xyz;
    let c2 = model[2].xyz;
    out.normal = c0 * (v.normal.x / dot(c0, c0)) + c1 * (v.normal.y / dot(c1, c1)) + c2 * (v.normal.z / dot(c2, c2));
    out.color = i.color;
    return out;
}

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    return lit(in);
}
