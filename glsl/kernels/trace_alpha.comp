#version 460
// Traces a buffer of rays like trace.comp, but through scene.glsl, the integrators' own
// traversal: triangles whose material's alpha texture is below its cutoff at the hit are
// skipped, in closest-hit and any-hit queries alike. Needs the scene buffers bound
// (GpuScene::binds) and its SceneFeatures specialisation constants.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "scene.glsl"
#include "trace_kernel.glsl"
