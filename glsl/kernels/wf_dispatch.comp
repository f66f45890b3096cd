#version 460
// The indirect dispatch of the next launch of one of BDPT's wavefront passes
// (glsl/common/wf_active.glsl): from the slots the launch before listed, the workgroups of the
// path kernels (PT_WG_SIZE wide) that run them. It runs between a launch and its traces, and
// resets the persistent trace kernels' ray counters for them.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#include "wf_active.glsl"

layout(local_size_x = 1) in;
layout(push_constant) uniform Push { WfDispatchPush pc; };
layout(std430, binding = BIND_RAY_COUNTER) writeonly buffer ClosestCounter { uint closest_next_ray; };
layout(std430, binding = BIND_RAY_COUNTER_ANY) writeonly buffer AnyCounter { uint any_next_ray; };

void main() {
    uint n = wf_dispatch[pc.entry].w;
    wf_dispatch[pc.entry].xyz = uvec3((n + PT_WG_SIZE - 1u) / PT_WG_SIZE, 1u, 1u);
    closest_next_ray = 0u;
    any_next_ray = 0u;
}
