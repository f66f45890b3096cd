// Vertex merging at a camera vertex (the camera pass of `--integrator vcm`): every cached
// light vertex within the merge radius r, found through the merge grid (merge_grid.glsl),
// is merged with the camera vertex (Georgiev 2012, tech. report, the vertex-merging weights:
// the estimator f_cam(wo, y.wi) beta_y / (pi r^2 N) with weight 1 / (w_light + 1 + w_camera),
// w_light = dVCM_y mis(1/eta) + dVM_y mis(pdf_cam(wo -> y.wi)) and
// w_camera = dVCM mis(1/eta) + dVM mis(pdf_cam(y.wi -> wo))).
#ifndef BIDIR_VCM_MERGE_GLSL
#define BIDIR_VCM_MERGE_GLSL

layout(std430, binding = BIND_MERGE_CELLS) readonly buffer MergeCells { uint merge_cells[]; };
layout(std430, binding = BIND_MERGE_ITEMS) readonly buffer MergeItems { MergeItem merge_items[]; };

// Camera vertex at p (shading and geometric normals facing wo, continuous BSDF c, `depth`
// segments from the eye, MIS quantities d_vcm, d_vm). Returns the weighted sum over light
// vertices y within r of f_cam(wo, y.wi) beta_y / P(y stored); the caller multiplies by the
// camera throughput and 1 / (pi r^2 N). Without connections (progressive photon mapping)
// every merge has weight 1. A light vertex stored with probability stored / seen (the
// reservoir) counts seen / stored times. With shading normals the photon's flux, a density
// over geometric area, is converted to the shading cosine the camera's BSDF integral uses:
// |wi.ns| / |wi.ng|.
vec3 vcm_merge(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wo, Continuous c, float d_vcm, float d_vm, uint depth, float r, VcmFactors k) {
    float cell_size = 2.0 * r;
    ivec3 c0 = merge_cell(p, cell_size);
    vec3 frac = p / cell_size - vec3(c0);
    // The 2 x 2 x 2 block of cells nearest to p: toward the lower neighbour on an axis where p
    // lies in the lower half of its cell.
    ivec3 lo = c0 - ivec3(lessThan(frac, vec3(0.5)));
    uint hashes[8];
    vec3 sum = vec3(0.0);
    for (uint n = 0u; n < 8u; n++) {
        uint h = merge_cell_hash(lo + ivec3(n & 1u, (n >> 1u) & 1u, (n >> 2u) & 1u));
        hashes[n] = h;
        bool repeated = false;
        for (uint m = 0u; m < n; m++) {
            repeated = repeated || hashes[m] == h;
        }
        if (repeated) {
            continue; // two cells of the block share a hash entry: visit it once
        }
        uint end = merge_cells[h];
        for (uint e = h == 0u ? 0u : merge_cells[h - 1u]; e < end; e++) {
            // The distance test reads the cell's contiguous entries; the vertex itself (96
            // bytes elsewhere) only where it lies within r.
            MergeItem item = merge_items[e];
            vec3 v = item.pos - p;
            if (dot(v, v) > r * r) {
                continue;
            }
            uint slot = item.slot;
            LightVertex y = load_light_vertex(slot);
            if (pc.max_depth != 0u && uint(y.segments) + depth > pc.max_depth) {
                continue;
            }
            vec3 wi = y.wi;
            float cos_g = dot(ng_f, wi);
            if (cos_g <= 0.0) {
                continue; // the light arrived on the other side of the surface
            }
            float cam_dir_pdf_w, cam_rev_pdf_w;
            vec3 f = continuous_eval(c, ns_f, wo, wi, cam_dir_pdf_w, cam_rev_pdf_w);
            if (max3(f) <= 0.0) {
                continue;
            }
            float weight = 1.0;
            if (VCM_CONNECTS) {
                float w_light = y.d_vcm * k.vc + y.d_vm * mis(cam_dir_pdf_w);
                // A light vertex one segment from the light merged at the first camera
                // vertex: a path light -> surface -> eye, whose camera dVCM is light tracing's
                // term (vcm.glsl, direct_light_tracing).
                float lt = depth == 1u && uint(y.segments) == 1u ? direct_light_tracing() : 1.0;
                float w_camera = lt * d_vcm * k.vc + d_vm * mis(cam_rev_pdf_w);
                weight = 1.0 / (w_light + 1.0 + w_camera);
            }
            uvec2 counts = light_counts[slot / pc.light_path_len]; // (stored, seen)
            float inv_q = float(counts.y) / float(counts.x);
            float adjoint = HAS_NORMALS != 0u ? abs(dot(wi, ns_f)) / cos_g : 1.0;
            sum += f * y.beta_f * (weight * inv_q * adjoint);
        }
    }
    return sum;
}

#endif
