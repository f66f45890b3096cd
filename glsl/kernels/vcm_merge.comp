#version 460
// VCM, merging at the first continuous camera vertex (vcm.glsl, VCM_MERGE_DEFERRED): after
// the camera pass, one invocation per camera sample merges the vertex the pass recorded
// (BIND_MERGE_QUERIES) with the light vertices around it (vcm_merge.glsl) and adds the result
// to the sample's pixel, where the camera pass left the rest of the sample (the accumulation
// with one sample per pixel and iteration, else its slice). Apart from the camera pass, that
// pass keeps BDPT's registers, and the merges of neighbouring pixels run side by side.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "scene.glsl"
#include "bsdf.glsl"
#include "bdpt.glsl"
#include "vcm.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(std430, binding = BIND_MERGE_QUERIES) readonly buffer MergeQueries { MergeQuery merge_queries[]; };
layout(push_constant) uniform Push { BdptPush pc; };
#include "vcm_merge.glsl"

void main() {
    // Entry slice x pixels + pixel, as the camera pass wrote it.
    uint samples = max(pc.camera_samples, 1u);
    uint pixels = pc.camera.window_size.x * pc.camera.window_size.y;
    uint i = gl_GlobalInvocationID.x;
    if (i >= samples * pixels) {
        return;
    }
    MergeQuery q = merge_queries[i];
    if (q.depth == 0u) {
        return;
    }
    Continuous c = continuous_at(materials[q.material], q.uv); // pick > 0: recorded only so
    float r = vcm_radius(pc.sample_base);
    VcmFactors k = vcm_factors(pc.sample_base, pc.light_path_total);
    vec3 merged = vcm_merge(q.pos, q.ns, q.ng, q.wo, c, q.d_vcm, q.d_vm, q.depth, r, k);
    vec3 add = q.beta * merged / (PI * r * r * float(pc.light_path_total));
    if (any(isnan(add)) || any(isinf(add))) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], 1u);
        return;
    }
    if (max3(add) <= 0.0) {
        return;
    }
    if (samples == 1u) {
        accum[i].xyz += add;
    } else {
        slices_out[i].xyz += add;
    }
}
