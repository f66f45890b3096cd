// 4-wide BVH traversal over full-precision boxes (Bvh4Node in src/gpu/abi.rs, built by
// src/bvh/wide4.rs from the binary tree). Included by traverse.glsl when TRAVERSE_BVH4 is
// defined; same interface as its binary trace_ray, same speculative while-while structure
// (Aila & Laine 2009) and leaf pointers: only the node step differs.
//
// Node step: a ray reads each axis' near planes of the four children at 2 a + (d[a] < 0) and
// the far ones at 2 a + 1 - (d[a] < 0), so the slab test needs no min/max per plane pair; an
// empty slot (lower +inf, upper -inf) gets near +inf and far -inf and is never hit. The hit
// children are ordered by entry distance with a five-comparator sorting network on keys that
// hold the distance's bits with the child's slot in the two lowest (distances are not
// negative, so their bits sort as unsigned integers; the two bits only break near-ties). The
// nearest is visited next, the others pushed far to near. Any-hit rays skip the ordering:
// they traverse their own copy of the nodes (src/bvh/occlusion.rs), whose slots the build
// ordered for them, from the root that node 0's reserved.x names (0: the one tree).

layout(std430, binding = BIND_NODES) readonly buffer Bvh4Nodes { Bvh4Node bvh4_nodes[]; };

// Where a ray starts: the root of the any-hit copy for any-hit rays, else node 0.
int bvh4_root(bool any_hit) {
    return any_hit ? int(bvh4_nodes[0].reserved.x) : 0;
}

// Child pointer of slot (s & 3), as selects (see pick3 in intersect.glsl).
int pick4(ivec4 v, uint s) {
    return (s & 2u) != 0u ? ((s & 1u) != 0u ? v.w : v.z) : ((s & 1u) != 0u ? v.y : v.x);
}

// What a ray's node steps need: its reciprocal direction, the origin's slab term widened
// for near and far planes, and the index of each axis' near planes.
struct Bvh4Ray {
    vec3 idir;
    vec3 ood_near;
    vec3 ood_far;
    uint nx, ny, nz;
};

Bvh4Ray bvh4_ray(vec3 o, vec3 d) {
    vec3 idir = traversal_inverse_direction(d);
    // Slab distances as one multiply-add per plane, p idir - o idir, with o idir computed
    // once per ray (written plainly, the compiler factors it back into (p - o) idir, two
    // instructions). o idir's rounding is an absolute error that BOX_EXIT_SCALE's relative
    // widening does not cover far from the world's origin (tests/traversal.rs,
    // small_triangles_far_from_the_origin...), so near planes subtract it raised, far planes
    // lowered, by four units of rounding of its magnitude (as the compressed wide kernel
    // widens its slabs); the multiply-add's own rounding stays relative, as Ize's bound has
    // it. H200, Sponza, leaf size 3, quality 3: 4.96 / 5.94 / 1.96 Grays/s against 4.85 /
    // 5.82 / 1.92 as (p - o) idir; the binary kernel gained nothing this way (session 12).
    precise vec3 ood = o * idir;
    precise vec3 slack = abs(ood) * (1.0 / 4194304.0);
    precise vec3 ood_near = ood + slack;
    precise vec3 ood_far = ood - slack;
    uint nx = idir.x < 0.0 ? 1u : 0u;
    uint ny = idir.y < 0.0 ? 3u : 2u;
    uint nz = idir.z < 0.0 ? 5u : 4u;
    return Bvh4Ray(idir, ood_near, ood_far, nx, ny, nz);
}

#ifdef TRACE_PACKET
#include "traverse_bvh4_packet.glsl"
#endif

// Closest hit in (tmin, tmax), or with `any_hit` the first hit found. `stats` counts 4-wide
// nodes visited (x) and triangles tested (y) when TRAVERSAL_STATS is set.
TraceHit trace_ray(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats) {
#ifdef TRACE_PACKET
    return trace_ray_packet(o, d, tmin, tmax, any_hit, stats);
#endif
    if (LOCKSTEP != 0u && SPECULATIVE != 0u) {
        return trace_ray_lockstep(o, d, tmin, tmax, any_hit, stats);
    }
    PreparedRay pr = prepare_ray(o, d, tmin);
    if (TRAVERSAL_STATS != 0u) {
        traversal_counts.x++;
    }
    Bvh4Ray br = bvh4_ray(o, d);
    vec3 idir = br.idir, ood_near = br.ood_near, ood_far = br.ood_far;
    uint nx = br.nx, ny = br.ny, nz = br.nz;

    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    TRAVERSAL_STACK_INIT();
    int node = bvh4_root(any_hit);
    int leaf = 0;   // postponed leaf (< 0), none if >= 0

    while (node != int(TRAVERSAL_SENTINEL)) {
        // Inner nodes: descend until this lane holds a leaf and every active lane does.
        while (uint(node) < TRAVERSAL_SENTINEL) {
            #include "traverse_bvh4_step.glsl"
            // As !subgroupAny rather than subgroupAll(leaf < 0): the same vote, 1-2 % faster on
            // the H200 (session 12).
            if (SPECULATIVE != 0u ? !subgroupAny(leaf >= 0) : leaf < 0) {
                break;
            }
        }
        TRAVERSAL_LEAVES();
    }
    return hit;
}
