// The megakernel path tracers' common part (pt, pt-nee): the thesis' megakernel, one invocation
// per pixel (and sample slice), its paths one after another, summed into the film. With NEE
// (pt-nee, the thesis' "explicit sampling") every non-delta vertex also samples an emitter by
// power and traces a shadow ray; emission found by BSDF sampling is then weighted with the
// power heuristic (Veach 1997, eq. 9.13) so nothing counts twice. The path itself is
// pt_path.glsl's. Three kernels include this, one per way of running an invocation's samples,
// each a module of its own so that a pipeline compiles only the loop it runs (lavapipe
// translates every branch of a module, a specialisation constant's dead ones included):
// pt.comp (path regeneration), pt_loop.comp (a loop of samples around a loop of bounces) and
// pt_queue.comp (pt-nee's shadow-ray queue). The wavefront form of the same paths is
// pt_wavefront.comp.
#ifndef BIDIR_PT_KERNEL_GLSL
#define BIDIR_PT_KERNEL_GLSL
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
layout(constant_id = SPEC_ONE_TRACE) const uint ONE_TRACE = 1u;
layout(constant_id = SPEC_SHADOW_SUSPEND) const uint SHADOW_SUSPEND = 0u;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(push_constant) uniform Push { PtPush pc; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
layout(std430, binding = BIND_PT_SUSPENDED) buffer Suspended { PtSuspended suspended[]; };

#include "pt_path.glsl"

// The invocation's place: sample slice `slice` of `slices` (slice j takes samples j, j + S,
// j + 2S, ... of the pass), film pixel `pixel` of the camera's window, image pixel
// `image_pixel` (the random numbers follow the full image's pixel) at position `xy`. False,
// and nothing else set, for an invocation past the image's tiles or the pass's slices.
bool pt_invocation(out uint slice, out uint slices, out uint pixel, out uint image_pixel, out vec2 xy) {
    uint tiles = tiled_count(pc.camera.window_size);
    slices = max(pc.slices, 1u);
    slice = gl_GlobalInvocationID.x / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(gl_GlobalInvocationID.x % tiles, pc.camera.window_size, valid);
    if (!valid || slice >= slices) {
        return false;
    }
    pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    image_pixel = px.y * pc.camera.size.x + px.x;
    xy = vec2(px);
    return true;
}

// The samples the invocation dropped as NaN or Inf, and its traversal counts.
void pt_store_counts(PixelSums sums) {
    if (sums.bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], sums.bad);
    }
    ADD_TRAVERSAL_COUNTS(render_stats);
}

// The invocation's samples of the pass into the film (added to its pixel with one slice,
// written to its slice's row with several: Film adds the rows), then pt_store_counts.
void pt_store(PixelSums sums, uint slice, uint slices, uint pixel) {
    if (slices == 1u) {
        accum[pixel] += vec4(sums.sum, sums.count);
    } else {
        slices_out[slice * pc.camera.window_size.x * pc.camera.window_size.y + pixel] = vec4(sums.sum, sums.count);
    }
    pt_store_counts(sums);
}

#endif
