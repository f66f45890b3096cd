#version 460
// Light vertex cache (Davidovic et al. 2014, "Progressive Light Transport Simulation on the
// GPU", section 5.1), step 2 of 3: after the light pass and the exclusive scan of every
// path's stored-vertex count, each light path lists its stored slots densely, so the camera
// pass can draw a vertex uniformly from all of them. The scan (not an atomic append) keeps the
// list's order, and so the image for a given seed, deterministic. Each entry carries beside
// the slot the inverse of the path's reservoir probability, seen / stored, so a connection
// reads the entry and the vertex, not the path's counts as well; where connections are
// resampled, a preview of the vertex too (lvc_entry.glsl).
#include "bidir_abi.glsl"
#include "ray.glsl"
// load_light_vertex's one use of the scene (scene.glsl, whose traversal this kernel does not need).
layout(constant_id = SPEC_HAS_NORMALS) const uint HAS_NORMALS = 0u;
#include "bdpt.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_LVC_OFFSETS) readonly buffer LvcOffsets { uint lvc_offsets[]; };
layout(std430, binding = BIND_LVC_INDEX) writeonly buffer LvcIndex { uvec4 lvc_index[]; };
layout(std430, binding = BIND_LVC_TOTAL) writeonly buffer LvcTotal { uint lvc_total; };
layout(push_constant) uniform Push { BdptPush pc; };
// 1: an invocation per slot of the store (a path's `light_path_len` slots side by side, so a
// subgroup reads its vertices in one run of memory), in a grid-stride loop over them all; 0: an
// invocation per light path, looping over its stored slots (the host's choice,
// render::default_lvc_listing_per_slot, with the measurements).
layout(constant_id = SPEC_LVC_LIST_PER_SLOT) const uint LIST_PER_SLOT = 0u;

// Slot j of light path `path` (j below its stored count) as entry `offset + j` of the listing.
void list_slot(uint path, uint j, uint offset, uvec2 counts) {
    uint slot = path * pc.light_path_len + j;
    uint inv_reservoir = floatBitsToUint(float(counts.y) / float(counts.x));
    uint e = (offset + j) * LVC_ENTRY_WORDS;
    if (LVC_ENTRY_WORDS == 1u) {
        lvc_index[e] = uvec4(slot, inv_reservoir, 0u, 0u);
    } else {
        LightVertex y = load_light_vertex(slot);
        // The light side's MIS sum at a connection, dVCM + dVC mis(reverse pdf).
        float light_sum = y.d_vcm + y.d_vc * mis(diffuse_rev_pdf_w(y));
        lvc_index[e] = uvec4(slot, inv_reservoir, lvc_preview_pack(y.ns, y.pick), floatBitsToUint(light_sum));
        lvc_index[e + 1u] = uvec4(floatBitsToUint(y.pos), floatBitsToUint(luminance(y.beta_f)));
    }
}

void main() {
    if (LIST_PER_SLOT != 0u) {
        uint len = pc.light_path_len;
        uint slots = pc.light_path_total * len;
        for (uint t = gl_GlobalInvocationID.x; t < slots; t += gl_NumWorkGroups.x * PT_WG_SIZE) {
            uint path = t / len;
            uint j = t - path * len;
            uvec2 counts = light_counts[path]; // (stored, seen)
            uint offset = lvc_offsets[path];
            if (j == 0u && path == pc.light_path_total - 1u) {
                lvc_total = offset + counts.x;
            }
            if (j < counts.x) {
                list_slot(path, j, offset, counts);
            }
        }
        return;
    }
    uint path = gl_GlobalInvocationID.x;
    if (path >= pc.light_path_total) {
        return;
    }
    uint offset = lvc_offsets[path];
    uvec2 counts = light_counts[path]; // (stored, seen)
    for (uint j = 0u; j < counts.x; j++) {
        list_slot(path, j, offset, counts);
    }
    if (path == pc.light_path_total - 1u) {
        lvc_total = offset + counts.x;
    }
}
