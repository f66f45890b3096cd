// What the driver's ray-tracing shaders (trace.rgen, trace.rchit, trace.rmiss) pass along a
// ray: the hit as the trace kernels report it (GpuHit's fields: distance, triangle index in
// the order the acceleration structure was built from, i.e. the scene's original order, and
// the barycentrics of vertices 1 and 2).
#ifndef BIDIR_RT_PAYLOAD_GLSL
#define BIDIR_RT_PAYLOAD_GLSL
struct RtPayload {
    float t;
    uint prim;
    vec2 bary;
};
#endif
