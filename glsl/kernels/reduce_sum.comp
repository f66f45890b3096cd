#version 460
// Sum of a u32 array: grid-stride loads, subgroupAdd, one atomic per subgroup.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"

layout(local_size_x = SCAN_WG_SIZE) in;
layout(std430, binding = REDUCE_BIND_INPUT) readonly buffer Input { uint values[]; };
layout(std430, binding = REDUCE_BIND_OUTPUT) buffer Output { uint sum; };
layout(push_constant) uniform Push { ScanPush pc; };

void main() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    uint acc = 0u;
    for (uint i = gl_GlobalInvocationID.x; i < pc.count; i += stride) {
        acc += values[i];
    }
    uint s = subgroupAdd(acc);
    if (subgroupElect()) {
        atomicAdd(sum, s);
    }
}
