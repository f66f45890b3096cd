#version 460
// Ray reordering within blocks (trace::RaySorter::record_local): each workgroup takes one
// block of pc.block consecutive rays and puts them in the order of their direction's cell on
// a pc.grid x pc.grid octahedral grid, so that a subgroup traces rays that start near each
// other (secondary rays come in 8x8-tile pixel order, so a block's origins lie close together)
// and head the same way. One pass, no global atomics or scan: a histogram of the cells in
// shared memory, its exclusive scan, a scatter inside the block. The order within a cell is
// arbitrary (shared atomics). Also writes each sorted ray's input index and its cell.
#include "bidir_abi.glsl"

layout(local_size_x = RAY_SORT_LOCAL_WG) in;
layout(std430, binding = RAY_SORT_BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = RAY_SORT_BIND_KEYS) writeonly buffer Keys { uint cells_out[]; };
layout(std430, binding = RAY_SORT_BIND_OUT) writeonly buffer RaysOut { GpuRay rays_out[]; };
layout(std430, binding = RAY_SORT_BIND_ORDER) writeonly buffer Order { uint order[]; };
layout(push_constant) uniform Push { RaySortLocalPush pc; };

shared uint cell_first[RAY_SORT_LOCAL_MAX_GRID * RAY_SORT_LOCAL_MAX_GRID];
// Per ray of the block: its cell (high 16 bits) and rank within the cell (low 16 bits).
shared uint cell_rank[RAY_SORT_LOCAL_MAX_BLOCK];

// The cell of direction d on a g x g grid over the octahedral map of the sphere (the lower
// hemisphere folded over the diagonals), as trace::sort::direction_cell computes it.
uint direction_cell(vec3 d, uint g) {
    precise float s = abs(d.x) + abs(d.y) + abs(d.z);
    precise vec2 p = d.xy / s;
    if (d.z < 0.0) {
        precise vec2 folded = vec2(1.0) - abs(p.yx);
        p = vec2(p.x >= 0.0 ? folded.x : -folded.x, p.y >= 0.0 ? folded.y : -folded.y);
    }
    precise vec2 u = (p + vec2(1.0)) * (0.5 * float(g));
    uvec2 c = min(uvec2(max(u, vec2(0.0))), uvec2(g - 1u));
    return c.y * g + c.x;
}

void main() {
    uint first = gl_WorkGroupID.x * pc.block;
    uint end = min(first + pc.block, pc.count);
    uint cells = pc.grid * pc.grid;
    uint lid = gl_LocalInvocationID.x;
    for (uint c = lid; c < cells; c += RAY_SORT_LOCAL_WG) {
        cell_first[c] = 0u;
    }
    barrier();
    for (uint i = first + lid; i < end; i += RAY_SORT_LOCAL_WG) {
        uint cell = direction_cell(rays[i].dir.xyz, pc.grid);
        cell_rank[i - first] = cell << 16 | atomicAdd(cell_first[cell], 1u);
    }
    barrier();
    if (lid == 0u) {
        uint sum = 0u;
        for (uint c = 0u; c < cells; c++) {
            uint n = cell_first[c];
            cell_first[c] = sum;
            sum += n;
        }
    }
    barrier();
    for (uint i = first + lid; i < end; i += RAY_SORT_LOCAL_WG) {
        uint cr = cell_rank[i - first];
        uint slot = first + cell_first[cr >> 16] + (cr & 0xffffu);
        rays_out[slot] = rays[i];
        order[slot] = i;
        cells_out[slot] = cr >> 16;
    }
}
