// One step of BDPT's camera subpath (and VCM's), as a fragment included in a loop body: what
// the segment just traced found (`h`, from o along d) and the scattering there — the emitter
// found (s = 0), the merges, the light sample (s = 1), the connections to stored light vertices
// (s >= 2), then the next segment (o, d) with Russian roulette. `break` ends the path. Included
// by the camera megakernel (bdpt_camera.comp, its loop over `depth`) and the wavefront camera
// pass (bdpt_camera_wavefront.comp, a one-pass loop per launch): a fragment rather than a
// function, so that the megakernel compiles as it did before the wavefront pass shared it (a
// function with a return per way a path ends, inlined into the loop, cost the megakernel 3 %
// on the H200: docs/results.md, "BDPT's camera pass as a wavefront").
// The includer has in scope: `pc` (BdptPush's fields), BDPT_JOIN, the light vertex cache, the
// path's o, d, beta, radiance, d_vcm, d_vc, d_vc_merge, d_vm, merge_pending, sigma_near, depth,
// the iteration's k (VcmFactors) and vm_light, the megakernel joins' lc and base, stats, rng,
// and camera_shadow_clear (bdpt_camera_path.glsl); without BDPT_WAVEFRONT (VCM's merges) also
// merge_queries, g_query and g_queued, and vcm_merge.glsl.
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
    rng_start_vertex(rng, depth);

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
#ifndef BDPT_WAVEFRONT
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
#endif
    if (VCM_CONNECTS && bsdf.pick > 0.0) {
        // The light samples' dVCM: at the first vertex it is light tracing's term alone
        // (vcm.glsl, direct_light_tracing).
        float d_vcm_s1 = depth == 1u ? direct_light_tracing() * d_vcm : d_vcm;
        // s = 1: the environment (probability env.pick; its "point" is a direction, the
        // cosine there is 1), a punctual light, or a fresh point on an emitter; in a group of
        // Sobol' dimensions, the light's kind first and the point's (or direction's) two
        // numbers after it.
        rng_start_group(rng);
        float u_kind = HAS_ENV != 0u || HAS_PUNCTUAL != 0u ? rng_next(rng) : 1.0;
        bool env_light = HAS_ENV != 0u && u_kind < env.pick;
        bool punctual_light = HAS_PUNCTUAL != 0u && !env_light && u_kind < (HAS_ENV != 0u ? env.pick : 0.0) + env.punctual_pick;
        if (punctual_light) {
            // A delta light: BSDF sampling cannot find it (w_light = 0); the camera side
            // weighs emission against direct sampling at cosine 1 (eqs. 45, 49).
            PunctualSample ps = punctual_sample(rng_next_uint(rng), s.p);
            float cos_s = dot(ns_f, ps.w);
            if (cos_s > 0.0 && dot(ng_f, ps.w) > 0.0 && max3(ps.li) > 0.0) {
                float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
                vec3 f = continuous_eval(bsdf, ns_f, wo, ps.w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
                float w_camera = mis(ps.emission_over_direct * cos_s) * (vm_camera + d_vcm_s1 + d_vc * mis(bsdf_rev_pdf_w));
                vec3 c = beta * volume_transmittance(sigma_in, ps.dist) * f * ps.li * (cos_s / (env.punctual_pick * ps.pick * (1.0 + w_camera)));
                if (max3(c) > 0.0 && camera_shadow_clear(punctual_shadow_ray(s.p, ng_f, ps), c, stats)) {
                    radiance += c;
                }
            }
        } else if (env_light) {
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            uint u_cell = rng_next_uint(rng);
            EnvSample es = env_sample(u_cell, rng_next(rng), u1, u2);
            float cos_s = dot(ns_f, es.w);
            if (cos_s > 0.0 && dot(ng_f, es.w) > 0.0 && es.pdf_w > 0.0) {
                float direct_pdf_w = env.pick * es.pdf_w;
                float emission_pdf_w = direct_pdf_w / env.disk_area;
                float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
                vec3 f = continuous_eval(bsdf, ns_f, wo, es.w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
                float w_light = mis(bsdf_dir_pdf_w / direct_pdf_w);
                float w_camera = mis(emission_pdf_w * cos_s / direct_pdf_w) * (vm_camera + d_vcm_s1 + d_vc * mis(bsdf_rev_pdf_w));
                vec3 c = beta * volume_transmittance(sigma_in, 3.0e38) * f * es.le * (cos_s / (direct_pdf_w * (w_light + 1.0 + w_camera)));
                if (max3(c) > 0.0 && camera_shadow_clear(env_shadow_ray(s.p, ng_f, es.w), c, stats)) {
                    radiance += c;
                }
            }
        } else if (pc.emitter_count > 0u) {
            float u1 = rng_next(rng);
            float u2 = rng_next(rng);
            LightSample ls = sample_emitter(pc.emitter_count, rng_next_uint(rng), u1, u2);
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
                if (max3(c) > 0.0 && camera_shadow_clear(shadow_ray_between(s.p, ng_f, ls.p, ls.n), c, stats)) {
                    radiance += c;
                }
            }
        }
        // s >= 2: stored light vertices. Vertex y has light subpath segments y.segments, so
        // the full path has y.segments + 1 + depth segments.
        if (BDPT_JOIN == JOIN_LVC) {
            // Light vertex cache: `joins` vertices drawn uniformly from the `total` stored
            // by all light paths. A drawn vertex y of path p was evaluated with
            // probability joins / total given the cache, and stored with p's reservoir
            // probability stored / seen; dividing by both and by the number of light
            // paths makes the expectation the full join's (docs/integrators.md). With
            // LVC_CANDIDATES > 1 each drawn vertex is resampled from that many.
            uint total = lvc_total;
            if (total > 0u) {
                uint joins = pc.join_k > 0u ? pc.join_k : max(1u, uint(float(total) / float(pc.light_path_total) + 0.5));
                float scale = float(total) / (float(joins) * float(pc.light_path_total));
                for (uint j = 0u; j < joins; j++) {
                    if (LVC_CANDIDATES > 1u) {
                        // Each connection's vertex resampled from several (bdpt_camera_path.glsl).
                        radiance += connect_resampled(s.p, ns_f, ng_f, wo, bsdf, sigma_in, d_vcm, d_vc, vm_camera, vm_light, depth, j, total, beta * scale, rng, stats);
                        continue;
                    }
                    uvec2 entry = lvc_index[rng_below(rng, total) * LVC_ENTRY_WORDS].xy; // (slot, seen / stored)
                    LightVertex y = load_light_vertex(entry.x);
                    if (pc.max_depth != 0u && uint(y.segments) + 1u + depth > pc.max_depth) {
                        continue;
                    }
                    float inv_q = scale * uintBitsToFloat(entry.y);
                    radiance += connect(s.p, ns_f, ng_f, wo, bsdf, sigma_in, d_vcm, d_vc, vm_camera, vm_light, y, beta * inv_q, stats);
                }
            }
        } else if (lc.x > 0u) {
            bool full = BDPT_JOIN == JOIN_FULL || pc.join_k >= lc.x;
            uint joins = full ? lc.x : pc.join_k;
            // Evaluation probability of a vertex: reservoir (stored / seen) times the
            // join's choice (joins / stored).
            float inv_q = float(lc.y) / float(joins);
            for (uint j = 0u; j < joins; j++) {
                uint slot = full ? j : rng_below(rng, lc.x);
                LightVertex y = load_light_vertex(base + slot);
                if (pc.max_depth != 0u && uint(y.segments) + 1u + depth > pc.max_depth) {
                    continue;
                }
                radiance += connect(s.p, ns_f, ng_f, wo, bsdf, sigma_in, d_vcm, d_vc, vm_camera, vm_light, y, beta * inv_q, stats);
            }
        }
    }

    // Continue by sampling the BSDF (radiance transport), in a group of Sobol' dimensions.
    rng_start_group(rng);
    uint lobe = choose_lobe_drawn(m, s.uv, rng);
    if (lobe == LOBE_DIFFUSE && VCM_PHOTON_MAPPING) {
        break; // progressive photon mapping: the merge above estimated the rest
    }
    if (lobe == LOBE_DIFFUSE) {
        if (!continuous_ok) {
            break;
        }
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        float u_lobe = HAS_GLOSSY != 0u ? rng_next(rng) : 0.0;
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
    } else if (!scatter_unconnected_lobe(lobe, m, s, ns_f, ng_f, true, rng, d, beta, d_vcm, d_vc, d_vm)) {
        break; // mirror, glass or rough glass (vcm.glsl)
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
