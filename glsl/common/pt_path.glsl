// One path of the path tracers (pt, pt-nee) between its segments: its state, its start and
// the scattering at what a segment found (path_scatter), shared by the megakernels (pt.comp, pt_loop.comp, pt_queue.comp,
// which trace in path_bounce) and the wavefront kernel (pt_wavefront.comp, whose segments
// and shadow rays are traced by the trace kernels between its launches; PT_WAVEFRONT).
// The includer declares `pc` (PtPush), the specialisation constants NEE, ONE_TRACE and
// SHADOW_SUSPEND, and includes ray, rng, scene, bsdf, lights, emission, env, punctual and
// volume (and, without PT_WAVEFRONT, shadow_queue.glsl); with PT_WAVEFRONT it declares
// wf_shadow, wf_shadow_contrib and wf_shadow_pending, where add_if_clear leaves a shadow ray.
#ifndef BIDIR_PT_PATH_GLSL
#define BIDIR_PT_PATH_GLSL

// Power heuristic with beta = 2 for two strategies.
float power_heuristic(float pdf_a, float pdf_b) {
    float a = pdf_a * pdf_a;
    return a / (a + pdf_b * pdf_b);
}

// One path in flight, between bounces. The invocation keeps one and regenerates: when a path
// ends, the next sample of the pixel starts in the same loop iteration's place, so the
// invocations of a subgroup keep tracing until the pass's samples are spent rather than
// idling behind the longest path (path regeneration, Novak, Havran & Dachsbacher 2010).
// The random numbers and the order of the sums are those of one path after another.
struct PathState {
    vec3 o;              // origin of the next segment
    vec3 d;              // its direction
    vec3 throughput;
    vec3 radiance;       // the estimate so far
    bool specular;       // the last bounce was a delta lobe (or the camera)
    float prev_pdf_w;    // solid-angle pdf of the last non-delta bounce
    uint depth;          // vertices so far, the one the next segment finds included
    vec3 sigma_near;     // sigma_a where the next segment leaves its surface (volume.glsl)
    // pt-nee with ONE_TRACE: the light sample's shadow ray, traced by the step after the one
    // that drew it from `o` (the surface point it leaves, where the path also continues):
    // its direction and length (> 0: pending), what it adds if unoccluded, and whether the
    // path ends after it.
    vec3 shadow_d;
    float shadow_tmax;
    vec3 shadow_contrib;
    bool ended;
};

// A new path through image position `pixel` (pixels, row 0 on top); `rng` has drawn its jitter.
PathState path_start(vec2 pixel, inout Rng rng) {
    if (HAS_ALPHA != 0u) {
        blend_seed = rng_next_uint(rng); // BLEND's stochastic opacity
    }
    PathState path;
    path.o = pc.camera.eye.xyz;
    path.d = camera_direction(pc.camera, pixel);
    path.throughput = vec3(1.0);
    path.radiance = vec3(0.0);
    path.specular = true;
    path.prev_pdf_w = 0.0;
    path.depth = 1u;
    path.sigma_near = vec3(0.0);
    path.shadow_d = vec3(0.0);
    path.shadow_tmax = 0.0;
    path.shadow_contrib = vec3(0.0);
    path.ended = false;
    return path;
}

// The path ends here: its radiance is final once a pending shadow ray is traced.
#define PATH_END \
    { \
        path.radiance = radiance; \
        path.ended = true; \
        return ONE_TRACE != 0u && NEE != 0u && path.shadow_tmax > 0.0; \
    }

// A light sample's contribution `contrib` if the shadow ray `r` (from the offset surface
// point the path continues from) is clear: with SHADOW_QUEUE queued for shadow_queue.comp
// while this invocation has slots left; else with ONE_TRACE pending for the next step's
// trace unless `r` is too short to hold an occluder, else traced here.
void add_if_clear(inout PathState path, ShadowRay r, vec3 contrib, inout vec3 radiance, inout uvec2 stats) {
#ifdef PT_WAVEFRONT
    // The wavefront kernel (pt_wavefront.comp) hands the ray to the any-hit trace kernel that
    // runs after it; at most one per bounce.
    if (r.tmax > 0.0) {
        wf_shadow = r;
        wf_shadow_contrib = contrib;
        wf_shadow_pending = true;
    } else {
        radiance += contrib;
    }
#else
    if (SHADOW_QUEUE != 0u && SHADOW_SUSPEND != 0u) {
        // A slot is always free (main() stops before a bounce that could find none), so this
        // kernel holds no shadow-ray traversal; a segment too short to hold an occluder
        // (tmax <= 0, or NaN) is not queued and counts as clear, as shadow_ray_clear has it.
        if (!queue_shadow(r, contrib)) {
            radiance += contrib;
        }
    } else if (queue_shadow(r, contrib)) {
        // traced by shadow_queue.comp
    } else if (ONE_TRACE == 0u) {
        if (shadow_ray_clear(r, stats)) {
            radiance += contrib;
        }
    } else if (r.tmax > 0.0) {
        path.o = r.o;
        path.shadow_d = r.d;
        path.shadow_tmax = r.tmax;
        path.shadow_contrib = contrib;
    } else {
        radiance += contrib;
    }
#endif
}

// What `path`'s next segment found (`h`, traced from path.o along path.d) and the scattering
// there: emission seen, the light sample (add_if_clear) and the next segment, or the end of the
// path (false; its radiance is then final once a pending shadow ray is traced).
bool path_scatter(inout PathState path, TraceHit h, inout Rng rng, inout uvec2 stats) {
    vec3 o = path.o;
    vec3 d = path.d;
    vec3 throughput = path.throughput;
    vec3 radiance = path.radiance;
    bool specular = path.specular;
    float prev_pdf_w = path.prev_pdf_w;
    uint depth = path.depth;
    vec3 sigma_near = path.sigma_near;

    if (h.prim == NO_HIT) {
        // The environment, weighted against sampling it as a light (pt-nee).
        if (HAS_ENV != 0u) {
            EnvSample e = env_lookup(d);
            float w = NEE != 0u && !specular ? power_heuristic(prev_pdf_w, env.pick * e.pdf_w) : 1.0;
            radiance += throughput * volume_transmittance(sigma_near, 3.0e38) * e.le * w;
        }
        PATH_END;
    }
    Surface s = surface_at(o, d, h);
    GpuMaterial m = materials[s.material];
    // Beer-Lambert over the segment just traced, inside a volume at either of its ends.
    vec3 sigma_in = volume_sigma(m, !s.front);
    if (HAS_VOLUME != 0u) {
        throughput *= volume_transmittance(segment_sigma(sigma_near, sigma_in), h.t);
    }

    // Emission seen by this segment: front faces only.
    if (m.emission_luminance > 0.0 && s.front) {
        float w = 1.0;
        if (NEE != 0u && !specular && pc.emitter_count > 0u) {
            float cos_l = -dot(s.ng, d);
            float pdf_light_w = triangle_light_pick(HAS_PUNCTUAL != 0u) * light_pdf_a(m.emission_luminance, pc.emitter_weight) * h.t * h.t / cos_l;
            w = power_heuristic(prev_pdf_w, pdf_light_w);
        }
        radiance += throughput * material_emission(m, s.uv) * w;
    }
    if (pc.max_depth != 0u && depth >= pc.max_depth) {
        PATH_END;
    }

    // Normals facing the side the ray came from.
    vec3 ng_f = s.front ? s.ng : -s.ng;
    vec3 ns_f = s.front ? s.ns : -s.ns;
    rng_start_vertex(rng, depth);
    uint lobe = choose_lobe_drawn(m, s.uv, rng);
    if (lobe == LOBE_MIRROR) {
        d = reflect(d, ns_f);
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);
        specular = true;
    } else if (lobe == LOBE_GLASS) {
        float eta = s.front ? 1.0 / m.ior : m.ior;
        float scale;
        bool refracted;
        d = sample_dielectric(d, ns_f, eta, rng_next(rng), scale, refracted);
        throughput *= refracted ? scale * glass_tint(m, s.uv) : vec3(scale);
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);
        specular = true;
    } else if (HAS_ROUGH_GLASS != 0u && lobe == LOBE_ROUGH_GLASS) {
        // Rough glass is sampled only (no light sampling here), so emission found next
        // counts in full, as after a delta lobe; its weight f |cos| / pdf_w is G2 / G1
        // (times eta^2 and the tint on refraction).
        float eta = s.front ? 1.0 / m.ior : m.ior;
        float u_sel = rng_next(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        vec3 dn;
        float weight, pdf_fwd_w, pdf_rev_w;
        bool refracted;
        if (!rough_dielectric_sample_world(ns_f, -d, eta, glass_alpha(m, s.uv), true, u_sel, u1, u2, dn, weight, pdf_fwd_w, pdf_rev_w, refracted)
            || (dot(dn, ng_f) > 0.0) == refracted) {
            PATH_END; // masked, or the geometric normal disagrees with the shading normal's side
        }
        throughput *= refracted ? weight * glass_tint(m, s.uv) : vec3(weight);
        d = dn;
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);
        specular = true;
    } else {
        // The continuous part (diffuse, GGX), chosen with probability c.pick: it is zero
        // unless both directions lie above the shading normal too (a reciprocal BSDF, so
        // light paths can follow it: docs/integrators.md). Its pdfs include c.pick; NEE
        // and BSDF sampling are weighed with the pdfs given this choice.
        if (HAS_NORMALS != 0u && dot(ns_f, -d) <= 0.0) {
            PATH_END;
        }
        Continuous c = continuous_at(m, s.uv);
        vec3 p_off = offset_ray_origin(s.p, ng_f);
        // Next-event estimation: the environment (probability env.pick) or an emitter
        // point by power, one shadow ray; in a group of Sobol' dimensions, the light's kind
        // first and the point's (or direction's) two numbers after it.
        bool nee = NEE != 0u && (pc.emitter_count > 0u || HAS_ENV != 0u || HAS_PUNCTUAL != 0u) && (pc.max_depth == 0u || depth + 1u <= pc.max_depth);
        rng_start_group(rng);
        float u_kind = nee && (HAS_ENV != 0u || HAS_PUNCTUAL != 0u) ? rng_next(rng) : 1.0;
        bool env_light = nee && HAS_ENV != 0u && u_kind < env.pick;
        bool punctual_light = nee && HAS_PUNCTUAL != 0u && !env_light && u_kind < (HAS_ENV != 0u ? env.pick : 0.0) + env.punctual_pick;
        if (punctual_light) {
            // A delta light: BSDF sampling never finds it, so no MIS.
            PunctualSample ps = punctual_sample(rng_next_uint(rng), s.p);
            float cos_s = dot(ps.w, ns_f);
            if (cos_s > 0.0 && dot(ps.w, ng_f) > 0.0 && max3(ps.li) > 0.0) {
                // The contribution first, so only it stays live across the shadow ray.
                float pdf_fwd_w, pdf_rev_w;
                vec3 f = continuous_eval(c, ns_f, -d, ps.w, pdf_fwd_w, pdf_rev_w);
                vec3 contrib = throughput * volume_transmittance(sigma_in, ps.dist) * (f / c.pick) * ps.li * (cos_s / (env.punctual_pick * ps.pick));
                if (max3(contrib) > 0.0) {
                    add_if_clear(path, punctual_shadow_ray(s.p, ng_f, ps), contrib, radiance, stats);
                }
            }
        } else if (env_light) {
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            uint u_cell = rng_next_uint(rng);
            EnvSample es = env_sample(u_cell, rng_next(rng), u1, u2);
            float cos_s = dot(es.w, ns_f);
            if (cos_s > 0.0 && dot(es.w, ng_f) > 0.0 && es.pdf_w > 0.0) {
                float pdf_light_w = env.pick * es.pdf_w;
                float pdf_fwd_w, pdf_rev_w;
                vec3 f = continuous_eval(c, ns_f, -d, es.w, pdf_fwd_w, pdf_rev_w);
                float w = power_heuristic(pdf_light_w, pdf_fwd_w / c.pick);
                vec3 contrib = throughput * volume_transmittance(sigma_in, 3.0e38) * (f / c.pick) * es.le * (cos_s * w / pdf_light_w);
                if (max3(contrib) > 0.0) {
                    add_if_clear(path, env_shadow_ray(s.p, ng_f, es.w), contrib, radiance, stats);
                }
            }
        } else if (nee) {
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            LightSample ls = sample_emitter(pc.emitter_count, rng_next_uint(rng), u1, u2);
            vec3 to_l = ls.p - s.p;
            float dist2 = dot(to_l, to_l);
            float dist = sqrt(dist2);
            vec3 wi = to_l / dist;
            float cos_s = dot(wi, ns_f);
            float cos_l = -dot(wi, ls.n);
            if (cos_s > 0.0 && cos_l > 0.0 && dot(wi, ng_f) > 0.0) {
                float pdf_light_w = triangle_light_pick(HAS_PUNCTUAL != 0u) * light_pdf_a(luminance(ls.le), pc.emitter_weight) * dist2 / cos_l;
                float pdf_fwd_w, pdf_rev_w;
                vec3 f = continuous_eval(c, ns_f, -d, wi, pdf_fwd_w, pdf_rev_w);
                float w = power_heuristic(pdf_light_w, pdf_fwd_w / c.pick);
                // The shadow ray leaves on the side the path arrived on and reaches the
                // emitter's front: only this end can lie inside a volume.
                vec3 contrib = throughput * volume_transmittance(sigma_in, dist) * (f / c.pick) * light_sample_radiance(ls) * (cos_s * w / pdf_light_w);
                if (max3(contrib) > 0.0) {
                    add_if_clear(path, shadow_ray_between(s.p, ng_f, ls.p, ls.n), contrib, radiance, stats);
                }
            }
        }
        // Continuation by the continuous part's sampling: f cos / pdf_fwd_w; the direction's
        // two numbers first in their group, the lobe's after.
        rng_start_group(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        float u_lobe = HAS_GLOSSY != 0u ? rng_next(rng) : 0.0;
        vec3 dn;
        if (!continuous_sample(c, ns_f, -d, u_lobe, u1, u2, dn) || dot(dn, ng_f) <= 0.0) {
            PATH_END; // below the surface (shading-normal artefact) or a masked reflection
        }
        float pdf_fwd_w, pdf_rev_w;
        vec3 f = continuous_eval(c, ns_f, -d, dn, pdf_fwd_w, pdf_rev_w);
        if (pdf_fwd_w <= 0.0) {
            PATH_END;
        }
        prev_pdf_w = pdf_fwd_w / c.pick;
        throughput *= f * (dot(dn, ns_f) / pdf_fwd_w);
        d = dn;
        o = p_off;
        specular = false;
    }
    sigma_near = volume_sigma(m, dot(d, s.ng) < 0.0);

    // Russian roulette on throughput.
    if (depth >= pc.rr_depth) {
        float q = min(max3(throughput), 0.95);
        if (q <= 0.0 || rng_next(rng) >= q) {
            PATH_END;
        }
        throughput /= q;
    }
    path.o = o;
    path.d = d;
    path.throughput = throughput;
    path.radiance = radiance;
    path.specular = specular;
    path.prev_pdf_w = prev_pdf_w;
    path.depth = depth + 1u;
    path.sigma_near = sigma_near;
    return true;
}
#undef PATH_END

#ifndef PT_WAVEFRONT
// One step of `path`: the pending shadow ray if there is one, else the next segment and the
// scattering at what it finds (which may leave a shadow ray pending); false when the path
// has ended. Both rays go through the one trace_ray call here: the traversal is inlined
// once, and lanes of a subgroup tracing either kind run it together (the extension and the
// shadow ray used to be two call sites, run one after the other). The random numbers and the
// order of the sums are those of tracing the shadow ray where it is drawn.
bool path_bounce(inout PathState path, inout Rng rng) {
    uvec2 stats = uvec2(0u);
    bool shadow = ONE_TRACE != 0u && NEE != 0u && path.shadow_tmax > 0.0;
    TraceHit h = trace_ray(path.o, shadow ? path.shadow_d : path.d, 0.0, shadow ? path.shadow_tmax : 3.0e38, shadow, stats);
    if (shadow) {
        if (h.prim == NO_HIT) {
            path.radiance += path.shadow_contrib;
        }
        path.shadow_tmax = 0.0;
        return !path.ended;
    }
    return path_scatter(path, h, rng, stats);
}
#endif

// The pixel's sums of a pass: finite samples add to `sum` and `count`; a NaN or Inf sample
// never reaches the film, it is counted in `bad` and reported.
struct PixelSums {
    vec3 sum;
    float count;
    uint bad;
};

bool add_sample(inout PixelSums px, vec3 l) {
    if (any(isnan(l)) || any(isinf(l))) {
        px.bad++;
        return false;
    }
    px.sum += l;
    px.count += 1.0;
    return true;
}

// Sample `s` of the pixel: its random numbers and the start of its path.
PathState sample_start(uint image_pixel, uint s, vec2 xy, inout Rng rng) {
    rng = rng_init(image_pixel, pc.sample_base + s, pc.seed);
    vec2 jitter = vec2(rng_next(rng), rng_next(rng));
    return path_start(xy + jitter, rng);
}

#endif
