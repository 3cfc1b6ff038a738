// SPDX-License-Identifier: MIT OR Apache-2.0
// Gouraud (eq. 1 with p linear): p_i = p_a + i dp by the recurrence, one invocation per span.
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
    if (p != s.first) { return; } // the recurrence: pixel 0's invocation runs the span
    let nf = f32(s.n);
    let pa = dot(s.na.xyz, s.l.xyz);
    let pb = dot(s.nb.xyz, s.l.xyz);
    let dp = (pb - pa) / nf;
    var g = pa;
    for (var i = 0u; i <= s.n; i++) {
        out[s.first + i] = g;
        g = g + dp;
    }
}
