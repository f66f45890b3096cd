#version 460
// The first-hit pass: what each camera sample's ray finds, for the EXR's alpha and the AOVs
// a denoiser takes (`--aov albedo,normal,depth`; docs/integrators.md, "Alpha and AOVs").
// One invocation per window pixel adds, over the pass's samples, the coverage (1 where the
// camera ray hits geometry), the camera-ray distance to the first hit, and the first
// non-specular surface seen through mirror and glass: its reflectance (Intel Open Image
// Denoise's "albedo": delta lobes pass it through with weight 1) and its shading normal,
// facing the ray. Every integrator runs this same pass after its own in one submission, only
// when alpha or AOVs are asked for. Camera rays are generated as the integrators generate
// them (same random numbers for the jitter), so coverage follows the colour's samples.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "scene.glsl"
#include "bsdf.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_FIRST_HIT) buffer FirstHit { FirstHitSums first_hit[]; };
layout(push_constant) uniform Push { FirstHitPush pc; };
layout(constant_id = SPEC_FIRST_HIT_AOVS) const uint FIRST_HIT_AOVS = 1u;

// Reflectance of the continuous part given that choose_lobe took it: the diffuse lobe under
// its coat plus the GGX lobe's Schlick F0 (its albedo at normal incidence), under any clear
// coat (seen through it twice) plus the clear coat's own F0.
vec3 continuous_albedo(Continuous c) {
    vec3 a = c.diffuse * (1.0 - c.coat * c.coat_f0) + c.spec * c.spec_f0;
    if (has_clearcoat(c)) {
        float t = clearcoat_transmittance(c, 1.0);
        a = a * t * t + c.pick * c.clearcoat * CLEARCOAT_F0;
    }
    return c.pick > 0.0 ? a / c.pick : vec3(0.0);
}

// Adds one camera sample through image position `pixel` to `sum`.
void first_hit_sample(vec2 pixel, inout Rng rng, inout FirstHitSums sum) {
    if (HAS_ALPHA != 0u) {
        blend_seed = rng_next_uint(rng); // BLEND's stochastic opacity, as pt
    }
    uvec2 stats = uvec2(0u);
    vec3 o = pc.camera.eye.xyz;
    vec3 d = camera_direction(pc.camera, pixel);
    if (FIRST_HIT_AOVS == 0u) {
        // Alpha alone: whether anything covers the ray, not what is nearest. An any-hit ray
        // accepts a surface under the same BLEND/MASK test as the closest-hit ray (the
        // decision hashes the primitive and the hit point), so the count is the same.
        if (trace_ray(o, d, 0.0, 3.0e38, true, stats).prim != NO_HIT) {
            sum.hits += 1.0;
        }
        return;
    }
    TraceHit h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
    if (h.prim == NO_HIT) {
        return;
    }
    sum.hits += 1.0;
    sum.depth += h.t; // d is a unit vector
    for (uint bounce = 0u;; bounce++) {
        Surface s = surface_at(o, d, h);
        GpuMaterial m = materials[s.material];
        vec3 ns_f = s.front ? s.ns : -s.ns;
        uint lobe = choose_lobe_drawn(m, s.uv, rng);
        if (lobe == LOBE_DIFFUSE) {
            sum.albedo += continuous_albedo(continuous_at(m, s.uv));
            sum.normal += ns_f;
            return;
        }
        if (lobe == LOBE_ROUGH_GLASS) {
            // A rough dielectric scatters like a glossy surface: it ends the chain, its
            // albedo the transmission tint.
            sum.albedo += glass_tint(m, s.uv);
            sum.normal += ns_f;
            return;
        }
        if (bounce + 1u >= FIRST_HIT_SPECULAR_DEPTH) {
            sum.normal += ns_f; // a specular chain too long to follow: albedo 0
            return;
        }
        if (lobe == LOBE_MIRROR) {
            d = reflect(d, ns_f);
        } else {
            float eta = s.front ? 1.0 / m.ior : m.ior;
            float scale;
            bool refracted;
            d = sample_dielectric(d, ns_f, eta, rng_next(rng), scale, refracted);
        }
        o = offset_ray_origin(s.p, dot(d, s.ng) > 0.0 ? s.ng : -s.ng);
        h = trace_ray(o, d, 0.0, 3.0e38, false, stats);
        if (h.prim == NO_HIT) {
            // Through the specular chain to the environment: no surface reflects it, so the
            // albedo is 0; the normal is the last specular surface's.
            sum.normal += ns_f;
            return;
        }
    }
}

void main() {
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x, pc.camera.window_size, valid);
    if (!valid) {
        return;
    }
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    FirstHitSums sum;
    sum.albedo = vec3(0.0);
    sum.hits = 0.0;
    sum.normal = vec3(0.0);
    sum.depth = 0.0;
    for (uint s = 0u; s < pc.spp; s++) {
        Rng rng = rng_init(image_pixel, pc.sample_base + s, pc.seed);
        vec2 jitter = vec2(rng_next(rng), rng_next(rng));
        first_hit_sample(vec2(px) + jitter, rng, sum);
    }
    if (FIRST_HIT_AOVS == 0u) {
        first_hit[pixel].hits += sum.hits;
        return;
    }
    FirstHitSums total = first_hit[pixel];
    total.albedo += sum.albedo;
    total.hits += sum.hits;
    total.normal += sum.normal;
    total.depth += sum.depth;
    first_hit[pixel] = total;
}
