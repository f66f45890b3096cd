#version 460
// trace.comp over a compressed 8-wide BVH (glsl/common/traverse_cwbvh.glsl; Ylitie, Karras &
// Laine 2017): bind a BVH built with BvhLayout::Cwbvh.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_CWBVH
#include "traverse.glsl"
#include "trace_kernel.glsl"
