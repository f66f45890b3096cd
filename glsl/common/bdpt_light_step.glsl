// One step of BDPT's light subpath (and VCM's), as a fragment included in a loop body: what the
// segment just traced found (`h`, from o along d) and the scattering there — the vertex offered
// to the store (a reservoir of `pc.light_path_len` slots), its join to the eye (t = 1,
// `connect_to_camera`), then the next segment (o, d) with Russian roulette. `break` ends the
// path. Included by the light megakernel (bdpt_light.comp, its loop over `depth`) and the
// wavefront light pass (bdpt_light_wavefront.comp, a one-pass loop per launch); a fragment for
// the reason bdpt_camera_step.glsl is one (the megakernel compiles as it did before).
// The includer has in scope: `pc` (BdptPush's fields), the light vertex store, the path's o, d,
// beta, beta0, d_vcm, d_vc, d_vm, sigma_near, at_infinity, depth, seen, stored and base, the
// iteration's k (VcmFactors), stats, rng, and
// `void connect_to_camera(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wi, Continuous c, vec3 beta,
// vec3 sigma, float d_vcm, float d_vc, float vm, inout uvec2 stats)` (bdpt_light_path.glsl's
// camera_join, then traced, queued or splatted).
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

    rng_start_vertex(rng, depth);

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
        uint slot = seen <= pc.light_path_len ? seen - 1u : rng_below(rng, seen);
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
    } else if (!scatter_unconnected_lobe(lobe, m, s, ns_f, ng_f, false, rng, d, beta, d_vcm, d_vc, d_vm)) {
        break; // mirror, glass or rough glass (importance: no eta^2; vcm.glsl)
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
