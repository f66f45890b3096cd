#version 460
// trace_bvh4.comp with the leaf phase's triangle tests shared among the subgroup's lanes, in
// dynamic fetch and in the lockstep loops of one ray per invocation (`TraceOptions::
// share_leaves`, `bench traversal --bvh bvh4 --share-leaves`; TRACE_SHARE_LEAVES in
// glsl/common/traverse.glsl). Not a default: measured on lavapipe only so far (session 30;
// docs/traversal.md).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_shuffle : require
#include "bidir_abi.glsl"
#define TRAVERSE_BVH4
#define TRACE_SHARE_LEAVES
#include "traverse.glsl"
#include "trace_kernel.glsl"
