#version 460
// Second half of the multi-block scan: add each block's scanned offset to its elements.
#include "bidir_abi.glsl"

layout(local_size_x = SCAN_WG_SIZE) in;
layout(std430, binding = SCAN_BIND_DATA) buffer Data { uint data[]; };
layout(std430, binding = SCAN_BIND_BLOCK_SUMS) readonly buffer BlockSums { uint block_sums[]; };
layout(push_constant) uniform Push { ScanPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.count) {
        data[i] += block_sums[gl_WorkGroupID.x];
    }
}
