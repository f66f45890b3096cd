#version 460
// trace_alpha.comp over a quantised binary BVH (32-byte nodes,
// glsl/common/traverse_bvh2q.glsl): bind a BVH built with BvhLayout::Bvh2q.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_BVH2Q
#include "ray.glsl"
#include "scene.glsl"
#include "trace_kernel.glsl"
