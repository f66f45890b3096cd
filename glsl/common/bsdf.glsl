// The thesis' material model as BSDF lobes, chosen stochastically by their fractions:
// perfect mirror (reflectivity), smooth dielectric (refractivity, IOR) and Lambertian
// diffuse (the rest, times the albedo). Measures are named: pdf_w is per unit solid angle.
#ifndef BIDIR_BSDF_GLSL
#define BIDIR_BSDF_GLSL

const uint LOBE_DIFFUSE = 0u;
const uint LOBE_MIRROR = 1u;
const uint LOBE_GLASS = 2u;

// Picks a lobe with probability equal to its fraction, so the fraction cancels.
uint choose_lobe(GpuMaterial m, float u) {
    float r = HAS_MIRROR != 0u ? m.params.x : 0.0;
    float g = HAS_GLASS != 0u ? m.params.y : 0.0;
    if (u < r) {
        return LOBE_MIRROR;
    }
    if (u < r + g) {
        return LOBE_GLASS;
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

#endif
