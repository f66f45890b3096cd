// The ray a wavefront path kernel queues for the trace kernels (trace_kernel.glsl, whose
// ray_tmin reads it back): from `o` along `d` up to `tmax`; its tmin slot carries the path's
// stochastic-opacity seed where the scene has alpha (SPEC_RAY_SEED), else 0. Shared by the
// wavefront path tracer and BDPT's wavefront passes; the includer has included scene.glsl.
#ifndef BIDIR_WF_RAY_GLSL
#define BIDIR_WF_RAY_GLSL

GpuRay wavefront_ray(vec3 o, vec3 d, float tmax, uint seed) {
    return GpuRay(vec4(o, HAS_ALPHA != 0u ? uintBitsToFloat(seed) : 0.0), vec4(d, tmax));
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

// A queue place with no segment to trace (tmax < 0: the trace kernels leave it at once).
const GpuRay WF_NO_SEGMENT = GpuRay(vec4(0.0), vec4(0.0, 0.0, 1.0, -1.0));

#endif
