// Text and its background boxes, in screen space: glyph coverage from the atlas (one
// channel) times the colour. `globals.wgsl` is prepended (for the sRGB flag).

@group(1) @binding(0) var atlas: texture_2d<f32>;
@group(1) @binding(1) var atlas_sampler: sampler;

struct VertexIn {
    // Normalised device coordinates.
    @location(0) position: vec2<f32>,
    @location(1) uv: vec2<f32>,
    // Linear RGB and alpha.
    @location(2) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = vec4<f32>(v.position, 0.0, 1.0);
    out.uv = v.uv;
    out.color = v.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let coverage = textureSample(atlas, atlas_sampler, in.uv).r;
    return vec4<f32>(encode(in.color.rgb), in.color.a * coverage);
}
