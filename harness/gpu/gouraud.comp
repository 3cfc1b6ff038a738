// SPDX-License-Identifier: MIT OR Apache-2.0
// Gouraud in GLSL for Vulkan: p_i = p_a + i dp by the recurrence, one invocation per span.
//
// The interface: corrected_euler.comp's header and docs/conformance.md §6.
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
    if (p != s.first) return;
    float nf = float(s.n);
    float pa = dot(s.na.xyz, s.l.xyz), pb = dot(s.nb.xyz, s.l.xyz);
    float dp = (pb - pa) / nf;
    float g = pa;
    for (uint i = 0u; i <= s.n; i++) {
        outp[s.first + i] = g;
        g = g + dp;
    }
}
