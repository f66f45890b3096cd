#version 460
// In-place exclusive prefix sum of each SCAN_WG_SIZE-element block; each block's total goes
// to block_sums[block]. The host scans block_sums recursively and adds it back (scan_add).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#define WG_SCAN_SIZE SCAN_WG_SIZE
#include "workgroup_scan.glsl"

layout(local_size_x = SCAN_WG_SIZE) in;
layout(std430, binding = SCAN_BIND_DATA) buffer Data { uint data[]; };
layout(std430, binding = SCAN_BIND_BLOCK_SUMS) writeonly buffer BlockSums { uint block_sums[]; };
layout(push_constant) uniform Push { ScanPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint v = i < pc.count ? data[i] : 0u;
    uint total;
    uint ex = workgroup_exclusive_add(v, total);
    if (i < pc.count) {
        data[i] = ex;
    }
    if (gl_LocalInvocationIndex == 0u) {
        block_sums[gl_WorkGroupID.x] = total;
    }
}
