#version 460
// trace.comp with the traversal stack's top in registers and the rest in workgroup shared
// memory (glsl/common/traverse_short_stack.glsl) instead of local memory.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_SHORT_STACK
#include "traverse.glsl"
#include "trace_kernel.glsl"
