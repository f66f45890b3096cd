// Which slots a launch of BDPT's wavefront passes runs (BIND_WF_ACTIVE; src/gpu/abi.rs): the
// pass's first launch runs every slot; each later one runs the slots the launch before it
// listed, those that queued a ray, from an indirect dispatch its last workgroup sized
// (wf_end_launch), as it sized the launch's two traces from the rays it queued.
// `launch_word` is the kernel's BdptWavefrontPush::launch (the launch in its batch, and
// WF_ALL_SLOTS for the pass's first, WF_FIRST_HITS for the launch after it).
#ifndef BIDIR_WF_ACTIVE_GLSL
#define BIDIR_WF_ACTIVE_GLSL

// The includer's workgroup size (its local_size_x). Not gl_WorkGroupSize: glslang takes that
// as (1, 1, 1) in code compiled before the layout declaration, which follows the includes.
#ifndef WF_WG_SIZE
#define WF_WG_SIZE PT_WG_SIZE
#endif

// A path's vertex count in its stored state once the path has ended (the status, read back from
// the count: no path reaches it).
const uint WF_PATH_DONE = 0xffffffffu;

// Where a slot's launch queued its rays, kept in its path's state (bdpt_camera_wavefront.glsl,
// bdpt_light_wavefront.glsl): the segment's place, then the first shadow ray's with their count
// from bit WF_SHADOW_COUNT_SHIFT up.
uvec2 wf_queue_word(uvec2 places, uint shadow_count) {
    return uvec2(places.x, places.y | (shadow_count << WF_SHADOW_COUNT_SHIFT));
}

// wf_queue_word's (segment, first shadow ray, their count).
uvec3 wf_queued(uvec2 word) {
    return uvec3(word.x, word.y & ((1u << WF_SHADOW_COUNT_SHIFT) - 1u), word.y >> WF_SHADOW_COUNT_SHIFT);
}

// Per launch l of a batch: the segments (2 l) and shadow rays (2 l + 1) it queued.
layout(std430, binding = BIND_WF_COUNTS) coherent buffer Counts { uint wf_counts[]; };
// The most workgroups a trace kernel of these launches starts (`Tracer::queued_groups`: a
// persistent kernel's resident workgroups; unbounded for one invocation per ray).
layout(constant_id = SPEC_WF_TRACE_GROUPS) const uint WF_TRACE_GROUPS = 0xffffffffu;

layout(std430, binding = BIND_WF_ACTIVE) coherent buffer Active {
    // Per launch of the batch: (groups, 1, 1, listed slots); entry l + 1 is filled by launch l.
    uvec4 wf_dispatch[WF_DISPATCH_ENTRIES];
    // Per launch l of the batch: its traces' (groups, 1, 1, -), closest hit at 2 l, any hit at
    // 2 l + 1 (wf_end_launch); w of the first counts the launch's finished workgroups.
    uvec4 wf_trace_dispatch[WF_TRACE_DISPATCH_ENTRIES];
    // Two halves of slot lists, by the launches' parity.
    uint wf_active[];
};

// The launch in its batch.
uint wf_launch(uint launch_word) {
    return launch_word & ~(WF_ALL_SLOTS | WF_FIRST_HITS);
}

// The launch after the pass's first: every path it runs has only its first segment behind it,
// queued at its slot's place, and no stored state (the first launch writes none: the path
// kernels start each path again from its random numbers, which costs less than its state's
// write and read).
bool wf_first_hits(uint launch_word) {
    return (launch_word & WF_FIRST_HITS) != 0u;
}

// The slot this invocation runs, if any: one of `slots` in the pass's first launch and in the
// launch after it (the first launch queues a segment, or one without a segment, at every slot's
// place, and lists none: wf_list_next), else one of those the launch before listed.
bool wf_slot(uint launch_word, uint slots, out uint slot) {
    uint j = gl_GlobalInvocationID.x;
    slot = j;
    if ((launch_word & (WF_ALL_SLOTS | WF_FIRST_HITS)) != 0u) {
        return j < slots;
    }
    uint launch = wf_launch(launch_word);
    if (j >= wf_dispatch[launch].w) {
        return false;
    }
    uint half_len = uint(wf_active.length()) / 2u;
    slot = wf_active[(launch & 1u) * half_len + j];
    return true;
}

// Lists `slot` for the next launch where `listed` (the slot queued a ray this launch), packed
// at the front of the other half (a subgroup's slots together); every invocation that runs a
// slot calls it, in uniform control flow. The pass's first launch lists nothing: the launch
// after it runs every slot (wf_slot), so that the first launch, whose every slot queues its
// segment at its own place, takes no atomic at all (its subgroups' atomics on one counter were
// most of its time: 0.61 ms of a 16 M-slot camera launch on an H100, session 56).
void wf_list_next(uint launch_word, uint slot, bool listed) {
    if ((launch_word & WF_ALL_SLOTS) != 0u) {
        return;
    }
    uint launch = wf_launch(launch_word);
    uvec4 lanes = subgroupBallot(listed);
    uint n = subgroupBallotBitCount(lanes);
    uint base = 0u;
    if (subgroupElect() && n > 0u) {
        base = atomicAdd(wf_dispatch[launch + 1u].w, n);
    }
    base = subgroupBroadcastFirst(base);
    if (listed) {
        uint half_len = uint(wf_active.length()) / 2u;
        wf_active[((launch + 1u) & 1u) * half_len + base + subgroupBallotExclusiveBitCount(lanes)] = slot;
    }
}

// A trace kernel's dispatch for `rays` queued rays: a workgroup per TRACE_WG_SIZE of them (each
// lane's first fetch takes one), at most WF_TRACE_GROUPS.
uvec4 wf_trace_dispatch_for(uint rays) {
    return uvec4(min((rays + TRACE_WG_SIZE - 1u) / TRACE_WG_SIZE, WF_TRACE_GROUPS), 1u, 1u, 0u);
}

shared bool wf_last_group;

// Ends the launch; every invocation calls it last, in uniform control flow. The launch's last
// workgroup to finish (its finished workgroups counted in wf_trace_dispatch[2 l].w, which the
// host zeroes with the batch's entries) sizes the next launch's dispatch from the slots this
// one listed and this one's two traces from the rays it queued (where a pass's tail queues few
// rays, a persistent trace kernel would otherwise start all its workgroups for them), so that
// no kernel runs between a launch and its traces. The pattern is the atomic counter of CUDA's
// threadFenceReduction sample: each workgroup's writes are made visible before it counts
// itself, and the counts are read with atomics.
//
// In the pass's first launch (`slots` its slots) every slot queues one segment (or one without a
// segment) at its own place and no shadow ray, and none counts them: the first invocation writes
// the count and the sizes (the next launch over every slot), and no workgroup counts itself
// (a 16 M-slot launch's 262,144 atomics on one word).
void wf_end_launch(uint launch_word, uint slots) {
    uint launch = wf_launch(launch_word);
    if ((launch_word & WF_ALL_SLOTS) != 0u) {
        if (gl_GlobalInvocationID.x == 0u) {
            wf_counts[2u * launch] = slots;
            wf_dispatch[launch + 1u] = uvec4((slots + WF_WG_SIZE - 1u) / WF_WG_SIZE, 1u, 1u, slots);
            wf_trace_dispatch[2u * launch] = wf_trace_dispatch_for(slots);
            wf_trace_dispatch[2u * launch + 1u] = wf_trace_dispatch_for(0u);
        }
        return;
    }
    memoryBarrierBuffer();
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uint finished = atomicAdd(wf_trace_dispatch[2u * launch].w, 1u);
        wf_last_group = finished + 1u == gl_NumWorkGroups.x;
    }
    barrier();
    if (wf_last_group && gl_LocalInvocationIndex == 0u) {
        memoryBarrierBuffer();
        uint listed = atomicAdd(wf_dispatch[launch + 1u].w, 0u);
        wf_dispatch[launch + 1u].xyz = uvec3((listed + WF_WG_SIZE - 1u) / WF_WG_SIZE, 1u, 1u);
        wf_trace_dispatch[2u * launch] = wf_trace_dispatch_for(atomicAdd(wf_counts[2u * launch], 0u));
        wf_trace_dispatch[2u * launch + 1u] = wf_trace_dispatch_for(atomicAdd(wf_counts[2u * launch + 1u], 0u));
    }
}

#endif
