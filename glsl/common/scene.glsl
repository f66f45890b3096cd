// The scene as the integrators see it: traversal, per-triangle data, materials, vertex
// attributes and textures (only what the scene has: see the HAS_* constants), and the
// surface record at a hit.
#ifndef BIDIR_SCENE_GLSL
#define BIDIR_SCENE_GLSL

layout(constant_id = SPEC_HAS_NORMALS) const uint HAS_NORMALS = 0u;
layout(constant_id = SPEC_HAS_UVS) const uint HAS_UVS = 0u;
layout(constant_id = SPEC_HAS_TEXTURES) const uint HAS_TEXTURES = 0u;
layout(constant_id = SPEC_HAS_MIRROR) const uint HAS_MIRROR = 0u;
layout(constant_id = SPEC_HAS_GLASS) const uint HAS_GLASS = 0u;
layout(constant_id = SPEC_HAS_ALPHA) const uint HAS_ALPHA = 0u;
layout(constant_id = SPEC_HAS_GLOSSY) const uint HAS_GLOSSY = 0u;
layout(constant_id = SPEC_HAS_EMISSION_TEXTURES) const uint HAS_EMISSION_TEXTURES = 0u;
layout(constant_id = SPEC_HAS_NORMAL_MAPS) const uint HAS_NORMAL_MAPS = 0u;
layout(constant_id = SPEC_HAS_ROUGH_GLASS) const uint HAS_ROUGH_GLASS = 0u;
layout(constant_id = SPEC_HAS_CLEARCOAT) const uint HAS_CLEARCOAT = 0u;

#define TRAVERSE_WITH_ALPHA
#include "traverse.glsl"
#include "bsdf.glsl"
#include "rng.glsl"

// (vertex 0, vertex 1, vertex 2, material) of each triangle, in leaf order.
layout(std430, binding = BIND_PRIM_INFO) readonly buffer PrimInfo { uvec4 prim_info[]; };
layout(std430, binding = BIND_MATERIALS) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = BIND_NORMALS) readonly buffer Normals { float vertex_normals[]; };
layout(std430, binding = BIND_UVS) readonly buffer Uvs { vec2 vertex_uvs[]; };
layout(std430, binding = BIND_TEXTURES) readonly buffer Textures { GpuTexture textures[]; };
layout(std430, binding = BIND_TEXELS) readonly buffer Texels { uint texels[]; };
layout(std430, binding = BIND_POSITIONS) readonly buffer Positions { float vertex_positions[]; };
layout(std430, binding = BIND_TANGENTS) readonly buffer Tangents { vec4 vertex_tangents[]; };

vec3 vertex_position(uint i) {
    return vec3(vertex_positions[3u * i], vertex_positions[3u * i + 1u], vertex_positions[3u * i + 2u]);
}

// The hit point from barycentrics of the triangle's vertices, not o + t d: offsetting rays
// off surfaces (offset_ray_origin) assumes a point with only the rounding error of the
// vertices themselves (exactly on axis-aligned planes such as y = 0), which o + t d, with an
// error proportional to t, does not have.
vec3 hit_point(TraceHit h) {
    vec3 v0, v1, v2;
    if (TRI_TEST == TRI_TEST_WATERTIGHT) {
        GpuTri t = bvh_tris[h.prim];
        v0 = t.a.xyz;
        v1 = t.b.xyz;
        v2 = t.c.xyz;
    } else {
        uvec4 info = prim_info[h.prim];
        v0 = vertex_position(info.x);
        v1 = vertex_position(info.y);
        v2 = vertex_position(info.z);
    }
    return (1.0 - h.bary.x - h.bary.y) * v0 + h.bary.x * v1 + h.bary.y * v2;
}

vec3 srgb_to_linear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

vec4 texel_fetch(GpuTexture t, int x, int y) {
    int w = int(t.width), h = int(t.height);
    x = ((x % w) + w) % w; // repeat
    y = ((y % h) + h) % h;
    vec4 c = unpackUnorm4x8(texels[t.offset + uint(y * w + x)]);
    if ((t.flags & TEXTURE_SRGB) != 0u) {
        c.rgb = srgb_to_linear(c.rgb);
    }
    return c;
}

// Bilinear, repeat wrap; uv (0, 0) is the top-left corner of the image.
vec4 sample_texture(uint index, vec2 uv) {
    GpuTexture t = textures[index];
    vec2 p = uv * vec2(t.width, t.height) - 0.5;
    vec2 f = p - floor(p);
    ivec2 i = ivec2(floor(p));
    vec4 a = mix(texel_fetch(t, i.x, i.y), texel_fetch(t, i.x + 1, i.y), f.x);
    vec4 b = mix(texel_fetch(t, i.x, i.y + 1), texel_fetch(t, i.x + 1, i.y + 1), f.x);
    return mix(a, b, f.y);
}

vec2 interpolate_uv(uvec4 info, vec2 bary) {
    return (1.0 - bary.x - bary.y) * vertex_uvs[info.x] + bary.x * vertex_uvs[info.y] + bary.y * vertex_uvs[info.z];
}

// Per-path seed of BLEND's stochastic opacity: the kernels set it from their random numbers
// at the start of every path (while HAS_ALPHA).
uint blend_seed = 0u;

// A uniform number in [0, 1) for a hit of triangle prim at bary on this path: a hash, so the
// closest-hit search may ask again and get the same answer, while distinct hits (another
// point, another triangle, another path) get independent-looking ones.
float blend_random(uint prim, vec2 bary) {
    uint h = blend_seed ^ (prim * 0x9e3779b9u) ^ (floatBitsToUint(bary.x) * 0x85ebca6bu) ^ (floatBitsToUint(bary.y) * 0xc2b2ae35u);
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return float(h >> 8u) * (1.0 / 16777216.0);
}

// MASK: kept where the alpha texture reaches the cutoff (m.alpha_cutoff > 0). BLEND: kept with
// probability opacity x texture alpha, so a path passes with probability 1 - alpha and the
// surface's contribution is weighted by alpha in expectation (stochastic opacity, unbiased).
bool traverse_alpha_hit(uint prim, vec2 bary) {
    uvec4 info = prim_info[prim];
    GpuMaterial m = materials[info.w];
    if (m.alpha_cutoff > 0.0) {
        return m.alpha_texture == 0u || sample_texture(m.alpha_texture - 1u, interpolate_uv(info, bary)).a >= m.alpha_cutoff;
    }
    if (m.opacity >= 1.0 && m.alpha_texture == 0u) {
        return true;
    }
    float alpha = m.opacity;
    if (HAS_UVS != 0u && m.alpha_texture != 0u) {
        alpha *= sample_texture(m.alpha_texture - 1u, interpolate_uv(info, bary)).a;
    }
    return blend_random(prim, bary) < alpha;
}

// The shading normal n perturbed by the material's tangent-space normal map (glTF 2.0:
// bitangent = cross(n, t) * t.w; X and Y scaled by normalTexture.scale), n where there is
// none or the tangent frame degenerates.
vec3 normal_mapped(uvec4 info, vec2 bary, vec2 uv, vec3 n) {
    GpuMaterial m = materials[info.w];
    if (m.normal_texture == 0u) {
        return n;
    }
    vec4 t = (1.0 - bary.x - bary.y) * vertex_tangents[info.x] + bary.x * vertex_tangents[info.y] + bary.y * vertex_tangents[info.z];
    vec3 tt = t.xyz - n * dot(n, t.xyz);
    if (dot(tt, tt) <= 1.0e-12) {
        return n;
    }
    tt = normalize(tt);
    vec3 bt = cross(n, tt) * (t.w < 0.0 ? -1.0 : 1.0);
    vec3 c = sample_texture(m.normal_texture - 1u, uv).xyz * 2.0 - 1.0;
    c.xy *= m.normal_scale;
    vec3 p = c.x * tt + c.y * bt + c.z * n;
    return dot(p, p) > 0.0 ? normalize(p) : n;
}

// What shading needs at a hit.
struct Surface {
    vec3 p;
    vec3 ng;      // unit geometric normal, CCW front
    vec3 ns;      // unit shading normal, in ng's hemisphere
    vec2 uv;
    uint material;
    bool front;   // the ray arrived at the front face
};

Surface surface_at(vec3 o, vec3 d, TraceHit h) {
    Surface s;
    uvec4 info = prim_info[h.prim];
    s.p = hit_point(h);
    s.ng = normalize(tri_geometric_normal(bvh_tris[h.prim]));
    s.ns = s.ng;
    if (HAS_NORMALS != 0u) {
        vec3 n0 = vec3(vertex_normals[3u * info.x], vertex_normals[3u * info.x + 1u], vertex_normals[3u * info.x + 2u]);
        vec3 n1 = vec3(vertex_normals[3u * info.y], vertex_normals[3u * info.y + 1u], vertex_normals[3u * info.y + 2u]);
        vec3 n2 = vec3(vertex_normals[3u * info.z], vertex_normals[3u * info.z + 1u], vertex_normals[3u * info.z + 2u]);
        vec3 n = (1.0 - h.bary.x - h.bary.y) * n0 + h.bary.x * n1 + h.bary.y * n2;
        s.uv = HAS_UVS != 0u ? interpolate_uv(info, h.bary) : vec2(0.0);
        if (dot(n, n) > 0.0) {
            n = normalize(n);
            if (HAS_NORMAL_MAPS != 0u) {
                n = normal_mapped(info, h.bary, s.uv, n);
            }
            s.ns = dot(n, s.ng) < 0.0 ? -n : n;
        }
    }
    s.uv = HAS_UVS != 0u ? interpolate_uv(info, h.bary) : vec2(0.0);
    s.material = info.w;
    s.front = dot(s.ng, d) < 0.0;
    return s;
}

// Whether the segment between surface points a and b (geometric normals na, nb facing the
// segment) is unoccluded. Both ends are offset off their surfaces; the far end is then
// approached only up to a bound on the rounding of o + t d at that distance (32 ulps of the
// largest coordinate involved), so the target's own surface never counts as an occluder —
// the offset alone is too small there when b lies near a coordinate plane through the
// origin (offset_ray_origin's absolute branch) and the ray comes from far away.
//
// The *_shadow_ray functions build a shadow ray and shadow_ray_clear traces it, so an
// integrator may trace it later (pt.comp); the *_visible functions do both at once.
struct ShadowRay {
    vec3 o;
    vec3 d;
    float tmax; // < 0: a segment too short to hold an occluder, unoccluded without a trace
};

ShadowRay shadow_ray_between(vec3 a, vec3 na, vec3 b, vec3 nb) {
    vec3 o = offset_ray_origin(a, na);
    vec3 target = offset_ray_origin(b, nb);
    vec3 v = target - o;
    float len = length(v);
    vec3 m = max(abs(o), abs(target));
    float slack = max(m.x, max(m.y, m.z)) * (32.0 / 8388608.0);
    if (len <= slack) {
        return ShadowRay(o, v, -1.0);
    }
    return ShadowRay(o, v / len, len - slack);
}

bool shadow_ray_clear(ShadowRay r, inout uvec2 stats) {
    return r.tmax < 0.0 || trace_ray(r.o, r.d, 0.0, r.tmax, true, stats).prim == NO_HIT;
}

vec3 material_albedo(GpuMaterial m, vec2 uv) {
    vec3 a = m.albedo;
    if (HAS_TEXTURES != 0u && m.albedo_texture != 0u) {
        a *= sample_texture(m.albedo_texture - 1u, uv).rgb;
    }
    return a;
}

// Emitted radiance of material m at uv (front faces): the emission factor times the
// emission texture. Its luminance weight for light sampling (m.emission_luminance) is the factor's.
vec3 material_emission(GpuMaterial m, vec2 uv) {
    vec3 e = m.emission;
    if (HAS_EMISSION_TEXTURES != 0u && m.emission_texture != 0u) {
        e *= sample_texture(m.emission_texture - 1u, uv).rgb;
    }
    return e;
}

// Fraction of glass at uv: the refractivity times the red channel of the transmission
// texture (glTF transmissionTexture).
float glass_fraction(GpuMaterial m, vec2 uv) {
    if (HAS_GLASS == 0u) {
        return 0.0;
    }
    float g = m.refractivity;
    if (HAS_TEXTURES != 0u && m.transmission_texture != 0u) {
        g *= sample_texture(m.transmission_texture - 1u, uv).r;
    }
    return g;
}

// choose_lobe with a fresh random number, drawn only where the scene has a delta lobe: a
// scene of continuous materials spends no sample dimension (no scrambled Sobol' number) on it.
uint choose_lobe_drawn(GpuMaterial m, vec2 uv, inout Rng rng) {
    if (HAS_MIRROR == 0u && HAS_GLASS == 0u) {
        return LOBE_DIFFUSE;
    }
    return choose_lobe(m, glass_fraction(m, uv), rng_next(rng));
}

// Transmission tint of the glass fraction: glTF's baseColor (KHR_materials_transmission:
// specular_btdf x baseColor); the thesis' glass is untinted.
vec3 glass_tint(GpuMaterial m, vec2 uv) {
    return m.model == MATERIAL_METAL_ROUGH ? material_albedo(m, uv) : vec3(1.0);
}

// GGX alpha of the rough glass (LOBE_ROUGH_GLASS): roughness^2, the roughness times the
// green channel of the roughness texture.
float glass_alpha(GpuMaterial m, vec2 uv) {
    float roughness = m.roughness;
    if (HAS_TEXTURES != 0u && m.roughness_texture != 0u) {
        roughness *= sample_texture(m.roughness_texture - 1u, uv).g;
    }
    return max(roughness * roughness, GGX_MIN_ALPHA);
}

// The continuous (non-delta) part of material m at texture coordinate uv (bsdf.glsl):
// - MATERIAL_THESIS: the Lambertian rest 1 - reflectivity - refractivity times the albedo,
//   and, where the material is rough, its reflectivity as a GGX conductor with F = 1;
// - MATERIAL_METAL_ROUGH (glTF): metallic and roughness (times the B channel of the metallic
//   texture and the G channel of the roughness texture: glTF's metallicRoughness texture is
//   both), baseColor = the albedo; the glass fraction (transmission)
//   is a delta lobe and the rest is this model.
Continuous continuous_at(GpuMaterial m, vec2 uv) {
    vec3 albedo = material_albedo(m, uv);
    float refl = mirror_fraction(m);
    float refr = glass_fraction(m, uv);
    Continuous c;
    c.pick = max(0.0, 1.0 - refl - refr);
    c.diffuse = c.pick * albedo;
    c.spec_f0 = vec3(1.0);
    c.spec = 0.0;
    c.coat_f0 = 0.0;
    c.coat = 0.0;
    c.alpha = GGX_MIN_ALPHA;
    c.clearcoat = 0.0;
    c.cc_alpha = GGX_MIN_ALPHA;
    if (HAS_GLOSSY == 0u) {
        return c;
    }
    float roughness = m.roughness;
    float metallic = m.metallic;
    if (HAS_TEXTURES != 0u && (m.roughness_texture != 0u || m.metallic_texture != 0u)) {
        vec4 tr = m.roughness_texture != 0u ? sample_texture(m.roughness_texture - 1u, uv) : vec4(1.0);
        vec4 tm = m.metallic_texture == m.roughness_texture ? tr : (m.metallic_texture != 0u ? sample_texture(m.metallic_texture - 1u, uv) : vec4(1.0));
        roughness *= tr.g;
        metallic *= tm.b;
    }
    if (m.model == MATERIAL_METAL_ROUGH) {
        // KHR_materials_specular: the dielectric Fresnel is specular * Schlick(specular_f0)
        // (F90 = specular) and the diffuse lobe keeps 1 - its largest channel; mixed with the
        // metal's Schlick(albedo) by metallic this is one Schlick lobe of F0 = f0 / f90 and
        // weight f90 (glTF's plain model at specular = 1, specular_f0 = F0(ior)).
        float specular = m.specular;
        vec3 f0 = m.specular_f0;
        if (HAS_TEXTURES != 0u && m.specular_texture != 0u) {
            specular *= sample_texture(m.specular_texture - 1u, uv).a;
        }
        if (HAS_TEXTURES != 0u && m.specular_colour_texture != 0u) {
            f0 *= sample_texture(m.specular_colour_texture - 1u, uv).rgb;
        }
        f0 = min(f0, vec3(1.0));
        float f90 = specular + (1.0 - specular) * metallic;
        c.diffuse = c.pick * (1.0 - metallic) * albedo;
        c.coat = specular;
        c.coat_f0 = max(f0.r, max(f0.g, f0.b));
        c.spec_f0 = f90 > 0.0 ? mix(specular * f0, albedo, metallic) / f90 : vec3(1.0);
        c.spec = c.pick * f90;
        // KHR_materials_clearcoat: the coat's weight (x the red channel of its texture) and
        // roughness (x the green channel of its texture).
        if (HAS_CLEARCOAT != 0u && m.clearcoat > 0.0) {
            float cc = m.clearcoat;
            float cc_roughness = m.clearcoat_roughness;
            if (HAS_TEXTURES != 0u && m.clearcoat_texture != 0u) {
                cc *= sample_texture(m.clearcoat_texture - 1u, uv).r;
            }
            if (HAS_TEXTURES != 0u && m.clearcoat_roughness_texture != 0u) {
                cc_roughness *= sample_texture(m.clearcoat_roughness_texture - 1u, uv).g;
            }
            c.clearcoat = cc;
            c.cc_alpha = max(cc_roughness * cc_roughness, GGX_MIN_ALPHA);
        }
    } else if (m.roughness > 0.0) {
        // The thesis' reflectivity, made rough: a conductor with F = 1.
        float r = HAS_MIRROR != 0u ? m.reflectivity : 0.0;
        c.diffuse = max(0.0, 1.0 - r - refr) * albedo;
        c.spec = r;
    }
    c.alpha = max(roughness * roughness, GGX_MIN_ALPHA);
    return c;
}

#endif
