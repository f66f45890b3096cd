// The body of the trace kernels (trace.comp: geometry only; trace_alpha.comp: through
// scene.glsl, so alpha-masked triangles are skipped exactly as the integrators skip them).
// Traces a buffer of rays: closest hit, or any hit when SPEC_ANY_HIT is set (shadow rays).
// The includer has included the ABI header and traverse.glsl (directly or via scene.glsl).
#ifndef BIDIR_TRACE_KERNEL_GLSL
#define BIDIR_TRACE_KERNEL_GLSL

layout(local_size_x = TRACE_WG_SIZE) in;
layout(constant_id = SPEC_ANY_HIT) const uint ANY_HIT = 0u;
layout(std430, binding = BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = BIND_HITS) writeonly buffer Hits { GpuHit hits[]; };
layout(std430, binding = BIND_STATS) buffer Stats { uint stat_nodes; uint stat_tris; };
layout(push_constant) uniform Push { TracePush pc; };

void trace_one(uint i, inout uvec2 stats) {
    GpuRay r = rays[i];
    TraceHit h = TraceHit(r.dir.w, NO_HIT, vec2(0.0));
    if (r.dir.w >= 0.0) {
        h = trace_ray(r.origin.xyz, r.dir.xyz, r.origin.w, r.dir.w, ANY_HIT != 0u, stats);
    }
    hits[i] = GpuHit(h.t, h.prim, h.bary.x, h.bary.y);
}

void main() {
    uvec2 stats = uvec2(0u);
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.count) {
        trace_one(i, stats);
    }
    if (TRAVERSAL_STATS != 0u) {
        uvec2 s = subgroupAdd(stats);
        if (subgroupElect()) {
            atomicAdd(stat_nodes, s.x);
            atomicAdd(stat_tris, s.y);
        }
    }
}

#endif
