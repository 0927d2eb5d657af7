// Unlit coloured lines: the ground grid and the path traced by the platform centre.
// `globals.wgsl` is prepended.

struct VertexIn {
    @location(0) position: vec3<f32>,
    // Linear RGB and alpha.
    @location(1) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = globals.view_proj * vec4<f32>(v.position, 1.0);
    out.color = v.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(encode(in.color.rgb), in.color.a);
}
