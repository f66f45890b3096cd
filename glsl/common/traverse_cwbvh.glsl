// Compressed wide BVH traversal: Ylitie, Karras & Laine 2017, "Efficient Incoherent Ray
// Traversal on GPUs Through Compressed Wide BVHs", section 4 (algorithm 1), triangle
// postponing optional (SPEC_CWBVH_POSTPONE). Needs GL_KHR_shader_subgroup_ballot. Included by traverse.glsl when TRAVERSE_CWBVH is defined; same interface as its
// binary trace_ray. Node format: CwbvhNode in src/gpu/abi.rs (obvhs' CwBvhNode).
//
// The stack holds node groups: (first child node, hit bits) where bits 24..31 mark hit inner
// children by traversal priority (bit 24 + (slot ^ octant): children were ordered at build
// time by the octant of the direction they are best visited from, so the highest set bit is
// the nearest child for this ray) and bits 0..7 carry the node's imask, which locates a
// child's node (first child + inner children in lower slots). A triangle group holds the
// node's first triangle and one bit per triangle of the hit leaves (bits 0..23); postponed
// ones share the stack (no bit above 23 tells them apart). Each level of the tree holds at
// most one node group and one triangle group there.

layout(std430, binding = BIND_NODES) readonly buffer CwbvhNodes { CwbvhNode cwbvh_nodes[]; };
layout(constant_id = SPEC_CWBVH_POSTPONE) const uint CWBVH_POSTPONE = 0u;

// 2^-22: four units of rounding (of float's 2^-24) on each term of a quantised slab distance.
const float CWBVH_SLAB_SLACK = 1.0 / 4194304.0;

// The hit bits (see above) of node `n`'s children for a ray with origin `o`, reciprocal
// direction `idir` and interval (tmin, tmax); `oct_inv4` is the inverse octant in each byte.
//
// Slab distances use the node's grid (section 3.1): a child's plane lies at p + q e, so
// t = q (e idir) + (p - o) idir, one multiply-add per plane (e is a power of two: e idir is
// exact). Boxes were rounded outwards when quantised, but the planes of a box that touches
// the node's own bounds sit on them exactly, so rounding here could cull a box the ray just
// grazes; each axis' interval is widened by a bound on that rounding (a few units of the
// terms' magnitudes, |(p - o) idir| + 255 |e idir|) — the role BOX_EXIT_SCALE plays in the
// binary kernel (Ize 2013).
uint cwbvh_intersect_children(CwbvhNode n, vec3 o, vec3 idir, bvec3 neg, float tmin, float tmax, uint oct_inv4) {
    vec3 e = vec3(uintBitsToFloat((n.p_e.w & 0xffu) << 23),
                  uintBitsToFloat(((n.p_e.w >> 8) & 0xffu) << 23),
                  uintBitsToFloat(((n.p_e.w >> 16) & 0xffu) << 23));
    vec3 scale = e * idir;
    vec3 org = (uintBitsToFloat(n.p_e.xyz) - o) * idir;
    vec3 slack = (abs(org) + 255.0 * abs(scale)) * CWBVH_SLAB_SLACK;
    vec3 org_near = org - slack;
    vec3 org_far = org + slack;
    // Near and far planes per axis: the min plane is the near one unless the ray goes down
    // that axis.
    uvec4 qxn = neg.x ? n.qx.zwxy : n.qx;
    uvec4 qyn = neg.y ? n.qy.zwxy : n.qy;
    uvec4 qzn = neg.z ? n.qz.zwxy : n.qz;
    uint hits = 0u;
    for (uint h = 0u; h < 2u; h++) {
        uint meta4 = h == 0u ? n.meta.z : n.meta.w;
        // Per byte: inner children (meta 001 11xxx: bits 3 and 4 both set) get bit index
        // 24 + (slot ^ octant) and one bit; leaves get their triangle offset and their
        // unary triangle count (Ylitie et al., section 4, "node intersection").
        uint is_inner4 = (meta4 & (meta4 << 1)) & 0x10101010u;
        uint inner_mask4 = (is_inner4 >> 4) * 0xffu;
        uint bit_index4 = (meta4 ^ (oct_inv4 & inner_mask4)) & 0x1f1f1f1fu;
        uint child_bits4 = (meta4 >> 5) & 0x07070707u;
        uint xn = qxn[h], xf = qxn[h + 2u];
        uint yn = qyn[h], yf = qyn[h + 2u];
        uint zn = qzn[h], zf = qzn[h + 2u];
        for (uint j = 0u; j < 4u; j++) {
            uint sh = 8u * j;
            float tx0 = float((xn >> sh) & 0xffu) * scale.x + org_near.x;
            float ty0 = float((yn >> sh) & 0xffu) * scale.y + org_near.y;
            float tz0 = float((zn >> sh) & 0xffu) * scale.z + org_near.z;
            float tx1 = float((xf >> sh) & 0xffu) * scale.x + org_far.x;
            float ty1 = float((yf >> sh) & 0xffu) * scale.y + org_far.y;
            float tz1 = float((zf >> sh) & 0xffu) * scale.z + org_far.z;
            float t0, t1;
            if (INT_SLABS != 0u) {
                // On the bits as signed integers, as in the binary kernel: tmin and tmax are
                // not negative, so a negative distance loses to tmin in t0 and rejects the
                // box in t1 whichever the integer order picks.
                t0 = intBitsToFloat(max(max(floatBitsToInt(tx0), floatBitsToInt(ty0)), max(floatBitsToInt(tz0), floatBitsToInt(tmin))));
                t1 = intBitsToFloat(min(min(floatBitsToInt(tx1), floatBitsToInt(ty1)), min(floatBitsToInt(tz1), floatBitsToInt(tmax))));
            } else {
                t0 = max(max(tx0, ty0), max(tz0, tmin));
                t1 = min(min(tx1, ty1), min(tz1, tmax));
            }
            if (t0 <= t1) {
                hits |= ((child_bits4 >> sh) & 0xffu) << ((bit_index4 >> sh) & 0xffu);
            }
        }
    }
    return hits;
}

// Closest hit in (tmin, tmax), or with `any_hit` the first hit found. `stats` counts wide
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
    bvec3 neg = lessThan(dd, vec3(0.0));
    // Inverse octant (7 - octant) in every byte, octant bits x: 4, y: 2, z: 1 (negative).
    uint oct_inv4 = ((neg.x ? 0u : 4u) | (neg.y ? 0u : 2u) | (neg.z ? 0u : 1u)) * 0x01010101u;

    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    uvec2 stack[CWBVH_STACK_SIZE];
    int sp = 0;
    // The root as the only hit child of a virtual node: bit 31 (slot 7 ^ octant), imask 0,
    // so it is child 0 from node 0.
    uvec2 node_group = uvec2(0u, 0x80000000u);
    uvec2 tri_group = uvec2(0u);

    while (true) {
        if (node_group.y > 0x00ffffffu) {
            // Visit the nearest remaining child of the group; keep the rest on the stack.
            uint bit = uint(findMSB(node_group.y));
            uint imask = node_group.y & 0xffu;
            uint child = node_group.x + uint(bitCount(imask & ~(0xffffffffu << ((bit - 24u) ^ (oct_inv4 & 0xffu)))));
            node_group.y &= ~(1u << bit);
            if (node_group.y > 0x00ffffffu) {
                stack[sp++] = node_group;
            }
            CwbvhNode n = cwbvh_nodes[child];
            if (TRAVERSAL_STATS != 0u) {
                stats.x++;
                traversal_counts.y++;
            }
            uint hits = cwbvh_intersect_children(n, o, idir, neg, tmin, hit.t, oct_inv4);
            node_group = uvec2(n.meta.x, (hits & 0xff000000u) | (n.p_e.w >> 24));
            tri_group = uvec2(n.meta.y, hits & 0x00ffffffu);
        } else {
            // A postponed triangle group from the stack (node groups pushed there always hold
            // node bits), or nothing.
            tri_group = node_group;
            node_group = uvec2(0u);
        }
        // Triangle postponing (Ylitie et al., section 4): when few lanes of the subgroup have
        // triangles to test, defer them and keep descending rather than idle the others.
        if (CWBVH_POSTPONE != 0u && tri_group.y != 0u && node_group.y > 0x00ffffffu &&
            subgroupBallotBitCount(subgroupBallot(tri_group.y != 0u)) * 5u < gl_SubgroupSize) {
            stack[sp++] = tri_group;
            tri_group = uvec2(0u);
        }
        while (tri_group.y != 0u) {
            uint bit = uint(findMSB(tri_group.y));
            tri_group.y &= ~(1u << bit);
            if (test_leaf_triangle(pr, tri_group.x + bit, hit, stats) && any_hit) {
                return hit;
            }
        }
        if (node_group.y <= 0x00ffffffu) {
            if (sp == 0) {
                break;
            }
            node_group = stack[--sp];
        }
    }
    return hit;
}
