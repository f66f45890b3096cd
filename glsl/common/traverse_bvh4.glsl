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
// nearest is visited next, the others pushed far to near. Any-hit rays skip the ordering.

layout(std430, binding = BIND_NODES) readonly buffer Bvh4Nodes { Bvh4Node bvh4_nodes[]; };

// Child pointer of slot (s & 3), as selects (see pick3 in intersect.glsl).
int pick4(ivec4 v, uint s) {
    return (s & 2u) != 0u ? ((s & 1u) != 0u ? v.w : v.z) : ((s & 1u) != 0u ? v.y : v.x);
}

// Closest hit in (tmin, tmax), or with `any_hit` the first hit found. `stats` counts 4-wide
// nodes visited (x) and triangles tested (y) when TRAVERSAL_STATS is set.
TraceHit trace_ray(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats) {
    PreparedRay pr = prepare_ray(o, d, tmin);
    if (TRAVERSAL_STATS != 0u) {
        traversal_counts.x++;
    }
    vec3 dd = vec3(abs(d.x) > 1e-20 ? d.x : (d.x >= 0.0 ? 1e-20 : -1e-20),
                   abs(d.y) > 1e-20 ? d.y : (d.y >= 0.0 ? 1e-20 : -1e-20),
                   abs(d.z) > 1e-20 ? d.z : (d.z >= 0.0 ? 1e-20 : -1e-20));
    vec3 idir = 1.0 / dd;
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
    uint nx = dd.x < 0.0 ? 1u : 0u;
    uint ny = dd.y < 0.0 ? 3u : 2u;
    uint nz = dd.z < 0.0 ? 5u : 4u;

    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    TRAVERSAL_STACK_INIT();
    int node = 0;   // root
    int leaf = 0;   // postponed leaf (< 0), none if >= 0

    while (node != int(TRAVERSAL_SENTINEL)) {
        // Inner nodes: descend until this lane holds a leaf and every active lane does.
        while (uint(node) < TRAVERSAL_SENTINEL) {
            if (TRAVERSAL_STATS != 0u) {
                stats.x++;
                traversal_counts.y++;
            }
            // The children's pointers are read with the planes; the next node is chosen
            // without a branch (TRAVERSAL_STACK_NEXT).
            ivec4 children = bvh4_nodes[node].children;
            vec4 near_x = bvh4_nodes[node].planes[nx] * idir.x - ood_near.x;
            vec4 far_x = bvh4_nodes[node].planes[nx ^ 1u] * idir.x - ood_far.x;
            vec4 near_y = bvh4_nodes[node].planes[ny] * idir.y - ood_near.y;
            vec4 far_y = bvh4_nodes[node].planes[ny ^ 1u] * idir.y - ood_far.y;
            vec4 near_z = bvh4_nodes[node].planes[nz] * idir.z - ood_near.z;
            vec4 far_z = bvh4_nodes[node].planes[nz ^ 1u] * idir.z - ood_far.z;
            vec4 t_near, t_far;
            if (INT_SLABS != 0u) {
                // On the bits as signed integers, as in the binary kernel: tmin and hit.t are
                // not negative, so a negative distance loses to tmin in t_near and rejects the
                // box in t_far whichever the integer order picks.
                ivec4 lo = ivec4(floatBitsToInt(tmin)), hi = ivec4(floatBitsToInt(hit.t));
                t_near = intBitsToFloat(max(max(floatBitsToInt(near_x), floatBitsToInt(near_y)), max(floatBitsToInt(near_z), lo)));
                t_far = intBitsToFloat(min(min(floatBitsToInt(far_x), floatBitsToInt(far_y)), min(floatBitsToInt(far_z), hi)));
            } else {
                t_near = max(max(near_x, near_y), max(near_z, vec4(tmin)));
                t_far = min(min(far_x, far_y), min(far_z, vec4(hit.t)));
            }
            bvec4 hit4 = lessThanEqual(t_near, t_far * BOX_EXIT_SCALE);
            if (any_hit) {
                // Any hit ends the ray, so the order of the hit children matters less than
                // the work of ordering them: the lowest hit slot next, the others pushed as
                // they come (no keys, no sorting network). H200, Sponza, leaf size 3, quality
                // 3: shadow rays 6.30-6.32 against 5.97-6.02 Grays/s sorted, though they
                // visit 15.8 nodes against 14.8 (session 13).
                uint m = (hit4.x ? 1u : 0u) | (hit4.y ? 2u : 0u) | (hit4.z ? 4u : 0u) | (hit4.w ? 8u : 0u);
                TRAVERSAL_STACK_NEXT(node, m == 0u, pick4(children, uint(findLSB(m))), 0);
                m &= m - 1u;
                for (int i = 0; i < 3 && m != 0u; i++) {
                    TRAVERSAL_STACK_PUSH(pick4(children, uint(findLSB(m))), 0);
                    m &= m - 1u;
                }
            } else {
                uvec4 key = mix(uvec4(0xffffffffu), (floatBitsToUint(t_near) & ~3u) | uvec4(0u, 1u, 2u, 3u), hit4);
                // Sorting network (0,1) (2,3) (0,2) (1,3) (1,2): k0 nearest .. k3 farthest.
                uint a = min(key.x, key.y), b = max(key.x, key.y);
                uint c = min(key.z, key.w), e = max(key.z, key.w);
                uint k0 = min(a, c), k3 = max(b, e);
                uint f = max(a, c), g = min(b, e);
                uint k1 = min(f, g), k2 = max(f, g);
                bool none = k0 == 0xffffffffu;
                TRAVERSAL_STACK_NEXT(node, none, pick4(children, k0), stack_cull_bits(hit.t));
                if (k3 != 0xffffffffu) {
                    TRAVERSAL_STACK_PUSH(pick4(children, k3), int(k3 & ~3u));
                }
                if (k2 != 0xffffffffu) {
                    TRAVERSAL_STACK_PUSH(pick4(children, k2), int(k2 & ~3u));
                }
                if (k1 != 0xffffffffu) {
                    TRAVERSAL_STACK_PUSH(pick4(children, k1), int(k1 & ~3u));
                }
            }
            // Postpone a leaf and keep descending (speculative traversal).
            if (node < 0 && leaf >= 0) {
                leaf = node;
                TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));
            }
            // As !subgroupAny rather than subgroupAll(leaf < 0): the same vote, 1-2 % faster on
            // the H200 (session 12).
            if (SPECULATIVE != 0u ? !subgroupAny(leaf >= 0) : leaf < 0) {
                break;
            }
        }
        // Leaves: this lane's postponed leaf, then `node` if it is a leaf too.
        while (leaf < 0) {
            uint first = uint(leaf) & ((1u << LEAF_FIRST_BITS) - 1u);
            uint count = ((uint(leaf) >> LEAF_FIRST_BITS) & 15u) + 1u;
            for (uint i = first; i < first + count; i++) {
                if (test_leaf_triangle(pr, i, hit, stats) && any_hit) {
                    return hit;
                }
            }
            leaf = node;
            if (node < 0) {
                TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));
            }
        }
    }
    return hit;
}
