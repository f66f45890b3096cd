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

// A unit vector as two 12-bit octahedral coordinates (bdpt.glsl's oct_encode at lower
// precision: about 0.05 degrees, enough for a resampling target).
uint oct_encode12(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0) {
        p = (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    }
    uvec2 q = uvec2(round(clamp(p * 0.5 + 0.5, 0.0, 1.0) * 4095.0));
    return q.x | (q.y << 12u);
}

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path >= pc.light_path_total) {
        return;
    }
    uint offset = lvc_offsets[path];
    uvec2 counts = light_counts[path]; // (stored, seen)
    uint inv_reservoir = floatBitsToUint(float(counts.y) / float(counts.x));
    for (uint j = 0u; j < counts.x; j++) {
        uint slot = path * pc.light_path_len + j;
        uint e = (offset + j) * LVC_ENTRY_WORDS;
        if (LVC_ENTRY_WORDS == 1u) {
            lvc_index[e] = uvec4(slot, inv_reservoir, 0u, 0u);
        } else {
            LightVertex y = load_light_vertex(slot);
            // The light side's MIS sum at a connection, dVCM + dVC mis(reverse pdf), with the
            // reverse pdf of a diffuse lobe (light_vertex_f); exact without GGX lobes.
            float rev_pdf_w = y.pick * max(0.0, dot(y.ns, y.wi)) / PI;
            float light_sum = y.d_vcm + y.d_vc * mis(rev_pdf_w);
            uint pick8 = uint(round(clamp(y.pick, 0.0, 1.0) * 255.0));
            lvc_index[e] = uvec4(slot, inv_reservoir, oct_encode12(y.ns) | (pick8 << 24u), floatBitsToUint(light_sum));
            lvc_index[e + 1u] = uvec4(floatBitsToUint(y.pos), floatBitsToUint(luminance(y.beta_f)));
        }
    }
    if (path == pc.light_path_total - 1u) {
        lvc_total = offset + counts.x;
    }
}
