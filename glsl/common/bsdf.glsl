// The thesis' material model as BSDF lobes, chosen stochastically by their fractions:
// perfect mirror (reflectivity), smooth dielectric (refractivity, IOR) and Lambertian
// diffuse (the rest, times the albedo). Measures are named: pdf_w is per unit solid angle.
// Where the scene has rough materials (HAS_GLOSSY), the non-delta part of a material is a
// `Continuous` BSDF: the Lambertian lobe plus a GGX lobe (glsl/common/microfacet.glsl) — the
// glTF metallic-roughness model, or the thesis' mirror made rough.
#ifndef BIDIR_BSDF_GLSL
#define BIDIR_BSDF_GLSL

#include "microfacet.glsl"

const uint LOBE_DIFFUSE = 0u;
const uint LOBE_MIRROR = 1u;
const uint LOBE_GLASS = 2u;
// The glass fraction of a material with roughness > 0 (rough_dielectric.glsl): sampled, never
// connected (no light sampling or BDPT connection at its vertices), with exact pdfs.
const uint LOBE_ROUGH_GLASS = 3u;

// Fraction of the perfect mirror: the thesis' reflectivity, unless the material is rough
// (its reflectivity is then a rough conductor, part of the continuous BSDF).
float mirror_fraction(GpuMaterial m) {
    if (HAS_MIRROR == 0u || (HAS_GLOSSY != 0u && m.roughness > 0.0)) {
        return 0.0;
    }
    return m.reflectivity;
}

// Picks a lobe with probability equal to its fraction, so the fraction cancels; `glass` is
// the glass fraction at the surface point (glass_fraction in scene.glsl).
uint choose_lobe(GpuMaterial m, float glass, float u) {
    float r = mirror_fraction(m);
    float g = HAS_GLASS != 0u ? glass : 0.0;
    if (u < r) {
        return LOBE_MIRROR;
    }
    if (u < r + g) {
        return HAS_ROUGH_GLASS != 0u && m.roughness > 0.0 ? LOBE_ROUGH_GLASS : LOBE_GLASS;
    }
    return LOBE_DIFFUSE;
}

// Fresnel reflectance of a smooth dielectric for unpolarised light (exact form, the average
// of the s and p reflectances). eta = n_incident / n_transmitted; cos_t from Snell's law.
float fresnel_dielectric(float cos_i, float eta, float cos_t) {
    float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Samples the smooth dielectric for incoming direction d (travelling toward the surface)
// at a surface whose normal faces the incoming side (n_f) and relative index eta =
// n_incident / n_transmitted. Reflects with probability F (total internal reflection
// included), refracts otherwise. `radiance_scale` is the factor radiance picks up on
// refraction, eta^2 (pbrt-v4 section 9.5.2; 1 on reflection). Returns the new direction.
vec3 sample_dielectric(vec3 d, vec3 n_f, float eta, float u, out float radiance_scale, out bool refracted) {
    float cos_i = min(1.0, -dot(d, n_f));
    float sin2_t = eta * eta * max(0.0, 1.0 - cos_i * cos_i);
    radiance_scale = 1.0;
    refracted = false;
    if (sin2_t >= 1.0) {
        return reflect(d, n_f); // total internal reflection
    }
    float cos_t = sqrt(1.0 - sin2_t);
    float f = fresnel_dielectric(cos_i, eta, cos_t);
    if (u < f) {
        return reflect(d, n_f);
    }
    refracted = true;
    radiance_scale = eta * eta;
    return normalize(eta * d + (eta * cos_i - cos_t) * n_f);
}

#include "rough_dielectric.glsl"

// The non-delta part of a material at a surface point (its lobes weighted by their
// fractions): f(wo, wi) = diffuse / pi (1 - coat F(coat_f0, wo.h))
//                      + spec F(spec_f0, wo.h) D G2 / (4 |wo.n| |wi.n|),
// glTF 2.0 appendix B (dielectric_brdf = fresnel_mix of the coat over the base, metal_brdf
// = the conductor Fresnel with F0 = baseColor, mixed by metallic; Schlick Fresnel is linear
// in F0, so the two specular terms are one lobe with F0 = mix(coat_f0, baseColor, metallic)).
// Reciprocal: F depends on |wo.h| = |wi.h| only. It is zero unless both directions lie above
// the shading normal (as the diffuse lobe always was: docs/integrators.md).
//
// A clear coat (KHR_materials_clearcoat, where HAS_CLEARCOAT) is a smooth-to-rough dielectric
// layer of ior 1.5 (F0 = 0.04) over all of that: its own GGX lobe of weight clearcoat and
// F(0.04, wo.h), and the layers below seen through it twice, on the way in and on the way
// out, each time weighted by its transmittance 1 - clearcoat F(0.04, cos) about the normal:
//   f = T(wo) T(wi) f_base + clearcoat F(0.04, wo.h) D G2 / (4 |wo.n| |wi.n|).
// glTF's own form (the extension's fresnel_coat) attenuates the base by T(wo) alone, which
// is not reciprocal; the product is, and adds no energy to the base's (tests/
// sampling_glossy.rs). The coat shares the shading normal (clearcoatNormalTexture is not read).
struct Continuous {
    vec3 diffuse;   // Lambertian reflectance, weighted (0 for a metal)
    float pick;     // probability that choose_lobe takes the continuous part
    vec3 spec_f0;   // Schlick F0 of the GGX lobe (1: the thesis' rough conductor, F = 1)
    float spec;     // weight of the GGX lobe (0: none)
    float coat_f0;  // F0 of the dielectric coat over the diffuse lobe
    float coat;     // the diffuse lobe is weighted by 1 - coat F(coat_f0): 1 (glTF; its
                    // specularFactor with KHR_materials_specular) or 0 (the thesis)
    float alpha;    // GGX alpha = roughness^2
    float clearcoat; // the clear coat's weight (0: none; times pick for its lobe)
    float cc_alpha;  // the clear coat's GGX alpha
};

// F0 of the clear coat: ior 1.5, as KHR_materials_clearcoat fixes it.
const float CLEARCOAT_F0 = 0.04;

bool has_clearcoat(Continuous c) {
    return HAS_CLEARCOAT != 0u && c.clearcoat > 0.0;
}

// The fraction of light the clear coat lets through at cos about the normal.
float clearcoat_transmittance(Continuous c, float cos_n) {
    return 1.0 - c.clearcoat * schlick(CLEARCOAT_F0, cos_n);
}

// Albedo estimates of the base's GGX lobe (x) and diffuse lobe (y) leaving toward cos_o
// (Schlick Fresnel at the normal), below any clear coat.
vec2 continuous_base_estimates(Continuous c, float cos_o) {
    float fs = c.spec * dot(schlick(c.spec_f0, cos_o), vec3(0.2126, 0.7152, 0.0722));
    float fd = dot(c.diffuse, vec3(0.2126, 0.7152, 0.0722)) * (1.0 - c.coat * schlick(c.coat_f0, cos_o));
    return vec2(fs, fd);
}

// Probability of sampling the base's GGX lobe rather than the diffuse one when leaving
// toward wo (local frame): their albedo estimates at cos = wo.z.
float continuous_spec_probability(Continuous c, float cos_o) {
    if (HAS_GLOSSY == 0u || c.spec <= 0.0) {
        return 0.0;
    }
    vec2 e = continuous_base_estimates(c, cos_o);
    return e.x + e.y > 0.0 ? e.x / (e.x + e.y) : 1.0;
}

// Probabilities of sampling the clear coat's lobe (x) and the base's GGX lobe (y) leaving
// toward cos_o; the diffuse lobe takes the rest. The coat's share is its albedo estimate,
// clearcoat F(0.04, cos_o), against the base's seen through the coat.
vec2 continuous_lobe_probabilities(Continuous c, float cos_o) {
    float ps = continuous_spec_probability(c, cos_o);
    if (!has_clearcoat(c)) {
        return vec2(0.0, ps);
    }
    vec2 e = continuous_base_estimates(c, cos_o);
    float e_base = (e.x + e.y) * clearcoat_transmittance(c, cos_o);
    float e_coat = c.pick * c.clearcoat * schlick(CLEARCOAT_F0, cos_o);
    float pc = e_coat + e_base > 0.0 ? e_coat / (e_coat + e_base) : 1.0;
    return vec2(pc, (1.0 - pc) * ps);
}

// Solid-angle pdf of continuous_sample leaving toward wo and producing wi (local frame),
// without the choice of the continuous part (times c.pick for the material's pdf).
float continuous_pdf_w(Continuous c, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) {
        return 0.0;
    }
    vec2 p = continuous_lobe_probabilities(c, wo.z);
    float pdf = (1.0 - p.x - p.y) * wi.z / PI;
    if (p.y > 0.0) {
        pdf += p.y * ggx_reflect_pdf_w(wo, wi, c.alpha);
    }
    if (p.x > 0.0) {
        pdf += p.x * ggx_reflect_pdf_w(wo, wi, c.cc_alpha);
    }
    return pdf;
}

// World to the local frame of unit n.
vec3 to_local(vec3 n, vec3 v) {
    vec3 t, b;
    onb(n, t, b);
    return vec3(dot(v, t), dot(v, b), dot(v, n));
}

// f(wo, wi) of the continuous part about the shading normal ns (wo toward where the path
// came from, wi the other direction; both unit, world space), and the material's pdfs of
// sampling wi from wo (pdf_fwd_w) and wo from wi (pdf_rev_w), each including c.pick.
vec3 continuous_eval(Continuous c, vec3 ns, vec3 wo_w, vec3 wi_w, out float pdf_fwd_w, out float pdf_rev_w) {
    pdf_fwd_w = 0.0;
    pdf_rev_w = 0.0;
    if (HAS_GLOSSY == 0u || (c.spec <= 0.0 && !has_clearcoat(c))) {
        float co = dot(ns, wo_w), ci = dot(ns, wi_w);
        if (co <= 0.0 || ci <= 0.0) {
            return vec3(0.0);
        }
        pdf_fwd_w = c.pick * ci / PI;
        pdf_rev_w = c.pick * co / PI;
        return c.diffuse / PI;
    }
    vec3 wo = to_local(ns, wo_w), wi = to_local(ns, wi_w);
    if (wo.z <= 0.0 || wi.z <= 0.0) {
        return vec3(0.0);
    }
    float cos_h = dot(wo, normalize(wo + wi));
    vec3 f = c.diffuse / PI * (1.0 - c.coat * schlick(c.coat_f0, cos_h));
    f += c.spec * schlick(c.spec_f0, cos_h) * ggx_brdf(wo, wi, c.alpha);
    if (has_clearcoat(c)) {
        f *= clearcoat_transmittance(c, wo.z) * clearcoat_transmittance(c, wi.z);
        f += c.pick * c.clearcoat * schlick(CLEARCOAT_F0, cos_h) * ggx_brdf(wo, wi, c.cc_alpha);
    }
    pdf_fwd_w = c.pick * continuous_pdf_w(c, wo, wi);
    pdf_rev_w = c.pick * continuous_pdf_w(c, wi, wo);
    return f;
}

// Samples wi for the continuous part leaving toward wo_w: a GGX lobe (a visible normal; the
// clear coat's or the base's) with continuous_lobe_probabilities, else the cosine-weighted
// hemisphere.
// `u_lobe` is only read where the scene has GGX lobes. False if nothing can be sampled
// (wo below the shading normal, or a reflection below it).
bool continuous_sample(Continuous c, vec3 ns, vec3 wo_w, float u_lobe, float u1, float u2, out vec3 wi_w) {
    wi_w = vec3(0.0);
    float cos_o = dot(ns, wo_w);
    if (cos_o <= 0.0) {
        return false;
    }
    vec2 p = continuous_lobe_probabilities(c, cos_o);
    float ps = p.x + p.y;
    if (ps > 0.0 && u_lobe < ps) {
        vec3 t, b;
        onb(ns, t, b);
        vec3 wo = vec3(dot(wo_w, t), dot(wo_w, b), cos_o);
        vec3 h = ggx_sample_visible_normal(wo, u_lobe < p.x ? c.cc_alpha : c.alpha, u1, u2);
        vec3 wi = reflect(-wo, h);
        if (wi.z <= 0.0) {
            return false;
        }
        wi_w = normalize(wi.x * t + wi.y * b + wi.z * ns);
        return true;
    }
    wi_w = sample_cosine_hemisphere(ns, u1, u2);
    return true;
}

#endif
