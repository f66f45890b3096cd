// BVH traversal: Aila & Laine 2009, "Understanding the Efficiency of Ray Traversal on GPUs",
// the "speculative while-while" kernel. An inner-node loop and a leaf loop; a ray that
// reaches a leaf postpones it and keeps descending until every active lane of its subgroup
// holds a leaf (a subgroup vote, as the paper's warp __any), so the leaf loop runs with the
// subgroup converged. Correct for any subgroup size: the vote only steers scheduling.
//
// Needs GL_KHR_shader_subgroup_vote and the ABI header. Declares the node and triangle
// buffers at BIND_NODES / BIND_TRIS. With TRAVERSE_CWBVH defined before inclusion, the nodes
// are compressed 8-wide ones and trace_ray is the one of traverse_cwbvh.glsl; with
// TRAVERSE_BVH2Q, they are quantised binary ones, decoded by traverse_bvh2q.glsl's fetch_node.
// With TRAVERSE_BVH4, they are 4-wide ones and trace_ray is traverse_bvh4.glsl's (the same
// stack and speculative loop). With TRAVERSE_SHORT_STACK (trace kernels only: it declares workgroup shared memory), the
// binary traversal's stack is traverse_short_stack.glsl's.
#ifndef BIDIR_TRAVERSE_GLSL
#define BIDIR_TRAVERSE_GLSL

#include "intersect.glsl"

layout(std430, binding = BIND_TRIS) readonly buffer BvhTris { GpuTri bvh_tris[]; };

layout(constant_id = SPEC_STATS) const uint TRAVERSAL_STATS = 0u;

// This invocation's rays (x), node visits (y) and triangle tests (z) over every trace_ray
// call, when TRAVERSAL_STATS is set; the integrator kernels add them to the render stats at
// their end (ADD_TRAVERSAL_COUNTS), the trace kernels count through their `stats` instead.
uvec3 traversal_counts = uvec3(0u);
#define ADD_TRAVERSAL_COUNTS(stats_buffer)                                                         \
    if (TRAVERSAL_STATS != 0u) {                                                                   \
        atomicAdd(stats_buffer[STAT_RAYS], traversal_counts.x);                                    \
        atomicAdd(stats_buffer[STAT_NODES], traversal_counts.y);                                   \
        atomicAdd(stats_buffer[STAT_TRIS], traversal_counts.z);                                    \
    }

// Slightly widens a box's exit distance so rounding in the slab test never culls a box the
// ray touches (cf. Ize 2013, "Robust BVH Ray Traversal").
const float BOX_EXIT_SCALE = 1.0000004;

// The ray's reciprocal direction, with zero components replaced by tiny ones of the same sign
// (every slab distance finite; each component has the sign of the direction's).
vec3 traversal_inverse_direction(vec3 d) {
    vec3 dd = vec3(abs(d.x) > 1e-20 ? d.x : (d.x >= 0.0 ? 1e-20 : -1e-20),
                   abs(d.y) > 1e-20 ? d.y : (d.y >= 0.0 ? 1e-20 : -1e-20),
                   abs(d.z) > 1e-20 ? d.z : (d.z >= 0.0 ? 1e-20 : -1e-20));
    return 1.0 / dd;
}

#ifdef TRAVERSE_WITH_ALPHA
// Defined by the includer (scene.glsl): false where an alpha-tested triangle has a hole.
bool traverse_alpha_hit(uint prim, vec2 bary);
#endif

// Result of a query. `prim` is the leaf-order triangle index (bvh_tris), NO_HIT if none.
struct TraceHit {
    float t;
    uint prim;
    vec2 bary;
};

// Tests leaf triangle `i` (leaf order) against the ray: true if it is hit nearer than `hit`
// (and, with alpha testing, not through a hole), `hit` then holding it. Both layouts' leaf
// loops call it.
bool test_leaf_triangle(PreparedRay pr, uint i, inout TraceHit hit, inout uvec2 stats) {
    if (TRAVERSAL_STATS != 0u) {
        stats.y++;
        traversal_counts.z++;
    }
    float t;
    vec2 bary;
    GpuTri tri = bvh_tris[i];
    if (!intersect_tri(pr, tri, hit.t, t, bary)) {
        return false;
    }
#ifdef TRAVERSE_WITH_ALPHA
    // A watertight triangle says in a.w whether its material may reject a hit (0: it never
    // does; Bvh::alpha_marked_tris): an opaque one takes no material lookup. Woop's
    // triangles use w, so each of their hits looks.
    bool may_reject = TRI_TEST != TRI_TEST_WATERTIGHT || floatBitsToUint(tri.a.w) != 0u;
    if (HAS_ALPHA != 0u && may_reject && !traverse_alpha_hit(i, bary)) {
        return false;
    }
#endif
    hit = TraceHit(t, i, bary);
    return true;
}

// 1 (default): the slab tests' minima and maxima on the distances' bits as signed integers
// (see trace_ray and cwbvh_intersect_children); 0: as floats. The same boxes are hit either way.
layout(constant_id = SPEC_INT_SLABS) const uint INT_SLABS = 1u;
// Lockstep loops (SPEC_LOCKSTEP; trace_ray_lockstep of the binary and 4-wide layouts, with
// speculative traversal): every lane of the subgroup runs the traversal's loops until no lane
// has work left, a lane whose ray is done idling, and the loops end on subgroup votes. The
// speculative vote then sits in loops the subgroup runs together, which NVIDIA's compiler
// turns into one vote and a cheap check of the lanes, instead of a convergence test (MATCH,
// REDUX) with an active mask kept in shared memory per step (scripts/device/sass.py). H200,
// Sponza, `bench traversal`: binary +4 % / +9 % / +3 %, 4-wide (leaf size 3, quality 3) +4 %
// / +5 % / +2.5 % on primary / shadow / diffuse rays; in the integrators' megakernels the same
// loops cost 3-19 %, so only the trace kernels use them (session 16, docs/traversal.md).
layout(constant_id = SPEC_LOCKSTEP) const uint LOCKSTEP = 0u;

#ifdef TRAVERSE_CWBVH
#include "traverse_cwbvh.glsl"
#else

#if defined(TRAVERSE_BVH2Q)
#include "traverse_bvh2q.glsl"
#elif !defined(TRAVERSE_BVH4)
layout(std430, binding = BIND_NODES) readonly buffer BvhNodes { BvhNode bvh_nodes[]; };
BvhNode fetch_node(int node) {
    return bvh_nodes[node];
}
#endif
layout(constant_id = SPEC_SPECULATIVE) const uint SPECULATIVE = 1u;

#ifdef TRAVERSE_SHORT_STACK
#include "traverse_short_stack.glsl"
#else
// The traversal stack: TRAVERSAL_STACK_SIZE entries per ray in local memory, the sentinel at
// the bottom. Each entry holds a pushed child and its box's entry distance (as the bits of a
// float that is not negative, at most the distance the box test computed); a pop skips the
// entries past `cull`, the bits of the nearest hit's distance widened as the box test widens
// a box's exit (BOX_EXIT_SCALE). Those are exactly the boxes the test would reject if run
// again, so the hits do not change; a closest-hit ray no longer visits the far nodes it
// pushed before it found its hit (Sponza, 4-wide, leaf size 3: primary rays 22.1 -> 18.3
// nodes and 7.3 -> 4.8 triangles, diffuse 22.1 -> 20.1 and 9.9 -> 7.3; session 12). The
// sentinel (distance 0) is never skipped.
#define TRAVERSAL_STACK_INIT()                                                                     \
    ivec2 stack[TRAVERSAL_STACK_SIZE];                                                             \
    int sp = 0;                                                                                    \
    stack[0] = ivec2(int(TRAVERSAL_SENTINEL), 0)
// Any-hit rays (`any_hit`, constant where trace_ray is inlined) skip nothing: they stop at
// their first hit, and their entries' distances are neither stored nor read.
#define TRAVERSAL_STACK_PUSH(child, t_bits)                                                        \
    if (any_hit) {                                                                                 \
        stack[++sp].x = (child);                                                                   \
    } else {                                                                                       \
        stack[++sp] = ivec2((child), (t_bits));                                                    \
    }
#define TRAVERSAL_STACK_POP(dst, cull)                                                             \
    if (any_hit) {                                                                                 \
        dst = stack[sp--].x;                                                                       \
    } else {                                                                                       \
        ivec2 e_ = stack[sp--];                                                                    \
        while (e_.y > (cull)) {                                                                    \
            e_ = stack[sp--];                                                                      \
        }                                                                                          \
        dst = e_.x;                                                                                \
    }
// The top entry (node, distance bits) without popping it, and a pop of it only where `c`
// holds: with these a node step chooses its next node without a branch (see
// TRAVERSAL_STACK_NEXT).
#define TRAVERSAL_STACK_TOP() (any_hit ? ivec2(stack[sp].x, 0) : stack[sp])
#define TRAVERSAL_STACK_DROP_IF(c) sp -= (c) ? 1 : 0
#endif

// A node step's next node: `nearest` (the nearest hit child, read with the node) unless no
// child was hit (`none`), then the stack's top, or the first entry below it not past `cull`.
// The choice is a select, not a branch: with the child read only where a box was hit, the
// compiler sank its load after the box test, a second dependent fetch per step (seen in the
// machine code, scripts/device/sass.py; session 12).
#define TRAVERSAL_STACK_NEXT(dst, none, nearest, cull)                                            \
    {                                                                                              \
        ivec2 top_ = TRAVERSAL_STACK_TOP();                                                        \
        dst = (none) ? top_.x : (nearest);                                                         \
        TRAVERSAL_STACK_DROP_IF(none);                                                             \
        if ((none) && top_.y > (cull)) {                                                           \
            TRAVERSAL_STACK_POP(dst, cull);                                                        \
        }                                                                                          \
    }

// The bits `cull` of TRAVERSAL_STACK_POP for a nearest hit at distance t.
int stack_cull_bits(float t) {
    return floatBitsToInt(t * BOX_EXIT_SCALE);
}

// The leaf phase of trace_ray (the binary and 4-wide layouts' divergent loops): this lane's
// postponed leaf, then `node` if it is a leaf too, each leaf's triangles in turn; an any-hit
// ray returns at its first hit.
#define TRAVERSAL_LEAVES()                                                                         \
    while (leaf < 0) {                                                                             \
        uint first_ = uint(leaf) & ((1u << LEAF_FIRST_BITS) - 1u);                                 \
        uint count_ = ((uint(leaf) >> LEAF_FIRST_BITS) & 15u) + 1u;                                \
        for (uint i_ = first_; i_ < first_ + count_; i_++) {                                       \
            if (test_leaf_triangle(pr, i_, hit, stats) && any_hit) {                               \
                return hit;                                                                        \
            }                                                                                      \
        }                                                                                          \
        leaf = node;                                                                               \
        if (node < 0) {                                                                            \
            TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));                                     \
        }                                                                                          \
    }

// Lockstep loops (LOCKSTEP): the descent ends when no lane has an inner node and no leaf yet
// (lanes holding a postponed leaf keep descending speculatively, done lanes idle).
#define TRAVERSAL_DESCEND_LOCKSTEP() !subgroupAny(uint(node) < TRAVERSAL_SENTINEL && leaf >= 0)
// Their leaf phase: this lane's postponed leaf, then `node` if it is a leaf too; an any-hit
// ray that finds a hit ends its traversal (node = the sentinel) and idles. Closest-hit rays
// loop over the leaves and, inside, over a leaf's triangles. Any-hit rays run one loop over
// triangles: a lane moves on to its next leaf as soon as it has tested one, instead of
// waiting at the end of the inner loop for the lane with the most triangles in its leaf
// (session 29, H200, Sponza CameraMain: shadow rays +1-2 % lockstep, +3 % with dynamic fetch;
// closest-hit rays lost up to 1.5 % that way with dynamic fetch, so they keep the two loops,
// but in the lockstep kernel, below). A leaf pointer counts its triangles less one in the bits
// above LEAF_FIRST_BITS, so the next triangle of a leaf is the pointer plus
// 1 - 2^LEAF_FIRST_BITS.
//
// The 4-wide lockstep kernel (trace_bvh4_lockstep.comp, TRACE_LOCKSTEP_KERNEL: one ray per
// invocation, not persistent) keeps each ray's origin in shared memory and reads it back for
// its leaf tests: no origin stays live through the node loop, so the compiler keeps the slab
// terms o idir (with their slack) in registers instead of recomputing them from the origin in
// every node step (56 registers instead of 48, 36 resident warps instead of 42). With it, its
// closest-hit rays also take the one loop over triangles. H200, Sponza, quality 5, lockstep
// (session 29): primary rays +3-4 % from every camera (CameraMain 5.94 against 5.76 Grays/s in
// the same run), shadow rays up to +2 %, diffuse rays within 1 %. Dynamic fetch keeps its kernel
// (trace_bvh4.comp), which declares no shared array (an unused one cost primary rays 2 % in a
// measurement build: the L1 cache gives way to shared memory whether it is used or not).
#ifdef TRACE_LOCKSTEP_KERNEL
shared vec4 lockstep_origin[TRACE_WG_SIZE];
#define TRAVERSAL_FLAT_LEAVES true
#define TRAVERSAL_LEAF_ORIGIN() pr.o = lockstep_origin[gl_LocalInvocationIndex].xyz
#else
#define TRAVERSAL_FLAT_LEAVES any_hit
#define TRAVERSAL_LEAF_ORIGIN()
#endif
// After a lane has tested `n` triangles of its leaf, `found` whether one was hit: an any-hit
// ray that found one ends its traversal (node = the sentinel) and idles; otherwise the lane
// moves on by n triangles, or, its leaf done (`done`), to `node` if that is a leaf too (then
// popping the stack for the next node) or back to the descent.
#define TRAVERSAL_LEAF_NEXT(found, n, done)                                                        \
    if ((found) && any_hit) {                                                                      \
        node = int(TRAVERSAL_SENTINEL);                                                            \
        leaf = 0;                                                                                  \
    } else if (!(done)) {                                                                          \
        leaf += (n) * (1 - (1 << LEAF_FIRST_BITS));                                                \
    } else {                                                                                       \
        leaf = node;                                                                               \
        if (node < 0) {                                                                            \
            TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));                                     \
        }                                                                                          \
    }
#define TRAVERSAL_LEAVES_LOCKSTEP()                                                                \
    if (TRAVERSAL_FLAT_LEAVES) {                                                                   \
        while (leaf < 0) {                                                                         \
            uint first_ = uint(leaf) & ((1u << LEAF_FIRST_BITS) - 1u);                             \
            bool last_ = ((uint(leaf) >> LEAF_FIRST_BITS) & 15u) == 0u;                            \
            TRAVERSAL_LEAF_ORIGIN();                                                               \
            TRAVERSAL_LEAF_NEXT(test_leaf_triangle(pr, first_, hit, stats), 1, last_);             \
        }                                                                                          \
    } else {                                                                                       \
        while (leaf < 0) {                                                                         \
            uint first_ = uint(leaf) & ((1u << LEAF_FIRST_BITS) - 1u);                             \
            uint count_ = ((uint(leaf) >> LEAF_FIRST_BITS) & 15u) + 1u;                            \
            TRAVERSAL_LEAF_ORIGIN();                                                               \
            for (uint i_ = first_; i_ < first_ + count_; i_++) {                                   \
                test_leaf_triangle(pr, i_, hit, stats);                                            \
            }                                                                                      \
            leaf = node;                                                                           \
            if (node < 0) {                                                                        \
                TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));                                 \
            }                                                                                      \
        }                                                                                          \
    }

#ifdef TRACE_SHARE_LEAVES
// The lockstep leaf phase with its triangle tests shared among the subgroup's lanes
// (trace_bvh4_share.comp, session 30). In the lockstep leaf phase a subgroup runs as many
// rounds as its busiest lane has triangles, the others idle (Sponza's diffuse rays: 19-21
// rounds for 6.7 tests a ray, session 24). Here each round the B lanes that hold a leaf (busy)
// test their leaf's next triangle and the others help: the idle lane of rank s tests triangle
// 1 + s / B of the busy lane of rank s % B, so a busy lane moves on by 1 + its helpers. A
// helper reads the busy lane's ray from shared memory (written when the ray starts: origin, tmin,
// the watertight test's shear and axes; Woop's test adds the direction), tests against the
// busy lane's nearest hit so far, and the busy lane gathers its helpers' hits by shuffles,
// keeping the nearest, on a tie its own and then the lower helper's, that is the earlier
// triangle: the hits of a lane testing its triangles in order. Any-hit rays end at any hit.
// Used by dynamic fetch and by the lockstep loops of one ray per invocation, where the lanes
// past the launch's last ray sit out (only active lanes are ranked, owners and helpers alike).
// Shared slots go by gl_SubgroupID and lane: the workgroup must hold whole subgroups.
const uint SHARE_DIR_N = TRI_TEST == TRI_TEST_WOOP ? TRACE_WG_SIZE : 1u;
shared vec4 share_ray[2u * TRACE_WG_SIZE];
shared vec4 share_dir[SHARE_DIR_N];
shared uint share_lane[TRACE_WG_SIZE];
uint share_slot(uint lane) {
    return gl_SubgroupID * gl_SubgroupSize + lane;
}
void share_store_ray(PreparedRay pr) {
    uint i = share_slot(gl_SubgroupInvocationID);
    share_ray[2u * i] = vec4(pr.o, pr.tmin);
    share_ray[2u * i + 1u] = vec4(pr.sx, pr.sy, pr.sz, uintBitsToFloat(pr.kx | (pr.ky << 2u) | (pr.kz << 4u)));
    if (TRI_TEST == TRI_TEST_WOOP) {
        share_dir[i] = vec4(pr.d, 0.0);
    }
}
PreparedRay share_load_ray(uint lane) {
    uint i = share_slot(lane);
    vec4 a = share_ray[2u * i];
    vec4 b = share_ray[2u * i + 1u];
    uint k = floatBitsToUint(b.w);
    vec3 d = TRI_TEST == TRI_TEST_WOOP ? share_dir[i].xyz : vec3(0.0);
    return PreparedRay(a.xyz, d, a.w, k & 3u, (k >> 2u) & 3u, k >> 4u, b.x, b.y, b.z);
}
#define TRAVERSAL_LEAVES_SHARED()                                                                  \
    while (true) {                                                                                 \
        bool busy_ = leaf < 0;                                                                     \
        uvec4 bm_ = subgroupBallot(busy_);                                                         \
        uint nb_ = subgroupBallotBitCount(bm_);                                                    \
        if (nb_ == 0u) {                                                                           \
            break;                                                                                 \
        }                                                                                          \
        uvec4 im_ = subgroupBallot(!busy_);                                                        \
        uint ni_ = subgroupBallotBitCount(im_);                                                    \
        uint lane_ = gl_SubgroupInvocationID;                                                      \
        uint rank_ = busy_ ? subgroupBallotExclusiveBitCount(bm_) : nb_ + subgroupBallotExclusiveBitCount(im_); \
        share_lane[share_slot(rank_)] = lane_;                                                     \
        subgroupMemoryBarrierShared();                                                             \
        subgroupBarrier();                                                                         \
        uint owner_ = busy_ ? lane_ : share_lane[share_slot((rank_ - nb_) % nb_)];                 \
        uint off_ = busy_ ? 0u : 1u + (rank_ - nb_) / nb_;                                         \
        int oleaf_ = subgroupShuffle(leaf, owner_);                                                \
        float obound_ = subgroupShuffle(hit.t, owner_);                                            \
        uint orem_ = ((uint(oleaf_) >> LEAF_FIRST_BITS) & 15u) + 1u;                               \
        TraceHit h_ = TraceHit(obound_, NO_HIT, vec2(0.0));                                        \
        if (off_ < orem_) {                                                                        \
            test_leaf_triangle(share_load_ray(owner_), (uint(oleaf_) & ((1u << LEAF_FIRST_BITS) - 1u)) + off_, h_, stats); \
        }                                                                                          \
        uint rem_ = busy_ ? orem_ : 0u;                                                            \
        uint jmax_ = min((ni_ + nb_ - 1u) / nb_, subgroupMax(rem_) - 1u);                          \
        uint q_ = busy_ ? rank_ : 0u;                                                              \
        TraceHit best_ = h_;                                                                       \
        for (uint j_ = 0u; j_ < jmax_; j_++) {                                                     \
            uint s_ = q_ + j_ * nb_;                                                               \
            bool valid_ = busy_ && s_ < ni_ && 1u + j_ < rem_;                                     \
            uint hl_ = valid_ ? share_lane[share_slot(nb_ + s_)] : lane_;                          \
            float ht_ = subgroupShuffle(h_.t, hl_);                                                \
            uint hp_ = subgroupShuffle(h_.prim, hl_);                                              \
            vec2 hb_ = subgroupShuffle(h_.bary, hl_);                                              \
            if (valid_ && hp_ != NO_HIT && (best_.prim == NO_HIT || ht_ < best_.t)) {              \
                best_ = TraceHit(ht_, hp_, hb_);                                                   \
            }                                                                                      \
        }                                                                                          \
        subgroupBarrier();                                                                         \
        if (busy_) {                                                                               \
            if (best_.prim != NO_HIT) {                                                            \
                hit = best_;                                                                       \
            }                                                                                      \
            uint helpers_ = ni_ > q_ ? (ni_ - 1u - q_) / nb_ + 1u : 0u;                            \
            uint used_ = min(rem_, 1u + helpers_);                                                 \
            TRAVERSAL_LEAF_NEXT(best_.prim != NO_HIT, int(used_), used_ == rem_);                   \
        }                                                                                          \
    }
#endif

// The lockstep traversal of the binary and 4-wide layouts (below), which their trace_ray calls.
TraceHit trace_ray_lockstep(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats);

#ifdef TRAVERSE_BVH4
#include "traverse_bvh4.glsl"
#else

// Closest hit in (tmin, tmax), or with `any_hit` the first hit found. `stats` counts inner
// nodes visited (x) and triangles tested (y) when TRAVERSAL_STATS is set.
TraceHit trace_ray(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats) {
    if (LOCKSTEP != 0u && SPECULATIVE != 0u) {
        return trace_ray_lockstep(o, d, tmin, tmax, any_hit, stats);
    }
    PreparedRay pr = prepare_ray(o, d, tmin);
    if (TRAVERSAL_STATS != 0u) {
        traversal_counts.x++;
    }
    vec3 idir = traversal_inverse_direction(d);
    vec4 o_xy = o.xxyy;
    vec4 idir_xy = idir.xxyy;

    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    TRAVERSAL_STACK_INIT();
    int node = 0;   // root
    int leaf = 0;   // postponed leaf (< 0), none if >= 0

    while (node != int(TRAVERSAL_SENTINEL)) {
        // Inner nodes: descend until this lane holds a leaf and every active lane does.
        while (uint(node) < TRAVERSAL_SENTINEL) {
            #include "traverse_bvh2_step.glsl"
            // As !subgroupAny rather than subgroupAll(leaf < 0): the same vote, 3 % faster on
            // the H200 (session 12).
            if (SPECULATIVE != 0u ? !subgroupAny(leaf >= 0) : leaf < 0) {
                break;
            }
        }
        TRAVERSAL_LEAVES();
    }
    return hit;
}
#endif // TRAVERSE_BVH4

// trace_ray with the loops in lockstep over the subgroup (LOCKSTEP, the trace kernels): the
// same node step as the layout's trace_ray (its include file), a lane whose ray is done
// idling until every lane's is.
TraceHit trace_ray_lockstep(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats) {
    PreparedRay pr = prepare_ray(o, d, tmin);
#ifdef TRACE_LOCKSTEP_KERNEL
    lockstep_origin[gl_LocalInvocationIndex] = vec4(o, 0.0);
#endif
#ifdef TRACE_SHARE_LEAVES
    share_store_ray(pr);
#endif
    if (TRAVERSAL_STATS != 0u) {
        traversal_counts.x++;
    }
#ifdef TRAVERSE_BVH4
    Bvh4Ray br = bvh4_ray(o, d);
    vec3 idir = br.idir, ood_near = br.ood_near, ood_far = br.ood_far;
    uint nx = br.nx, ny = br.ny, nz = br.nz;
#else
    vec3 idir = traversal_inverse_direction(d);
    vec4 o_xy = o.xxyy;
    vec4 idir_xy = idir.xxyy;
#endif
    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    TRAVERSAL_STACK_INIT();
    // A ray without a segment (tmax < 0) is done at once (no branch around the loops).
#ifdef TRAVERSE_BVH4
    int node = tmax >= 0.0 ? bvh4_root(any_hit) : int(TRAVERSAL_SENTINEL);
#else
    int node = tmax >= 0.0 ? 0 : int(TRAVERSAL_SENTINEL);
#endif
    int leaf = 0;
    while (true) {
        while (true) {
            if (uint(node) < TRAVERSAL_SENTINEL) {
#ifdef TRAVERSE_BVH4
                #include "traverse_bvh4_step.glsl"
#else
                #include "traverse_bvh2_step.glsl"
#endif
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
        if (!subgroupAny(node != int(TRAVERSAL_SENTINEL))) {
            break;
        }
    }
    return hit;
}

#endif // TRAVERSE_CWBVH
#endif
