// The ray a wavefront path kernel queues for the trace kernels (trace_kernel.glsl, whose
// ray_tmin reads it back): from `o` along `d` up to `tmax`; its tmin slot carries the path's
// stochastic-opacity seed where the scene has alpha (SPEC_RAY_SEED), else 0. Shared by the
// wavefront path tracer and BDPT's wavefront passes; the includer has included scene.glsl.
#ifndef BIDIR_WF_RAY_GLSL
#define BIDIR_WF_RAY_GLSL

GpuRay wavefront_ray(vec3 o, vec3 d, float tmax, uint seed) {
    return GpuRay(vec4(o, HAS_ALPHA != 0u ? uintBitsToFloat(seed) : 0.0), vec4(d, tmax));
}

// A queue place with no segment to trace (tmax < 0: the trace kernels leave it at once).
const GpuRay WF_NO_SEGMENT = GpuRay(vec4(0.0), vec4(0.0, 0.0, 1.0, -1.0));

#endif
