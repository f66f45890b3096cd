// The rays a wavefront path kernel queues for the trace kernels (trace_kernel.glsl reads them
// back): segments from `o` along `d`, unbounded, and shadow rays up to their `tmax`. Where rays
// carry no opacity seed they take the compact forms of ray_words.glsl (the host sets
// SPEC_WF_SEGMENT_WORDS and SPEC_WF_SHADOW_WORDS as it sets the trace kernels' SPEC_RAY_WORDS,
// `wavefront_queues::ray_words`); else whole GpuRays, whose tmin slot carries the path's
// stochastic-opacity seed where the scene has alpha (SPEC_RAY_SEED), else 0. Shared by the
// wavefront path tracer and BDPT's wavefront passes; the includer has included scene.glsl.
#ifndef BIDIR_WF_RAY_GLSL
#define BIDIR_WF_RAY_GLSL

#include "ray_words.glsl"

layout(constant_id = SPEC_WF_SEGMENT_WORDS) const uint WF_SEGMENT_WORDS = RAY_WORDS_FULL;
layout(constant_id = SPEC_WF_SHADOW_WORDS) const uint WF_SHADOW_WORDS = RAY_WORDS_FULL;
// Each queue viewed as whole GpuRays, and as the 16-, 8- and 4-byte words of the compact forms.
layout(std430, binding = BIND_WF_RAYS) writeonly buffer Rays { GpuRay wf_rays[]; };
layout(std430, binding = BIND_WF_RAYS) writeonly buffer RayQuads { uvec4 wf_ray_quads[]; };
layout(std430, binding = BIND_WF_RAYS) writeonly buffer RayPairs { uvec2 wf_ray_pairs[]; };
layout(std430, binding = BIND_WF_SHADOW_RAYS) writeonly buffer ShadowRays { GpuRay wf_shadow_rays[]; };
layout(std430, binding = BIND_WF_SHADOW_RAYS) writeonly buffer ShadowQuads { uvec4 wf_shadow_quads[]; };
layout(std430, binding = BIND_WF_SHADOW_RAYS) writeonly buffer ShadowPairs { uvec2 wf_shadow_pairs[]; };
layout(std430, binding = BIND_WF_SHADOW_RAYS) writeonly buffer ShadowWords { uint wf_shadow_words[]; };

GpuRay wavefront_ray(vec3 o, vec3 d, float tmax, uint seed) {
    return GpuRay(vec4(o, HAS_ALPHA != 0u ? uintBitsToFloat(seed) : 0.0), vec4(d, tmax));
}

// Queues the segment from `o` along `d` (the path's opacity seed `seed`) at place i.
void wf_queue_segment(uint i, vec3 o, vec3 d, uint seed) {
    if (WF_SEGMENT_WORDS == RAY_WORDS_SEGMENT) {
        uint cap = uint(wf_ray_quads.length()) / 2u;
        wf_ray_quads[i] = floatBitsToUint(vec4(o, d.x));
        wf_ray_pairs[ray_pair_index(i, cap)] = floatBitsToUint(d.yz);
    } else {
        wf_rays[i] = wavefront_ray(o, d, 3.0e38, seed);
    }
}

// Queues no segment at place i (the trace kernels leave it at once).
void wf_queue_no_segment(uint i) {
    if (WF_SEGMENT_WORDS == RAY_WORDS_SEGMENT) {
        uint cap = uint(wf_ray_quads.length()) / 2u;
        wf_ray_quads[i] = uvec4(0u); // a zero direction
        wf_ray_pairs[ray_pair_index(i, cap)] = uvec2(0u);
    } else {
        wf_rays[i] = GpuRay(vec4(0.0), vec4(0.0, 0.0, 1.0, -1.0));
    }
}

// Queues the shadow ray from `o` along `d` up to `tmax` (the path's opacity seed `seed`) at place i.
void wf_queue_shadow(uint i, vec3 o, vec3 d, float tmax, uint seed) {
    if (WF_SHADOW_WORDS == RAY_WORDS_BOUNDED) {
        uint cap = uint(wf_shadow_quads.length()) / 2u;
        wf_shadow_quads[i] = floatBitsToUint(vec4(o, tmax));
        wf_shadow_pairs[ray_pair_index(i, cap)] = floatBitsToUint(d.xy);
        wf_shadow_words[ray_word_index(i, cap)] = floatBitsToUint(d.z);
    } else {
        wf_shadow_rays[i] = wavefront_ray(o, d, tmax, seed);
    }
}

// Whether the wavefront paths' states keep a fifth 16-byte word, for the medium and the
// opacity seed (pt_wavefront.glsl, bdpt_camera_wavefront.glsl, bdpt_light_wavefront.glsl): only
// in scenes with either.
const bool WF_STATE_SIGMA_SEED = HAS_VOLUME != 0u || HAS_ALPHA != 0u;
// The words a slot's path takes, so its stride in BIND_PT_SUSPENDED's 16-byte words.
const uint WF_STATE_STRIDE = WF_STATE_SIGMA_SEED ? WF_STATE_WORDS : WF_STATE_WORDS - 1u;

// The halves of a contribution buffer of `len` entries that launch `launch` reads (what the
// launch before it wrote) and writes, by its parity, so that no slot overwrites a contribution
// another slot has yet to read (batches have even lengths): (read offset, write offset).
uvec2 wf_contrib_halves(uint launch, uint len) {
    uint half_len = len / 2u;
    uint read_half = (launch & 1u) == 0u ? half_len : 0u;
    return uvec2(read_half, half_len - read_half);
}

#endif
