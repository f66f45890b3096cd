// One node step of the 4-wide traversal (traverse_bvh4.glsl), included where a loop visits
// the inner node `node`: its children's boxes against the ray (idir, ood_near, ood_far, nx,
// ny, nz of bvh4_ray) within (tmin, hit.t), the nearest hit child next (or the stack's top),
// the others pushed, a leaf postponed. Reads and writes the includer's node, leaf, hit, stack
// and stats; `any_hit` as in trace_ray. Included by trace_ray, trace_ray_lockstep and the
// trace kernels' dynamic fetch (trace_kernel.glsl), so that all run the same step.
if (TRAVERSAL_STATS != 0u) {
    stats.x++;
    traversal_counts.y++;
}
// The children's pointers are read with the planes; the next node is chosen
// without a branch (TRAVERSAL_STACK_NEXT). Where the includer defines
// TRAVERSAL_CHILDREN_ON_HIT (the trace kernels' dynamic fetch), a closest-hit step reads them
// only after its box tests, and only where a child was hit: one memory request fewer for the
// steps that hit no child. NVIDIA H100, Sponza CameraMain's diffuse rays at --refill 24:
// 1 % faster; the same read in any-hit rays' dynamic fetch was 1.5 % slower and in the
// lockstep kernel's primary rays 5 % (session 59, docs/traversal.md).
#ifdef TRAVERSAL_CHILDREN_ON_HIT
bool children_on_hit = !any_hit;
#else
const bool children_on_hit = false;
#endif
ivec4 children = ivec4(0);
if (!children_on_hit) {
    children = bvh4_nodes[node].children;
}
#include "traverse_bvh4_slabs.glsl"
if (children_on_hit && any(hit4)) {
    children = bvh4_nodes[node].children;
}
if (any_hit) {
    // Any hit ends the ray: no keys, no sorting network (session 13: faster than the
    // distance order), but the slots' own order, which the build chose for occlusion in
    // any-hit rays' copy of the nodes (src/bvh/occlusion.rs: the likeliest occluder per
    // unit of work first). The lowest hit slot next; the others pushed highest first, so
    // that they pop in slot order (session 27: Sponza's shadow rays 10-31 % faster than
    // over the closest-hit nodes, 11-19 % from CameraMain).
    uint m = (hit4.x ? 1u : 0u) | (hit4.y ? 2u : 0u) | (hit4.z ? 4u : 0u) | (hit4.w ? 8u : 0u);
    TRAVERSAL_STACK_NEXT(node, m == 0u, pick4(children, uint(findLSB(m))), 0);
    m &= m - 1u;
    for (int i = 0; i < 3 && m != 0u; i++) {
        uint s = uint(findMSB(m));
        TRAVERSAL_STACK_PUSH(pick4(children, s), 0);
        m &= ~(1u << s);
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
