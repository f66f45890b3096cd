// The forms of a ray queue (SPEC_RAY_WORDS for the trace kernels, SPEC_WF_SEGMENT_WORDS and
// SPEC_WF_SHADOW_WORDS for the wavefront path kernels that fill their queues; wf_ray.glsl).
// A queue of `cap` rays takes cap 32-byte places:
// - RAY_WORDS_FULL: a GpuRay at place i (origin and tmin, or the opacity seed where the scene
//   has alpha; direction and tmax).
// - RAY_WORDS_SEGMENT, a segment from 0 to unbounded (tmax 3.0e38): (o, d.x) as the 16-byte word
//   i, (d.y, d.z) as the 8-byte word 2 cap + i; a zero direction is no segment (tmax < 0).
// - RAY_WORDS_BOUNDED, a shadow ray from 0 to tmax: (o, tmax) as the 16-byte word i, (d.x, d.y)
//   as the 8-byte word 2 cap + i, d.z as the 4-byte word 6 cap + i.
// Each part of a compact ray lies beside its neighbours' (a subgroup's lanes write and read whole
// 32-byte sectors), and a queue takes 24 or 28 bytes a ray of memory traffic instead of 32.
#ifndef BIDIR_RAY_WORDS_GLSL
#define BIDIR_RAY_WORDS_GLSL

// Where ray i's 8-byte part lies among a queue's 8-byte words, of `cap` rays.
uint ray_pair_index(uint i, uint cap) {
    return 2u * cap + i;
}

// Where ray i's 4-byte part (RAY_WORDS_BOUNDED) lies among a queue's words.
uint ray_word_index(uint i, uint cap) {
    return 6u * cap + i;
}

// The GpuRay a compact ray stands for, from its parts (`word` unused by RAY_WORDS_SEGMENT).
GpuRay ray_from_parts(uint words, uvec4 quad, uvec2 pair, uint word) {
    vec4 q = uintBitsToFloat(quad);
    vec2 p = uintBitsToFloat(pair);
    if (words == RAY_WORDS_SEGMENT) {
        vec3 d = vec3(q.w, p);
        return GpuRay(vec4(q.xyz, 0.0), vec4(d, all(equal(d, vec3(0.0))) ? -1.0 : 3.0e38));
    }
    return GpuRay(vec4(q.xyz, 0.0), vec4(p, uintBitsToFloat(word), q.w));
}

#endif
