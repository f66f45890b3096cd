#version 460
// The shadow-ray queue after pt_queue.comp and bdpt_camera.comp: traces the shadow rays a launch
// queued and adds the clear ones to the pixel sums it wrote (glsl/common/shadow_queue_kernel.glsl).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "scene.glsl"
#include "shadow_queue_kernel.glsl"
