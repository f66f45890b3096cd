// Which slots a launch of BDPT's wavefront passes runs (BIND_WF_ACTIVE; src/gpu/abi.rs): the
// pass's first launch runs every slot; each later one runs the slots the launch before it
// listed, those that queued a ray, from an indirect dispatch sized by wf_dispatch.comp.
// `launch_word` is the kernel's BdptWavefrontPush::launch (the launch in its batch, and
// WF_ALL_SLOTS for the pass's first).
#ifndef BIDIR_WF_ACTIVE_GLSL
#define BIDIR_WF_ACTIVE_GLSL

layout(std430, binding = BIND_WF_ACTIVE) buffer Active {
    // Per launch of the batch: (groups, 1, 1, listed slots); entry l + 1 is filled by launch l.
    uvec4 wf_dispatch[WF_DISPATCH_ENTRIES];
    // Two halves of slot lists, by the launches' parity.
    uint wf_active[];
};

// The launch in its batch.
uint wf_launch(uint launch_word) {
    return launch_word & ~WF_ALL_SLOTS;
}

// The slot this invocation runs, if any: one of `slots` in the pass's first launch, else one of
// those the launch before listed.
bool wf_slot(uint launch_word, uint slots, out uint slot) {
    uint j = gl_GlobalInvocationID.x;
    slot = j;
    if ((launch_word & WF_ALL_SLOTS) != 0u) {
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
// slot calls it, in uniform control flow.
void wf_list_next(uint launch_word, uint slot, bool listed) {
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

#endif
