// The body of BDPT's light pass as a wavefront (glsl/kernels/bdpt_light_wavefront.comp, and
// with BDPT_WF_FINISH defined bdpt_light_finish.comp, whose launch runs each listed path to its
// end, tracing its joins and segments itself, as bdpt_camera_wavefront.glsl says; `--wavefront`
// with bdpt and the light vertex cache; after
// Laine, Karras & Aila 2013, as bdpt_camera_wavefront.glsl does for the camera pass): the light
// megakernel's subpaths (glsl/common/bdpt_light_path.glsl, bdpt_light_step.glsl) with their
// segments and their joins' shadow rays traced by the trace kernels (trace_kernel.glsl) between
// its launches.
//
// One slot per light path of the iteration, with its random numbers. Each launch takes up what
// the trace kernels found for the slot's last rays: the join to the eye, splatted where its
// shadow ray is clear, then the step at its segment's hit (one pass of the megakernel's loop:
// the vertex offered to the store, its join, the next segment); or, in the first launch of a
// pass, the path's start at a light. The host runs launch, closest-hit trace, any-hit trace,
// launch, ... until a launch queues no ray (src/render/bdpt_wavefront.rs); each launch after
// the first runs only the slots that queued a ray in the launch before (wf_active.glsl), which
// matters here: light paths have long tails. A path that ends writes its stored and seen
// counts for the light vertex cache, as the megakernel does. The join's contribution waits in
// BIND_WF_CONTRIB at its ray's place, in the half of the buffer of the launch's parity, its
// film pixel in w; a NaN or Inf contribution is dropped and counted.
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
#include "wf_ray.glsl"
#include "bdpt.glsl"
#include "vcm.glsl"
#include "wf_active.glsl"

layout(local_size_x = WF_WG_SIZE) in;
layout(std430, binding = BIND_SPLAT) buffer Splat { float splat[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
// Stored vertices per path, for the light vertex cache's scan.
layout(std430, binding = BIND_LVC_OFFSETS) writeonly buffer LvcOffsets { uint lvc_offsets[]; };
// The light paths (`light_state_load`).
layout(std430, binding = BIND_PT_SUSPENDED) buffer State { uvec4 state_words[]; };
layout(std430, binding = BIND_WF_HITS) readonly buffer Hits { GpuHit wf_hits[]; };
// Per shadow ray its any-hit trace's word (SPEC_HIT_WORDS): NO_HIT where it is clear.
layout(std430, binding = BIND_WF_SHADOW_HITS) readonly buffer ShadowHits { uint wf_shadow_hits[]; };
// A join's contribution (rgb, a float's bits) and its film pixel (w), at its shadow ray's place.
layout(std430, binding = BIND_WF_CONTRIB) buffer Contrib { uvec4 wf_contrib[]; };
layout(push_constant) uniform Push { BdptWavefrontPush pc; };
#include "bdpt_light_path.glsl"

// This launch's join to the eye (a step makes at most one): its shadow ray for the any-hit
// trace kernel, the contribution and the film pixel.
ShadowRay wf_join;
vec3 wf_join_contrib;
uint wf_join_pixel = 0u;
uint wf_join_count = 0u;
// A join's splat, or the count of those that are NaN or Inf.
uint wf_bad = 0u;

void splat_join(vec3 contrib, uint pix) {
    if (any(isnan(contrib)) || any(isinf(contrib))) {
        wf_bad++;
        return;
    }
    atomicAdd(splat[3u * pix + 0u], contrib.r);
    atomicAdd(splat[3u * pix + 1u], contrib.g);
    atomicAdd(splat[3u * pix + 2u], contrib.b);
}

// Strategy t = 1 for the step (bdpt_light_step.glsl): the join's shadow ray waits for the next
// trace; one too short to hold an occluder is clear now, as shadow_ray_clear has it.
void connect_to_camera(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wi, Continuous c, vec3 beta, vec3 sigma, float d_vcm, float d_vc, float vm, inout uvec2 stats) {
    ShadowRay ray;
    vec3 contrib;
    uint pix;
    if (!camera_join(p, ns_f, ng_f, wi, c, beta, sigma, d_vcm, d_vc, vm, ray, contrib, pix)) {
        return;
    }
    if (!(ray.tmax > 0.0)) {
        splat_join(contrib, pix);
        return;
    }
    wf_join = ray;
    wf_join_contrib = contrib;
    wf_join_pixel = pix;
    wf_join_count = 1u;
}

// A light path and where its last launch queued its rays, in 16-byte words at
// path * WF_STATE_STRIDE: the direction and dVCM, the throughput and dVC, then beta0 with the
// counts (the vertex count, WF_PATH_DONE once the path has ended; seen; stored with the light at
// infinity in bit 31), then the random numbers' state and dimension with the segment's place in
// its queue and the join's shadow ray's with their count from bit WF_SHADOW_COUNT_SHIFT up;
// last, only in scenes with a medium or alpha, the medium and the opacity seed. Without them a
// path takes four words, two 32-byte sectors (six took four sectors and the index's entry one),
// and one read brings its queue's places too. No origin: a launch's step finds its surface from
// the hit and the direction alone (surface_at) and makes the next segment's origin itself. The
// random numbers' sample index is rng_init's (`rng_init_index`), the status follows from the
// vertex count, and the join's film pixel waits with its contribution (BIND_WF_CONTRIB's w).

// Path p's state and its queued rays: segment, join's shadow ray, their count. Of a path that
// ended in the launch after the pass's first (which stores its counts' and queue words alone),
// the other words are another pass's: unused, as the status says it is done.
BdptLightState light_state_load(uint p, out uvec3 queued) {
    uint w = p * WF_STATE_STRIDE;
    uvec4 beta0_counts = state_words[w + 2u];
    uvec4 rng_queue = state_words[w + 3u];
    uvec4 sigma_seed = WF_STATE_SIGMA_SEED ? state_words[w + 4u] : uvec4(0u);
    queued = wf_queued(rng_queue.zw);
    uint status = beta0_counts.y == WF_PATH_DONE ? PT_DONE : PT_SUSPENDED;
    return BdptLightState(vec4(vec3(0.0), uintBitsToFloat(beta0_counts.x)), uintBitsToFloat(state_words[w]),
        uintBitsToFloat(state_words[w + 1u]), vec4(uintBitsToFloat(sigma_seed.xyz), 0.0),
        uvec4(beta0_counts.yzw, sigma_seed.w), uvec4(rng_queue.x, rng_init_index(pc.sample_base), rng_queue.y, status));
}

void light_state_store(uint p, BdptLightState st, uvec2 queue) {
    uint w = p * WF_STATE_STRIDE;
    state_words[w] = floatBitsToUint(st.d_dvcm);
    state_words[w + 1u] = floatBitsToUint(st.beta_dvc);
    state_words[w + 2u] = uvec4(floatBitsToUint(st.o_beta0.w), st.counts.xyz);
    state_words[w + 3u] = uvec4(st.rng_status.x, st.rng_status.z, queue);
    if (WF_STATE_SIGMA_SEED) {
        state_words[w + 4u] = uvec4(floatBitsToUint(st.sigma.xyz), st.counts.w);
    }
}

// The start of light path `path` (bdpt_light.comp: light_path) as a path state of `status`:
// its random numbers after the opacity seed's and the emission's draws, the emitted ray (its
// origin in o_beta0.xyz) and throughput, one vertex; `started` false where no path starts. The
// same values each time: the pass's first launch starts a path with it, the next starts it
// again (PT_SUSPENDED) instead of reading a stored state.
BdptLightState light_start(uint path, uint status, out bool started) {
    Rng rng = rng_init(path, pc.sample_base, pc.seed ^ 0x6c8e9cf5u);
    uint seed = HAS_ALPHA != 0u ? rng_next_uint(rng) : 0u; // BLEND's stochastic opacity
    vec3 o, d, beta;
    float d_vcm, d_vc;
    bool at_infinity;
    started = light_path_start(rng, o, d, beta, d_vcm, d_vc, at_infinity);
    return BdptLightState(vec4(o, max3(beta)), vec4(d, d_vcm), vec4(beta, d_vc), vec4(0.0),
        uvec4(1u, 0u, at_infinity ? 0x80000000u : 0u, seed), uvec4(rng.state, rng.index, rng.dim, status));
}

// One launch's work for this invocation's slot, if it has one.
void run_slot() {
    uint path;
    if (!wf_slot(pc.launch, pc.light_path_total, path)) {
        return; // past the slots, or not listed
    }
    // The pass's first launch starts every slot's path and queues its segment at the slot's
    // place, storing nothing; the launch after it starts each path again (the same numbers)
    // and takes up the segment's hit there (wf_first_hits); later launches read the state.
    bool fresh = (pc.launch & WF_ALL_SLOTS) != 0u;
    uint launch = wf_launch(pc.launch);
    BdptLightState st;
    uvec3 queued; // where the last launch queued its rays: segment, join, their count
    bool started = true;
    if (fresh || wf_first_hits(pc.launch)) {
        st = light_start(path, fresh ? PT_FRESH : PT_SUSPENDED, started);
        if (!fresh && !started) {
            return; // ended in the first launch (the launch after it runs every slot: wf_slot)
        }
        queued = uvec3(path, 0u, 0u);
    } else {
        st = light_state_load(path, queued);
    }
    uint status = st.rng_status.w;
    if (status == PT_DONE && queued.z == 0u) {
        return; // nothing left, nothing pending
    }

    // The last launch's join, splatted if its shadow ray is clear. The contributions alternate
    // between the buffer's halves from launch to launch (batches have even lengths).
    uvec2 halves = wf_contrib_halves(launch, uint(wf_contrib.length()));
    uint read_half = halves.x;
    uint write_half = halves.y;
    if (queued.z > 0u && wf_shadow_hits[queued.y] == NO_HIT) {
        uvec4 join = wf_contrib[read_half + queued.y];
        splat_join(uintBitsToFloat(join.rgb), join.w);
    }

    // The light subpath: one step at what its segment found (the megakernel's loop body,
    // bdpt_light_step.glsl, run once), or its start.
    Rng rng = Rng(st.rng_status.x, st.rng_status.y, st.rng_status.z);
    vec3 o = vec3(0.0); // the step sets it (the last segment's origin is not needed)
    float beta0 = st.o_beta0.w;
    vec3 d = st.d_dvcm.xyz;
    float d_vcm = st.d_dvcm.w;
    vec3 beta = st.beta_dvc.xyz;
    float d_vc = st.beta_dvc.w;
    vec3 sigma_near = st.sigma.xyz;
    uint depth = st.counts.x;
    uint seen = st.counts.y;
    uint stored = st.counts.z & 0x7fffffffu;
    bool at_infinity = (st.counts.z >> 31) != 0u;
    blend_seed = st.counts.w;
    // BDPT's values of VCM's terms (vcm.glsl: no merging).
    float d_vm = 0.0;
    VcmFactors k = VcmFactors(0.0, 0.0);
    uint base = path * pc.light_path_len;
    uvec2 stats = uvec2(0u);
    bool alive = false;
    if (status == PT_SUSPENDED) {
        GpuHit gh = wf_hits[queued.x];
        TraceHit h = TraceHit(gh.t, gh.tri, vec2(gh.u, gh.v));
#ifdef BDPT_WF_FINISH
        for (;;) {
#endif
        do {
#include "bdpt_light_step.glsl"
            alive = true;
            depth++;
        } while (false);
#ifdef BDPT_WF_FINISH
            // The step's join to the eye, then the next segment.
            if (wf_join_count > 0u) {
                if (shadow_ray_clear(wf_join, stats)) {
                    splat_join(wf_join_contrib, wf_join_pixel);
                }
                wf_join_count = 0u;
            }
            if (!alive) {
                break;
            }
            alive = false;
            h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
        }
#endif
    } else if (status == PT_FRESH) {
        o = st.o_beta0.xyz; // the emitted segment, queued below
        alive = started;
    }

    // The rays, packed at the front of the queues (a subgroup's together, in lane order); in
    // the pass's first launch each path's segment (or none) at its own place.
    uvec4 ext_lanes = subgroupBallot(alive || fresh);
    uvec4 join_lanes = subgroupBallot(wf_join_count > 0u);
    uint ext_count = subgroupBallotBitCount(ext_lanes);
    uint join_count = subgroupBallotBitCount(join_lanes);
    uvec2 queue_base = uvec2(0u);
    if (subgroupElect() && !fresh) { // (the first launch's rays are at the slots' places)
        queue_base.x = ext_count > 0u ? atomicAdd(wf_counts[2u * launch], ext_count) : 0u;
        queue_base.y = join_count > 0u ? atomicAdd(wf_counts[2u * launch + 1u], join_count) : 0u;
    }
    queue_base = subgroupBroadcastFirst(queue_base);
    uvec2 next = uvec2(queue_base.x + subgroupBallotExclusiveBitCount(ext_lanes), queue_base.y + subgroupBallotExclusiveBitCount(join_lanes));
    if (fresh) {
        if (alive) {
            wf_queue_segment(path, o, d, blend_seed);
        } else {
            wf_queue_no_segment(path);
        }
    }
    if (alive) {
        if (!fresh) { // (the first launch stores no state)
            light_state_store(path, BdptLightState(vec4(o, beta0), vec4(d, d_vcm), vec4(beta, d_vc), vec4(sigma_near, 0.0),
                uvec4(depth, seen, stored | (at_infinity ? 0x80000000u : 0u), blend_seed), uvec4(rng.state, rng.index, rng.dim, PT_SUSPENDED)),
                wf_queue_word(next, wf_join_count));
            wf_queue_segment(next.x, o, d, blend_seed);
        }
    } else {
        if (status != PT_DONE) {
            // The path ended: its counts for the light vertex cache.
            light_counts[path] = uvec2(stored, seen);
            lvc_offsets[path] = stored;
            state_words[path * WF_STATE_STRIDE + 2u].y = WF_PATH_DONE;
        }
        if (wf_join_count > 0u || queued.z > 0u) {
            state_words[path * WF_STATE_STRIDE + 3u].zw = wf_queue_word(next, wf_join_count);
        }
    }
    if (wf_join_count > 0u) {
        wf_queue_shadow(next.y, wf_join.o, wf_join.d, wf_join.tmax, blend_seed);
        wf_contrib[write_half + next.y] = uvec4(floatBitsToUint(wf_join_contrib), wf_join_pixel);
    }
    wf_list_next(pc.launch, path, alive || wf_join_count > 0u);
    if (wf_bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], wf_bad);
    }
}

void main() {
    run_slot();
#ifndef BDPT_WF_FINISH
    wf_end_launch(pc.launch, pc.light_path_total);
#endif
}
