#version 460
// The shadow-ray queue (docs/integrators.md, "Shadow-ray queue", glsl/common/shadow_queue.glsl):
// traces the shadow rays a megakernel launch (pt.comp, bdpt_camera.comp) queued and adds the
// contributions of the clear ones to the pixel sums it wrote. Invocation i is the
// megakernel's invocation i (same workgroup size, same launch, same invocation -> slice and
// pixel mapping) and takes its queue slots in the order they were filled, so the sums are
// reproducible. The megakernel keeps only the extension ray's traversal; this kernel's is a
// plain any-hit loop with few live values.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "scene.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(constant_id = SPEC_SHADOW_QUEUE) const uint SHADOW_QUEUE = 1u;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
layout(std430, binding = BIND_SHADOW_QUEUE) readonly buffer ShadowQueue { QueuedShadow shadow_queue[]; };
layout(std430, binding = BIND_SHADOW_COUNTS) readonly buffer ShadowCounts { uint shadow_counts[]; };
layout(push_constant) uniform Push { ShadowQueuePush pc; };

void main() {
    // The megakernels' mapping: invocation -> (slice, pixel of the camera's window).
    uvec2 size = uvec2(pc.width, pc.height);
    uint tiles = tiled_count(size);
    uint slices = max(pc.slices, 1u);
    uint slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, size, valid);
    if (!valid || slice >= slices) {
        return;
    }
    uint pixel = wp.y * size.x + wp.x;
    uint invocations = gl_NumWorkGroups.x * PT_WG_SIZE; // as shadow_queue.glsl counts them
    uint count = min(shadow_counts[gl_GlobalInvocationID.x], SHADOW_QUEUE);
    uvec2 stats = uvec2(0u);
    vec3 sum = vec3(0.0);
    uint bad = 0u;
    for (uint j = 0u; j < count; j++) {
        QueuedShadow q = shadow_queue[j * invocations + gl_GlobalInvocationID.x];
        if (HAS_ALPHA != 0u) {
            blend_seed = floatBitsToUint(q.dir.w); // the path's stochastic opacity
        }
        if (trace_ray(q.origin_tmax.xyz, q.dir.xyz, 0.0, q.origin_tmax.w, true, stats).prim == NO_HIT) {
            // A NaN or Inf contribution never reaches the film (pt.comp drops such samples
            // whole; a queued one is dropped alone), it is counted and reported.
            if (any(isnan(q.contrib.rgb)) || any(isinf(q.contrib.rgb))) {
                bad++;
            } else {
                sum += q.contrib.rgb;
            }
        }
    }
    if (count > 0u) {
        if (slices == 1u) {
            accum[pixel].rgb += sum;
        } else {
            slices_out[slice * size.x * size.y + pixel].rgb += sum;
        }
    }
    if (bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], bad);
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}
