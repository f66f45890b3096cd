#version 460
// The thesis' megakernel path tracer: one invocation per pixel (and sample slice), its paths
// one after another with path regeneration (PathState, glsl/common/pt_path.glsl), summed into
// the film. With NEE (pt-nee, the thesis' "explicit sampling") every non-delta vertex also
// samples an emitter by power and traces a shadow ray; emission found by BSDF sampling is then
// weighted with the power heuristic (Veach 1997, eq. 9.13) so nothing counts twice. The
// wavefront form of the same paths is pt_wavefront.comp.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "bidir_abi.glsl"
#include "ray.glsl"
#include "rng.glsl"
#include "scene.glsl"
#include "bsdf.glsl"
#include "lights.glsl"
#include "emission.glsl"
#include "env.glsl"
#include "punctual.glsl"
#include "volume.glsl"
#include "shadow_queue.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(constant_id = SPEC_NEE) const uint NEE = 1u;
layout(constant_id = SPEC_PATH_REGENERATION) const uint PATH_REGENERATION = 1u;
layout(constant_id = SPEC_ONE_TRACE) const uint ONE_TRACE = 1u;
layout(constant_id = SPEC_SHADOW_SUSPEND) const uint SHADOW_SUSPEND = 0u;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { PtPush pc; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
layout(std430, binding = BIND_PT_SUSPENDED) buffer Suspended { PtSuspended suspended[]; };

#include "pt_path.glsl"

void main() {
    // Invocation -> (slice, pixel): slice j takes samples j, j + S, j + 2S, ... of the pass.
    // The film holds the camera's window; random numbers follow the full image's pixel.
    uint tiles = tiled_count(pc.camera.window_size);
    uint slices = max(pc.slices, 1u);
    uint slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, pc.camera.window_size, valid);
    if (!valid || slice >= slices) {
        return;
    }
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    vec2 xy = vec2(px);
    PixelSums sums = PixelSums(vec3(0.0), 0.0, 0u);
    Rng rng;
    if (SHADOW_QUEUE != 0u) {
        // The shadow-ray queue: a pass is several launches, the host running shadow_queue.comp
        // after each. Launch c renders the invocation's samples below pc.spp (the host raises
        // it launch by launch, the last one to the pass's count), regenerating as below, from
        // where the launch before stopped: at a sample not yet started (PT_NEXT), or (with
        // SHADOW_SUSPEND) before a bounce that found every queue slot taken, the path left in
        // `suspended` (PT_SUSPENDED). The pass clears `suspended` (PT_FRESH: sample `slice`
        // next) and the slices, and every launch adds its sums to them.
        uint g = gl_GlobalInvocationID.x;
        PtSuspended st = suspended[g];
        uint status = st.rng_status.w;
        uint s = status == PT_FRESH ? slice : st.sigma_sample.w;
        shadow_queue_finish(0u);
        if (status != PT_SUSPENDED && s >= pc.spp) {
            return; // done, or nothing more in this launch
        }
        PathState path;
        if (status == PT_SUSPENDED) {
            rng = Rng(st.rng_status.x, st.rng_status.y, st.rng_status.z);
            path = PathState(uintBitsToFloat(st.o_depth.xyz), st.d_pdf.xyz, st.throughput_specular.xyz, uintBitsToFloat(st.radiance_seed.xyz),
                st.throughput_specular.w != 0.0, st.d_pdf.w, st.o_depth.w, uintBitsToFloat(st.sigma_sample.xyz),
                vec3(0.0), 0.0, vec3(0.0), false);
            blend_seed = st.radiance_seed.w;
        } else {
            path = sample_start(image_pixel, s, xy, rng);
        }
        status = PT_NEXT;
        uint sample_slots = 0u; // the sample's first slot in this launch
        for (;;) {
            if (SHADOW_SUSPEND != 0u && shadow_queued >= SHADOW_QUEUE) {
                status = PT_SUSPENDED;
                break;
            }
            if (path_bounce(path, rng)) {
                continue;
            }
            if (!add_sample(sums, path.radiance)) {
                shadow_queued = sample_slots; // a dropped sample's light samples with it
            }
            sample_slots = shadow_queued;
            s += slices;
            if (s >= pc.spp) {
                break;
            }
            path = sample_start(image_pixel, s, xy, rng);
        }
        if (status == PT_SUSPENDED) {
            suspended[g] = PtSuspended(uvec4(floatBitsToUint(path.o), path.depth), vec4(path.d, path.prev_pdf_w),
                vec4(path.throughput, path.specular ? 1.0 : 0.0), uvec4(floatBitsToUint(path.radiance), blend_seed),
                uvec4(floatBitsToUint(path.sigma_near), s),
                uvec4(rng.state, rng.index, rng.dim, PT_SUSPENDED));
        } else {
            suspended[g].sigma_sample.w = s;
            suspended[g].rng_status.w = PT_NEXT;
        }
        shadow_queue_finish(shadow_queued);
        if (sums.count > 0.0) {
            if (slices == 1u) {
                accum[pixel] += vec4(sums.sum, sums.count);
            } else {
                slices_out[slice * pc.camera.window_size.x * pc.camera.window_size.y + pixel] += vec4(sums.sum, sums.count);
            }
        }
    } else if (PATH_REGENERATION != 0u) {
        // One loop of bounces: where a path ends, the invocation's next sample starts
        // (Novak, Havran & Dachsbacher 2010), so a subgroup's lanes do not wait for its
        // longest path while they have samples left.
        uint s = slice; // samples s, s + slices, ... of the pass
        if (s < pc.spp) {
            PathState path = sample_start(image_pixel, s, xy, rng);
            for (;;) {
                if (path_bounce(path, rng)) {
                    continue;
                }
                add_sample(sums, path.radiance);
                s += slices;
                if (s >= pc.spp) {
                    break;
                }
                path = sample_start(image_pixel, s, xy, rng);
            }
        }
    } else {
        // A loop of samples around a loop of bounces: fewer values live across the trace.
        for (uint s = slice; s < pc.spp; s += slices) {
            PathState path = sample_start(image_pixel, s, xy, rng);
            while (path_bounce(path, rng)) {
            }
            add_sample(sums, path.radiance);
        }
    }
    if (SHADOW_QUEUE == 0u) { // (the queue's launches added theirs above)
        if (slices == 1u) {
            accum[pixel] += vec4(sums.sum, sums.count);
        } else {
            slices_out[slice * pc.camera.window_size.x * pc.camera.window_size.y + pixel] = vec4(sums.sum, sums.count);
        }
    }
    if (sums.bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], sums.bad);
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}
