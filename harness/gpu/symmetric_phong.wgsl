// SPDX-License-Identifier: MIT OR Apache-2.0
// Symmetric Phong: Duff's q recurrence to the middle only, its roots mirrored
// (q_i = q_{n-i} for unit edges); one invocation per span. The roots are parked in
// the span's upper half of `out` and read back before they are overwritten.
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
    let n = s.n;
    let half = n / 2u;
    let k = (nb - na) / f32(n);
    let a = dot(k, l);
    let c = dot(k, k);
    let d = 2.0 * dot(k, na);
    var q = dot(na, na);
    var dq = c + d;
    // root_j = sqrt(q_j) at out[first + n - j], j = 0..=half
    for (var j = 0u; j <= half; j++) {
        out[s.first + n - j] = sqrt(q);
        q = q + dq;
        dq = dq + 2.0 * c;
    }
    var pp = dot(na, l);
    for (var i = 0u; i <= n; i++) {
        var r: f32;
        if (i <= half) { r = out[s.first + n - i]; } else { r = out[s.first + i]; }
        out[s.first + i] = pp / r;
        pp = pp + a;
    }
}
