#version 460
// Stable compaction of valid rays (dir.w >= 0) using exclusive-scanned flags as offsets;
// the scan's extra last element holds the count.
#include "bidir_abi.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(std430, binding = BIND_RAYS) readonly buffer Rays { GpuRay rays[]; };
layout(std430, binding = BIND_FLAGS) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = BIND_RAYS_OUT) writeonly buffer RaysOut { GpuRay rays_out[]; };
layout(push_constant) uniform Push { TracePush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) {
        return;
    }
    GpuRay r = rays[i];
    if (r.dir.w >= 0.0) {
        rays_out[offsets[i]] = r;
    }
}
