// BDPT's light subpath (and VCM's): its start at a light and its join to the eye (t = 1),
// shared by the light megakernel (bdpt_light.comp) and the wavefront light pass
// (bdpt_light_wavefront.comp), which both include the step of a path, bdpt_light_step.glsl.
// The includer declares `pc` (BdptPush's fields).
#ifndef BIDIR_BDPT_LIGHT_PATH_GLSL
#define BIDIR_BDPT_LIGHT_PATH_GLSL

// The start of a light subpath: the first segment (o, d), the throughput beta leaving the
// light, dVCM and dVC there (Georgiev 2012, "Implementing Vertex Connection and Merging"), and
// whether the light is at infinity (an environment or directional light: its first segment's
// length does not enter dVCM). An emitter point chosen by power and a cosine-distributed
// direction, an environment direction from its map, or a punctual light. False where the scene
// has no light or the sample carries none.
bool light_path_start(inout Rng rng, out vec3 o, out vec3 d, out vec3 beta, out float d_vcm, out float d_vc, out bool at_infinity) {
    o = vec3(0.0);
    d = vec3(0.0, 0.0, 1.0);
    beta = vec3(0.0);
    d_vcm = 0.0;
    d_vc = 0.0;
    at_infinity = false;
    if (pc.emitter_count == 0u && HAS_ENV == 0u && HAS_PUNCTUAL == 0u) {
        return false;
    }
    float u_kind = HAS_ENV != 0u || HAS_PUNCTUAL != 0u ? rng_next(rng) : 1.0;
    bool from_env = HAS_ENV != 0u && u_kind < env.pick;
    bool from_punctual = HAS_PUNCTUAL != 0u && !from_env && u_kind < (HAS_ENV != 0u ? env.pick : 0.0) + env.punctual_pick;
    at_infinity = from_env;
    if (from_punctual) {
        // A delta light (eqs. 48-50): dVCM = mis(direct pdf / emission pdf), dVC = 0.
        uint count = env.punctual_count;
        GpuPunctual l = punctual[index_below(rng_next_uint(rng), count)];
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
            return false;
        }
        d_vcm = mis(pick / emission_pdf_w);
        d_vc = 0.0;
    } else if (from_env) {
        // From the environment: a direction from the map, an origin on the disk facing it
        // (emission pdf = pick * pdf_w / disk area, cosine 1; Georgiev 2012, section 5.1).
        uint u_cell = rng_next_uint(rng);
        float u_coin = rng_next(rng);
        float u1 = rng_next(rng);
        EnvSample es = env_sample(u_cell, u_coin, u1, rng_next(rng));
        float direct_pdf_w = env.pick * es.pdf_w;
        float emission_pdf_w = direct_pdf_w / env.disk_area;
        if (!(emission_pdf_w > 0.0)) {
            return false;
        }
        d = -es.w;
        o = env_disk_origin(es.w, rng_next(rng), rng_next(rng));
        beta = es.le / emission_pdf_w;
        d_vcm = mis(direct_pdf_w / emission_pdf_w);
        d_vc = mis(1.0 / emission_pdf_w);
    } else {
        // The emitted ray: point by power (pdf_a = lum / total), direction cosine about the front.
        uint u_pick = rng_next_uint(rng);
        float u1 = rng_next(rng);
        LightSample ls = sample_emitter(pc.emitter_count, u_pick, u1, rng_next(rng));
        d = sample_cosine_hemisphere(ls.n, rng_next(rng), rng_next(rng));
        float cos0 = dot(d, ls.n);
        float direct_pdf_a = triangle_light_pick(HAS_PUNCTUAL != 0u) * luminance(ls.le) / pc.emitter_weight;
        float emission_pdf_w = direct_pdf_a * cos0 / PI;
        if (cos0 <= 0.0 || emission_pdf_w <= 0.0) {
            return false;
        }
        beta = light_sample_radiance(ls) * cos0 / emission_pdf_w;
        d_vcm = mis(direct_pdf_a / emission_pdf_w);
        d_vc = mis(cos0 / emission_pdf_w);
        o = offset_ray_origin(ls.p, ls.n);
    }
    return true;
}

// Strategy t = 1: the join of the light vertex at `p` to the eye. `c` is the vertex's
// continuous BSDF, `beta` the throughput arriving along wi, `sigma` the absorption on the side
// of the surface the path arrived on (volume.glsl). Where the eye sees the vertex inside the
// camera's window: true, the shadow ray toward the eye, the contribution it carries if clear
// and the film pixel it lands on.
bool camera_join(vec3 p, vec3 ns_f, vec3 ng_f, vec3 wi, Continuous c, vec3 beta, vec3 sigma, float d_vcm, float d_vc, float vm, out ShadowRay ray, out vec3 contrib, out uint pix) {
    ray = ShadowRay(vec3(0.0), vec3(0.0), 0.0);
    contrib = vec3(0.0);
    pix = 0u;
    vec3 to_eye = pc.camera.eye.xyz - p;
    float dist2 = dot(to_eye, to_eye);
    float dist = sqrt(dist2);
    vec3 w = to_eye / dist;
    float cos_cam = -dot(pc.camera.forward.xyz, w);
    vec2 raster;
    if (cos_cam <= 0.0 || !project_to_raster(pc.camera, p, raster)) {
        return false;
    }
    float cos_to_cam = dot(ns_f, w);
    if (cos_to_cam <= 0.0 || dot(ng_f, w) <= 0.0) {
        return false;
    }
    float r = image_plane_distance(pc.camera) / cos_cam;
    float image_to_solid_angle = r * r / cos_cam;
    float image_to_surface = image_to_solid_angle * cos_to_cam / dist2; // camera pdf_a
    // The BSDF toward the camera; its reverse pdf samples wi from w.
    float bsdf_dir_pdf_w, bsdf_rev_pdf_w;
    vec3 f = continuous_eval(c, ns_f, wi, w, bsdf_dir_pdf_w, bsdf_rev_pdf_w);
    float w_light = mis(image_to_surface / float(pc.light_paths)) * (vm + d_vcm + d_vc * mis(bsdf_rev_pdf_w));
    float adjoint = HAS_NORMALS != 0u ? shading_normal_adjoint(wi, w, ns_f, ng_f) : 1.0;
    contrib = beta * volume_transmittance(sigma, dist) * f * (adjoint * image_to_surface / float(pc.light_paths)) / (w_light + 1.0);
    if (max3(contrib) <= 0.0) {
        return false;
    }
    // Only the camera's window is on the film.
    uvec2 origin = uvec2(pc.camera.window_x, pc.camera.window_y);
    uvec2 wp = uvec2(raster) - origin;
    if (any(lessThan(uvec2(raster), origin)) || any(greaterThanEqual(wp, pc.camera.window_size))) {
        return false;
    }
    pix = wp.y * pc.camera.window_size.x + wp.x;
    vec3 o = offset_ray_origin(p, ng_f);
    vec3 to = pc.camera.eye.xyz - o;
    float len = length(to);
    ray = ShadowRay(o, to / len, len);
    return true;
}

#endif
