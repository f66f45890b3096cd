#version 460
// trace_bvh4.comp for one ray per invocation in lockstep loops (the trace kernels' default
// launch over the 4-wide BVH; `Tracer` takes trace_bvh4.comp for persistent launches and
// dynamic fetch): each ray's origin waits in shared memory for its leaf tests, and closest-hit
// rays test their leaves in one loop over triangles too (TRACE_LOCKSTEP_KERNEL in
// glsl/common/traverse.glsl).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_BVH4
#define TRACE_LOCKSTEP_KERNEL
#include "traverse.glsl"
#include "trace_kernel.glsl"
