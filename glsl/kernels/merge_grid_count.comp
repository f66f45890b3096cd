#version 460
// Merge grid, step 1 of 3 (after the light vertex cache is listed): every cached light vertex
// counts itself into its hash cell. Then the exclusive scan of the counts gives each cell's
// first entry, and merge_grid_scatter.comp fills the cells.
#include "bidir_abi.glsl"
#include "merge_grid.glsl"
#include "lvc_entry.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_LIGHT_VERTICES) readonly buffer LightVertices { LightVertex light_vertices[]; };
layout(std430, binding = BIND_LVC_INDEX) readonly buffer LvcIndex { uvec4 lvc_index[]; }; // entries of LVC_ENTRY_WORDS (lvc_entry.glsl)
layout(std430, binding = BIND_LVC_TOTAL) readonly buffer LvcTotal { uint lvc_total; };
layout(std430, binding = BIND_MERGE_CELLS) buffer MergeCells { uint merge_cells[]; };
layout(push_constant) uniform Push { BdptPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= lvc_total) {
        return;
    }
    vec3 p = light_vertices[lvc_index[i * LVC_ENTRY_WORDS].x].pos;
    atomicAdd(merge_cells[merge_cell_hash(merge_cell(p, 2.0 * vcm_radius(pc.sample_base)))], 1u);
}
