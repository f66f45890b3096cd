// Packet traversal of the 4-wide BVH (trace_bvh4_packet.comp, TRACE_PACKET; `bench traversal
// --bvh bvh4 --packet`): the subgroup's rays walk the tree together, one node at a time, as
// the packet traversals of CPU ray tracers do (Wald et al. 2001; Günther et al. 2007 on GPUs).
// Every lane tests the node's four boxes against its own ray; the subgroup visits a child that
// any of its lanes hits, so a lane sees the union of the nodes its packet's rays need and tests
// the triangles of every leaf in it (a superset of its own: its closest hit is the same, but a
// tie between two triangles at one distance may fall the other way). What it buys over the
// lockstep loops: one node address per step for the whole subgroup (one memory request instead
// of one per distinct node), a stack whose top is the same in every lane (each lane keeps its
// copy in local memory, as the other kernels do, at an index the lanes share), no postponed
// leaves and no sorting per lane. What it costs: the union's extra
// node steps and triangle tests, which coherent rays (camera rays in 8x4 pixel blocks) keep
// small and incoherent ones do not. Not a default: NVIDIA H100, Sponza CameraMain, quality 5,
// against the lockstep loops in the same start, camera rays 2.4 % slower (11 % more node steps,
// 1.9x the triangle tests per lane), shadow rays 22 %, diffuse rays 3.4x (session 62,
// docs/traversal.md, "Packet traversal").
//
// Closest-hit rays take a child in the order of its least entry distance over the lanes that
// hit it (subgroupMin of the same keys the per-ray step sorts, so the slot survives in the low
// bits), push the others with that distance, and pop past entries beyond every lane's nearest
// hit (subgroupMax of the lanes' cull bits): the per-ray stack's culling, for the packet.
// Any-hit rays take the hit children in their copy's slot order (src/bvh/occlusion.rs), a lane
// with a hit sits out, and the packet ends when every lane has one. The stack never holds more
// than a single ray's worst path pushes (src/bvh/wide4.rs bounds that by TRAVERSAL_STACK_SIZE).
//
// Included by traverse_bvh4.glsl after bvh4_ray and pick4; needs the subgroup vote and
// arithmetic extensions.
TraceHit trace_ray_packet(vec3 o, vec3 d, float tmin, float tmax, bool any_hit, inout uvec2 stats) {
    PreparedRay pr = prepare_ray(o, d, tmin);
    if (TRAVERSAL_STATS != 0u) {
        traversal_counts.x++;
    }
    Bvh4Ray br = bvh4_ray(o, d);
    vec3 idir = br.idir, ood_near = br.ood_near, ood_far = br.ood_far;
    uint nx = br.nx, ny = br.ny, nz = br.nz;
    TraceHit hit = TraceHit(tmax, NO_HIT, vec2(0.0));
    // A lane is done without a segment (tmax < 0) or, any-hit, at its first hit; a done lane
    // hits no box and tests no triangle.
    bool done = tmax < 0.0;
    TRAVERSAL_STACK_INIT();
    int node = subgroupAll(done) ? int(TRAVERSAL_SENTINEL) : bvh4_root(any_hit);
    while (node != int(TRAVERSAL_SENTINEL)) {
        if (node >= 0) {
            if (TRAVERSAL_STATS != 0u) {
                stats.x++;
                traversal_counts.y++;
            }
            ivec4 children = bvh4_nodes[node].children;
            #include "traverse_bvh4_slabs.glsl"
            if (done) {
                hit4 = bvec4(false);
            }
            if (any_hit) {
                // The children any lane hits, lowest slot next, the others pushed highest
                // first so that they pop in slot order.
                uint m = (hit4.x ? 1u : 0u) | (hit4.y ? 2u : 0u) | (hit4.z ? 4u : 0u) | (hit4.w ? 8u : 0u);
                m = subgroupOr(m);
                if (m == 0u) {
                    TRAVERSAL_STACK_POP(node, 0);
                } else {
                    node = pick4(children, uint(findLSB(m)));
                    m &= m - 1u;
                    for (int i = 0; i < 3 && m != 0u; i++) {
                        uint s = uint(findMSB(m));
                        TRAVERSAL_STACK_PUSH(pick4(children, s), 0);
                        m &= ~(1u << s);
                    }
                }
            } else {
                // Each child's least entry distance over the lanes that hit it (no lane: all
                // ones), sorted by the per-ray step's network: k0 nearest .. k3 farthest.
                uvec4 key = mix(uvec4(0xffffffffu), (floatBitsToUint(t_near) & ~3u) | uvec4(0u, 1u, 2u, 3u), hit4);
                key = subgroupMin(key);
                uint a = min(key.x, key.y), b = max(key.x, key.y);
                uint c = min(key.z, key.w), e = max(key.z, key.w);
                uint k0 = min(a, c), k3 = max(b, e);
                uint f = max(a, c), g = min(b, e);
                uint k1 = min(f, g), k2 = max(f, g);
                if (k0 == 0xffffffffu) {
                    TRAVERSAL_STACK_POP(node, subgroupMax(stack_cull_bits(hit.t)));
                } else {
                    node = pick4(children, k0);
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
            }
        } else {
            // A leaf: every lane not done tests its triangles in order.
            uint first = uint(node) & ((1u << LEAF_FIRST_BITS) - 1u);
            uint count = ((uint(node) >> LEAF_FIRST_BITS) & 15u) + 1u;
            if (!done) {
                for (uint i = first; i < first + count; i++) {
                    if (test_leaf_triangle(pr, i, hit, stats) && any_hit) {
                        done = true;
                        break;
                    }
                }
            }
            if (any_hit && subgroupAll(done)) {
                break;
            }
            TRAVERSAL_STACK_POP(node, any_hit ? 0 : subgroupMax(stack_cull_bits(hit.t)));
        }
    }
    return hit;
}
