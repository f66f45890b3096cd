#version 460
// BDPT, pass 2: one camera subpath per pixel, joined to the light subpath of the same index.
// At each vertex: s = 0 when it is an emitter, s = 1 with a fresh light sample, and s >= 2
// with stored light vertices — all of them (full join), `join_k` chosen uniformly (k-step
// join), or `join_k` drawn from every path's vertices (light vertex cache). A connection's
// contribution is divided by the probability that it was evaluated (the reservoir's L / n,
// k-step's k / stored, the cache's k / total), so with the fixed full-BDPT MIS weights the
// estimator stays unbiased whichever join runs (docs/integrators.md).
// With SPEC_VCM (`--integrator vcm`, vcm.glsl) the same pass also carries dVM, adds the
// merging terms to every weight and merges at the first continuous camera vertex (or, with
// VCM_MERGE_ALL, at each; vcm.glsl, vcm_merge.glsl). Full VCM at the first vertex records that
// vertex (BIND_MERGE_QUERIES) for vcm_merge.comp instead of merging here.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "scene.glsl"
#include "bsdf.glsl"
#include "lights.glsl"
#include "emission.glsl"
#include "env.glsl"
#include "punctual.glsl"
#include "volume.glsl"
#include "bdpt.glsl"
#include "vcm.glsl"
#include "shadow_queue.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { BdptPush pc; };
layout(std430, binding = BIND_SLICES) writeonly buffer Slices { vec4 slices_out[]; };
// The light vertex cache (JOIN_LVC): stored slots of every light path, densely listed.
layout(std430, binding = BIND_LVC_INDEX) readonly buffer LvcIndex { uint lvc_index[]; };
layout(std430, binding = BIND_LVC_TOTAL) readonly buffer LvcTotal { uint lvc_total; };
#include "vcm_merge.glsl"
layout(std430, binding = BIND_MERGE_QUERIES) writeonly buffer MergeQueries { MergeQuery merge_queries[]; };
// This invocation's camera sample: its entry in merge_queries, and whether it recorded one.
uint g_query = 0u;
bool g_queued = false;

// The BSDF of light vertex y toward direction w and its pdfs (forward: sampling w from y.wi;
// reverse: y.wi from w). Without GGX lobes y stores beta f and its lobe probability.
vec3 light_vertex_f(LightVertex y, vec3 w, out float pdf_fwd_w, out float pdf_rev_w) {
    if (HAS_GLOSSY != 0u || VCM_MERGES) {
        Continuous c = continuous_at(materials[y.material], y.uv);
        return y.beta_f * continuous_eval(c, y.ns, y.wi, w, pdf_fwd_w, pdf_rev_w);
    }
    pdf_fwd_w = y.pick * max(0.0, dot(y.ns, w)) / PI;
    pdf_rev_w = y.pick * max(0.0, dot(y.ns, y.wi)) / PI;
    return y.beta_f;
}

// Connection of camera vertex (p, ns_f, ng_f, continuous BSDF c, wo toward the previous
// camera vertex, sigma_a on the side it was reached from, d_vcm, d_vc) to light vertex y.
// Both ends connect on the side their paths arrived on; either may lie inside a volume.
// vm_camera / vm_light: the merging factor where merging at the camera / light vertex is a
// strategy of this path, else 0 (vcm.glsl). Returns `scale` times the contribution where it
// is added now; 0 where the shadow ray is blocked or queued (shadow_queue.glsl).
vec3 connect(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wo, Continuous c, vec3 sigma, float d_vcm, float d_vc, float vm_camera, float vm_light, LightVertex y, vec3 scale, inout uvec2 stats) {
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
    if (max3(contrib) <= 0.0 || !shadow_clear_now(shadow_ray_between(p, ng_f, y.pos, y.ng), scale * contrib, stats)) {
        return vec3(0.0);
    }
    return scale * contrib;
}

// `path`: the light path of this camera sample (megakernel joins).
vec3 camera_path(uint path, vec2 xy, inout Rng rng) {
    if (HAS_ALPHA != 0u) {
        blend_seed = uint(rng_next(rng) * 4294967296.0); // BLEND's stochastic opacity
    }
    uvec2 stats = uvec2(0u);
    vec3 o = pc.camera.eye.xyz;
    vec3 d = camera_direction(pc.camera, xy);
    vec3 beta = vec3(1.0);
    vec3 radiance = vec3(0.0);
    float d_vcm = mis(float(pc.light_paths) / camera_pdf_w(pc.camera, d));
    float d_vc = 0.0;
    // dVC at the second vertex less light tracing's term: the merging term of the first
    // vertex (0 in BDPT), for the emitter hits there (vcm.glsl, emitter_hit_d_vc).
    float d_vc_merge = 0.0;
    float d_vm = 0.0;
    VcmFactors k = vcm_factors(pc.sample_base, pc.light_path_total);
    // Merging at a light vertex joined to this camera vertex is a strategy only when merging
    // runs everywhere; at this camera vertex, also while every earlier vertex scattered
    // through a delta lobe (`merge_pending`; vcm.glsl).
    float vm_light = k.vm * vcm_light_merge_terms();
    bool merge_pending = true;
    uvec2 lc = light_counts[path];   // (stored, seen) of this sample's light path
    uint base = path * pc.light_path_len;
    vec3 sigma_near = vec3(0.0); // sigma_a where the next segment leaves its surface (volume.glsl)

    for (uint depth = 1u;; depth++) {
        TraceHit h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
        if (h.prim == NO_HIT) {
            // s = 0 at the environment: its vertex is a direction, so dVCM and dVC stay as
            // the last scattering left them (no distance or cosine to convert; Georgiev
            // 2012, section 5.1). Light sampling picks it with pdf_w env.pick * pdf; a light
            // path emits it with that over the disk area.
            if (HAS_ENV != 0u) {
                EnvSample e = env_lookup(d);
                beta *= volume_transmittance(sigma_near, 3.0e38);
                if (depth == 1u || VCM_PHOTON_MAPPING) {
                    radiance += beta * e.le; // the eye, or (photon mapping) only delta bounces before
                } else {
                    float direct_pdf_w = env.pick * e.pdf_w;
                    float emission_pdf_w = direct_pdf_w / env.disk_area;
                    float w_camera = mis(direct_pdf_w) * d_vcm + mis(emission_pdf_w) * emitter_hit_d_vc(depth, d_vc, d_vc_merge);
                    radiance += beta * e.le / (1.0 + w_camera);
                }
            }
            break;
        }
        Surface s = surface_at(o, d, h);
        GpuMaterial m = materials[s.material];
        // Beer-Lambert over the segment just traced, inside a volume at either of its ends.
        vec3 sigma_in = volume_sigma(m, !s.front);
        if (HAS_VOLUME != 0u) {
            beta *= volume_transmittance(segment_sigma(sigma_near, sigma_in), h.t);
        }
        vec3 ng_f = s.front ? s.ng : -s.ng;
        vec3 ns_f = s.front ? s.ns : -s.ns;
        float cos_in = abs(dot(ns_f, -d));
        // Pdf of sampling the way back (light paths' view): zero where a tilted shading
        // normal puts the previous vertex below the shading hemisphere.
        float cos_back = max(0.0, dot(ns_f, -d));
        d_vcm *= mis(h.t * h.t);
        d_vcm /= mis(cos_in);
        d_vc /= mis(cos_in);
        d_vc_merge /= mis(cos_in);
        if (VCM != 0u) {
            d_vm /= mis(cos_in);
        }

        // s = 0: the camera subpath found an emitter (front faces emit).
        if (m.emission_luminance > 0.0 && s.front) {
            if (depth == 1u || VCM_PHOTON_MAPPING) {
                // Seen from the eye, or (progressive photon mapping, which stops at the first
                // merge) after delta bounces only: no other strategy has this path.
                radiance += beta * material_emission(m, s.uv);
            } else {
                float direct_pdf_a = triangle_light_pick(HAS_PUNCTUAL != 0u) * m.emission_luminance / pc.emitter_weight;
                float cos_l = max(0.0, -dot(s.ng, d));
                float emission_pdf_w = direct_pdf_a * cos_l / PI;
                // Light sampling and emission see an emitter through its geometric normal:
                // redo this vertex's solid-angle-to-area step (done above with the shading
                // cosine) with it, or s = 0 and s = 1 would weigh the path inconsistently.
                float to_geometric = HAS_NORMALS != 0u ? mis(cos_in / cos_l) : 1.0;
                float w_camera = (mis(direct_pdf_a) * d_vcm + mis(emission_pdf_w) * emitter_hit_d_vc(depth, d_vc, d_vc_merge)) * to_geometric;
                radiance += beta * material_emission(m, s.uv) / (1.0 + w_camera);
            }
        }
        if (pc.max_depth != 0u && depth >= pc.max_depth) {
            break;
        }

        // The continuous part (diffuse, GGX) is zero unless both directions lie above the
        // shading normal too (reciprocal, as the light paths need); cos_back is 0 exactly then.
        Continuous bsdf = continuous_at(m, s.uv);
        bool continuous_ok = HAS_NORMALS == 0u || cos_back > 0.0;
        if (!continuous_ok) {
            bsdf.pick = 0.0;
        }
        vec3 wo = -d;
        bool merge_here = VCM_MERGE_EVERYWHERE || merge_pending;
        float vm_camera = merge_here ? k.vm : 0.0;
        if (VCM_MERGES && merge_here && bsdf.pick > 0.0) {
            if (VCM_MERGE_DEFERRED) {
                // No mixed materials: this vertex takes its continuous lobe, the only merge.
                merge_queries[g_query] = MergeQuery(s.p, d_vcm, ns_f, d_vm, ng_f, depth, wo, s.material, beta, 0u, s.uv, 0u, 0u);
                g_queued = true;
            } else {
                float r = vcm_radius(pc.sample_base);
                vec3 merged = vcm_merge(s.p, ns_f, ng_f, wo, bsdf, d_vcm, d_vm, depth, r, k);
                radiance += beta * merged / (PI * r * r * float(pc.light_path_total));
            }
        }
        if (VCM_CONNECTS && bsdf.pick > 0.0) {
            // The light samples' dVCM: at the first vertex it is light tracing's term alone
            // (vcm.glsl, direct_light_tracing).
            float d_vcm_s1 = depth == 1u ? direct_light_tracing() * d_vcm : d_vcm;
            // s = 1: the environment (probability env.pick; its "point" is a direction, the
            // cosine there is 1), a punctual light, or a fresh point on an emitter.
            float u_kind = HAS_ENV != 0u || HAS_PUNCTUAL != 0u ? rng_next(rng) : 1.0;
            bool env_light = HAS_ENV != 0u && u_kind < env.pick;
            bool punctual_light = HAS_PUNCTUAL != 0u && !env_light && u_kind < (HAS_ENV != 0u ? env.pick : 0.0) + env.punctual_pick;
            if (punctual_light) {
                // A delta light: BSDF sampling cannot find it (w_light = 0); the camera side
                // weighs emission against direct sampling at cosine 1 (eqs. 45, 49).
                PunctualSample ps = punctual_sample(rng_next(rng), s.p);
                float cos_s = dot(ns_f, ps.w);
                if (cos_s > 0.0 && dot(ng_f, ps.w) > 0.0 && max3(ps.li) > 0.0) {
                    float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
                    vec3 f = continuous_eval(bsdf, ns_f, wo, ps.w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
                    float w_camera = mis(ps.emission_over_direct * cos_s) * (vm_camera + d_vcm_s1 + d_vc * mis(bsdf_rev_pdf_w));
                    vec3 c = beta * volume_transmittance(sigma_in, ps.dist) * f * ps.li * (cos_s / (env.punctual_pick * ps.pick * (1.0 + w_camera)));
                    if (max3(c) > 0.0 && shadow_clear_now(punctual_shadow_ray(s.p, ng_f, ps), c, stats)) {
                        radiance += c;
                    }
                }
            } else if (env_light) {
                EnvSample es = env_sample(rng_next(rng), rng_next(rng), rng_next(rng), rng_next(rng));
                float cos_s = dot(ns_f, es.w);
                if (cos_s > 0.0 && dot(ng_f, es.w) > 0.0 && es.pdf_w > 0.0) {
                    float direct_pdf_w = env.pick * es.pdf_w;
                    float emission_pdf_w = direct_pdf_w / env.disk_area;
                    float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
                    vec3 f = continuous_eval(bsdf, ns_f, wo, es.w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
                    float w_light = mis(bsdf_dir_pdf_w / direct_pdf_w);
                    float w_camera = mis(emission_pdf_w * cos_s / direct_pdf_w) * (vm_camera + d_vcm_s1 + d_vc * mis(bsdf_rev_pdf_w));
                    vec3 c = beta * volume_transmittance(sigma_in, 3.0e38) * f * es.le * (cos_s / (direct_pdf_w * (w_light + 1.0 + w_camera)));
                    if (max3(c) > 0.0 && shadow_clear_now(env_shadow_ray(s.p, ng_f, es.w), c, stats)) {
                        radiance += c;
                    }
                }
            } else if (pc.emitter_count > 0u) {
                LightSample ls = sample_emitter(pc.emitter_count, rng_next(rng), rng_next(rng), rng_next(rng));
                ls.pick *= triangle_light_pick(HAS_PUNCTUAL != 0u);
                vec3 to_l = ls.p - s.p;
                float dist2 = dot(to_l, to_l);
                vec3 wi = to_l * inversesqrt(dist2);
                float cos_s = dot(ns_f, wi);
                float cos_l = -dot(ls.n, wi);
                if (cos_s > 0.0 && cos_l > 0.0 && dot(ng_f, wi) > 0.0) {
                    float direct_pdf_w = dist2 / (ls.area * cos_l);
                    float emission_pdf_w = cos_l / (ls.area * PI);
                    float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
                    vec3 f = continuous_eval(bsdf, ns_f, wo, wi, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
                    float w_light = mis(bsdf_dir_pdf_w / (ls.pick * direct_pdf_w));
                    // With merging, vm_camera counts merging at this vertex (a light path's
                    // first vertex found here).
                    float w_camera = mis(emission_pdf_w * cos_s / (direct_pdf_w * cos_l)) * (vm_camera + d_vcm_s1 + d_vc * mis(bsdf_rev_pdf_w));
                    // The shadow ray leaves on the side the path arrived on and reaches the
                    // emitter's front: only this end can lie inside a volume.
                    vec3 c = beta * volume_transmittance(sigma_in, sqrt(dist2)) * f * light_sample_radiance(ls) * (cos_s / (ls.pick * direct_pdf_w * (w_light + 1.0 + w_camera)));
                    if (max3(c) > 0.0 && shadow_clear_now(shadow_ray_between(s.p, ng_f, ls.p, ls.n), c, stats)) {
                        radiance += c;
                    }
                }
            }
            // s >= 2: stored light vertices. Vertex y has light subpath segments y.segments, so
            // the full path has y.segments + 1 + depth segments.
            if (pc.join == JOIN_LVC) {
                // Light vertex cache: `joins` vertices drawn uniformly from the `total` stored
                // by all light paths. A drawn vertex y of path p was evaluated with
                // probability joins / total given the cache, and stored with p's reservoir
                // probability stored / seen; dividing by both and by the number of light
                // paths makes the expectation the full join's (docs/integrators.md).
                uint total = lvc_total;
                if (total > 0u) {
                    uint joins = pc.join_k > 0u ? pc.join_k : max(1u, uint(float(total) / float(pc.light_path_total) + 0.5));
                    float scale = float(total) / (float(joins) * float(pc.light_path_total));
                    for (uint j = 0u; j < joins; j++) {
                        uint slot = lvc_index[rng_below(rng, total)];
                        uvec2 c = light_counts[slot / pc.light_path_len];
                        LightVertex y = load_light_vertex(slot);
                        if (pc.max_depth != 0u && uint(y.segments) + 1u + depth > pc.max_depth) {
                            continue;
                        }
                        float inv_q = scale * float(c.y) / float(c.x);
                        radiance += connect(s.p, ns_f, ng_f, wo, bsdf, sigma_in, d_vcm, d_vc, vm_camera, vm_light, y, beta * inv_q, stats);
                    }
                }
            } else if (lc.x > 0u) {
                bool full = pc.join == JOIN_FULL || pc.join_k >= lc.x;
                uint joins = full ? lc.x : pc.join_k;
                // Evaluation probability of a vertex: reservoir (stored / seen) times the
                // join's choice (joins / stored).
                float inv_q = float(lc.y) / float(joins);
                for (uint j = 0u; j < joins; j++) {
                    uint slot = full ? j : min(uint(rng_next(rng) * float(lc.x)), lc.x - 1u);
                    LightVertex y = load_light_vertex(base + slot);
                    if (pc.max_depth != 0u && uint(y.segments) + 1u + depth > pc.max_depth) {
                        continue;
                    }
                    radiance += connect(s.p, ns_f, ng_f, wo, bsdf, sigma_in, d_vcm, d_vc, vm_camera, vm_light, y, beta * inv_q, stats);
                }
            }
        }

        // Continue by sampling the BSDF (radiance transport).
        uint lobe = choose_lobe_drawn(m, s.uv, rng);
        if (lobe == LOBE_DIFFUSE && VCM_PHOTON_MAPPING) {
            break; // progressive photon mapping: the merge above estimated the rest
        }
        if (lobe == LOBE_DIFFUSE) {
            if (!continuous_ok) {
                break;
            }
            float u_lobe = HAS_GLOSSY != 0u ? rng_next(rng) : 0.0;
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            vec3 dn;
            if (!continuous_sample(bsdf, ns_f, wo, u_lobe, u1, u2, dn) || dot(dn, ng_f) <= 0.0) {
                break;
            }
            float pdf_fwd_w, pdf_rev_w;
            vec3 f = continuous_eval(bsdf, ns_f, wo, dn, pdf_fwd_w, pdf_rev_w);
            if (pdf_fwd_w <= 0.0) {
                break;
            }
            float cos_out = dot(dn, ns_f);
            beta *= f * (cos_out / pdf_fwd_w);
            // The merging terms of this vertex: 1 in dVM, k.vm in dVC, where it is one.
            if (VCM != 0u) {
                d_vm = mis(cos_out / pdf_fwd_w) * (d_vm * mis(pdf_rev_w) + d_vcm * k.vc + (merge_here ? 1.0 : 0.0));
            }
            d_vc_merge = depth == 1u ? mis(cos_out / pdf_fwd_w) * vm_camera : 0.0; // dVC is 0 at the first vertex
            d_vc = mis(cos_out / pdf_fwd_w) * (d_vc * mis(pdf_rev_w) + d_vcm + vm_camera);
            d_vcm = mis(1.0 / pdf_fwd_w);
            merge_pending = false; // the first continuous scattering: no merging after it
            d = dn;
        } else if (HAS_ROUGH_GLASS != 0u && lobe == LOBE_ROUGH_GLASS) {
            // Rough glass: never connected, so the strategies whose connecting edge touches
            // this vertex are impossible: dVCM (the edge to the next vertex) is 0 and dVC
            // keeps only its own term, with the real pdf ratio (a delta lobe's cancels).
            float eta = s.front ? 1.0 / m.ior : m.ior;
            float u_sel = rng_next(rng);
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            vec3 dn;
            float weight, pdf_fwd_w, pdf_rev_w;
            bool refracted;
            if (!rough_dielectric_sample_world(ns_f, wo, eta, glass_alpha(m, s.uv), true, u_sel, u1, u2, dn, weight, pdf_fwd_w, pdf_rev_w, refracted)
                || (dot(dn, ng_f) > 0.0) == refracted) {
                break;
            }
            beta *= refracted ? weight * glass_tint(m, s.uv) : vec3(weight);
            d_vcm = 0.0;
            d_vc *= mis(abs(dot(dn, ns_f)) * pdf_rev_w / pdf_fwd_w);
            d_vm *= mis(abs(dot(dn, ns_f)) * pdf_rev_w / pdf_fwd_w); // VCM: as dVC (a vertex that is never merged)
            d = dn;
        } else {
            vec3 dn;
            if (lobe == LOBE_MIRROR) {
                dn = reflect(d, ns_f);
            } else {
                float eta = s.front ? 1.0 / m.ior : m.ior;
                float scale;
                bool refracted;
                dn = sample_dielectric(d, ns_f, eta, rng_next(rng), scale, refracted);
                beta *= refracted ? scale * glass_tint(m, s.uv) : vec3(scale);
            }
            d_vcm = 0.0;
            d_vc *= mis(abs(dot(dn, ns_f)));
            d_vm *= mis(abs(dot(dn, ns_f)));
            d = dn;
        }
        sigma_near = volume_sigma(m, dot(d, s.ng) < 0.0);
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);

        if (depth >= pc.rr_depth) {
            float q = min(max3(beta), 0.95);
            if (q <= 0.0 || rng_next(rng) >= q) {
                break;
            }
            beta /= q;
        }
    }
    return radiance;
}

void main() {
    // Invocation -> (slice, pixel): slice j is camera sample sample_base + j, joined (by the
    // megakernel joins) to light path j * pixels + pixel.
    // The film holds the camera's window; random numbers and light paths follow the full
    // image's pixel.
    uint tiles = tiled_count(pc.camera.window_size);
    uint samples = max(pc.camera_samples, 1u);
    uint slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, pc.camera.window_size, valid);
    if (!valid || slice >= samples) {
        return;
    }
    uint pixels = pc.camera.window_size.x * pc.camera.window_size.y;
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    Rng rng = rng_init(image_pixel, pc.sample_base + slice, pc.seed);
    vec2 xy = vec2(px) + vec2(rng_next(rng), rng_next(rng));
    g_query = slice * pixels + pixel;
    vec3 l = camera_path(slice * pc.camera.size.x * pc.camera.size.y + image_pixel, xy, rng);
    if (VCM_MERGE_DEFERRED && !g_queued) {
        merge_queries[g_query].depth = 0u; // nothing to merge for this sample
    }
    vec4 add = vec4(l, 1.0);
    if (any(isnan(l)) || any(isinf(l))) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], 1u);
        add = vec4(0.0);
        shadow_queued = 0u; // the dropped sample's queued shadow rays with it
    }
    shadow_queue_finish(shadow_queued);
    if (samples == 1u) {
        accum[pixel] += add;
    } else {
        slices_out[slice * pixels + pixel] = add;
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}
