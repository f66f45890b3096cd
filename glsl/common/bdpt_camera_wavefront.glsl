// The body of BDPT's camera pass as a wavefront (glsl/kernels/bdpt_camera_wavefront.comp, and
// with BDPT_WF_FINISH defined bdpt_camera_finish.comp; `--wavefront` with bdpt and the light
// vertex cache; after
// Laine, Karras & Aila 2013, as pt_wavefront.comp does for the path tracers): the megakernel's
// camera subpaths (glsl/common/bdpt_camera_step.glsl, bdpt_camera_path.glsl) with their
// segments, light samples' shadow rays and connections' shadow rays traced by the trace
// kernels (trace_kernel.glsl) between its launches.
//
// One slot per megakernel invocation (pixel of the window and camera sample of the iteration),
// with its random numbers. Each launch takes up what the trace kernels found for the slot's
// last rays: the contribution of each of its shadow rays that is clear, then the scattering at
// its segment's hit (one step of the megakernel's loop), which leaves the next segment and up to
// BDPT_WF_SHADOW_RAYS shadow rays; or, in the first launch of a pass, the start of the slot's
// camera sample, whose segment it queues at the slot's own place and whose state it does not
// store: the launch after it (WF_FIRST_HITS) starts the path again (`camera_start`). The host
// runs launch, closest-hit trace, any-hit trace, launch, ... until a launch queues no ray
// (src/render/bdpt_wavefront.rs); each launch after a pass's first runs only the slots that
// queued a ray in the launch before (wf_active.glsl). The rays are packed at the front of
// their queues (counted in BIND_WF_COUNTS, where the trace kernels read how many there are);
// a shadow ray's contribution waits in BIND_WF_CONTRIB at the ray's place (in the half of
// the buffer of the launch's parity). A slot's contributions add up in its path's state and go
// to its pixel (or its slice) once the sample has nothing left to add; a NaN or Inf
// contribution is dropped and counted.
//
// With BDPT_WF_FINISH (the pass's finishing launch, src/render/bdpt_wavefront.rs): each listed
// slot runs the rest of its path in this launch, tracing each step's shadow rays and next
// segment itself (trace_ray over the BVH the trace kernels traverse, as the megakernel does),
// so that a pass's long tail of launches over a few live paths becomes one launch. It queues
// no ray and sizes no launch after it. The sums are the same terms as the launches' would be.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_shuffle : require
#define BDPT_WAVEFRONT
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
#include "packed_contrib.glsl"

layout(local_size_x = WF_WG_SIZE) in;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
// The light vertex cache: stored slots of every light path, densely listed.
layout(std430, binding = BIND_LVC_INDEX) readonly buffer LvcIndex { uvec4 lvc_index[]; }; // entries of LVC_ENTRY_WORDS (lvc_entry.glsl)
layout(std430, binding = BIND_LVC_TOTAL) readonly buffer LvcTotal { uint lvc_total; };
// The slots' paths (`camera_state_load`).
layout(std430, binding = BIND_PT_SUSPENDED) buffer State { uvec4 state_words[]; };
layout(std430, binding = BIND_WF_HITS) readonly buffer Hits { GpuHit wf_hits[]; };
// Per shadow ray its any-hit trace's word (SPEC_HIT_WORDS): NO_HIT where it is clear.
layout(std430, binding = BIND_WF_SHADOW_HITS) readonly buffer ShadowHits { uint wf_shadow_hits[]; };
layout(std430, binding = BIND_WF_CONTRIB) buffer Contrib { uvec2 wf_contrib[]; }; // contrib_pack
layout(push_constant) uniform Push { BdptWavefrontPush pc; };
#define BDPT_JOIN JOIN_LVC

// The shadow rays of this launch's scattering and what each adds if it is clear.
ShadowRay wf_shadow[BDPT_WF_SHADOW_RAYS];
vec3 wf_shadow_contrib[BDPT_WF_SHADOW_RAYS];
uint wf_shadow_count = 0u;

// A shadow ray for the any-hit trace kernel that runs after this launch; one too short to
// hold an occluder counts as clear now, as shadow_ray_clear has it. `contrib` is rounded as
// BIND_WF_CONTRIB keeps it (packed_contrib.glsl), whether the ray is queued or not.
bool camera_shadow_clear(ShadowRay r, inout vec3 contrib, inout uvec2 stats) {
    contrib = contrib_round(contrib);
    if (!(r.tmax > 0.0)) {
        return true;
    }
    wf_shadow[wf_shadow_count] = r;
    wf_shadow_contrib[wf_shadow_count] = contrib;
    wf_shadow_count++;
    return false;
}

#include "bdpt_camera_path.glsl"

// A slot's path and where its last launch queued its rays, in 16-byte words at
// g * WF_STATE_STRIDE: the sample's sum so far and the vertex count (WF_PATH_DONE once the
// path has ended), the direction and dVCM, the throughput and dVC, then the random-number state and dimension
// with the segment's place in its queue and the first shadow ray's with their count from bit
// WF_SHADOW_COUNT_SHIFT up; last, only in scenes with a medium or alpha, the medium and the
// opacity seed. Without them a slot takes four words, two 32-byte sectors (five straddle three
// or four), and one read of them brings the queue's places too. The random numbers' sample index
// is rng_init's (`rng_init_index`), the status follows from the vertex count. No origin: a
// launch's step finds its surface from the hit and the direction alone (surface_at) and makes
// the next segment's origin itself. The sum goes to the film once, when the sample has nothing
// left to add (the end of `run_slot`): a read and a write of the film per launch cost the Cornell box's
// BDPT 6 % on an H100 (session 44).

// Slot g's path (its sample index `sample_index`) and its queued rays: segment, first shadow
// ray, their count. Of a path that ended in the launch after the pass's first (which stores its
// sum and queue word alone, `run_slot`), the other words are another pass's: unused, as the
// status says it is done.
BdptCameraState camera_state_load(uint g, uint sample_index, out uvec3 queued) {
    uint w = g * WF_STATE_STRIDE;
    uvec4 sum_depth = state_words[w];
    uvec4 rng_queue = state_words[w + 3u];
    queued = wf_queued(rng_queue.zw);
    uint status = sum_depth.w == WF_PATH_DONE ? PT_DONE : PT_SUSPENDED;
    return BdptCameraState(sum_depth, uintBitsToFloat(state_words[w + 1u]), uintBitsToFloat(state_words[w + 2u]),
        WF_STATE_SIGMA_SEED ? state_words[w + 4u] : uvec4(0u), uvec4(rng_queue.x, rng_init_index(sample_index), rng_queue.y, status));
}

void camera_state_store(uint g, BdptCameraState st, uvec2 queue) {
    uint w = g * WF_STATE_STRIDE;
    state_words[w] = st.sum_depth;
    state_words[w + 1u] = floatBitsToUint(st.d_dvcm);
    state_words[w + 2u] = floatBitsToUint(st.beta_dvc);
    state_words[w + 3u] = uvec4(st.rng_status.x, st.rng_status.z, queue);
    if (WF_STATE_SIGMA_SEED) {
        state_words[w + 4u] = st.sigma_seed;
    }
}

// The start of the camera sample `sample_index` at image pixel px (`image_pixel` its index;
// bdpt_camera.comp: main and camera_path) as a path state of `status`: its random numbers after
// the pixel's and the opacity seed's draws, its direction with dVCM, a throughput of 1, one
// vertex (the eye). The same values each time: the pass's first launch starts a path with it,
// the next starts it again (PT_SUSPENDED) instead of reading a stored state.
BdptCameraState camera_start(uvec2 px, uint image_pixel, uint sample_index, uint status) {
    Rng rng = rng_init(image_pixel, sample_index, pc.seed);
    vec2 xy = vec2(px) + vec2(rng_next(rng), rng_next(rng));
    uint seed = HAS_ALPHA != 0u ? rng_next_uint(rng) : 0u; // BLEND's stochastic opacity
    vec3 d = camera_direction(pc.camera, xy);
    float d_vcm = mis(float(pc.light_paths) / camera_pdf_w(pc.camera, d));
    return BdptCameraState(uvec4(0u, 0u, 0u, 1u), vec4(d, d_vcm), vec4(1.0, 1.0, 1.0, 0.0), uvec4(0u, 0u, 0u, seed),
        uvec4(rng.state, rng.index, rng.dim, status));
}

// A finite contribution adds to `sum`; a NaN or Inf one is counted in `bad`.
void add_finite(inout vec3 sum, inout uint bad, vec3 c) {
    if (any(isnan(c)) || any(isinf(c))) {
        bad++;
    } else {
        sum += c;
    }
}

// The pass's slots: the camera window's tiled pixels times the iteration's camera samples.
uint camera_slots() {
    return tiled_count(pc.camera.window_size) * max(pc.camera_samples, 1u);
}

// One launch's work for this invocation's slot, if it has one.
void run_slot() {
    // Slot -> (slice, pixel of the camera's window), as bdpt_camera.comp maps its invocations.
    uint tiles = tiled_count(pc.camera.window_size);
    uint samples = max(pc.camera_samples, 1u);
    uint g;
    if (!wf_slot(pc.launch, camera_slots(), g)) {
        return; // past the slots, or not listed
    }
    uint slice = g / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(g % tiles, pc.camera.window_size, valid);
    // The pass's first launch starts every slot's path and queues its segment at the slot's
    // place, storing nothing; the launch after it starts each path again (the same numbers)
    // and takes up the segment's hit there (wf_first_hits); later launches read the state.
    bool fresh = (pc.launch & WF_ALL_SLOTS) != 0u;
    bool first_hits = wf_first_hits(pc.launch);
    uint launch = wf_launch(pc.launch);
    if (!valid) {
        if (fresh) {
            // A slot past the window's pixels (tiled_pixel) still has its place in the queue
            // (counted with every slot's: wf_end_launch).
            wf_queue_no_segment(g);
        }
        return;
    }
    uint pixels = pc.camera.window_size.x * pc.camera.window_size.y;
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    BdptCameraState st;
    uvec3 queued; // where the last launch queued its rays: segment, shadow rays, their count
    if (fresh || first_hits) {
        st = camera_start(px, image_pixel, pc.sample_base + slice, fresh ? PT_FRESH : PT_SUSPENDED);
        queued = uvec3(g, 0u, 0u);
    } else {
        st = camera_state_load(g, pc.sample_base + slice, queued);
    }
    uint status = st.rng_status.w;
    if (status == PT_DONE && queued.z == 0u) {
        return; // nothing left, nothing pending
    }
    lvc_group = lvc_group_seed(px, pc.sample_base + slice, pc.seed);
    vec3 sum = uintBitsToFloat(st.sum_depth.xyz); // the sample's contributions so far
    uint bad = 0u;

    // The last launch's shadow rays: what each that is clear adds. The contributions
    // alternate between the buffer's halves from launch to launch (batches have even lengths),
    // so that no slot overwrites one another slot has yet to read.
    uvec2 halves = wf_contrib_halves(launch, uint(wf_contrib.length()));
    uint read_half = halves.x;
    uint write_half = halves.y;
    // The segment's hit, the shadow rays' trace words and their contributions are asked for
    // together, before any is used: one round trip of dependent reads, not a trace word's, then
    // a contribution's, then the hit's (the kernel is bound by them: 2 % of its time on an H100,
    // session 53; the light kernel's one join gained nothing so and reads as before).
    GpuHit gh = GpuHit(0.0, NO_HIT, 0.0, 0.0);
    if (status == PT_SUSPENDED) {
        gh = wf_hits[queued.x];
    }
    uint words[BDPT_WF_SHADOW_RAYS];
    vec3 contribs[BDPT_WF_SHADOW_RAYS];
    for (uint i = 0u; i < BDPT_WF_SHADOW_RAYS; i++) {
        if (i < queued.z) {
            words[i] = wf_shadow_hits[queued.y + i];
            contribs[i] = contrib_unpack(wf_contrib[read_half + queued.y + i]);
        }
    }
    for (uint i = 0u; i < BDPT_WF_SHADOW_RAYS; i++) {
        if (i < queued.z && words[i] == NO_HIT) {
            add_finite(sum, bad, contribs[i]);
        }
    }

    // The camera subpath: one step at what its segment found (the megakernel's loop body,
    // bdpt_camera_step.glsl, run once), or its start.
    Rng rng = Rng(st.rng_status.x, st.rng_status.y, st.rng_status.z);
    blend_seed = st.sigma_seed.w;
    vec3 o = vec3(0.0); // the step sets it (the last segment's origin is not needed)
    uint depth = st.sum_depth.w;
    vec3 d = st.d_dvcm.xyz;
    float d_vcm = st.d_dvcm.w;
    vec3 beta = st.beta_dvc.xyz;
    float d_vc = st.beta_dvc.w;
    vec3 sigma_near = uintBitsToFloat(st.sigma_seed.xyz);
    // BDPT's values of VCM's terms (vcm.glsl: no merging) and of the megakernel joins'.
    float d_vc_merge = 0.0;
    float d_vm = 0.0;
    bool merge_pending = false;
    VcmFactors k = VcmFactors(0.0, 0.0);
    float vm_light = 0.0;
    uvec2 lc = uvec2(0u);
    uint base = 0u;
    bool alive = false;
    vec3 radiance = vec3(0.0);
    uvec2 stats = uvec2(0u);
    if (status == PT_SUSPENDED) {
        TraceHit h = TraceHit(gh.t, gh.tri, vec2(gh.u, gh.v));
#ifdef BDPT_WF_FINISH
        for (;;) {
#endif
        do {
#include "bdpt_camera_step.glsl"
            alive = true;
            depth++;
        } while (false);
#ifdef BDPT_WF_FINISH
            // The step's sums and its shadow rays, each clear one's contribution on its own
            // (as the next launch would add them), then the next segment.
            add_finite(sum, bad, radiance);
            radiance = vec3(0.0);
            for (uint i = 0u; i < wf_shadow_count; i++) {
                if (shadow_ray_clear(wf_shadow[i], stats)) {
                    add_finite(sum, bad, wf_shadow_contrib[i]);
                }
            }
            wf_shadow_count = 0u;
            if (!alive) {
                break;
            }
            alive = false;
            h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
        }
#endif
    } else if (status == PT_FRESH) {
        o = pc.camera.eye.xyz; // the segment from the eye, queued below
        alive = true;
    }
    add_finite(sum, bad, radiance);

    // The rays, packed at the front of the queues (a subgroup's together, in lane order); in
    // the pass's first launch each path's segment at its slot's place instead (the count is
    // the same: every slot queues one, a slot past the window's pixels one without a segment).
    uvec4 ext_lanes = subgroupBallot(alive);
    uint ext_count = subgroupBallotBitCount(ext_lanes);
    uint shadow_total = subgroupAdd(wf_shadow_count);
    uvec2 queue_base = uvec2(0u);
    if (subgroupElect() && !fresh) { // (the first launch's rays are at the slots' places)
        queue_base.x = ext_count > 0u ? atomicAdd(wf_counts[2u * launch], ext_count) : 0u;
        queue_base.y = shadow_total > 0u ? atomicAdd(wf_counts[2u * launch + 1u], shadow_total) : 0u;
    }
    queue_base = subgroupBroadcastFirst(queue_base);
    uvec2 next = uvec2(queue_base.x + subgroupBallotExclusiveBitCount(ext_lanes), queue_base.y + subgroupExclusiveAdd(wf_shadow_count));
    if (fresh) {
        wf_queue_segment(g, o, d, blend_seed); // every path is live: no state yet
    } else if (alive) {
        camera_state_store(g, BdptCameraState(uvec4(floatBitsToUint(sum), depth), vec4(d, d_vcm), vec4(beta, d_vc),
            uvec4(floatBitsToUint(sigma_near), blend_seed), uvec4(rng.state, rng.index, rng.dim, PT_SUSPENDED)),
            wf_queue_word(next, wf_shadow_count));
        wf_queue_segment(next.x, o, d, blend_seed);
    } else if (wf_shadow_count > 0u) {
        // The path ended with shadow rays pending: the next launch adds what they carry.
        state_words[g * WF_STATE_STRIDE] = uvec4(floatBitsToUint(sum), WF_PATH_DONE);
        state_words[g * WF_STATE_STRIDE + 3u].zw = wf_queue_word(next, wf_shadow_count);
    }
    for (uint i = 0u; i < wf_shadow_count; i++) {
        wf_queue_shadow(next.y + i, wf_shadow[i].o, wf_shadow[i].d, wf_shadow[i].tmax, blend_seed);
        wf_contrib[write_half + next.y + i] = contrib_pack(wf_shadow_contrib[i]);
    }
    wf_list_next(pc.launch, g, alive || wf_shadow_count > 0u);

    if (!alive && wf_shadow_count == 0u) {
        // Nothing left to add: the sample's sum and count to its pixel (or its slice's), once.
        if (samples == 1u) {
            accum[pixel] += vec4(sum, 1.0);
        } else {
            slices_out[slice * pixels + pixel] += vec4(sum, 1.0);
        }
    }
    if (bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], bad);
    }
}

void main() {
    run_slot();
#ifndef BDPT_WF_FINISH
    wf_end_launch(pc.launch, camera_slots());
#endif
}
