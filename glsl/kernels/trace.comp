#version 460
// Traces a buffer of rays: closest hit, or any hit when SPEC_ANY_HIT is set (shadow rays).
// The traversal benchmark times exactly this kernel.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "traverse.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(constant_id = SPEC_ANY_HIT) const uint ANY_HIT = 0u;
layout(std430, binding = BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = BIND_HITS) writeonly buffer Hits { GpuHit hits[]; };
layout(std430, binding = BIND_STATS) buffer Stats { uint stat_nodes; uint stat_tris; };
layout(push_constant) uniform Push { TracePush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    GpuRay r = rays[i];
    uvec2 stats = uvec2(0u);
    TraceHit h = TraceHit(r.dir.w, NO_HIT, vec2(0.0));
    if (r.dir.w >= 0.0) {
        h = trace_ray(r.origin.xyz, r.dir.xyz, r.origin.w, r.dir.w, ANY_HIT != 0u, stats);
    }
    hits[i] = GpuHit(h.t, h.prim, h.bary.x, h.bary.y);
    if (TRAVERSAL_STATS != 0u) {
        uvec2 s = subgroupAdd(stats);
        if (subgroupElect()) {
            atomicAdd(stat_nodes, s.x);
            atomicAdd(stat_tris, s.y);
        }
    }
}
