// SPDX-License-Identifier: MIT OR Apache-2.0
// Phong in closed form (eqs. 2-4): p = A i + B, q = (C i + D) i + E by Horner, p/sqrt(q);
// one invocation per pixel.
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
    let l = s.l.xyz;
    let k = (s.nb.xyz - na) / f32(s.n);
    let a = dot(k, l);
    let b = dot(na, l);
    let c = dot(k, k);
    let d = 2.0 * dot(k, na);
    let e = dot(na, na);
    let x = f32(i);
    let q = (c * x + d) * x + e;
    out[p] = (a * x + b) / sqrt(q);
}
