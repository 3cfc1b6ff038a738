// SPDX-License-Identifier: MIT OR Apache-2.0
// Euler (eqs. 12-14): p_{i+1} = p_i + s_i, s_{i+1} = s_i + ds from s_0 = di_a; one invocation per span.
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
    let na = s.na.xyz;
    let nb = s.nb.xyz;
    let l = s.l.xyz;
    let nf = f32(s.n);
    // Set-up (eqs. 2-3, 10-11): k = (N_b - N_a)/n, p = A x + B, q = C x^2 + D x + E.
    let k = (nb - na) / nf;
    let a = dot(k, l);
    let c = dot(k, k);
    let d = 2.0 * dot(k, na);
    let pa = dot(na, l);
    let pb = dot(nb, l);
    let dqb = 2.0 * nf * c + d;
    let dia = a - 0.5 * pa * d;
    let dib = a - 0.5 * pb * dqb;
    let ds = (dib - dia) / nf;
    var pi = pa;
    var t = dia;
    for (var i = 0u; i <= s.n; i++) {
        out[s.first + i] = pi;
        pi = pi + t;
        t = t + ds;
    }
}
