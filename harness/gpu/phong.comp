// SPDX-License-Identifier: MIT OR Apache-2.0
// Phong in GLSL for Vulkan: N_a + i k normalized, dotted with L; one invocation per pixel.
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
    uint i = p - s.first;
    vec3 k = (s.nb.xyz - s.na.xyz) / float(s.n);
    vec3 normal = s.na.xyz + float(i) * k;
    outp[p] = dot(normalize(normal), s.l.xyz);
}
