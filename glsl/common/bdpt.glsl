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

layout(std430, binding = BIND_LIGHT_VERTICES) buffer LightVertices { LightVertex light_vertices[]; };
// Per light path: (vertices stored, vertices seen). The store is a reservoir.
layout(std430, binding = BIND_LIGHT_COUNTS) buffer LightCounts { uvec2 light_counts[]; };

// Power heuristic, beta = 2.
float mis(float x) {
    return x * x;
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
