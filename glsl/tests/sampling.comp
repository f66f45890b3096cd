#version 460
// Runs the renderer's own sampling routines from glsl/common/ (nothing copied) so that
// tests/sampling.rs can check their distributions with chi-square and binomial tests:
// - SAMPLING_COSINE: sample_cosine_hemisphere about pc.a.xyz, out[i] = (direction, 0);
// - SAMPLING_COSINE_PDF: cosine_hemisphere_pdf of the direction in[i] about pc.a.xyz,
//   out[i].x (the pdf the integrators divide by);
// - SAMPLING_EMITTER: sample_emitter over the bound emitter and alias buffers,
//   out[2i] = (point, chosen index by choose_emitter with the same number),
//   out[2i + 1] = (normal, reported pick probability);
// - SAMPLING_DIELECTRIC: sample_dielectric for incident direction pc.a.xyz, normal pc.b.xyz
//   and eta pc.a.w, out[i] = (new direction, radiance scale if refracted else 0);
// - SAMPLING_GLOSSY / SAMPLING_GLOSSY_EVAL: continuous_sample / continuous_eval of the
//   BSDF given in the push (src/gpu/abi.rs says where each value is).
// - SAMPLING_ROUGH_GLASS / SAMPLING_ROUGH_GLASS_EVAL: the rough dielectric (rough_dielectric.glsl).
// - SAMPLING_ENV: env_sample over the bound environment, out[2i] = (direction, its pdf_w),
//   out[2i + 1] = (radiance, pdf_w) that env_lookup reports for that direction.
// - SAMPLING_INDEX: index_below(u, n) for u, n = the bits of in[i].x, in[i].y:
//   out[i] = (the index as bits, what is left of u within it).
// - SAMPLING_FMA: precise fma(a, b, c) and a * b + c for in[i].xyz = (a, b, c), out[i].xy.
// - SAMPLING_BALLOT_CURSOR: ballot.glsl's cursor over the ballot in[i] (as bits) from lane
//   s = 37 i mod 129, taken until empty: out[i] = (first and second lane taken or 128, lanes
//   taken, their order folded as h 31 + lane + 1) as bits.
// - SAMPLING_RNG: rng.glsl's numbers themselves, with groups of Sobol' dimensions started
//   among them, for tests/sampling.rs's bit-for-bit comparison with its CPU twin (the kernel
//   created with the sampler to test).
// - SAMPLING_CONTRIB_PACK: packed_contrib.glsl on in[i].xyz: out[3i] = (contrib_round, 0),
//   out[3i + 1] = (contrib_unpack of contrib_pack, 0), out[3i + 2] = (contrib_pack's words as
//   bits, contrib_round of the rounded x and y).
// Uniform numbers come from rng.glsl (the independent sampler unless the kernel is created
// with another), as in the integrators.
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"

// bsdf.glsl reads these scene constants (scene.glsl declares them for the integrators).
layout(constant_id = SPEC_HAS_MIRROR) const uint HAS_MIRROR = 0u;
layout(constant_id = SPEC_HAS_GLASS) const uint HAS_GLASS = 1u;
layout(constant_id = SPEC_HAS_GLOSSY) const uint HAS_GLOSSY = 1u;
layout(constant_id = SPEC_HAS_ROUGH_GLASS) const uint HAS_ROUGH_GLASS = 1u;
layout(constant_id = SPEC_HAS_CLEARCOAT) const uint HAS_CLEARCOAT = 1u;
#include "bsdf.glsl"
#include "lights.glsl"
#include "env.glsl"
#include "ballot.glsl"
#include "packed_contrib.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SAMPLING_BIND_OUT) writeonly buffer Out { vec4 result[]; };
layout(std430, binding = SAMPLING_BIND_IN) readonly buffer In { vec4 input_dirs[]; };
layout(push_constant) uniform Push { SamplingTestPush pc; };

Continuous push_bsdf() {
    Continuous c;
    c.diffuse = pc.c.rgb;
    c.coat = pc.c.w;
    c.spec_f0 = pc.d.rgb;
    c.spec = pc.d.w;
    c.coat_f0 = pc.e.x;
    c.alpha = pc.e.y;
    c.clearcoat = pc.e.z;
    c.cc_alpha = max(pc.e.w, GGX_MIN_ALPHA);
    c.pick = 1.0;
    return c;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    Rng rng = rng_init(i, 0u, pc.seed);
    if (pc.mode == SAMPLING_RNG) {
        // Sixteen numbers, path vertices and new groups of Sobol' dimensions started among
        // them (SAMPLING_RNG_VERTEX_STARTS, SAMPLING_RNG_GROUP_STARTS: a bit per number).
        rng = rng_init(i / 8u, floatBitsToUint(input_dirs[i].x), pc.seed);
        uint vertex = 0u;
        for (uint k = 0u; k < 4u; k++) {
            uvec4 v;
            for (uint c = 0u; c < 4u; c++) {
                if ((SAMPLING_RNG_VERTEX_STARTS & (1u << (4u * k + c))) != 0u) {
                    vertex++;
                    rng_start_vertex(rng, vertex);
                }
                if ((SAMPLING_RNG_GROUP_STARTS & (1u << (4u * k + c))) != 0u) {
                    rng_start_group(rng);
                }
                v[c] = rng_next_uint(rng);
            }
            result[4u * i + k] = uintBitsToFloat(v);
        }
    } else if (pc.mode == SAMPLING_COSINE) {
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        result[i] = vec4(sample_cosine_hemisphere(pc.a.xyz, u1, u2), 0.0);
    } else if (pc.mode == SAMPLING_COSINE_PDF) {
        result[i] = vec4(cosine_hemisphere_pdf(dot(pc.a.xyz, input_dirs[i].xyz)), 0.0, 0.0, 0.0);
    } else if (pc.mode == SAMPLING_EMITTER) {
        uint u0 = rng_next_uint(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        LightSample s = sample_emitter(pc.emitter_count, u0, u1, u2);
        result[2u * i] = vec4(s.p, float(choose_emitter(u0, pc.emitter_count)));
        result[2u * i + 1u] = vec4(s.n, s.pick);
    } else if (pc.mode == SAMPLING_DIELECTRIC) {
        float scale;
        bool refracted;
        vec3 d = sample_dielectric(pc.a.xyz, pc.b.xyz, pc.a.w, rng_next(rng), scale, refracted);
        result[i] = vec4(d, refracted ? scale : 0.0);
    } else if (pc.mode == SAMPLING_GLOSSY) {
        Continuous c = push_bsdf();
        float u_lobe = rng_next(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        vec3 wi;
        bool ok = continuous_sample(c, pc.b.xyz, pc.a.xyz, u_lobe, u1, u2, wi);
        float pdf_fwd_w = 0.0, pdf_rev_w = 0.0;
        vec3 f = ok ? continuous_eval(c, pc.b.xyz, pc.a.xyz, wi, pdf_fwd_w, pdf_rev_w) : vec3(0.0);
        vec3 weight = pdf_fwd_w > 0.0 ? f * dot(wi, pc.b.xyz) / pdf_fwd_w : vec3(0.0);
        result[2u * i] = vec4(wi, ok ? 1.0 : 0.0);
        result[2u * i + 1u] = vec4(weight, pdf_fwd_w);
    } else if (pc.mode == SAMPLING_GLOSSY_EVAL) {
        Continuous c = push_bsdf();
        vec3 wo = input_dirs[2u * i].xyz;
        vec3 wi = input_dirs[2u * i + 1u].xyz;
        float fwd, rev, fwd_swapped, rev_swapped;
        vec3 f = continuous_eval(c, pc.b.xyz, wo, wi, fwd, rev);
        vec3 f_swapped = continuous_eval(c, pc.b.xyz, wi, wo, fwd_swapped, rev_swapped);
        result[2u * i] = vec4(f, fwd);
        result[2u * i + 1u] = vec4(f_swapped, rev);
    } else if (pc.mode == SAMPLING_ROUGH_GLASS) {
        float u_sel = rng_next(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        vec3 wi;
        float weight, fwd, rev;
        bool refracted;
        bool ok = rough_dielectric_sample_world(pc.b.xyz, pc.a.xyz, pc.c.x, pc.c.y, pc.c.z > 0.0, u_sel, u1, u2, wi, weight, fwd, rev, refracted);
        result[2u * i] = vec4(wi, ok ? 1.0 : 0.0);
        result[2u * i + 1u] = vec4(weight, fwd, rev, refracted ? 1.0 : 0.0);
    } else if (pc.mode == SAMPLING_ROUGH_GLASS_EVAL) {
        vec3 wo = to_local(pc.b.xyz, input_dirs[2u * i].xyz);
        vec3 wi = to_local(pc.b.xyz, input_dirs[2u * i + 1u].xyz);
        float eta = pc.c.x, alpha = pc.c.y;
        result[2u * i] = vec4(rough_dielectric_f(wo, wi, eta, alpha, true), rough_dielectric_f(wo, wi, eta, alpha, false),
                              rough_dielectric_pdf_w(wo, wi, eta, alpha), rough_dielectric_rev_pdf_w(wo, wi, eta, alpha));
        // The pair swapped, seen from wi's side (z negated and eta inverted on transmission).
        bool t = wi.z < 0.0;
        vec3 a = t ? vec3(wi.xy, -wi.z) : wi;
        vec3 b = t ? vec3(wo.xy, -wo.z) : wo;
        float eta_s = t ? 1.0 / eta : eta;
        result[2u * i + 1u] = vec4(rough_dielectric_f(a, b, eta_s, alpha, true), rough_dielectric_f(a, b, eta_s, alpha, false),
                                   rough_dielectric_pdf_w(a, b, eta_s, alpha), rough_dielectric_rev_pdf_w(a, b, eta_s, alpha));
    } else if (pc.mode == SAMPLING_ENV) {
        uint u_cell = rng_next_uint(rng);
        float u_coin = rng_next(rng);
        float u1 = rng_next(rng);
        EnvSample e = env_sample(u_cell, u_coin, u1, rng_next(rng));
        EnvSample l = env_lookup(e.w);
        result[2u * i] = vec4(e.w, e.pdf_w);
        result[2u * i + 1u] = vec4(l.le, l.pdf_w);
    } else if (pc.mode == SAMPLING_INDEX) {
        float rest;
        uint index = index_below(floatBitsToUint(input_dirs[i].x), floatBitsToUint(input_dirs[i].y), rest);
        result[i] = vec4(uintBitsToFloat(index), rest, 0.0, 0.0);
    } else if (pc.mode == SAMPLING_FMA) {
        vec3 v = input_dirs[i].xyz;
        precise float fused = fma(v.x, v.y, v.z);
        precise float separate = v.x * v.y + v.z;
        result[i] = vec4(fused, separate, 0.0, 0.0);
    } else if (pc.mode == SAMPLING_BALLOT_CURSOR) {
        uint s = (37u * i) % 129u;
        uvec4 b = ballot_from(floatBitsToUint(input_dirs[i]), s);
        uvec4 took = uvec4(128u, 128u, 0u, 0u);
        for (uint n = 0u; n < 128u && b != uvec4(0u); n++) {
            uint lane = ballot_take_lowest(b);
            took.x = n == 0u ? lane : took.x;
            took.y = n == 1u ? lane : took.y;
            took.z = n + 1u;
            took.w = took.w * 31u + lane + 1u;
        }
        result[i] = uintBitsToFloat(took);
    } else if (pc.mode == SAMPLING_CONTRIB_PACK) {
        vec3 c = input_dirs[i].xyz;
        vec3 r = contrib_round(c);
        result[3u * i] = vec4(r, 0.0);
        result[3u * i + 1u] = vec4(contrib_unpack(contrib_pack(c)), 0.0);
        result[3u * i + 2u] = vec4(uintBitsToFloat(contrib_pack(c)), contrib_round(r).xy);
    }
}
