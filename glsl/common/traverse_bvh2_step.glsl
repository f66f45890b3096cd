// One node step of the binary traversal (traverse.glsl), included where a loop visits the
// inner node `node`: both children's boxes against the ray (o, o_xy, idir, idir_xy) within
// (tmin, hit.t), the nearer hit child next (or the stack's top), the other pushed, a leaf
// postponed. Reads and writes the includer's node, leaf, hit, stack and stats. Included by
// trace_ray and trace_ray_lockstep, so that both run the same step.
BvhNode n = fetch_node(node);
if (TRAVERSAL_STATS != 0u) {
    stats.x++;
    traversal_counts.y++;
}
// (p - o) idir, as written: its rounding is what BOX_EXIT_SCALE covers (Ize 2013).
// p idir - o idir with o idir computed once is one instruction less per plane
// but, contracted to a multiply-add (as lavapipe's compiler does), off by the
// rounding of o idir, an absolute error that lost hits far from the world's origin
// (tests/traversal.rs, small_triangles_far_from_the_origin...). That form with the
// origin term widened by its rounding (the 4-wide kernel's) was mixed here on the
// H200: shadow rays 4.91 against 4.73 Grays/s, diffuse 1.48 against 1.55.
vec4 t0xy = (n.c0_xy - o_xy) * idir_xy;
vec4 t1xy = (n.c1_xy - o_xy) * idir_xy;
vec4 tz = (n.c01_z - o.z) * idir.z;
float c0min, c0max, c1min, c1max;
if (INT_SLABS != 0u) {
    // The same selections on the floats' bits as signed integers (Aila & Laine
    // 2009's Kepler trick): exact where it matters, since tmin and hit.t are not
    // negative and a negative float, whichever the integer order picks, loses
    // to tmin in a near distance and rejects the box in a far one.
    ivec4 a0 = floatBitsToInt(t0xy), a1 = floatBitsToInt(t1xy), az = floatBitsToInt(tz);
    int lo = floatBitsToInt(tmin), hi = floatBitsToInt(hit.t);
    c0min = intBitsToFloat(max(max(min(a0.x, a0.y), min(a0.z, a0.w)), max(min(az.x, az.y), lo)));
    c0max = intBitsToFloat(min(min(max(a0.x, a0.y), max(a0.z, a0.w)), min(max(az.x, az.y), hi)));
    c1min = intBitsToFloat(max(max(min(a1.x, a1.y), min(a1.z, a1.w)), max(min(az.z, az.w), lo)));
    c1max = intBitsToFloat(min(min(max(a1.x, a1.y), max(a1.z, a1.w)), min(max(az.z, az.w), hi)));
} else {
    c0min = max(max(min(t0xy.x, t0xy.y), min(t0xy.z, t0xy.w)), max(min(tz.x, tz.y), tmin));
    c0max = min(min(max(t0xy.x, t0xy.y), max(t0xy.z, t0xy.w)), min(max(tz.x, tz.y), hit.t));
    c1min = max(max(min(t1xy.x, t1xy.y), min(t1xy.z, t1xy.w)), max(min(tz.z, tz.w), tmin));
    c1max = min(min(max(t1xy.x, t1xy.y), max(t1xy.z, t1xy.w)), min(max(tz.z, tz.w), hit.t));
}
bool hit0 = c0min <= c0max * BOX_EXIT_SCALE;
bool hit1 = c1min <= c1max * BOX_EXIT_SCALE;
bool none = !hit0 && !hit1;
bool near1 = hit1 && (!hit0 || c1min < c0min);
TRAVERSAL_STACK_NEXT(node, none, near1 ? n.children.y : n.children.x, stack_cull_bits(hit.t));
if (hit0 && hit1) {
    TRAVERSAL_STACK_PUSH(near1 ? n.children.x : n.children.y, floatBitsToInt(near1 ? c0min : c1min));
}
// Postpone a leaf and keep descending (speculative traversal).
if (node < 0 && leaf >= 0) {
    leaf = node;
    TRAVERSAL_STACK_POP(node, stack_cull_bits(hit.t));
}
