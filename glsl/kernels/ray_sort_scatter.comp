#version 460
// Ray reordering, pass 3 of the counting sort (trace::RaySorter): each ray to the first slot
// of its key (the scanned bins) plus its rank, and its input index beside it.
#include "bidir_abi.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(std430, binding = RAY_SORT_BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = RAY_SORT_BIND_KEYS) readonly buffer Keys { uvec2 keys[]; };
layout(std430, binding = RAY_SORT_BIND_BINS) readonly buffer Bins { uint bins[]; };
layout(std430, binding = RAY_SORT_BIND_OUT) writeonly buffer RaysOut { GpuRay rays_out[]; };
layout(std430, binding = RAY_SORT_BIND_ORDER) writeonly buffer Order { uint order[]; };
layout(push_constant) uniform Push { RaySortPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    uvec2 key_rank = keys[i];
    uint slot = bins[key_rank.x] + key_rank.y;
    rays_out[slot] = rays[i];
    order[slot] = i;
}
