// SPDX-License-Identifier: MIT OR Apache-2.0
// Squared corrected Euler (the paper's §7.1, question b): corrected Euler's
// construction (eqs. 15-17) on g = (N.L)^2/|N|^2, no square root in the set-up; the
// value sign(p) sqrt(max(0, g)), p by its own recurrence. One invocation runs a span.
//
// The interface of every kernel here (docs/conformance.md §6): one invocation per
// pixel; `pixel_span[p]` is the span of pixel `p`, `spans[k].first` its pixel 0; write
// `n + 1` values, pixel 0 at N_a, pixel n at N_b.
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
    // p = A x + B, q = C x^2 + D x + E (eqs. 2-3), edge normals of any length.
    let k = (nb - na) / nf;
    let a = dot(k, l);
    let b = dot(na, l);
    let c = dot(k, k);
    let d = 2.0 * dot(k, na);
    let e = dot(na, na);
    let pb = dot(nb, l);
    let qb = dot(nb, nb);
    let dqb = 2.0 * nf * c + d;
    // g = p^2/q at the ends, g' = p (2 A q - p q')/q^2 there: no square root.
    let ga = b * b / e;
    let gb = pb * pb / qb;
    let dga = b * (2.0 * a * e - b * d) / (e * e);
    let dgb = pb * (2.0 * a * qb - pb * dqb) / (qb * qb);
    let ds = (dgb - dga) / nf;
    // Eqs. 14-17 on g: eps = g_a + n g'_a + n(n-1)/2 ds - g_b, t0 = g'_a - eps/n.
    let tri = f32((s.n * (s.n - 1u)) / 2u);
    let eps = ga + nf * dga + tri * ds - gb;
    let t0 = dga - eps / nf;
    var g = ga;
    var t = t0;
    var pi = b;
    for (var i = 0u; i <= s.n; i++) {
        var v = 0.0;
        if (g > 0.0) { v = sqrt(g); }
        if (pi < 0.0) { v = -v; }
        if (pi == 0.0) { v = 0.0; }
        out[s.first + i] = v;
        g = g + t;
        t = t + ds;
        pi = pi + a;
    }
}
