// Vertex connection and merging's MIS: Georgiev, Krivanek, Davidovic and Slusallek 2012,
// "Light Transport Simulation with Vertex Connection and Merging" (SIGGRAPH Asia), in the
// recursive form of Georgiev's technical report "Implementing Vertex Connection and Merging"
// (2012). BDPT carries dVCM and dVC (bdpt.glsl); VCM adds dVM and the merging weight
// eta_VCM = pi r^2 N (N light paths merged per camera sample: the ratio of a merging pdf to
// a connection pdf). Everything here compiles to BDPT's
// arithmetic when VCM (a specialisation constant) is 0: both factors are then constant 0 and
// dVM is never read.
#ifndef BIDIR_VCM_GLSL
#define BIDIR_VCM_GLSL

#include "merge_grid.glsl"

// Merging / connecting are in use (BDPT connects and never merges).
#define VCM_MERGES ((VCM & VCM_MERGE) != 0u)
#define VCM_CONNECTS (VCM == 0u || (VCM & VCM_CONNECT) != 0u)
// Merging alone (progressive photon mapping). Spelled out rather than !VCM_CONNECTS: shaderc's
// optimiser loses a LogicalNot of a specialisation-constant expression.
#define VCM_PHOTON_MAPPING (VCM != 0u && (VCM & VCM_CONNECT) == 0u)
// Where merging is a strategy. VCM_MERGE_ALL: at every continuous camera vertex (Georgiev
// 2012). Without it (the default) only at a camera path's first vertex that scatters through
// a continuous lobe, reached from the eye by delta (or rough-glass) scatterings only, as
// photon mapping's visible point: a path has one merging strategy instead of one per vertex.
// Both sides know which vertex that is: on a camera subpath the vertex where the first
// continuous lobe is taken (merging is evaluated at each vertex with a continuous component
// until then, `merge_pending`); on a light subpath only the vertex joined to the eye (t = 1)
// can be it, so light subpaths carry no merging terms in dVC and dVM
// (vcm_light_merge_terms() = 0) and a light vertex joined to a camera vertex never is it.
// Photon mapping (no connections) follows the same rule without weights.
#define VCM_MERGE_EVERYWHERE ((VCM & VCM_MERGE_ALL) != 0u)
// Merging runs apart from the camera pass (vcm_merge.comp, over the vertex the camera pass
// records): set by the host for full VCM at the first continuous vertex in scenes where no
// material mixes a continuous lobe with a delta one, so that a camera sample merges at most
// once (SceneFeatures::mixed_lobes; elsewhere a path may merge at each mixed vertex it
// leaves by a delta lobe, and merging stays in the camera pass).
#define VCM_MERGE_DEFERRED ((VCM & VCM_MERGE_APART) != 0u)
// 1 where light tracing (t = 1) is a strategy of the paths of two segments, light -> surface
// -> eye, else 0 (bdpt.glsl, DIRECT_LIGHT_TRACING). Where it is not, every weight of such a
// path counts light tracing's samples as 0: the camera pass's light samples at its first
// vertex (whose dVCM is light tracing's term alone), its emitter hits at its second (the part
// of dVC that is not merging's, `d_vc_merge`), its merges at its first vertex with a light
// vertex one segment from the light (vcm_merge.glsl), and the light pass's joins of first
// vertices, which it skips.
float direct_light_tracing() {
    return DIRECT_LIGHT_TRACING != 0u ? 1.0 : 0.0;
}

// The camera's dVC in the weight of an emitter its path finds at vertex `depth` (s = 0): at
// the second vertex dVC is light tracing's term and merging's, `d_vc_merge` merging's alone.
float emitter_hit_d_vc(uint depth, float d_vc, float d_vc_merge) {
    return depth == 2u && direct_light_tracing() == 0.0 ? d_vc_merge : d_vc;
}

// 1 where the light subpaths' recursion counts merging at their vertices, else 0.
float vcm_light_merge_terms() {
    return VCM_MERGE_EVERYWHERE ? 1.0 : 0.0;
}

// The report's "misVmWeightFactor" (mis(eta_VCM), 0 without merging) and
// "misVcWeightFactor" (mis(1 / eta_VCM), 0 without connections).
struct VcmFactors {
    float vm;
    float vc;
};

float vcm_eta(uint sample_base, uint light_path_total) {
    float r = vcm_radius(sample_base);
    return PI * r * r * float(light_path_total);
}

VcmFactors vcm_factors(uint sample_base, uint light_path_total) {
    VcmFactors k = VcmFactors(0.0, 0.0);
    if (VCM_MERGES) {
        float eta = vcm_eta(sample_base, light_path_total);
        k.vm = mis(eta);
        k.vc = VCM_CONNECTS ? mis(1.0 / eta) : 0.0;
    }
    return k;
}

// The scattering at a subpath vertex whose drawn lobe is not the continuous one: a smooth
// mirror or glass (delta lobes) or rough glass. Such a vertex is never connected or merged
// at, so dVCM (its edge to the next vertex) becomes 0 and dVC and dVM keep only their own
// term, the pdf ratio |cos| pdf_rev / pdf_fwd (Georgiev 2012, "Implementing Vertex Connection
// and Merging", the recursive update with the connection terms dropped).
// `radiance`: a camera subpath carries radiance (refraction scales it by eta^2, Veach 1997,
// section 5.2), a light subpath importance (no scaling). Updates d, beta and the three
// quantities; false where the path ends (rough glass masked, or the geometric normal
// disagreeing with the shading normal's side).
bool scatter_unconnected_lobe(uint lobe, GpuMaterial m, Surface s, vec3 ns_f, vec3 ng_f, bool radiance, inout Rng rng,
                              inout vec3 d, inout vec3 beta, inout float d_vcm, inout float d_vc, inout float d_vm) {
    float eta = s.front ? 1.0 / m.ior : m.ior;
    vec3 dn;
    float pdf_rev_w = 1.0, pdf_fwd_w = 1.0; // a delta lobe's pdfs cancel
    if (HAS_ROUGH_GLASS != 0u && lobe == LOBE_ROUGH_GLASS) {
        float u_sel = rng_next(rng);
        float u1 = rng_next(rng);
        float u2 = rng_next(rng);
        float weight;
        bool refracted;
        if (!rough_dielectric_sample_world(ns_f, -d, eta, glass_alpha(m, s.uv), radiance, u_sel, u1, u2, dn, weight, pdf_fwd_w, pdf_rev_w, refracted)
            || (dot(dn, ng_f) > 0.0) == refracted) {
            return false;
        }
        beta *= refracted ? weight * glass_tint(m, s.uv) : vec3(weight);
    } else if (lobe == LOBE_MIRROR) {
        dn = reflect(d, ns_f);
    } else {
        float scale;
        bool refracted;
        dn = sample_dielectric(d, ns_f, eta, rng_next(rng), scale, refracted);
        float k = radiance ? scale : 1.0;
        beta *= refracted ? k * glass_tint(m, s.uv) : vec3(k);
    }
    d_vcm = 0.0;
    d_vc *= mis(abs(dot(dn, ns_f)) * pdf_rev_w / pdf_fwd_w);
    d_vm *= mis(abs(dot(dn, ns_f)) * pdf_rev_w / pdf_fwd_w); // VCM: as dVC (a vertex that is never merged)
    d = dn;
    return true;
}

#endif
