// GGX (Trowbridge–Reitz) microfacet reflection: the specular lobe of the glTF
// metallic-roughness model and the thesis' rough conductor. Directions are in the local
// frame of the shading normal (+z); alpha = roughness^2 (glTF 2.0, appendix B).
// Measures: every pdf here is per unit solid angle (pdf_w).
#ifndef BIDIR_MICROFACET_GLSL
#define BIDIR_MICROFACET_GLSL

// Smallest alpha used: below it D overflows float precision for near-mirror lobes.
const float GGX_MIN_ALPHA = 1.0e-3;

// Normal distribution D(h) (Walter et al. 2007, eq. 33) for a unit half vector h. Written
// with sin^2 from h.xy so that small alpha keeps its precision:
// D = alpha^2 / (pi (cos^2 alpha^2 + sin^2)^2).
float ggx_d(vec3 h, float alpha) {
    if (h.z <= 0.0) {
        return 0.0;
    }
    float a2 = alpha * alpha;
    float den = h.z * h.z * a2 + (h.x * h.x + h.y * h.y);
    return a2 / (PI * den * den);
}

// Smith's Lambda for GGX (Heitz 2014, "Understanding the Masking-Shadowing Function",
// eq. 72): (sqrt(1 + alpha^2 tan^2) - 1) / 2.
float ggx_lambda(vec3 w, float alpha) {
    float c2 = w.z * w.z;
    float s2 = max(0.0, w.x * w.x + w.y * w.y);
    return 0.5 * (sqrt(c2 + alpha * alpha * s2) / abs(w.z) - 1.0);
}

// Masking G1 and height-correlated masking-shadowing G2 (Heitz 2014, eq. 43 and eq. 99).
float ggx_g1(vec3 w, float alpha) {
    return 1.0 / (1.0 + ggx_lambda(w, alpha));
}

float ggx_g2(vec3 wo, vec3 wi, float alpha) {
    return 1.0 / (1.0 + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// Schlick's Fresnel approximation, F0 + (1 - F0) (1 - cos)^5.
vec3 schlick(vec3 f0, float cos_h) {
    float m = clamp(1.0 - cos_h, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

float schlick(float f0, float cos_h) {
    return schlick(vec3(f0), cos_h).x;
}

// A visible normal for view direction wo (wo.z > 0), Heitz 2018, "Sampling the GGX
// Distribution of Visible Normals", section 3: stretch wo to the hemisphere configuration,
// sample the projected disk (warped toward the visible half), unstretch. Its density is
// D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (eq. 1 there).
vec3 ggx_sample_visible_normal(vec3 wo, float alpha, float u1, float u2) {
    vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float len2 = v.x * v.x + v.y * v.y;
    vec3 t1 = len2 > 0.0 ? vec3(-v.y, v.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u1);
    float phi = 2.0 * PI * u2;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + v.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 n = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
    return normalize(vec3(alpha * n.x, alpha * n.y, max(0.0, n.z)));
}

// Solid-angle pdf of reflecting wo into wi by a visible normal: D_wo(h) / (4 wo.h)
// = G1(wo) D(h) / (4 wo.z) (Heitz 2018, eq. 17). Zero unless both lie above the surface.
float ggx_reflect_pdf_w(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) {
        return 0.0;
    }
    vec3 h = normalize(wo + wi);
    return ggx_g1(wo, alpha) * ggx_d(h, alpha) / (4.0 * wo.z);
}

// The microfacet BRDF without Fresnel, D G2 / (4 wo.z wi.z) (Walter et al. 2007, eq. 20),
// symmetric in wo and wi.
float ggx_brdf(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) {
        return 0.0;
    }
    vec3 h = normalize(wo + wi);
    return ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) / (4.0 * wo.z * wi.z);
}

#endif
