// The merge grid of vertex merging: a hash grid over the light vertex cache, rebuilt every
// iteration (merge_grid_count.comp, the exclusive scan, merge_grid_scatter.comp) and queried
// by the camera pass (vcm_merge.glsl). A cell is a cube of side 2 r (the merge diameter), so
// the sphere of radius r about any point lies in the 2 x 2 x 2 cells nearest to it; the
// integer cell coordinates are hashed into a table of 2^MERGE_GRID_BITS entries.
#ifndef BIDIR_MERGE_GRID_GLSL
#define BIDIR_MERGE_GRID_GLSL

layout(constant_id = SPEC_VCM) const uint VCM = 0u;
layout(constant_id = SPEC_VCM_RADIUS) const float VCM_RADIUS = 0.0;
layout(constant_id = SPEC_VCM_ALPHA) const float VCM_ALPHA = 0.75;
layout(constant_id = SPEC_MERGE_GRID_BITS) const uint MERGE_GRID_BITS = 1u;

// The merge radius of the iteration starting at sample `sample_base`: r_i = r_1 i^((alpha - 1)
// / 2) with i = sample_base + 1 (progressive radius reduction, Knaus and Zwicker 2011, as in
// Georgiev et al. 2012). Every kernel of an iteration computes it from the same push constants.
float vcm_radius(uint sample_base) {
    return VCM_RADIUS * pow(float(sample_base) + 1.0, 0.5 * (VCM_ALPHA - 1.0));
}

ivec3 merge_cell(vec3 p, float cell_size) {
    // Clamped so that far-away points cannot overflow the integer conversion.
    return ivec3(clamp(floor(p / cell_size), vec3(-1.0e9), vec3(1.0e9)));
}

uint merge_cell_hash(ivec3 c) {
    uvec3 u = uvec3(c);
    uint h = (u.x * 73856093u) ^ (u.y * 19349663u) ^ (u.z * 83492791u);
    return h & ((1u << MERGE_GRID_BITS) - 1u);
}

#endif
