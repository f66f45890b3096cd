// The rough dielectric (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces"): GGX microfacets, exact dielectric Fresnel, visible-normal sampling (Heitz
// 2018). The glass fraction of a material with roughness > 0 (SPEC_HAS_ROUGH_GLASS).
// Local frame of the shading normal on wo's side (+z): wo.z > 0; wi.z > 0 is a reflection,
// wi.z < 0 a transmission. eta = n(wo's side) / n(the other side), as sample_dielectric.
// Every pdf is per unit solid angle (pdf_w) of wi given wo.
//
// Radiance and importance: the BTDF below (eq. 21) is the one for importance (light paths);
// radiance picks up eta^2 on transmission (pbrt-v4 section 9.5.2, Veach 1997 section 5.2),
// so f_radiance(wo, wi) = f_importance(wi, wo).
#ifndef BIDIR_ROUGH_DIELECTRIC_GLSL
#define BIDIR_ROUGH_DIELECTRIC_GLSL

#include "microfacet.glsl"

// Exact Fresnel reflectance for cos_i = cos(wo, h) > 0 (1 under total internal reflection).
float fresnel_dielectric_exact(float cos_i, float eta) {
    float sin2_t = eta * eta * max(0.0, 1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) {
        return 1.0;
    }
    return fresnel_dielectric(cos_i, eta, sqrt(1.0 - sin2_t));
}

// The microfacet normal of a transmission wo -> wi (Walter eq. 16, -(n_o wo + n_i wi)),
// turned to the upper hemisphere.
vec3 rough_dielectric_half_t(vec3 wo, vec3 wi, float eta) {
    vec3 h = normalize(eta * wo + wi);
    return h.z < 0.0 ? -h : h;
}

// pdf_w of rough_dielectric_sample producing wi from wo: a visible normal h, density
// G1(wo) (wo.h) D(h) / wo.z (Heitz 2018, eq. 1), then reflection with probability F(wo.h):
// times 1 / (4 wo.h) (Walter eq. 14); or transmission with probability 1 - F: times
// |wi.h| / (eta wo.h + wi.h)^2 (Walter eq. 17 with both indices divided by n(wi's side)).
float rough_dielectric_pdf_w(vec3 wo, vec3 wi, float eta, float alpha) {
    if (wo.z <= 0.0 || wi.z == 0.0) {
        return 0.0;
    }
    if (wi.z > 0.0) {
        vec3 h = normalize(wo + wi);
        float c = dot(wo, h);
        return fresnel_dielectric_exact(c, eta) * ggx_g1(wo, alpha) * ggx_d(h, alpha) / (4.0 * wo.z);
    }
    vec3 h = rough_dielectric_half_t(wo, wi, eta);
    float co = dot(wo, h), ci = dot(wi, h);
    float den = eta * co + ci;
    if (co <= 0.0 || ci >= 0.0 || den == 0.0) {
        return 0.0;
    }
    float t = 1.0 - fresnel_dielectric_exact(co, eta);
    return t * ggx_g1(wo, alpha) * co * ggx_d(h, alpha) / wo.z * (-ci) / (den * den);
}

// pdf_w of sampling wo from wi (the reverse direction of a path): the same routine from
// wi's side, whose frame is the mirror image (z negated) with the inverse eta on transmission.
float rough_dielectric_rev_pdf_w(vec3 wo, vec3 wi, float eta, float alpha) {
    if (wi.z > 0.0) {
        return rough_dielectric_pdf_w(wi, wo, eta, alpha);
    }
    return rough_dielectric_pdf_w(vec3(wi.xy, -wi.z), vec3(wo.xy, -wo.z), 1.0 / eta, alpha);
}

// f(wo, wi), without the tint. Reflection: F D G2 / (4 wo.z wi.z) (Walter eq. 20);
// transmission: |wi.h| |wo.h| (1 - F) D G2 / (wo.z |wi.z| (eta wo.h + wi.h)^2) (Walter eq. 21
// for importance), times eta^2 for radiance. G2 is the height-correlated Smith term with
// |cos| (Heitz 2014, eq. 99).
float rough_dielectric_f(vec3 wo, vec3 wi, float eta, float alpha, bool radiance) {
    if (wo.z <= 0.0 || wi.z == 0.0) {
        return 0.0;
    }
    if (wi.z > 0.0) {
        vec3 h = normalize(wo + wi);
        float fr = fresnel_dielectric_exact(dot(wo, h), eta);
        return fr * ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
    }
    vec3 h = rough_dielectric_half_t(wo, wi, eta);
    float co = dot(wo, h), ci = dot(wi, h);
    float den = eta * co + ci;
    if (co <= 0.0 || ci >= 0.0 || den == 0.0) {
        return 0.0;
    }
    float t = 1.0 - fresnel_dielectric_exact(co, eta);
    float f = t * ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) * co * (-ci) / (wo.z * (-wi.z) * den * den);
    return radiance ? f * eta * eta : f;
}

// Samples wi for wo (local frame): a visible normal, then reflection with probability
// F(wo.h) (total internal reflection included) or refraction. `weight` is f |wi.z| / pdf_w,
// G2 / G1(wo) (times eta^2 for a refraction carrying radiance): Fresnel and D cancel.
// False when the sampled direction lies on the wrong side (a masked reflection or refraction).
bool rough_dielectric_sample(vec3 wo, float eta, float alpha, bool radiance, float u_sel, float u1, float u2, out vec3 wi,
                             out float weight, out bool refracted) {
    vec3 h = ggx_sample_visible_normal(wo, alpha, u1, u2);
    float c = dot(wo, h);
    weight = 0.0;
    refracted = false;
    wi = vec3(0.0, 0.0, 1.0);
    if (c <= 0.0) {
        return false;
    }
    float sin2_t = eta * eta * max(0.0, 1.0 - c * c);
    float fr = 1.0;
    float cos_t = 0.0;
    if (sin2_t < 1.0) {
        cos_t = sqrt(1.0 - sin2_t);
        fr = fresnel_dielectric(c, eta, cos_t);
    }
    if (u_sel < fr) {
        wi = reflect(-wo, h);
        if (wi.z <= 0.0) {
            return false;
        }
    } else {
        wi = normalize(-eta * wo + (eta * c - cos_t) * h);
        if (wi.z >= 0.0) {
            return false;
        }
        refracted = true;
    }
    weight = ggx_g2(wo, wi, alpha) / ggx_g1(wo, alpha);
    if (refracted && radiance) {
        weight *= eta * eta;
    }
    return true;
}

// World-space form about the unit shading normal ns (on wo_w's side; the basis is onb's).
// Returns false where wo_w lies below ns or the sample is masked; pdf_fwd_w samples wi from
// wo, pdf_rev_w wo from wi.
bool rough_dielectric_sample_world(vec3 ns, vec3 wo_w, float eta, float alpha, bool radiance, float u_sel, float u1, float u2,
                                   out vec3 wi_w, out float weight, out float pdf_fwd_w, out float pdf_rev_w, out bool refracted) {
    vec3 t, b;
    onb(ns, t, b);
    vec3 wo = vec3(dot(wo_w, t), dot(wo_w, b), dot(wo_w, ns));
    wi_w = vec3(0.0);
    pdf_fwd_w = 0.0;
    pdf_rev_w = 0.0;
    weight = 0.0;
    refracted = false;
    if (wo.z <= 0.0) {
        return false;
    }
    vec3 wi;
    if (!rough_dielectric_sample(wo, eta, alpha, radiance, u_sel, u1, u2, wi, weight, refracted)) {
        return false;
    }
    pdf_fwd_w = rough_dielectric_pdf_w(wo, wi, eta, alpha);
    pdf_rev_w = rough_dielectric_rev_pdf_w(wo, wi, eta, alpha);
    wi_w = normalize(wi.x * t + wi.y * b + wi.z * ns);
    return pdf_fwd_w > 0.0;
}

#endif
