// Workgroup-wide exclusive prefix sum built on subgroup operations (the Vulkan twin of a CUDA
// block scan over warp shuffles). Correct for any subgroup size that divides the workgroup
// size, and for workgroups with more subgroups than a subgroup has lanes (lavapipe: 8 lanes,
// 256 invocations = 32 subgroups).
//
// Requires before inclusion: WG_SCAN_SIZE (invocations per workgroup) and the extensions
// GL_KHR_shader_subgroup_basic and GL_KHR_shader_subgroup_arithmetic.
#ifndef BIDIR_WORKGROUP_SCAN_GLSL
#define BIDIR_WORKGROUP_SCAN_GLSL

shared uint s_scan_partials[WG_SCAN_SIZE];
shared uint s_scan_total;

// Returns the sum of `v` over invocations with a lower gl_LocalInvocationIndex; `total` gets
// the sum over the whole workgroup. Every invocation of the workgroup must call it.
uint workgroup_exclusive_add(uint v, out uint total) {
    uint inclusive = subgroupInclusiveAdd(v);
    if (gl_SubgroupInvocationID == gl_SubgroupSize - 1u) {
        s_scan_partials[gl_SubgroupID] = inclusive;
    }
    memoryBarrierShared();
    barrier();
    if (gl_SubgroupID == 0u) {
        // Scan the per-subgroup totals, gl_SubgroupSize of them at a time.
        uint carry = 0u;
        for (uint base = 0u; base < gl_NumSubgroups; base += gl_SubgroupSize) {
            uint i = base + gl_SubgroupInvocationID;
            uint x = i < gl_NumSubgroups ? s_scan_partials[i] : 0u;
            uint ex = subgroupExclusiveAdd(x) + carry;
            if (i < gl_NumSubgroups) {
                s_scan_partials[i] = ex;
            }
            carry += subgroupAdd(x);
        }
        if (gl_SubgroupInvocationID == 0u) {
            s_scan_total = carry;
        }
    }
    memoryBarrierShared();
    barrier();
    total = s_scan_total;
    return inclusive - v + s_scan_partials[gl_SubgroupID];
}

#endif
