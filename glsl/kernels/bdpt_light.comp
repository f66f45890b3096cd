#version 460
// BDPT, pass 1: one light subpath per invocation (one per pixel): a light point and direction
// (bdpt_light_path.glsl), then BSDF sampling with Russian roulette and no length bound
// (bdpt_light_step.glsl, shared with the wavefront light pass, bdpt_light_wavefront.comp).
// Every diffuse-capable vertex (a) is offered to the vertex store, a reservoir of
// `light_path_len` slots (Vitter's algorithm R), so each vertex is kept with probability
// min(1, L / n) — the camera pass divides by it — and (b) is joined to the camera (strategy
// t = 1) and splatted into the pixel it projects to; a path's first vertex only with
// DIRECT_LIGHT_TRACING (bdpt.glsl).
// With SPEC_VCM (`--integrator vcm`, vcm.glsl) it also carries dVM and stores each vertex
// for merging; without connections (photon mapping) it does not splat.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_atomic_float : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "scene.glsl"
#include "bsdf.glsl"
#include "lights.glsl"
#include "emission.glsl"
#include "env.glsl"
#include "punctual.glsl"
#include "volume.glsl"
#include "bdpt.glsl"
#include "vcm.glsl"
#include "shadow_queue.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_SPLAT) buffer Splat { float splat[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { BdptPush pc; };
// Stored vertices per path, for the light vertex cache's scan (written whatever the join).
layout(std430, binding = BIND_LVC_OFFSETS) writeonly buffer LvcOffsets { uint lvc_offsets[]; };
#include "bdpt_light_path.glsl"

// Strategy t = 1: joins the light vertex at `p` to the eye (bdpt_light_path.glsl's camera_join)
// and splats its contribution, or queues the join's shadow ray.
void connect_to_camera(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wi, Continuous c, vec3 beta, vec3 sigma, float d_vcm, float d_vc, float vm, inout uvec2 stats) {
    ShadowRay ray;
    vec3 contrib;
    uint pix;
    if (!camera_join(p, ns_f, ng_f, wi, c, beta, sigma, d_vcm, d_vc, vm, ray, contrib, pix)) {
        return;
    }
    // Queued (shadow_queue_splat.comp traces it and splats if clear), or traced here.
    if (queue_tagged_shadow(ray, contrib, pix)) {
        return;
    }
    if (!shadow_ray_clear(ray, stats)) {
        return;
    }
    if (any(isnan(contrib)) || any(isinf(contrib))) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], 1u);
        return;
    }
    atomicAdd(splat[3u * pix + 0u], contrib.r);
    atomicAdd(splat[3u * pix + 1u], contrib.g);
    atomicAdd(splat[3u * pix + 2u], contrib.b);
}

// Light path `path`: its vertices to the store, its joins to the camera splatted or queued.
void light_path(uint path) {
    uvec2 stats = uvec2(0u);
    uint stored = 0u, seen = 0u;
    uint base = path * pc.light_path_len;
    Rng rng = rng_init(path, pc.sample_base, pc.seed ^ 0x6c8e9cf5u);
    if (HAS_ALPHA != 0u) {
        blend_seed = rng_next_uint(rng); // BLEND's stochastic opacity
    }
    vec3 beta, o, d;
    float d_vcm, d_vc;
    bool at_infinity;
    VcmFactors k = vcm_factors(pc.sample_base, pc.light_path_total);
    if (!light_path_start(rng, o, d, beta, d_vcm, d_vc, at_infinity)) {
        light_counts[path] = uvec2(0u);
        lvc_offsets[path] = 0u;
        return;
    }
    float beta0 = max3(beta);
    float d_vm = d_vc * k.vc; // dVM starts as dVC / eta (0 for a delta light)
    vec3 sigma_near = vec3(0.0); // sigma_a where the next segment leaves its surface (volume.glsl)

    for (uint depth = 1u;; depth++) {
        TraceHit h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
#include "bdpt_light_step.glsl"
    }
    light_counts[path] = uvec2(stored, seen);
    lvc_offsets[path] = stored;
    ADD_TRAVERSAL_COUNTS(render_stats);
}

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path < pc.light_path_total) {
        light_path(path);
    }
    shadow_queue_finish(shadow_queued);
}
