// Punctual lights (KHR_lights_punctual): point, spot and directional. Delta lights: no ray
// can hit one, so they take part through light sampling (pdf in the delta's own measure),
// BDPT light paths and the connections and light tracing that follow (Georgiev 2012,
// "Implementing Vertex Connection and Merging", eqs. 48-50: dVC = 0 at a delta light).
// Needs env.glsl (the GpuEnv header holds the count, the pick probability and the disk from
// which directional lights' paths start).
#ifndef BIDIR_PUNCTUAL_GLSL
#define BIDIR_PUNCTUAL_GLSL

layout(constant_id = SPEC_HAS_PUNCTUAL) const uint HAS_PUNCTUAL = 0u;
layout(std430, binding = BIND_PUNCTUAL) readonly buffer Punctual { GpuPunctual punctual[]; };

// The extension's spot falloff toward unit direction w leaving the light: t^2 with
// t = clamp((cos - cos_outer) / (cos_inner - cos_outer), 0, 1); 1 for other kinds.
float punctual_falloff(GpuPunctual l, vec3 w) {
    if (l.kind != PUNCTUAL_SPOT) {
        return 1.0;
    }
    float t = clamp((dot(l.direction.xyz, w) - l.cos_outer) / max(l.cos_inner - l.cos_outer, 1e-3), 0.0, 1.0);
    return t * t;
}

// Solid-angle pdf with which a light path leaves point or spot light l in direction w:
// uniform over the sphere (point) or over the outer cone (spot).
float punctual_emission_dir_pdf(GpuPunctual l, vec3 w) {
    if (l.kind == PUNCTUAL_SPOT) {
        return dot(l.direction.xyz, w) >= l.cos_outer ? 1.0 / (2.0 * PI * (1.0 - l.cos_outer)) : 0.0;
    }
    return 1.0 / (4.0 * PI);
}

struct PunctualSample {
    vec3 w;            // unit direction from the shaded point toward the light
    float dist;        // distance to it (3e38 for directional lights)
    vec3 li;           // incident I falloff / d^2 (point, spot) or irradiance E (directional)
    float pick;        // probability of this light given a punctual light: 1 / count
    // emission pdf / direct pdf, both per pick (Georgiev's eq. 45 ratio for a delta light at
    // cosine 1): pdf_dir(-w) / d^2 (point, spot) or 1 / disk area (directional).
    float emission_over_direct;
};

// Light sampling: a punctual light uniformly (u), seen from point p.
PunctualSample punctual_sample(uint u, vec3 p) {
    uint count = env.punctual_count;
    GpuPunctual l = punctual[index_below(u, count)];
    PunctualSample s;
    s.pick = 1.0 / float(count);
    if (l.kind == PUNCTUAL_DIRECTIONAL) {
        s.w = -l.direction.xyz;
        s.dist = 3.0e38;
        s.li = l.intensity.rgb;
        s.emission_over_direct = 1.0 / env.disk_area;
    } else {
        vec3 v = l.position.xyz - p;
        float d2 = dot(v, v);
        s.dist = sqrt(d2);
        s.w = v / s.dist;
        s.li = l.intensity.rgb * (punctual_falloff(l, -s.w) / d2);
        s.emission_over_direct = punctual_emission_dir_pdf(l, -s.w) / d2;
    }
    return s;
}

#ifdef BIDIR_SCENE_GLSL
// The shadow ray from p (normal n_f on the side of s.w) to the light.
ShadowRay punctual_shadow_ray(vec3 p, vec3 n_f, PunctualSample s) {
    vec3 o = offset_ray_origin(p, n_f);
    float len = s.dist < 1.0e38 ? length(p + s.w * s.dist - o) : 3.0e38;
    return ShadowRay(o, s.w, len);
}
#endif

#endif
