// The body of the trace kernels (trace.comp: geometry only; trace_alpha.comp: through
// scene.glsl, so alpha-masked triangles are skipped exactly as the integrators skip them).
// Traces a buffer of rays: closest hit, or any hit when SPEC_ANY_HIT is set (shadow rays).
// The includer has included the ABI header and traverse.glsl (directly or via scene.glsl),
// and enabled GL_KHR_shader_subgroup_ballot.
#ifndef BIDIR_TRACE_KERNEL_GLSL
#define BIDIR_TRACE_KERNEL_GLSL

#include "ray_words.glsl"

// A kernel may pick another workgroup size (trace_wg*.comp: `bench traversal
// --workgroup-size`) by defining TRACE_KERNEL_WG_SIZE first.
#ifndef TRACE_KERNEL_WG_SIZE
#define TRACE_KERNEL_WG_SIZE TRACE_WG_SIZE
#endif
layout(local_size_x = TRACE_KERNEL_WG_SIZE) in;
layout(constant_id = SPEC_ANY_HIT) const uint ANY_HIT = 0u;
layout(constant_id = SPEC_PERSISTENT) const uint PERSISTENT = 0u;
layout(constant_id = SPEC_RAYS_PER_INVOCATION) const uint RAYS_PER_INVOCATION = 1u;
layout(std430, binding = BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
// The same rays in a compact form (SPEC_RAY_WORDS; ray_words.glsl), viewed as 16-, 8- and
// 4-byte words.
layout(constant_id = SPEC_RAY_WORDS) const uint RAY_WORDS = RAY_WORDS_FULL;
layout(std430, binding = BIND_RAYS) readonly buffer RayQuads { uvec4 ray_quads[]; };
layout(std430, binding = BIND_RAYS) readonly buffer RayPairs { uvec2 ray_pairs[]; };
layout(std430, binding = BIND_RAYS) readonly buffer RayWords { uint ray_words[]; };

// Ray i of the queue, in whichever form it was queued.
GpuRay load_ray(uint i) {
    if (RAY_WORDS == RAY_WORDS_FULL) {
        return rays[i];
    }
    uint cap = uint(ray_quads.length()) / 2u; // the queue's 32-byte places
    uint word = RAY_WORDS == RAY_WORDS_BOUNDED ? ray_words[ray_word_index(i, cap)] : 0u;
    return ray_from_parts(RAY_WORDS, ray_quads[i], ray_pairs[ray_pair_index(i, cap)], word);
}
// Per ray its GpuHit's four words (t, tri, u, v); with SPEC_HIT_WORDS (any-hit kernels) one
// word per ray instead, the hit's `tri` (NO_HIT: clear), the buffer read as words.
layout(std430, binding = BIND_HITS) writeonly buffer Hits { uvec4 hits[]; };
layout(constant_id = SPEC_HIT_WORDS) const uint HIT_WORDS = 0u;

void store_hit(uint i, TraceHit h) {
    if (HIT_WORDS != 0u) {
        hits[i >> 2u][i & 3u] = h.prim;
    } else {
        hits[i] = uvec4(floatBitsToUint(h.t), h.prim, floatBitsToUint(h.bary));
    }
}
layout(std430, binding = BIND_STATS) buffer Stats { uint stat_nodes; uint stat_tris; };
// Persistent kernels: the next ray to fetch, and the launch's finished workgroups; the last
// to finish leaves both at 0 for the next launch (`Tracer` zeroes them once, when made).
layout(std430, binding = BIND_RAY_COUNTER) coherent buffer RayCounter { uint next_ray; uint groups_done; };
layout(push_constant) uniform Push { TracePush pc; };
layout(constant_id = SPEC_RAY_COUNT_BUFFER) const uint RAY_COUNT_BUFFER = 0u;
layout(std430, binding = BIND_RAY_COUNTS) readonly buffer RayCounts { uint ray_counts[]; };

// Rays to trace: pc.count, or (SPEC_RAY_COUNT_BUFFER) as many as a kernel before queued.
uint ray_total = 0u;

#ifdef TRAVERSE_WITH_ALPHA
layout(constant_id = SPEC_RAY_SEED) const uint RAY_SEED = 0u;
#endif

// Where ray `r`'s segment starts: its tmin, or (SPEC_RAY_SEED, the wavefront path tracer's
// rays) 0, its tmin slot then holding the path's stochastic-opacity seed, set here.
float ray_tmin(GpuRay r) {
#ifdef TRAVERSE_WITH_ALPHA
    if (RAY_SEED != 0u) {
        blend_seed = floatBitsToUint(r.origin.w);
        return 0.0;
    }
#endif
    return r.origin.w;
}

void trace_one(uint i, inout uvec2 stats) {
    GpuRay r = load_ray(i);
    TraceHit h = TraceHit(r.dir.w, NO_HIT, vec2(0.0));
    // Lockstep loops (SPEC_LOCKSTEP) take every lane, a ray without a segment too (it is
    // done at once): the call then sits in no branch.
    if (LOCKSTEP != 0u || r.dir.w >= 0.0) {
        h = trace_ray(r.origin.xyz, r.dir.xyz, ray_tmin(r), r.dir.w, ANY_HIT != 0u, stats);
    }
    store_hit(i, h);
}

// (Not in the lockstep kernel, trace_bvh4_lockstep.comp: its leaf tests read the origin that
// trace_ray_lockstep keeps in shared memory; nor in the packet kernel, trace_bvh4_packet.comp.)
#if defined(TRAVERSE_BVH4) && !defined(TRACE_LOCKSTEP_KERNEL) && !defined(TRACE_PACKET)
layout(constant_id = SPEC_REFILL_LANES) const uint REFILL_LANES = 0u;

// Persistent threads with dynamic fetch (Aila & Laine 2009, section 3's "dynamic fetch"):
// the 4-wide traversal's lockstep loops (traverse_bvh4.glsl) with rays taken from the global
// counter whenever REFILL_LANES lanes of the subgroup are done, so that a subgroup keeps few
// lanes idle behind its slowest ray. A done lane writes its hit at the next refill; the loop
// ends when the rays have run out (or the subgroup's refills, pc.max_batches) and no lane
// holds one.
void trace_dynamic(inout uvec2 stats) {
    const uint NO_RAY = 0xffffffffu;
    bool any_hit = ANY_HIT != 0u;
    int root = bvh4_root(any_hit);
    uint ray = NO_RAY;
    bool exhausted = false;
    uint refills = 0u;
    PreparedRay pr = prepare_ray(vec3(0.0), vec3(0.0, 0.0, 1.0), 0.0);
    Bvh4Ray br = bvh4_ray(vec3(0.0), vec3(0.0, 0.0, 1.0));
    vec3 idir = br.idir, ood_near = br.ood_near, ood_far = br.ood_far;
    uint nx = br.nx, ny = br.ny, nz = br.nz;
    float tmin = 0.0;
    TraceHit hit = TraceHit(0.0, NO_HIT, vec2(0.0));
    TRAVERSAL_STACK_INIT();
    int node = int(TRAVERSAL_SENTINEL);
    int leaf = 0;
    // Every lane of a persistent subgroup runs the loop to its end.
    uint refill_at = min(REFILL_LANES, subgroupBallotBitCount(subgroupBallot(true)));
    while (true) {
        bool idle = node == int(TRAVERSAL_SENTINEL);
        uvec4 idle_lanes = subgroupBallot(idle);
        uint idle_count = subgroupBallotBitCount(idle_lanes);
        if (idle_count >= refill_at) {
            if (idle && ray != NO_RAY) {
                store_hit(ray, hit);
                ray = NO_RAY;
            }
            if (!exhausted) {
                uint base = 0u;
                if (subgroupElect()) {
                    base = atomicAdd(next_ray, idle_count);
                }
                base = subgroupBroadcastFirst(base);
                // At most pc.max_batches refills per subgroup (the host sizes the launch for
                // that; see persistent_launch: llvmpipe's loop limiter).
                refills++;
                exhausted = base + idle_count >= ray_total || refills >= pc.max_batches;
                uint i = base + subgroupBallotExclusiveBitCount(idle_lanes);
                if (idle && i < ray_total) {
                    GpuRay r = load_ray(i);
                    ray = i;
                    tmin = ray_tmin(r);
                    pr = prepare_ray(r.origin.xyz, r.dir.xyz, tmin);
#ifdef TRACE_SHARE_LEAVES
                    share_store_ray(pr);
#endif
                    br = bvh4_ray(r.origin.xyz, r.dir.xyz);
                    idir = br.idir;
                    ood_near = br.ood_near;
                    ood_far = br.ood_far;
                    nx = br.nx;
                    ny = br.ny;
                    nz = br.nz;
                    hit = TraceHit(r.dir.w, NO_HIT, vec2(0.0));
                    sp = 0;
                    // A ray without a segment (tmax < 0) is done at once, as trace_one has it.
                    node = r.dir.w >= 0.0 ? root : int(TRAVERSAL_SENTINEL);
                    leaf = 0;
                }
            }
            if (!subgroupAny(ray != NO_RAY)) {
                break;
            }
        }
        while (true) {
            if (uint(node) < TRAVERSAL_SENTINEL) {
#define TRAVERSAL_CHILDREN_ON_HIT
                #include "traverse_bvh4_step.glsl"
#undef TRAVERSAL_CHILDREN_ON_HIT
            }
            if (TRAVERSAL_DESCEND_LOCKSTEP()) {
                break;
            }
        }
#ifdef TRACE_SHARE_LEAVES
        TRAVERSAL_LEAVES_SHARED();
#else
        TRAVERSAL_LEAVES_LOCKSTEP();
#endif
    }
}
#endif

void main() {
    ray_total = RAY_COUNT_BUFFER != 0u ? min(ray_counts[pc.count_index], pc.count) : pc.count;
    uvec2 stats = uvec2(0u);
#if defined(TRAVERSE_BVH4) && !defined(TRACE_LOCKSTEP_KERNEL) && !defined(TRACE_PACKET)
    if (PERSISTENT != 0u && REFILL_LANES != 0u) {
        trace_dynamic(stats);
    } else
#endif
    if (PERSISTENT != 0u) {
        // Persistent threads (Aila & Laine 2009, section 3): only as many workgroups as the
        // GPU keeps resident are launched, and each subgroup fetches a batch of
        // gl_SubgroupSize rays from a global counter whenever all its lanes are done, until
        // the rays run out; the hardware's block scheduler never has to balance the long tail
        // of slow rays. The batch is traced by the lanes active at the fetch, each striding
        // by their count (one step when the subgroup is converged, as it is in practice), so
        // no ray is skipped or traced twice whatever the subgroup size or convergence.
        // At most pc.max_batches batches per subgroup: the host sizes the launch so that
        // this still covers every ray (see Tracer::record_trace; it matters on llvmpipe).
        for (uint batch = 0u; batch < pc.max_batches; batch++) {
            uint base = 0u;
            if (subgroupElect()) {
                base = atomicAdd(next_ray, gl_SubgroupSize);
            }
            base = subgroupBroadcastFirst(base);
            if (base >= ray_total) {
                break; // uniform: every active lane holds the same base
            }
            uvec4 lanes = subgroupBallot(true);
            uint stride = subgroupBallotBitCount(lanes);
            uint end = min(base + gl_SubgroupSize, ray_total);
            for (uint i = base + subgroupBallotExclusiveBitCount(lanes); i < end; i += stride) {
                trace_one(i, stats);
            }
        }
    } else {
        // RAYS_PER_INVOCATION rays, strided by the launch's invocations so that neighbouring
        // lanes keep tracing neighbouring (coherent) rays; the host launches
        // ceil(count / RAYS_PER_INVOCATION) invocations.
        uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
        for (uint k = 0u; k < RAYS_PER_INVOCATION; k++) {
            uint i = gl_GlobalInvocationID.x + k * stride;
            if (i < ray_total) {
                trace_one(i, stats);
            }
        }
    }
    if (TRAVERSAL_STATS != 0u) {
        uvec2 s = subgroupAdd(stats);
        if (subgroupElect()) {
            atomicAdd(stat_nodes, s.x);
            atomicAdd(stat_tris, s.y);
        }
    }
    if (PERSISTENT != 0u) {
        // The counter reset for the next launch by the last workgroup to finish (every other
        // one is done fetching), so that no fill and barrier precede a launch: the pattern of
        // CUDA's threadFenceReduction sample, each workgroup's fetches ordered before its count.
        memoryBarrierBuffer();
        barrier();
        if (gl_LocalInvocationIndex == 0u && atomicAdd(groups_done, 1u) + 1u == gl_NumWorkGroups.x) {
            atomicExchange(next_ray, 0u);
            atomicExchange(groups_done, 0u);
        }
    }
}

#endif
