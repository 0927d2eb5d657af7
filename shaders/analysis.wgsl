// Translucent analysis meshes in world coordinates with a colour per vertex: the
// workspace surface and the slice coloured by the condition number. `globals.wgsl` is
// prepended; the renderer's `ColouredVertex` mirrors `VertexIn`.

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // Linear RGB and alpha.
    @location(2) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> LitOut {
    var out: LitOut;
    out.clip = globals.view_proj * vec4<f32>(v.position, 1.0);
    out.world = v.position;
    out.normal = v.normal;
    out.color = v.color;
    return out;
}

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    return lit(in);
}
