#version 460
// trace_alpha.comp over a 4-wide BVH (128-byte nodes,
// glsl/common/traverse_bvh4.glsl): bind a BVH built with BvhLayout::Bvh4.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_BVH4
#include "ray.glsl"
#include "scene.glsl"
#include "trace_kernel.glsl"
