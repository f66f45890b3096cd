#version 460
// BDPT, pass 2: one camera subpath per pixel, joined to the light subpath of the same index.
// At each vertex: s = 0 when it is an emitter, s = 1 with a fresh light sample, and s >= 2
// with stored light vertices — all of them (full join), `join_k` chosen uniformly (k-step
// join), or `join_k` drawn from every path's vertices (light vertex cache). A connection's
// contribution is divided by the probability that it was evaluated (the reservoir's L / n,
// k-step's k / stored, the cache's k / total), so with the fixed full-BDPT MIS weights the
// estimator stays unbiased whichever join runs (docs/integrators.md).
// With SPEC_VCM (`--integrator vcm`, vcm.glsl) the same pass also carries dVM, adds the
// merging terms to every weight and merges at the first continuous camera vertex (or, with
// VCM_MERGE_ALL, at each; vcm.glsl, vcm_merge.glsl). Full VCM at the first vertex records that
// vertex (BIND_MERGE_QUERIES) for vcm_merge.comp instead of merging here.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_shuffle : require
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
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { BdptPush pc; };
layout(std430, binding = BIND_SLICES) writeonly buffer Slices { vec4 slices_out[]; };
// The light vertex cache (JOIN_LVC): stored slots of every light path, densely listed.
layout(std430, binding = BIND_LVC_INDEX) readonly buffer LvcIndex { uvec4 lvc_index[]; }; // entries of LVC_ENTRY_WORDS (lvc_entry.glsl)
layout(std430, binding = BIND_LVC_TOTAL) readonly buffer LvcTotal { uint lvc_total; };
#include "vcm_merge.glsl"
layout(std430, binding = BIND_MERGE_QUERIES) writeonly buffer MergeQueries { MergeQuery merge_queries[]; };
// This invocation's camera sample: its entry in merge_queries, and whether it recorded one.
uint g_query = 0u;
bool g_queued = false;

#define BDPT_JOIN pc.join
#include "packed_contrib.glsl"

// The megakernel's shadow rays: queued for shadow_queue.comp where the queue has room, else
// traced here. With the light vertex cache's join, which has a wavefront form, `contrib` is
// rounded as that form keeps it (packed_contrib.glsl), in VCM too (tests/vcm.rs:
// vcm:no-merge gives bdpt's image); the other joins, which have none, keep every bit (a first
// rounding through the packed form cost bdpt:full 3 % and vcm 1.4 % on an H100, session 54).
bool camera_shadow_clear(ShadowRay r, inout vec3 contrib, inout uvec2 stats) {
    if (BDPT_JOIN == JOIN_LVC) {
        contrib = contrib_round(contrib);
    }
    return shadow_clear_now(r, contrib, stats);
}

#include "bdpt_camera_path.glsl"

// `path`: the light path of this camera sample (megakernel joins).
vec3 camera_path(uint path, vec2 xy, inout Rng rng) {
    if (HAS_ALPHA != 0u) {
        blend_seed = rng_next_uint(rng); // BLEND's stochastic opacity
    }
    uvec2 stats = uvec2(0u);
    vec3 o = pc.camera.eye.xyz;
    vec3 d = camera_direction(pc.camera, xy);
    vec3 beta = vec3(1.0);
    vec3 radiance = vec3(0.0);
    float d_vcm = mis(float(pc.light_paths) / camera_pdf_w(pc.camera, d));
    float d_vc = 0.0;
    // dVC at the second vertex less light tracing's term: the merging term of the first
    // vertex (0 in BDPT), for the emitter hits there (vcm.glsl, emitter_hit_d_vc).
    float d_vc_merge = 0.0;
    float d_vm = 0.0;
    VcmFactors k = vcm_factors(pc.sample_base, pc.light_path_total);
    // Merging at a light vertex joined to this camera vertex is a strategy only when merging
    // runs everywhere; at this camera vertex, also while every earlier vertex scattered
    // through a delta lobe (`merge_pending`; vcm.glsl).
    float vm_light = k.vm * vcm_light_merge_terms();
    bool merge_pending = true;
    uvec2 lc = light_counts[path];   // (stored, seen) of this sample's light path (megakernel joins)
    uint base = path * pc.light_path_len;
    vec3 sigma_near = vec3(0.0); // sigma_a where the next segment leaves its surface (volume.glsl)

    for (uint depth = 1u;; depth++) {
        TraceHit h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
#include "bdpt_camera_step.glsl"
    }
    return radiance;
}

void main() {
    // Invocation -> (slice, pixel): slice j is camera sample sample_base + j, joined (by the
    // megakernel joins) to light path j * pixels + pixel.
    // The film holds the camera's window; random numbers and light paths follow the full
    // image's pixel.
    uint tiles = tiled_count(pc.camera.window_size);
    uint samples = max(pc.camera_samples, 1u);
    uint slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, pc.camera.window_size, valid);
    if (!valid || slice >= samples) {
        return;
    }
    uint pixels = pc.camera.window_size.x * pc.camera.window_size.y;
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    Rng rng = rng_init(image_pixel, pc.sample_base + slice, pc.seed);
    lvc_group = lvc_group_seed(px, pc.sample_base + slice, pc.seed);
    vec2 xy = vec2(px) + vec2(rng_next(rng), rng_next(rng));
    g_query = slice * pixels + pixel;
    vec3 l = camera_path(slice * pc.camera.size.x * pc.camera.size.y + image_pixel, xy, rng);
    if (VCM_MERGE_DEFERRED && !g_queued) {
        merge_queries[g_query].depth = 0u; // nothing to merge for this sample
    }
    vec4 add = vec4(l, 1.0);
    if (any(isnan(l)) || any(isinf(l))) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], 1u);
        add = vec4(0.0);
        shadow_queued = 0u; // the dropped sample's queued shadow rays with it
    }
    shadow_queue_finish(shadow_queued);
    if (samples == 1u) {
        accum[pixel] += add;
    } else {
        slices_out[slice * pixels + pixel] = add;
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}
