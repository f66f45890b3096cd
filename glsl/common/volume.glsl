// KHR_materials_volume: Beer-Lambert absorption inside closed meshes (docs/integrators.md,
// "Volumes"). Transmittance over a segment of length t in a medium of absorption coefficient
// sigma_a (per unit length, per channel) is exp(-sigma_a t) (Beer-Lambert; pbrt-v4 eq.
// 11.13 without scattering); no pdf involves it, so MIS weights are untouched.
//
// Which medium a segment is in is decided by the segment alone, from the surfaces at its two
// ends: a segment lies inside the closed mesh of material m where it leaves or reaches a
// surface of m on that surface's back side. Both ends are asked (the larger sigma wins), so
// the answer is the same whichever way a strategy traces or connects the segment: pt,
// pt-nee and every BDPT join weigh the same path by the same transmittance. Exact for closed,
// non-nested meshes where every segment inside a volume touches its boundary; a segment
// between two other surfaces inside a volume (an opaque object inside a glass block, from one
// of its points to another) is not attenuated, consistently for every strategy.
#ifndef BIDIR_VOLUME_GLSL
#define BIDIR_VOLUME_GLSL

layout(constant_id = SPEC_HAS_VOLUME) const uint HAS_VOLUME = 0u;

// sigma_a of the medium on one side of a surface of material m: inside the mesh (`back`:
// the segment lies behind the geometric normal) where m has a volume, else none.
vec3 volume_sigma(GpuMaterial m, bool back) {
    return HAS_VOLUME != 0u && back ? m.sigma_a : vec3(0.0);
}

// sigma_a of a segment whose ends see media sigma_a and sigma_b (one of them 0 unless both
// ends lie on the same volume's boundary).
vec3 segment_sigma(vec3 sigma_a, vec3 sigma_b) {
    return max(sigma_a, sigma_b);
}

// Beer-Lambert transmittance exp(-sigma t) over length t; an infinite segment (an escaped ray)
// transmits nothing where sigma > 0 and everything where sigma = 0.
vec3 volume_transmittance(vec3 sigma, float t) {
    return HAS_VOLUME != 0u ? exp(-sigma * min(t, 1.0e30)) : vec3(1.0);
}

#endif
