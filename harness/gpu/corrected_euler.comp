// SPDX-License-Identifier: MIT OR Apache-2.0
// Corrected Euler (eqs. 15-17), the recurrence, in GLSL for Vulkan: one invocation
// runs a whole span. Compiled to SPIR-V by glslang (glslangValidator -V).
//
// The interface (docs/conformance.md §6), in std430 as corrected_euler.wgsl's.
#version 450
layout(local_size_x = 64) in;
struct Span {
    vec4 na; // N_a in xyz
    vec4 nb; // N_b in xyz
    vec4 l;  // L in xyz
    uint n;  // steps
    uint first; // index of pixel 0 in `outp`
    uint pad0;
    uint pad1;
};
layout(std430, set = 0, binding = 0) readonly buffer Spans { Span spans[]; };
layout(std430, set = 0, binding = 1) readonly buffer PixelSpan { uint pixel_span[]; };
layout(std430, set = 0, binding = 2) buffer Out { float outp[]; };

void main() {
    uint p = gl_GlobalInvocationID.x;
    if (p >= uint(outp.length())) return;
    Span s = spans[pixel_span[p]];
    if (p != s.first) return; // the recurrence: pixel 0's invocation runs the span
    vec3 na = s.na.xyz, nb = s.nb.xyz, l = s.l.xyz;
    float nf = float(s.n);
    // Set-up (eqs. 2-3, 10-11).
    vec3 k = (nb - na) / nf;
    float a = dot(k, l), c = dot(k, k), d = 2.0 * dot(k, na);
    float pa = dot(na, l), pb = dot(nb, l);
    float dqb = 2.0 * nf * c + d;
    float dia = a - 0.5 * pa * d;
    float dib = a - 0.5 * pb * dqb;
    float ds = (dib - dia) / nf;
    // Eq. 14 with n(n-1)/2 formed exactly as an integer; eqs. 15, 17.
    float tri = float((s.n * (s.n - 1u)) / 2u);
    float pn = pa + nf * dia + tri * ds;
    float t0 = dia - (pn - pb) / nf;
    // Eq. 16.
    float pi = pa, t = t0;
    for (uint i = 0u; i <= s.n; i++) {
        outp[s.first + i] = pi;
        pi = pi + t;
        t = t + ds;
    }
}
