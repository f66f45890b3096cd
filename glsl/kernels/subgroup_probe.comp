#version 460
// Records what each invocation sees of its subgroup, so tests can check the device's
// reported subgroup size against the shader's.
#extension GL_KHR_shader_subgroup_basic : require
#include "bidir_abi.glsl"

layout(local_size_x = SCAN_WG_SIZE) in;
layout(std430, binding = PROBE_BIND_OUT) writeonly buffer Out { SubgroupProbe probes[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    probes[i] = SubgroupProbe(gl_SubgroupSize, gl_SubgroupID, gl_SubgroupInvocationID, gl_NumSubgroups);
}
