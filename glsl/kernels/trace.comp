#version 460
// Traces a buffer of rays against the geometry alone (no alpha masks): closest hit, or any
// hit when SPEC_ANY_HIT is set (shadow rays). The traversal benchmark times exactly this
// kernel (trace_alpha.comp with --alpha).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#include "traverse.glsl"
#include "trace_kernel.glsl"
