// The body of the shadow-ray queue's kernels (docs/integrators.md, "Shadow-ray queue";
// glsl/common/shadow_queue.glsl fills the queue): traces the shadow rays a megakernel launch
// queued. Invocation i takes megakernel invocation i's slots in the order they were filled.
// - shadow_queue.comp (after pt_queue.comp and bdpt_camera.comp): the megakernel's invocation ->
//   (slice, pixel) mapping; each invocation adds its clear rays' contributions to its pixel's
//   sums in slot order, so the sums are reproducible.
// - shadow_queue_splat.comp (after bdpt_light.comp; defines SHADOW_QUEUE_SPLATS first): one
//   light path per invocation, `pc.width` of them; each clear ray's contribution is added
//   atomically to the splat buffer at the pixel its join to the camera projects to (the slot's
//   tag), as the light pass adds it when it traces the ray itself.
// The megakernels keep only their extension rays' traversal; these kernels' is a plain any-hit
// loop with few live values, their rays shared out over the subgroup.
// The includer has enabled the subgroup extensions (basic, vote, ballot, arithmetic) and
// included bidir_abi.glsl, ray.glsl and scene.glsl.
#ifndef BIDIR_SHADOW_QUEUE_KERNEL_GLSL
#define BIDIR_SHADOW_QUEUE_KERNEL_GLSL

layout(local_size_x = PT_WG_SIZE) in;
layout(constant_id = SPEC_SHADOW_QUEUE) const uint SHADOW_QUEUE = 1u;
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
#ifdef SHADOW_QUEUE_SPLATS
layout(std430, binding = BIND_SPLAT) buffer Splat { float splat[]; };
#else
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
#endif
layout(std430, binding = BIND_SHADOW_QUEUE) readonly buffer ShadowQueue { QueuedShadow shadow_queue[]; };
layout(std430, binding = BIND_SHADOW_COUNTS) readonly buffer ShadowCounts { uint shadow_counts[]; };
layout(push_constant) uniform Push { ShadowQueuePush pc; };

// A subgroup's lanes trace the rays of all of them together, a round of gl_SubgroupSize rays
// at a time (the k-th ray of the subgroup, counting the lanes' queues one after another, goes
// to lane k mod gl_SubgroupSize), so lanes whose paths queued few rays do not idle behind
// those that queued many. Per subgroup: which invocation and slot each lane traces this round,
// and (for the pixel sums) what it found.
shared uint round_owner[PT_WG_SIZE];
shared uint round_slot[PT_WG_SIZE];
#ifndef SHADOW_QUEUE_SPLATS
shared vec3 round_result[PT_WG_SIZE];
#endif

void main() {
#ifdef SHADOW_QUEUE_SPLATS
    bool valid = gl_GlobalInvocationID.x < pc.width; // one light path per invocation
#else
    // The megakernels' mapping: invocation -> (slice, pixel of the camera's window). Every
    // lane takes part in its subgroup's rounds; one without a pixel brings no rays.
    uvec2 size = uvec2(pc.width, pc.height);
    uint tiles = tiled_count(size);
    uint slices = max(pc.slices, 1u);
    uint slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, size, valid);
    valid = valid && slice < slices;
    vec3 sum = vec3(0.0);
#endif
    uint invocations = gl_NumWorkGroups.x * PT_WG_SIZE; // as shadow_queue.glsl counts them
    uint count = valid ? min(shadow_counts[gl_GlobalInvocationID.x], SHADOW_QUEUE) : 0u;
    uint first = subgroupExclusiveAdd(count); // this lane's first ray among the subgroup's
    uint total = subgroupAdd(count);
    uint base = gl_SubgroupID * gl_SubgroupSize; // the subgroup's part of the shared arrays
    uint lane = gl_SubgroupInvocationID;
    uvec2 stats = uvec2(0u);
    uint bad = 0u;
    for (uint k0 = 0u; k0 < total; k0 += gl_SubgroupSize) {
        // This lane's rays in the round [k0, k0 + gl_SubgroupSize), published for the lanes
        // that trace them.
        uint lo = max(first, k0);
        uint hi = min(first + count, k0 + gl_SubgroupSize);
        for (uint k = lo; k < hi; k++) {
            round_owner[base + k - k0] = gl_GlobalInvocationID.x;
            round_slot[base + k - k0] = k - first;
        }
        subgroupMemoryBarrierShared();
        subgroupBarrier();
        vec3 found = vec3(0.0);
        if (k0 + lane < total) {
            QueuedShadow q = shadow_queue[round_slot[base + lane] * invocations + round_owner[base + lane]];
            if (HAS_ALPHA != 0u) {
                blend_seed = floatBitsToUint(q.dir.w); // the path's stochastic opacity
            }
            if (trace_ray(q.origin_tmax.xyz, q.dir.xyz, 0.0, q.origin_tmax.w, true, stats).prim == NO_HIT) {
                // A NaN or Inf contribution never reaches the film (the megakernels drop such
                // samples whole; a queued one is dropped alone), it is counted and reported.
                if (any(isnan(q.contrib.rgb)) || any(isinf(q.contrib.rgb))) {
                    bad++;
                } else {
#ifdef SHADOW_QUEUE_SPLATS
                    uint pixel = floatBitsToUint(q.contrib.w);
                    atomicAdd(splat[3u * pixel + 0u], q.contrib.r);
                    atomicAdd(splat[3u * pixel + 1u], q.contrib.g);
                    atomicAdd(splat[3u * pixel + 2u], q.contrib.b);
#else
                    found = q.contrib.rgb;
#endif
                }
            }
        }
#ifndef SHADOW_QUEUE_SPLATS
        round_result[base + lane] = found;
        subgroupMemoryBarrierShared();
        subgroupBarrier();
        // The owner adds its rays' findings in slot order (a blocked one adds 0): the sum of
        // one lane tracing its slots one after another.
        for (uint k = lo; k < hi; k++) {
            sum += round_result[base + k - k0];
        }
#endif
        subgroupBarrier();
    }
#ifndef SHADOW_QUEUE_SPLATS
    if (valid && count > 0u) {
        uint pixel = wp.y * size.x + wp.x;
        if (slices == 1u) {
            accum[pixel].rgb += sum;
        } else {
            slices_out[slice * size.x * size.y + pixel].rgb += sum;
        }
    }
#endif
    if (bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], bad);
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}

#endif
