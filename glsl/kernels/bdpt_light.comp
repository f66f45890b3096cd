#version 460
// BDPT, pass 1: one light subpath per invocation (one per pixel). An emitter point chosen by
// power, a cosine-distributed direction, then BSDF sampling with Russian roulette and no
// length bound. Every diffuse-capable vertex (a) is offered to the vertex store, a
// reservoir of `light_path_len` slots (Vitter's algorithm R), so each vertex is kept with
// probability min(1, L / n) — the camera pass divides by it — and (b) is joined to the camera
// (strategy t = 1) and splatted into the pixel it projects to; a path's first vertex only
// with DIRECT_LIGHT_TRACING (bdpt.glsl).
// With SPEC_VCM (`--integrator vcm`, vcm.glsl) it also carries dVM and stores each vertex
// for merging; without connections (photon mapping) it does not splat.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_atomic_float : require
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
layout(std430, binding = BIND_SPLAT) buffer Splat { float splat[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { BdptPush pc; };
// Stored vertices per path, for the light vertex cache's scan (written whatever the join).
layout(std430, binding = BIND_LVC_OFFSETS) writeonly buffer LvcOffsets { uint lvc_offsets[]; };

// Strategy t = 1: joins the light vertex at `p` to the eye and splats its contribution.
// `c` is the vertex's continuous BSDF, `beta` the throughput arriving along wi, `sigma` the
// absorption on the side of the surface the path arrived on (volume.glsl).
void connect_to_camera(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wi, Continuous c, vec3 beta, vec3 sigma, float d_vcm, float d_vc, float vm, inout uvec2 stats) {
    vec3 to_eye = pc.camera.eye.xyz - p;
    float dist2 = dot(to_eye, to_eye);
    float dist = sqrt(dist2);
    vec3 w = to_eye / dist;
    float cos_cam = -dot(pc.camera.forward.xyz, w);
    vec2 raster;
    if (cos_cam <= 0.0 || !project_to_raster(pc.camera, p, raster)) {
        return;
    }
    float cos_to_cam = dot(ns_f, w);
    if (cos_to_cam <= 0.0 || dot(ng_f, w) <= 0.0) {
        return;
    }
    float r = image_plane_distance(pc.camera) / cos_cam;
    float image_to_solid_angle = r * r / cos_cam;
    float image_to_surface = image_to_solid_angle * cos_to_cam / dist2; // camera pdf_a
    // The BSDF toward the camera; its reverse pdf samples wi from w.
    float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
    vec3 f = continuous_eval(c, ns_f, wi, w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
    float w_light = mis(image_to_surface / float(pc.light_paths)) * (vm + d_vcm + d_vc * mis(bsdf_rev_pdf_w));
    float adjoint = HAS_NORMALS != 0u ? shading_normal_adjoint(wi, w, ns_f, ng_f) : 1.0;
    vec3 contrib = beta * volume_transmittance(sigma, dist) * f * (adjoint * image_to_surface / float(pc.light_paths)) / (w_light + 1.0);
    if (max3(contrib) <= 0.0) {
        return;
    }
    // Only the camera's window is on the film.
    uvec2 origin = uvec2(pc.camera.window_x, pc.camera.window_y);
    uvec2 wp = uvec2(raster) - origin;
    if (any(lessThan(uvec2(raster), origin)) || any(greaterThanEqual(wp, pc.camera.window_size))) {
        return;
    }
    uint pix = wp.y * pc.camera.window_size.x + wp.x;
    vec3 o = offset_ray_origin(p, ng_f);
    vec3 to = pc.camera.eye.xyz - o;
    float len = length(to);
    ShadowRay ray = ShadowRay(o, to / len, len);
    // Queued (shadow_queue_splat.comp traces it and splats if clear), or traced here.
    if (queue_tagged_shadow(ray, contrib, pix)) {
        return;
    }
    if (!shadow_ray_clear(ray, stats)) {
        return;
    }
    if (any(isnan(contrib)) || any(isinf(contrib))) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], 1u);
        return;
    }
    atomicAdd(splat[3u * pix + 0u], contrib.r);
    atomicAdd(splat[3u * pix + 1u], contrib.g);
    atomicAdd(splat[3u * pix + 2u], contrib.b);
}

// Light path `path`: its vertices to the store, its joins to the camera splatted or queued.
void light_path(uint path) {
    uvec2 stats = uvec2(0u);
    uint stored = 0u, seen = 0u;
    uint base = path * pc.light_path_len;
    if (pc.emitter_count == 0u && HAS_ENV == 0u && HAS_PUNCTUAL == 0u) {
        light_counts[path] = uvec2(0u);
        lvc_offsets[path] = 0u;
        return;
    }
    Rng rng = rng_init(path, pc.sample_base, pc.seed ^ 0x6c8e9cf5u);
    if (HAS_ALPHA != 0u) {
        blend_seed = uint(rng_next(rng) * 4294967296.0); // BLEND's stochastic opacity
    }

    vec3 beta, o, d;
    float d_vcm, d_vc;
    VcmFactors k = vcm_factors(pc.sample_base, pc.light_path_total);
    float u_kind = HAS_ENV != 0u || HAS_PUNCTUAL != 0u ? rng_next(rng) : 1.0;
    bool from_env = HAS_ENV != 0u && u_kind < env.pick;
    bool from_punctual = HAS_PUNCTUAL != 0u && !from_env && u_kind < (HAS_ENV != 0u ? env.pick : 0.0) + env.punctual_pick;
    // The light is at infinity (environment, directional): its first segment's length does
    // not enter dVCM.
    bool at_infinity = from_env;
    if (from_punctual) {
        // A delta light (eqs. 48-50): dVCM = mis(direct pdf / emission pdf), dVC = 0.
        uint count = env.punctual_count;
        GpuPunctual l = punctual[min(uint(rng_next(rng) * float(count)), count - 1u)];
        float pick = env.punctual_pick / float(count);
        float u1 = rng_next(rng), u2 = rng_next(rng);
        float emission_pdf_w;
        if (l.kind == PUNCTUAL_DIRECTIONAL) {
            d = l.direction.xyz;
            o = env_disk_origin(-d, u1, u2);
            emission_pdf_w = pick / env.disk_area;
            beta = l.intensity.rgb / emission_pdf_w;
            at_infinity = true;
        } else {
            d = l.kind == PUNCTUAL_SPOT ? sample_uniform_cone(l.direction.xyz, l.cos_outer, u1, u2) : sample_uniform_cone(vec3(0.0, 0.0, 1.0), -1.0, u1, u2);
            o = l.position.xyz;
            emission_pdf_w = pick * punctual_emission_dir_pdf(l, d);
            beta = l.intensity.rgb * punctual_falloff(l, d) / emission_pdf_w;
        }
        if (!(emission_pdf_w > 0.0) || max3(beta) <= 0.0) {
            light_counts[path] = uvec2(0u);
            lvc_offsets[path] = 0u;
            return;
        }
        d_vcm = mis(pick / emission_pdf_w);
        d_vc = 0.0;
    } else if (from_env) {
        // From the environment: a direction from the map, an origin on the disk facing it
        // (emission pdf = pick * pdf_w / disk area, cosine 1; Georgiev 2012, section 5.1).
        EnvSample es = env_sample(rng_next(rng), rng_next(rng), rng_next(rng), rng_next(rng));
        float direct_pdf_w = env.pick * es.pdf_w;
        float emission_pdf_w = direct_pdf_w / env.disk_area;
        if (!(emission_pdf_w > 0.0)) {
            light_counts[path] = uvec2(0u);
            lvc_offsets[path] = 0u;
            return;
        }
        d = -es.w;
        o = env_disk_origin(es.w, rng_next(rng), rng_next(rng));
        beta = es.le / emission_pdf_w;
        d_vcm = mis(direct_pdf_w / emission_pdf_w);
        d_vc = mis(1.0 / emission_pdf_w);
    } else {
        // The emitted ray: point by power (pdf_a = lum / total), direction cosine about the front.
        LightSample ls = sample_emitter(pc.emitter_count, rng_next(rng), rng_next(rng), rng_next(rng));
        d = sample_cosine_hemisphere(ls.n, rng_next(rng), rng_next(rng));
        float cos0 = dot(d, ls.n);
        float direct_pdf_a = triangle_light_pick(HAS_PUNCTUAL != 0u) * luminance(ls.le) / pc.emitter_weight;
        float emission_pdf_w = direct_pdf_a * cos0 / PI;
        if (cos0 <= 0.0 || emission_pdf_w <= 0.0) {
            light_counts[path] = uvec2(0u);
            lvc_offsets[path] = 0u;
            return;
        }
        beta = light_sample_radiance(ls) * cos0 / emission_pdf_w;
        d_vcm = mis(direct_pdf_a / emission_pdf_w);
        d_vc = mis(cos0 / emission_pdf_w);
        o = offset_ray_origin(ls.p, ls.n);
    }
    float beta0 = max3(beta);
    float d_vm = d_vc * k.vc; // dVM starts as dVC / eta (0 for a delta light)
    vec3 sigma_near = vec3(0.0); // sigma_a where the next segment leaves its surface (volume.glsl)

    for (uint depth = 1u;; depth++) {
        TraceHit h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
        if (h.prim == NO_HIT) {
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
        vec3 wi = -d;
        float cos_in = abs(dot(ns_f, wi));
        // An environment's first segment has no length in the measure (solid angle).
        if (!(at_infinity && depth == 1u)) {
            d_vcm *= mis(h.t * h.t);
        }
        d_vcm /= mis(cos_in);
        d_vc /= mis(cos_in);
        if (VCM != 0u) {
            d_vm /= mis(cos_in);
        }

        // The continuous part (diffuse, GGX) is zero unless light arrives from above the
        // shading normal too (the camera paths' BSDF, made reciprocal).
        Continuous c = continuous_at(m, s.uv);
        bool continuous_ok = HAS_NORMALS == 0u || dot(ns_f, wi) > 0.0;
        if (!continuous_ok) {
            c.pick = 0.0;
        }
        if (c.pick > 0.0) {
            // Without GGX lobes f does not depend on the outgoing direction: store beta f.
            vec3 beta_f = HAS_GLOSSY != 0u || VCM_MERGES ? beta : beta * c.diffuse / PI;
            // Reservoir: keep the seen-th vertex with probability L / seen.
            seen++;
            uint slot = seen <= pc.light_path_len ? seen - 1u : uint(rng_next(rng) * float(seen));
            if (slot < pc.light_path_len) {
                store_light_vertex(base + slot, LightVertex(s.p, d_vcm, ns_f, d_vc, ng_f, c.pick, wi, float(depth), beta_f, s.front ? 0u : 1u, s.uv, s.material, d_vm));
                stored = min(seen, pc.light_path_len);
            }
            // A first vertex is joined to the eye only where light tracing samples direct
            // lighting (bdpt.glsl, DIRECT_LIGHT_TRACING).
            bool joins_eye = depth > 1u || direct_light_tracing() > 0.0;
            if (VCM_CONNECTS && joins_eye && (pc.max_depth == 0u || depth + 1u <= pc.max_depth)) {
                connect_to_camera(s.p, ns_f, ng_f, wi, c, beta, sigma_in, d_vcm, d_vc, k.vm, stats);
            }
        }
        if (pc.max_depth != 0u && depth + 1u >= pc.max_depth) {
            break; // no longer light subpath can contribute
        }

        // Continue by sampling the BSDF (importance transport: no eta^2 radiance scaling).
        uint lobe = choose_lobe_drawn(m, s.uv, rng);
        if (lobe == LOBE_DIFFUSE) {
            if (!continuous_ok) {
                break;
            }
            float u_lobe = HAS_GLOSSY != 0u ? rng_next(rng) : 0.0;
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            vec3 dn;
            if (!continuous_sample(c, ns_f, wi, u_lobe, u1, u2, dn) || dot(dn, ng_f) <= 0.0) {
                break;
            }
            // f is symmetric, so the adjoint BSDF is f itself (up to the shading-normal factor
            // below); the reverse pdf samples wi from dn, 0 below the shading hemisphere.
            float pdf_fwd_w, pdf_rev_w;
            vec3 f = continuous_eval(c, ns_f, wi, dn, pdf_fwd_w, pdf_rev_w);
            if (pdf_fwd_w <= 0.0) {
                break;
            }
            float cos_out = dot(dn, ns_f);
            beta *= f * (cos_out / pdf_fwd_w);
            // Merging at this vertex: 1 (dVM) and k.vm (dVC) where light vertices can be
            // merged at (vcm.glsl, VCM_MERGE_EVERYWHERE); the vertex joined to the eye adds
            // its own (connect_to_camera's vm).
            float merge_here = vcm_light_merge_terms();
            if (VCM != 0u) {
                d_vm = mis(cos_out / pdf_fwd_w) * (d_vm * mis(pdf_rev_w) + d_vcm * k.vc + merge_here);
            }
            d_vc = mis(cos_out / pdf_fwd_w) * (d_vc * mis(pdf_rev_w) + d_vcm + k.vm * merge_here);
            d_vcm = mis(1.0 / pdf_fwd_w);
            d = dn;
        } else if (HAS_ROUGH_GLASS != 0u && lobe == LOBE_ROUGH_GLASS) {
            // Rough glass (importance: no eta^2), never connected: as bdpt_camera.comp.
            float eta = s.front ? 1.0 / m.ior : m.ior;
            float u_sel = rng_next(rng);
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            vec3 dn;
            float weight, pdf_fwd_w, pdf_rev_w;
            bool refracted;
            if (!rough_dielectric_sample_world(ns_f, wi, eta, glass_alpha(m, s.uv), false, u_sel, u1, u2, dn, weight, pdf_fwd_w, pdf_rev_w, refracted)
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
                if (refracted) {
                    beta *= glass_tint(m, s.uv);
                }
            }
            // Delta lobe: no connection is possible here; the pdf ratio cancels.
            d_vcm = 0.0;
            d_vc *= mis(abs(dot(dn, ns_f)));
            d_vm *= mis(abs(dot(dn, ns_f)));
            d = dn;
        }
        if (HAS_NORMALS != 0u) {
            beta *= shading_normal_adjoint(wi, d, ns_f, ng_f);
        }
        sigma_near = volume_sigma(m, dot(d, s.ng) < 0.0);
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);

        if (depth >= pc.rr_depth) {
            float q = min(max3(beta) / beta0, 0.95);
            if (q <= 0.0 || rng_next(rng) >= q) {
                break;
            }
            beta /= q;
        }
    }
    light_counts[path] = uvec2(stored, seen);
    lvc_offsets[path] = stored;
    ADD_TRAVERSAL_COUNTS(render_stats);
}

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path < pc.light_path_total) {
        light_path(path);
    }
    shadow_queue_finish(shadow_queued);
}
