// Node fetch of the quantised binary layout (QuantNode in src/gpu/abi.rs, built by
// src/bvh/quant.rs): included by traverse.glsl when TRAVERSE_BVH2Q is defined, whose binary
// trace_ray then runs unchanged on the decoded nodes. A 32-byte node holds both children's
// boxes in 8 bits per plane on a grid over the node's own box (origin, power-of-two cell per
// axis) and one child pointer; child 0 is the next node, or a leaf ending where child 1's
// leaf begins.

layout(std430, binding = BIND_NODES) readonly buffer QuantNodes { QuantNode quant_nodes[]; };

// The four planes of one axis, (child 0 lo, child 0 hi, child 1 lo, child 1 hi):
// origin + q 2^(e - 127). The product is exact (8-bit q, a normal power of two), so the
// plane is rounded once with or without a fused multiply-add: the value the builder checked
// encloses the child (src/bvh/quant.rs).
vec4 quant_planes(float origin, uint q, uint e) {
    float cell = uintBitsToFloat(e << 23);
    vec4 codes = vec4(uvec4(q & 0xffu, (q >> 8) & 0xffu, (q >> 16) & 0xffu, q >> 24));
    precise vec4 planes = origin + codes * cell;
    return planes;
}

BvhNode fetch_node(int node) {
    QuantNode n = quant_nodes[node];
    vec4 x = quant_planes(n.origin.x, n.qx, n.exps_left & 0xffu);
    vec4 y = quant_planes(n.origin.y, n.qy, (n.exps_left >> 8) & 0xffu);
    vec4 z = quant_planes(n.origin.z, n.qz, (n.exps_left >> 16) & 0xffu);
    uint left_count = n.exps_left >> QUANT_LEFT_SHIFT;
    int child0 = node + 1;
    if (left_count != 0u) {
        uint first1 = uint(n.child1) & ((1u << LEAF_FIRST_BITS) - 1u);
        child0 = int((1u << 31) | ((left_count - 1u) << LEAF_FIRST_BITS) | (first1 - left_count));
    }
    return BvhNode(vec4(x.xy, y.xy), vec4(x.zw, y.zw), z, ivec4(child0, n.child1, 0, 0));
}
