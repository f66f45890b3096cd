#version 460
// Merge grid, step 3 of 3: after the exclusive scan each cell holds its first entry; every
// cached light vertex takes the next entry of its cell. Afterwards a cell holds the end of its
// entries (its start is the previous cell's end). The order inside a cell depends on the
// atomics' order, so merged sums may differ in their last bits between runs.
#include "bidir_abi.glsl"
#include "merge_grid.glsl"
#include "lvc_entry.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_LIGHT_VERTICES) readonly buffer LightVertices { LightVertex light_vertices[]; };
layout(std430, binding = BIND_LVC_INDEX) readonly buffer LvcIndex { uvec4 lvc_index[]; }; // entries of LVC_ENTRY_WORDS (lvc_entry.glsl)
layout(std430, binding = BIND_LVC_TOTAL) readonly buffer LvcTotal { uint lvc_total; };
layout(std430, binding = BIND_MERGE_CELLS) buffer MergeCells { uint merge_cells[]; };
layout(std430, binding = BIND_MERGE_ITEMS) writeonly buffer MergeItems { MergeItem merge_items[]; };
layout(push_constant) uniform Push { BdptPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= lvc_total) {
        return;
    }
    uint slot = lvc_index[i * LVC_ENTRY_WORDS].x;
    vec3 p = light_vertices[slot].pos;
    uint at = atomicAdd(merge_cells[merge_cell_hash(merge_cell(p, 2.0 * vcm_radius(pc.sample_base)))], 1u);
    merge_items[at] = MergeItem(p, slot);
}
