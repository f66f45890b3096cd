// BDPT's camera subpath (and VCM's): its connections to stored light vertices, shared by the
// megakernel (bdpt_camera.comp) and the wavefront camera pass (bdpt_camera_wavefront.comp),
// which both include the step of a path, bdpt_camera_step.glsl, in their loops.
// The includer declares `pc` (BdptPush's fields), BDPT_JOIN (the join: pc.join, or JOIN_LVC in
// the wavefront pass), the light vertex cache's buffers, and
// `bool camera_shadow_clear(ShadowRay r, inout vec3 contrib, inout uvec2 stats)`: whether
// `contrib` counts now (the ray was traced and is clear) rather than later (queued) or never
// (blocked); it rounds `contrib` to what counts (packed_contrib.glsl).
#ifndef BIDIR_BDPT_CAMERA_PATH_GLSL
#define BIDIR_BDPT_CAMERA_PATH_GLSL

// The BSDF of light vertex y toward direction w and its pdfs (forward: sampling w from y.wi;
// reverse: y.wi from w). Without GGX lobes y stores beta f and its lobe probability.
vec3 light_vertex_f(LightVertex y, vec3 w, out float pdf_fwd_w, out float pdf_rev_w) {
    if (HAS_GLOSSY != 0u || VCM_MERGES) {
        Continuous c = continuous_at(materials[y.material], y.uv);
        return y.beta_f * continuous_eval(c, y.ns, y.wi, w, pdf_fwd_w, pdf_rev_w);
    }
    pdf_fwd_w = y.pick * max(0.0, dot(y.ns, w)) / PI;
    pdf_rev_w = diffuse_rev_pdf_w(y);
    return y.beta_f;
}

// Connection of camera vertex (p, ns_f, ng_f, continuous BSDF c, wo toward the previous
// camera vertex, sigma_a on the side it was reached from, d_vcm, d_vc) to light vertex y,
// before its shadow ray: the MIS-weighted contribution if y were visible (0 where it carries
// nothing). Both ends connect on the side their paths arrived on; either may lie inside a
// volume. vm_camera / vm_light: the merging factor where merging at the camera / light vertex
// is a strategy of this path, else 0 (vcm.glsl).
vec3 connection_unshadowed(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wo, Continuous c, vec3 sigma, float d_vcm, float d_vc, float vm_camera, float vm_light, LightVertex y) {
    vec3 v = y.pos - p;
    float dist2 = dot(v, v);
    vec3 dir = v * inversesqrt(dist2);
    float cos_c = dot(ns_f, dir);
    float cos_y = -dot(y.ns, dir);
    if (cos_c <= 0.0 || cos_y <= 0.0 || dot(ng_f, dir) <= 0.0 || dot(y.ng, dir) >= 0.0) {
        return vec3(0.0);
    }
    float cam_dir_pdf_w, cam_rev_pdf_w, light_dir_pdf_w, light_rev_pdf_w;
    vec3 f = continuous_eval(c, ns_f, wo, dir, cam_dir_pdf_w, cam_rev_pdf_w);
    vec3 beta_f_y = light_vertex_f(y, -dir, light_dir_pdf_w, light_rev_pdf_w);
    float cam_dir_pdf_a = cam_dir_pdf_w * cos_y / dist2;
    float light_dir_pdf_a = light_dir_pdf_w * cos_c / dist2;
    float w_light = mis(cam_dir_pdf_a) * (vm_light + y.d_vcm + y.d_vc * mis(light_rev_pdf_w));
    float w_camera = mis(light_dir_pdf_a) * (vm_camera + d_vcm + d_vc * mis(cam_rev_pdf_w));
    float g = cos_c * cos_y / dist2;
    if (HAS_NORMALS != 0u) {
        g *= shading_normal_adjoint(y.wi, -dir, y.ns, y.ng);
    }
    vec3 contrib = f * beta_f_y * (g / (w_light + 1.0 + w_camera));
    if (HAS_VOLUME != 0u) {
        vec3 sigma_y = volume_sigma(materials[y.material], y.back_face != 0u);
        contrib *= volume_transmittance(segment_sigma(sigma, sigma_y), sqrt(dist2));
    }
    return max3(contrib) > 0.0 ? contrib : vec3(0.0);
}

// The connection above with its shadow ray: `scale` times the contribution where it is added
// now; 0 where the shadow ray is blocked or queued (shadow_queue.glsl).
vec3 connect(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wo, Continuous c, vec3 sigma, float d_vcm, float d_vc, float vm_camera, float vm_light, LightVertex y, vec3 scale, inout uvec2 stats) {
    vec3 contrib = connection_unshadowed(p, ns_f, ng_f, wo, c, sigma, d_vcm, d_vc, vm_camera, vm_light, y);
    vec3 scaled = scale * contrib;
    if (max3(contrib) <= 0.0 || !camera_shadow_clear(shadow_ray_between(p, ng_f, y.pos, y.ng), scaled, stats)) {
        return vec3(0.0);
    }
    return scaled;
}

// One connection of the light vertex cache, its vertex resampled (Talbot et al. 2005,
// "Importance Resampling for Global Illumination") from LVC_CANDIDATES entries drawn uniformly
// from the `total` cached. Each candidate i is weighed by p_hat_i, its unshadowed,
// MIS-weighted connection over its probability of being drawn and stored, computed from the
// entry's preview of the vertex (lvc_compact.comp: position, shading normal, lobe pick,
// luminance of beta f and the light side's MIS sum, taken as diffuse); one candidate s is kept
// with probability p_hat_s / sum(p_hat), its vertex loaded, its exact one-draw estimate x_s
// evaluated and its shadow ray traced: x_s * mean(p_hat) / p_hat_s has the expectation of one
// uniform draw wherever p_hat > 0 covers x_s > 0. It does: p_hat is 0 only where the camera
// side's cosines are not positive, where x is 0 too (the light side's cosine enters as at least
// PREVIEW_COS_MIN, the normal being quantised). So the connection strategies' MIS weights are
// unchanged and still sum to one with the others; what changes is variance: the shadow ray
// goes where the unshadowed contributions are large. Returns the contribution where it is added
// now (as connect()).
//
// The candidates belong to a group, not to the lanes: every camera vertex of one 16 x 8 block
// of the full image's pixels, one sample index, one vertex count and one connection (`join`)
// draws the same LVC_CANDIDATES entries, by hashes of the group's key (lvc_group_seed), which
// no path's random numbers enter. So each vertex's candidates are independent uniform draws,
// independent of its path, and which vertices share them does not depend on which lanes
// connect together: the megakernels and the wavefront form make the same choices over the
// same light paths (the same sample slices), from run to run, and in a crop or a sample range
// of the image (docs/scale-out.md), up to the rounding of the two kernels' arithmetic. The
// connecting lanes of a subgroup share the reads where they can read all its groups'
// candidates at once (k groups, k N <= lanes: in the megakernels a 32-lane subgroup covers 8 x 4
// pixels, in one block where the window's origin is on a multiple of 8; in the wavefront form
// compaction lists the live slots of a few blocks in one subgroup): the lane of rank g N + i reads group g's candidate i (32 bytes), and every lane
// takes its group's N by shuffles from the N lanes from rank g N on, in one loop of N trips;
// elsewhere every lane reads its own N. The loop holds no more than the lanes' pools of session
// 38 held (in session 41 the wavefront camera kernel took 72 registers on NVIDIA's driver with
// it, 96 with session 39 and 40's passes over the entries; docs/results.md). A block's pixels
// share their candidates at one sample, so their errors are correlated (at a few samples per
// pixel the noise may show the 16 x 8 grid faintly), not larger. A shared candidate costs
// shuffles and arithmetic (docs/integrators.md: the first design's 32-byte read per candidate
// cost an H100 6 ms per 1024 spp each on the Cornell box).

#include "ballot.glsl"

const float PREVIEW_COS_MIN = 1.0e-3;

// The key of this camera sample's candidate groups (connect_resampled): its pixel's 16 x 8
// block of the full image, its sample index and the seed (blocks of 8 x 4 took 2 % more on an
// H100's Cornell box, more keys sharing a subgroup). Set by the includer before the path.
uint lvc_group = 0u;
uint lvc_group_seed(uvec2 px, uint sample_index, uint seed) {
    uint block = (px.y >> 3u) * 0x10000u + (px.x >> 4u);
    return pcg_hash(pcg_hash(block ^ 0x632be5abu) ^ pcg_hash(sample_index ^ pcg_hash(seed ^ 0x9e3779b9u)));
}

// Candidate i of the group of key `key`: its entry's first word in the light vertex cache's
// listing of `total` entries. The one definition of a group's candidates, whichever lane reads
// them (connect_resampled).
uint lvc_candidate_entry(uint key, uint i, uint total) {
    return index_below(pcg_hash(key ^ pcg_hash(i + 0x7f4a7c15u)), total) * LVC_ENTRY_WORDS;
}

vec3 connect_resampled(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wo, Continuous c, vec3 sigma, float d_vcm, float d_vc, float vm_camera, float vm_light, uint depth, uint join, uint total, vec3 scale, inout Rng rng, inout uvec2 stats) {
    uint key = pcg_hash(lvc_group ^ pcg_hash(depth ^ pcg_hash(join ^ 0x2c1b3c6du)));
    // The connecting lanes (the active ones) and this lane's rank among them.
    uvec4 connecting = subgroupBallot(true);
    uint lanes = subgroupBallotBitCount(connecting);
    uint rank = subgroupBallotExclusiveBitCount(connecting);
    // The subgroup's distinct keys (groups), numbered in the order found (one per pass of a
    // uniform loop). Where the subgroup's connecting lanes can read every group's candidates
    // at once (k groups, k N <= lanes), group g's candidate i is read by the lane of rank g N
    // + i, and this lane takes its group's from the N lanes from rank `group` N on by a
    // cursor; else each lane reads its own. Either way candidate i of a group is entry
    // hash(key, i): the same values in the same order whoever reads them. Branch-free and
    // bounded by the subgroup's size, so that lanes which had not rejoined (Vulkan promises
    // it only with VK_KHR_shader_maximal_reconvergence) could not keep it from ending; the
    // leader leaves `todo` in any case (a lane that matched no ballot, possible only where
    // lanes had not rejoined and shuffles are undefined anyway, would read its own).
    uvec4 todo = connecting;
    uint group = gl_SubgroupSize;
    uint read_key = key;
    uint start = 0u; // the lane of rank group N
    uint groups = 0u;
    for (uint found = 0u; found < gl_SubgroupSize && todo != uvec4(0u); found++) {
        uint leader = subgroupBallotFindLSB(todo);
        uint leader_key = subgroupShuffle(key, leader);
        bool same = key == leader_key;
        todo &= ~subgroupBallot(same);
        todo[leader >> 5u] &= ~(1u << (leader & 31u));
        // (Past the connecting lanes, where the reads do not fit and the cursor goes unused, the
        // last lane: never an empty ballot.)
        uint first_reader = subgroupBallotFindLSB(subgroupBallot(rank == min(found * LVC_CANDIDATES, lanes - 1u)));
        group = same ? found : group;
        start = same ? first_reader : start;
        read_key = rank / LVC_CANDIDATES == found ? leader_key : read_key;
        groups = found + 1u;
    }
    bool fits = groups * LVC_CANDIDATES <= lanes; // uniform
    uvec4 own0 = uvec4(0u);
    uvec4 own1 = uvec4(0u);
    if (fits && rank < groups * LVC_CANDIDATES) {
        uint e = lvc_candidate_entry(read_key, rank % LVC_CANDIDATES, total);
        own0 = lvc_index[e];
        own1 = lvc_index[e + 1u];
    }
    // This lane's group's readers: the connecting lanes from `start` on (the first N of them).
    uvec4 cursor = ballot_from(connecting, start);
    bool share = subgroupAll(fits && group < groups);
    float p_hat_sum = 0.0;
    float p_hat_s = 0.0;
    uvec2 chosen = uvec2(0u);
    // The keep decisions' numbers: a hash chain from one draw, its seed moved off the sampler's
    // own chain (past the Sobol' dimensions each draw is pcg_hash of the last, rng.glsl: from the
    // draw itself this chain would repeat the numbers the path draws next, for its BSDF sample
    // and Russian roulette).
    uint keep = rng_next_uint(rng) ^ 0x2545f491u;
    for (uint i = 0u; i < LVC_CANDIDATES; i++) {
        uvec4 w0;
        uvec4 w1;
        if (share) {
            uint src;
            if (gl_SubgroupSize <= 32u) {
                // One word of lanes (a constant test once the driver knows the size).
                src = uint(findLSB(cursor.x));
                cursor.x &= cursor.x - 1u;
            } else {
                src = ballot_take_lowest(cursor);
            }
            w0 = subgroupShuffle(own0, src);
            w1 = subgroupShuffle(own1, src);
        } else {
            uint e = lvc_candidate_entry(key, i, total);
            w0 = lvc_index[e];
            w1 = lvc_index[e + 1u];
        }
        keep = pcg_hash(keep);
        float u_keep = float(keep >> 8u) * (1.0 / 16777216.0);
        vec3 v = uintBitsToFloat(w1.xyz) - p;
        float dist2 = dot(v, v);
        vec3 dir = v * inversesqrt(dist2);
        float cos_c = dot(ns_f, dir);
        // Where the camera side's cosines are not positive x is 0: so is p_hat.
        if (cos_c > 0.0 && dot(ng_f, dir) > 0.0) {
            vec3 ns_y;
            float pick;
            lvc_preview_unpack(w0.z, ns_y, pick);
            float cos_y = max(-dot(ns_y, dir), PREVIEW_COS_MIN);
            float cam_dir_pdf_w, cam_rev_pdf_w;
            vec3 f = continuous_eval(c, ns_f, wo, dir, cam_dir_pdf_w, cam_rev_pdf_w);
            float w_light = mis(cam_dir_pdf_w * cos_y / dist2) * (vm_light + uintBitsToFloat(w0.w));
            float w_camera = mis(pick * cos_y / PI * cos_c / dist2) * (vm_camera + d_vcm + d_vc * mis(cam_rev_pdf_w));
            float p_hat = luminance(f) * uintBitsToFloat(w1.w) * uintBitsToFloat(w0.y) * (cos_c * cos_y / dist2) / (w_light + 1.0 + w_camera);
            if (p_hat > 0.0) {
                p_hat_sum += p_hat;
                if (u_keep * p_hat_sum < p_hat) {
                    p_hat_s = p_hat;
                    chosen = w0.xy;
                }
            }
        }
    }
    if (p_hat_s <= 0.0) {
        return vec3(0.0);
    }
    LightVertex y = load_light_vertex(chosen.x);
    if (pc.max_depth != 0u && uint(y.segments) + 1u + depth > pc.max_depth) {
        return vec3(0.0);
    }
    vec3 x = connection_unshadowed(p, ns_f, ng_f, wo, c, sigma, d_vcm, d_vc, vm_camera, vm_light, y);
    if (max3(x) <= 0.0) {
        return vec3(0.0);
    }
    vec3 contrib = scale * uintBitsToFloat(chosen.y) * x * (p_hat_sum / (float(LVC_CANDIDATES) * p_hat_s));
    if (!camera_shadow_clear(shadow_ray_between(p, ng_f, y.pos, y.ng), contrib, stats)) {
        return vec3(0.0);
    }
    return contrib;
}

#endif
