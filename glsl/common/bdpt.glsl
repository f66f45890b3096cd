// Shared pieces of the BDPT kernels: the MIS function, the pinhole camera as a sensor (its
// pdfs and the projection of points onto the image), and the light-vertex store.
//
// MIS uses the recursive quantities of Georgiev 2012, "Implementing Vertex Connection and
// Merging" (tech. report, section 4 and appendix, vertex merging off): each subpath vertex
// carries dVCM and dVC, from which the power-heuristic weight of any connection follows in
// O(1). Strategies: s = 0 (camera path hits an emitter), s = 1 (a fresh light sample, NEE),
// s >= 2 (connection to a stored light vertex), t = 1 (light vertex to camera, splatted).
#ifndef BIDIR_BDPT_GLSL
#define BIDIR_BDPT_GLSL

// The light-vertex store: LIGHT_VERTEX_WORDS 16-byte words per slot. 6 hold a `LightVertex`
// as std430 lays it out (src/gpu/abi.rs); 4 are the compact form of scenes without GGX lobes
// or volumes, outside VCM's merging, which read none of uv, material, back_face and d_vm:
// pos, dVCM | ns, dVC | beta f, pick | ng and wi octahedral in 16 + 16 bits, segments. The
// store is written once and read about once per vertex, so its bytes are what a light vertex
// costs (src/render/bdpt.rs, `light_vertex_words`).
layout(constant_id = SPEC_LIGHT_VERTEX_WORDS) const uint LIGHT_VERTEX_WORDS = 6u;
layout(std430, binding = BIND_LIGHT_VERTICES) buffer LightVertices { uvec4 light_vertex_words[]; };
// Per light path: (vertices stored, vertices seen). The store is a reservoir.
layout(std430, binding = BIND_LIGHT_COUNTS) buffer LightCounts { uvec2 light_counts[]; };

// The octahedral map of unit vectors to [-1, 1]^2 and back (Cigolle et al. 2014, "A Survey of
// Efficient Representations for Independent Unit Vectors").
vec2 oct_fold(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0) {
        p = (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    }
    return p;
}

vec3 oct_unfold(vec2 p) {
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0) {
        n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    }
    return normalize(n);
}

// Unit vector as two 16-bit signed-normalised octahedral coordinates; error ~3e-5.
uint oct_encode(vec3 n) {
    return packSnorm2x16(oct_fold(n));
}

vec3 oct_decode(uint e) {
    return oct_unfold(unpackSnorm2x16(e));
}

void store_light_vertex(uint slot, LightVertex v) {
    uint b = slot * LIGHT_VERTEX_WORDS;
    light_vertex_words[b] = uvec4(floatBitsToUint(v.pos), floatBitsToUint(v.d_vcm));
    light_vertex_words[b + 1u] = uvec4(floatBitsToUint(v.ns), floatBitsToUint(v.d_vc));
    if (LIGHT_VERTEX_WORDS == 4u) {
        light_vertex_words[b + 2u] = uvec4(floatBitsToUint(v.beta_f), floatBitsToUint(v.pick));
        light_vertex_words[b + 3u] = uvec4(oct_encode(v.ng), oct_encode(v.wi), floatBitsToUint(v.segments), 0u);
    } else {
        light_vertex_words[b + 2u] = uvec4(floatBitsToUint(v.ng), floatBitsToUint(v.pick));
        light_vertex_words[b + 3u] = uvec4(floatBitsToUint(v.wi), floatBitsToUint(v.segments));
        light_vertex_words[b + 4u] = uvec4(floatBitsToUint(v.beta_f), v.back_face);
        light_vertex_words[b + 5u] = uvec4(floatBitsToUint(v.uv), v.material, floatBitsToUint(v.d_vm));
    }
}

// The includer has included scene.glsl (HAS_NORMALS): without shading normals ng is ns, exactly.
LightVertex load_light_vertex(uint slot) {
    uint b = slot * LIGHT_VERTEX_WORDS;
    uvec4 w0 = light_vertex_words[b];
    uvec4 w1 = light_vertex_words[b + 1u];
    uvec4 w2 = light_vertex_words[b + 2u];
    uvec4 w3 = light_vertex_words[b + 3u];
    LightVertex v;
    v.pos = uintBitsToFloat(w0.xyz);
    v.d_vcm = uintBitsToFloat(w0.w);
    v.ns = uintBitsToFloat(w1.xyz);
    v.d_vc = uintBitsToFloat(w1.w);
    if (LIGHT_VERTEX_WORDS == 4u) {
        v.beta_f = uintBitsToFloat(w2.xyz);
        v.pick = uintBitsToFloat(w2.w);
        v.ng = HAS_NORMALS != 0u ? oct_decode(w3.x) : v.ns;
        v.wi = oct_decode(w3.y);
        v.segments = uintBitsToFloat(w3.z);
        v.back_face = 0u;
        v.uv = vec2(0.0);
        v.material = 0u;
        v.d_vm = 0.0;
    } else {
        uvec4 w4 = light_vertex_words[b + 4u];
        uvec4 w5 = light_vertex_words[b + 5u];
        v.ng = uintBitsToFloat(w2.xyz);
        v.pick = uintBitsToFloat(w2.w);
        v.wi = uintBitsToFloat(w3.xyz);
        v.segments = uintBitsToFloat(w3.w);
        v.beta_f = uintBitsToFloat(w4.xyz);
        v.back_face = w4.w;
        v.uv = uintBitsToFloat(w5.xy);
        v.material = w5.z;
        v.d_vm = uintBitsToFloat(w5.w);
    }
    return v;
}

#include "lvc_entry.glsl"

// A cache entry's preview (lvc_entry.glsl), its third 32-bit word: the shading normal as two
// 12-bit octahedral coordinates (about 0.05 degrees, enough for a resampling target) and the
// lobe pick in the top 8 bits. Written by lvc_compact.comp, read by connect_resampled.
uint lvc_preview_pack(vec3 ns, float pick) {
    uvec2 q = uvec2(round(clamp(oct_fold(ns) * 0.5 + 0.5, 0.0, 1.0) * 4095.0));
    return q.x | (q.y << 12u) | (uint(round(clamp(pick, 0.0, 1.0) * 255.0)) << 24u);
}

void lvc_preview_unpack(uint bits, out vec3 ns, out float pick) {
    ns = oct_unfold(vec2(float(bits & 0xfffu), float((bits >> 12u) & 0xfffu)) * (2.0 / 4095.0) - 1.0);
    pick = float(bits >> 24u) * (1.0 / 255.0);
}

// The reverse pdf of light vertex y's continuous lobe taken as diffuse: of sampling y.wi, the
// direction its light path arrived from, given any outgoing direction (light_vertex_f, exact
// without GGX lobes).
float diffuse_rev_pdf_w(LightVertex y) {
    return y.pick * max(0.0, dot(y.ns, y.wi)) / PI;
}

// The MIS heuristic in the recursive form of Georgiev 2012 ("Implementing Vertex Connection
// and Merging", eqs. 38-47): every weight is a sum of mis(pdf ratio) terms, so any power of
// the ratio gives weights that sum to one. Veach 1997, section 9.2.4: the balance heuristic
// (beta = 1, MIS_BALANCE) or the power heuristic with beta = 2 (RenderSettings::mis,
// render::default_mis).
layout(constant_id = SPEC_MIS_BALANCE) const uint MIS_BALANCE = 0u;

float mis(float x) {
    return MIS_BALANCE != 0u ? x : x * x;
}

// Light tracing for direct lighting (`--direct-light-tracing`, RenderSettings::
// direct_light_tracing; off by default). A path of two segments, light -> x -> eye, is also
// sampled by the camera path that hits the emitter (s = 0) and by x's light sample (s = 1), both
// drawn from the pixel's own stratified (Owen-scrambled Sobol') dimensions; light tracing's
// joins land on whatever pixel they project to, which no stratification reaches. The power
// heuristic weighs strategies as if all were independent samples, and so gives light tracing
// a share of direct lighting that costs more noise than it saves (and a shadow ray for every
// light path's first vertex). Off, light tracing is not a strategy of these paths: its sample
// count is 0 in their MIS weights on both ends (vcm.glsl's direct_light_tracing(); the camera
// pass's s = 1 weights at its first vertex and s = 0 weights at its second, the light pass's
// t = 1 joins of first vertices, which it skips), and the remaining weights of every such path
// still sum to 1: the estimate stays unbiased. The camera path's first vertex is on a surface the
// light sample can reach, so no two-segment path is lost (a delta surface there is never joined
// by light tracing anyway). Cornell box, per-sample MSE against the sharper reference, without
// it / with it: 0.88 at 16 spp, 0.77-0.81 at 64, 0.67 at 256 (lavapipe, seeds 0-2), and lower
// also with independent samples, on the rough Cornell box and where the light hides (docs/
// results.md, "Light tracing for direct lighting").
layout(constant_id = SPEC_DIRECT_LIGHT_TRACING) const uint DIRECT_LIGHT_TRACING = 0u;

// Importance (light-path throughput) scattered at a vertex with shading normals is not
// symmetric with radiance: the adjoint BSDF picks up |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|)
// (Veach 1997, section 5.3.2, eq. 5.20), wo toward the vertex the light came from, wi the
// direction it leaves in. It is 1 where ns = ng (flat shading). Applied at every light-path
// scattering and at the light vertex of every connection; camera paths need none.
float shading_normal_adjoint(vec3 wo, vec3 wi, vec3 ns, vec3 ng) {
    float den = abs(dot(wo, ng)) * abs(dot(wi, ns));
    return den > 0.0 ? abs(dot(wo, ns)) * abs(dot(wi, ng)) / den : 0.0;
}

// Distance from the eye to the image plane on which a pixel is 1 x 1.
float image_plane_distance(GpuCamera cam) {
    return float(cam.size.y) / (2.0 * length(cam.up.xyz));
}

// Solid-angle pdf of the camera generating direction `d` (per unit pixel area), SmallVCM's
// "imageToSolidAngleFactor": (D / cos)^2 / cos.
float camera_pdf_w(GpuCamera cam, vec3 d) {
    float cos_c = dot(cam.forward.xyz, d);
    float r = image_plane_distance(cam) / cos_c;
    return r * r / cos_c;
}

// Raster position of world point `p` (pixels, row 0 on top); false if behind the camera or
// outside the image.
bool project_to_raster(GpuCamera cam, vec3 p, out vec2 raster) {
    vec3 v = p - cam.eye.xyz;
    float z = dot(v, cam.forward.xyz);
    raster = vec2(-1.0);
    if (z <= 0.0) {
        return false;
    }
    float x = dot(v, cam.right.xyz) / (z * dot(cam.right.xyz, cam.right.xyz));
    float y = dot(v, cam.up.xyz) / (z * dot(cam.up.xyz, cam.up.xyz));
    raster = vec2((x + 1.0) * 0.5 * float(cam.size.x), (1.0 - y) * 0.5 * float(cam.size.y));
    return raster.x >= 0.0 && raster.y >= 0.0 && raster.x < float(cam.size.x) && raster.y < float(cam.size.y);
}

#endif
