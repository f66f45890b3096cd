#version 460
// trace_bvh4.comp with the subgroup's rays traversing as one packet, one ray per invocation
// (`TraceOptions::packet`, `bench traversal --bvh bvh4 --packet`; TRACE_PACKET,
// glsl/common/traverse_bvh4_packet.glsl). Not a default: 2.4 % slower than the lockstep kernel
// on camera rays on an H100, more on others (session 62, docs/traversal.md).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#define TRAVERSE_BVH4
#define TRACE_PACKET
#include "traverse.glsl"
#include "trace_kernel.glsl"
