#version 460
// Light vertex cache (Davidovic et al. 2014, "Progressive Light Transport Simulation on the
// GPU", section 5.1), step 2 of 3: after the light pass and the exclusive scan of every
// path's stored-vertex count, each light path lists its stored slots densely, so the camera
// pass can draw a vertex uniformly from all of them. The scan (not an atomic append) keeps the
// list's order, and so the image for a given seed, deterministic.
#include "bidir_abi.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_LIGHT_COUNTS) readonly buffer LightCounts { uvec2 light_counts[]; };
layout(std430, binding = BIND_LVC_OFFSETS) readonly buffer LvcOffsets { uint lvc_offsets[]; };
layout(std430, binding = BIND_LVC_INDEX) writeonly buffer LvcIndex { uint lvc_index[]; };
layout(std430, binding = BIND_LVC_TOTAL) writeonly buffer LvcTotal { uint lvc_total; };
layout(push_constant) uniform Push { BdptPush pc; };

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path >= pc.light_path_total) {
        return;
    }
    uint offset = lvc_offsets[path];
    uint stored = light_counts[path].x;
    for (uint j = 0u; j < stored; j++) {
        lvc_index[offset + j] = path * pc.light_path_len + j;
    }
    if (path == pc.light_path_total - 1u) {
        lvc_total = offset + stored;
    }
}
