#version 460
// The shadow-ray queue after bdpt_light.comp: traces the rays of the light paths' joins to the
// camera and splats the clear ones (glsl/common/shadow_queue_kernel.glsl).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_atomic_float : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "scene.glsl"
#define SHADOW_QUEUE_SPLATS
#include "shadow_queue_kernel.glsl"
