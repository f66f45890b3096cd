// The 4-wide node step's box test: the four children's boxes of inner node `node` against the
// ray (idir, ood_near, ood_far, nx, ny, nz of bvh4_ray) within (tmin, hit.t), declaring t_near,
// t_far and hit4 (the children hit) in the includer's scope. Included by traverse_bvh4_step.glsl
// and the packet loop (traverse_bvh4_packet.glsl), so that both test boxes alike.
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
