#version 460
// trace.comp with workgroups of 128 invocations instead of TRACE_WG_SIZE (bench traversal
// --workgroup-size 128; one invocation per ray, not persistent).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRACE_KERNEL_WG_SIZE 128
#include "traverse.glsl"
#include "trace_kernel.glsl"
