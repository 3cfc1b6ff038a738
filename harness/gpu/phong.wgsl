// SPDX-License-Identifier: MIT OR Apache-2.0
// Phong: the interpolated normal N_a + i k normalized, dotted with L; one invocation per pixel.
//
// The interface: corrected_euler.wgsl's header and docs/conformance.md §6.
struct Span {
    na: vec4<f32>, // N_a in xyz
    nb: vec4<f32>, // N_b in xyz
    l: vec4<f32>,  // L in xyz
    n: u32,        // steps
    first: u32,    // index of pixel 0 in `out`
    pad0: u32,
    pad1: u32,
};
@group(0) @binding(0) var<storage, read> spans: array<Span>;
@group(0) @binding(1) var<storage, read> pixel_span: array<u32>;
@group(0) @binding(2) var<storage, read_write> out: array<f32>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let p = id.x;
    if (p >= arrayLength(&out)) { return; }
    let s = spans[pixel_span[p]];
    let i = p - s.first; // this invocation's pixel
    let na = s.na.xyz;
    let k = (s.nb.xyz - na) / f32(s.n);
    let normal = na + f32(i) * k;
    out[p] = dot(normalize(normal), s.l.xyz);
}
