// The environment light: radiance from infinitely far away, an equirectangular map with the
// conventions of src/scene/env.rs (+Y up, theta from +Y, phi = pi + atan2(x, -z) + rotate,
// row 0 at the top), looked up nearest-texel so that radiance is constant per texel.
//
// Sampling is a 2D piecewise-constant distribution: a texel by Walker's alias table with
// probability p_i proportional to luminance x texel solid angle (luminance x sin(theta),
// integrated over the texel), then a direction uniform in solid angle inside it (phi
// uniform, cos(theta) uniform). So pdf_w = p_i / Omega_i is constant in a texel and stored
// with it (GpuEnvTexel::pdf_w); a uniform environment (1 x 1) samples the sphere uniformly.
//
// A light path from the environment (BDPT) takes a direction w from the map and starts on a
// disk of radius R (the scene's bounding sphere), perpendicular to w, centred at C + R w,
// travelling along -w: its emission pdf is pdf_w / (pi R^2), per unit solid angle and disk
// area (SmallVCM's background light, Georgiev 2012 tech. report section 5.1).
#ifndef BIDIR_ENV_GLSL
#define BIDIR_ENV_GLSL

layout(constant_id = SPEC_HAS_ENV) const uint HAS_ENV = 0u;
layout(std430, binding = BIND_ENV) readonly buffer Env { GpuEnv env; };
layout(std430, binding = BIND_ENV_TEXELS) readonly buffer EnvTexels { GpuEnvTexel env_texels[]; };
layout(std430, binding = BIND_ENV_ALIAS) readonly buffer EnvAlias { GpuAlias env_alias[]; };

const float TWO_PI = 2.0 * PI;

struct EnvSample {
    vec3 w;       // unit direction toward the environment
    vec3 le;      // radiance arriving from it
    float pdf_w;  // solid-angle pdf of env_sample choosing w (not including env.pick)
};

// Texel seen in direction w (toward the environment).
uint env_texel_index(vec3 w) {
    float theta = acos(clamp(w.y, -1.0, 1.0));
    float phi = PI + atan(w.x, -w.z) + env.rotate;
    phi -= TWO_PI * floor(phi / TWO_PI);
    uint x = min(uint(phi / TWO_PI * float(env.width)), env.width - 1u);
    uint y = min(uint(theta / PI * float(env.height)), env.height - 1u);
    return y * env.width + x;
}

// A direction uniform in the cone of half-angle acos(cos_max) about unit axis a.
vec3 sample_uniform_cone(vec3 a, float cos_max, float u1, float u2) {
    float cos_t = 1.0 - u1 * (1.0 - cos_max);
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    float phi = TWO_PI * u2;
    vec3 t, b;
    onb(a, t, b);
    return cos_t * a + sin_t * (cos(phi) * t + sin(phi) * b);
}

// Adds the sun (a disk of uniform radiance, the alias table's last cell) where w sees it:
// the pdf is that of the mixture, texel plus sun.
EnvSample env_add_sun(EnvSample e) {
    if (dot(e.w, env.sun_direction.xyz) >= env.sun_cos_max) {
        e.le += env.sun_radiance.rgb;
        e.pdf_w += env.sun_pdf_w;
    }
    return e;
}

// Radiance from direction w and the solid-angle pdf with which env_sample picks it.
EnvSample env_lookup(vec3 w) {
    GpuEnvTexel t = env_texels[env_texel_index(w)];
    return env_add_sun(EnvSample(w, vec3(t.r, t.g, t.b), t.pdf_w));
}

// A direction from the map: a cell by the alias table (u_cell chooses the cell, u_coin its
// alias), then (u1, u2) uniform in solid angle inside the texel, or inside the sun's disk.
EnvSample env_sample(uint u_cell, float u_coin, float u1, float u2) {
    uint cells = env.cells;
    uint i = index_below(u_cell, cells); // every cell of a map past 2^24 texels too
    GpuAlias a = env_alias[i];
    uint c = u_coin < a.prob ? i : a.alias;
    if (c >= env.width * env.height) {
        return env_lookup(sample_uniform_cone(env.sun_direction.xyz, env.sun_cos_max, u1, u2));
    }
    uint col = c % env.width;
    uint row = c / env.width;
    float phi = TWO_PI * (float(col) + u1) / float(env.width) - env.rotate - PI;
    float cos0 = cos(PI * float(row) / float(env.height));
    float cos1 = cos(PI * float(row + 1u) / float(env.height));
    float cos_t = mix(cos0, cos1, u2);
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    GpuEnvTexel t = env_texels[c];
    return env_add_sun(EnvSample(vec3(sin_t * sin(phi), cos_t, -sin_t * cos(phi)), vec3(t.r, t.g, t.b), t.pdf_w));
}

// Origin of a light path arriving from direction w: uniform on the disk of radius R facing
// w, centred at C + R w (outside the bounding sphere); pdf_a = 1 / env.disk_area.
vec3 env_disk_origin(vec3 w, float u1, float u2) {
    vec3 t, b;
    onb(w, t, b);
    float r = env.bounds.w * sqrt(u1);
    float a = TWO_PI * u2;
    return env.bounds.xyz + env.bounds.w * w + r * (cos(a) * t + sin(a) * b);
}

#ifdef BIDIR_SCENE_GLSL
// The shadow ray from surface point p (normal n_f on the side of w) to the environment in
// direction w.
ShadowRay env_shadow_ray(vec3 p, vec3 n_f, vec3 w) {
    return ShadowRay(offset_ray_origin(p, n_f), w, 3.0e38);
}
#endif

// Probability that light sampling picks an emissive triangle rather than the environment
// or a punctual light (has_punctual: the kernel's HAS_PUNCTUAL).
float triangle_light_pick(bool has_punctual) {
    return 1.0 - (HAS_ENV != 0u ? env.pick : 0.0) - (has_punctual ? env.punctual_pick : 0.0);
}

#endif
