#version 460
// Secondary rays from the hits of a ray buffer: shadow rays toward a point light
// (SPEC_SECONDARY_KIND 0) or cosine-distributed diffuse rays about the geometric normal
// (1), each from the hit point offset off the surface on the side the primary came from.
// Rays of misses get tmax = -1; `flags` marks valid rays for compaction.
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "intersect.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(constant_id = SPEC_SECONDARY_KIND) const uint KIND = 0u;
layout(std430, binding = BIND_TRIS) readonly buffer BvhTris { GpuTri bvh_tris[]; };
layout(std430, binding = BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = BIND_HITS) readonly buffer Hits { GpuHit hits[]; };
layout(std430, binding = BIND_RAYS_OUT) writeonly buffer RaysOut { GpuRay rays_out[]; };
layout(std430, binding = BIND_FLAGS) writeonly buffer Flags { uint flags[]; };
layout(push_constant) uniform Push { SecondaryPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    GpuHit h = hits[i];
    GpuRay r = rays[i];
    if (h.tri == NO_HIT) {
        rays_out[i] = GpuRay(vec4(0.0), vec4(0.0, 0.0, 1.0, -1.0));
        flags[i] = 0u;
        return;
    }
    // Hit point from barycentrics where the vertices are at hand (see scene.glsl hit_point);
    // Woop-encoded triangles only give o + t d (good enough for timing rays).
    vec3 p = r.origin.xyz + h.t * r.dir.xyz;
    if (TRI_TEST == TRI_TEST_WATERTIGHT) {
        GpuTri t = bvh_tris[h.tri];
        p = (1.0 - h.u - h.v) * t.a.xyz + h.u * t.b.xyz + h.v * t.c.xyz;
    }
    vec3 n = normalize(tri_geometric_normal(bvh_tris[h.tri]));
    if (dot(n, r.dir.xyz) > 0.0) {
        n = -n; // face the side the ray came from
    }
    vec3 o = offset_ray_origin(p, n);
    vec3 d;
    float tmax;
    if (KIND == 0u) {
        vec3 to_light = pc.light.xyz - o;
        tmax = length(to_light);
        d = to_light / tmax;
    } else {
        Rng rng = rng_init(i, pc.seed, 0x9e3779b9u);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        d = sample_cosine_hemisphere(n, u1, u2);
        tmax = 3.0e38;
    }
    rays_out[i] = GpuRay(vec4(o, 0.0), vec4(d, tmax));
    flags[i] = 1u;
}
