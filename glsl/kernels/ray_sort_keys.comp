#version 460
// Ray reordering, pass 1 of a counting sort (then an exclusive scan of the bins, then
// ray_sort_scatter.comp; trace::RaySorter): each ray's key, its direction octant in the high
// bits above the Morton code of its origin's cell on a grid over the scene bounds, and its
// rank among the rays of that key (an atomic count: the order within a key is arbitrary).
#include "bidir_abi.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(std430, binding = RAY_SORT_BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = RAY_SORT_BIND_KEYS) writeonly buffer Keys { uvec2 keys[]; };
layout(std430, binding = RAY_SORT_BIND_BINS) buffer Bins { uint bins[]; };
layout(push_constant) uniform Push { RaySortPush pc; };

const uint CELLS = 1u << RAY_SORT_CELL_BITS;

// Bit b of v moved to bit 3 b.
uint spread3(uint v) {
    uint r = 0u;
    for (uint b = 0u; b < RAY_SORT_CELL_BITS; b++) {
        r |= ((v >> b) & 1u) << (3u * b);
    }
    return r;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    GpuRay r = rays[i];
    precise vec3 scaled = (r.origin.xyz - pc.bounds_lo) * pc.cells_per_unit; // as trace::sort::sort_key
    vec3 c = clamp(scaled, vec3(0.0), vec3(float(CELLS - 1u)));
    uvec3 cell = min(uvec3(c), uvec3(CELLS - 1u));
    uint octant = uint(r.dir.x < 0.0) | uint(r.dir.y < 0.0) << 1 | uint(r.dir.z < 0.0) << 2;
    uint key = octant << (3u * RAY_SORT_CELL_BITS) | spread3(cell.x) | spread3(cell.y) << 1 | spread3(cell.z) << 2;
    keys[i] = uvec2(key, atomicAdd(bins[key], 1u));
}
