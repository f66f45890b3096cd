// The shadow-ray queue of the megakernels (pt-nee's, BDPT's camera and light passes;
// docs/integrators.md, "Shadow-ray queue"): a light sample's or a connection's shadow ray goes,
// with what it adds if clear, to the invocation's slots, and shadow_queue.comp traces them
// after the kernel and adds the clear ones to the same pixel sums (shadow_queue_splat.comp,
// after the light pass: to the splat buffer at the pixel each ray's join projects to). Slot j
// of invocation i is j x invocations + i.
// The includer has included scene.glsl (blend_seed, ShadowRay).
#ifndef BIDIR_SHADOW_QUEUE_GLSL
#define BIDIR_SHADOW_QUEUE_GLSL

// Slots per invocation (0: no queue; every shadow ray is traced where it is drawn).
layout(constant_id = SPEC_SHADOW_QUEUE) const uint SHADOW_QUEUE = 0u;
layout(std430, binding = BIND_SHADOW_QUEUE) writeonly buffer ShadowQueue { QueuedShadow shadow_queue[]; };
layout(std430, binding = BIND_SHADOW_COUNTS) writeonly buffer ShadowCounts { uint shadow_counts[]; };

// Shadow rays this invocation has queued.
uint shadow_queued = 0u;

// Queues `r` with `contrib` (and `tag`, what the queue's kernel needs besides: the film pixel
// of a light path's join to the camera, shadow_queue_splat.comp) where the queue is on, `r`
// long enough to hold an occluder and a slot is left (true), else leaves it to the caller
// (false).
bool queue_tagged_shadow(ShadowRay r, vec3 contrib, uint tag) {
    if (SHADOW_QUEUE == 0u || !(r.tmax > 0.0) || shadow_queued >= SHADOW_QUEUE) {
        return false;
    }
    // The megakernels' workgroups are PT_WG_SIZE wide (not gl_WorkGroupSize: this file may be
    // included before the kernel's local_size layout, where it still reads 1).
    uint invocations = gl_NumWorkGroups.x * PT_WG_SIZE;
    shadow_queue[shadow_queued * invocations + gl_GlobalInvocationID.x] =
        QueuedShadow(vec4(r.o, r.tmax), vec4(r.d, uintBitsToFloat(blend_seed)), vec4(contrib, uintBitsToFloat(tag)));
    shadow_queued++;
    return true;
}

// queue_tagged_shadow for a camera path's ray: shadow_queue.comp adds `contrib` to the
// invocation's own pixel sums.
bool queue_shadow(ShadowRay r, vec3 contrib) {
    return queue_tagged_shadow(r, contrib, 0u);
}

// Whether `contrib` is to be added now: false where queued (shadow_queue.comp adds it if
// clear), else whether `r` is clear, traced here.
bool shadow_clear_now(ShadowRay r, vec3 contrib, inout uvec2 stats) {
    return !queue_shadow(r, contrib) && shadow_ray_clear(r, stats);
}

// The invocation's count for shadow_queue.comp (`count` of its slots; 0 discards them).
void shadow_queue_finish(uint count) {
    if (SHADOW_QUEUE != 0u) {
        shadow_counts[gl_GlobalInvocationID.x] = count;
    }
}

#endif
