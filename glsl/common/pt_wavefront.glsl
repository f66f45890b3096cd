// The body of the wavefront path tracer's path kernel (glsl/kernels/pt_wavefront.comp, and with
// PT_WF_FINISH defined pt_finish.comp; pt and pt-nee with `--wavefront`; after Laine, Karras &
// Aila 2013, "Megakernels Considered Harmful"): the megakernel's paths (glsl/common/pt_path.glsl)
// with their traversal taken out into the trace kernels (trace_kernel.glsl), which then run
// with their own loops and launch shape (on GPUs the 4-wide BVH's lockstep loops and dynamic
// fetch) instead of inside a kernel of many live values.
//
// One invocation per slot, a slot per megakernel invocation (pixel of the window and sample
// slice, the same random numbers). Each launch takes up what the trace kernels found for the
// slot's last rays: the light sample's contribution if its shadow ray was clear, then the
// scattering at the segment's hit (path_scatter), or where the path ended the start of the
// slot's next sample of the pass; and it leaves the next segment and the new light sample's
// shadow ray for them. The host runs launch, closest-hit trace, any-hit trace, launch, ...
// until a launch leaves no ray (src/render/pt_wavefront.rs). The rays are packed at the front
// of their queues (counted in BIND_WF_COUNTS, where the trace kernels read how many there are),
// so the launches that finish the longest paths trace only those. A sample's sum goes to the
// pixel (or its slice) when the sample ends; a light sample found clear is added to the radiance
// of the path that goes on in the slot (the ended sample's last one joins the next sample's),
// or to the pixel at once where none does. A NaN or Inf sample or light contribution is dropped
// and counted (so a light sample carried into a NaN sample is dropped with it, where the
// megakernel would keep it: a difference only where a sample is dropped).
//
// With PT_WF_FINISH (a pass's finishing launch, src/render/pt_wavefront.rs): each slot runs the
// rest of its samples in this launch, tracing its shadow rays and segments itself (trace_ray over
// the BVH the trace kernels traverse, as the megakernel does), each clear light contribution
// added to the pixel's sums on its own; it queues no ray.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#define PT_WAVEFRONT
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
#include "wf_ray.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(constant_id = SPEC_NEE) const uint NEE = 1u;
// The megakernel's ways of tracing a shadow ray, none of which runs here.
const uint ONE_TRACE = 0u;
const uint SHADOW_SUSPEND = 0u;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_RENDER_STATS) buffer Stats { uint render_stats[]; };
layout(std430, binding = BIND_SLICES) buffer Slices { vec4 slices_out[]; };
// The slots' paths (`WF_STATE_STRIDE` words each, below).
layout(std430, binding = BIND_PT_SUSPENDED) buffer State { uvec4 state_words[]; };
layout(std430, binding = BIND_WF_HITS) readonly buffer Hits { GpuHit wf_hits[]; };
// Per shadow ray its any-hit trace's word (SPEC_HIT_WORDS): NO_HIT where it is clear.
layout(std430, binding = BIND_WF_SHADOW_HITS) readonly buffer ShadowHits { uint wf_shadow_hits[]; };
// A light sample's contribution at its shadow ray's place, in the half of the buffer of the
// launch's parity (the next launch reads it where the ray is clear).
layout(std430, binding = BIND_WF_CONTRIB) buffer Contrib { vec4 wf_contrib[]; };
layout(std430, binding = BIND_WF_COUNTS) buffer Counts { uint wf_counts[]; };
layout(push_constant) uniform Push { PtWavefrontPush wpc; };
#define pc wpc.pt

// The light sample's shadow ray of this launch's bounce, if any (add_if_clear).
ShadowRay wf_shadow;
vec3 wf_shadow_contrib = vec3(0.0);
bool wf_shadow_pending = false;

#include "pt_path.glsl"

// A slot's path between launches, in 16-byte words at g * WF_STATE_STRIDE: the direction and the
// last non-delta bounce's pdf; the throughput and the vertex count (bit 31: the last bounce was
// a delta lobe); the estimate so far and the sample index; the random numbers' state and
// dimension, the segment's place in its queue, and the shadow ray's place with, from bit
// WF_SHADOW_COUNT_SHIFT, whether one is pending and the slot's status (PT_FRESH, PT_SUSPENDED, PT_DONE); last, only in
// scenes with a medium or alpha, the medium and the opacity seed. No origin: path_scatter finds
// its surface from the hit and the direction and makes the next origin itself. The random
// numbers' sample index is rng_init's (`rng_init_index`). A fill with zeros makes every slot
// PT_FRESH with nothing pending.
// (A queue of 32-byte rays within one binding's range, under 4 GiB, has fewer than 2^27
// places: device buffers are held to maxStorageBufferRange, src/vk/memory.rs.)
// The pending flag is BDPT's one-ray count (wf_active.glsl, `wf_queue_word`) and the status
// sits above it.
const uint PT_PLACE_MASK = (1u << WF_SHADOW_COUNT_SHIFT) - 1u;
const uint PT_STATUS_SHIFT = WF_SHADOW_COUNT_SHIFT + 1u;

uint pt_queue_word(uint shadow_place, bool pending, uint status) {
    return shadow_place | (pending ? 1u << WF_SHADOW_COUNT_SHIFT : 0u) | (status << PT_STATUS_SHIFT);
}

void main() {
    // Slot -> (slice, pixel of the camera's window), as the megakernel maps its invocations (pt_kernel.glsl, pt_invocation).
    uint g = gl_GlobalInvocationID.x;
    uint tiles = tiled_count(pc.camera.window_size);
    uint slices = max(pc.slices, 1u);
    if (g >= tiles * slices) {
        return; // past the slots
    }
    uint slice = g / tiles;
    bool valid;
    uvec2 wp = tiled_pixel(g % tiles, pc.camera.window_size, valid);
    if (!valid) {
        return;
    }
    // A slot whose samples are done, with no light sample pending, has nothing left to do.
    uint w = g * WF_STATE_STRIDE;
    uvec4 rng_queue = state_words[w + 3u];
    uint status = rng_queue.w >> PT_STATUS_SHIFT;
    bool pending = ((rng_queue.w >> WF_SHADOW_COUNT_SHIFT) & 1u) != 0u;
    if (status == PT_DONE && !pending) {
        return;
    }
    uvec2 queued = uvec2(rng_queue.z, rng_queue.w & PT_PLACE_MASK); // where the last launch queued its rays
    uvec2 halves = wf_contrib_halves(wpc.launch, uint(wf_contrib.length()));
    uint read_half = halves.x;
    uint write_half = halves.y;
    uint pixel = wp.y * pc.camera.window_size.x + wp.x;
    uvec2 px = uvec2(pc.camera.window_x, pc.camera.window_y) + wp;
    uint image_pixel = px.y * pc.camera.size.x + px.x;
    PixelSums sums = PixelSums(vec3(0.0), 0.0, 0u);

    // The last launch's light sample, if its shadow ray was clear: added to the path's radiance
    // below where a path goes on in this slot (the film then gets it with the sample's end, not
    // in a read and a write of its entry each launch), else to the film now.
    vec3 clear = vec3(0.0);
    if (pending && wf_shadow_hits[queued.y] == NO_HIT) {
        vec4 c = wf_contrib[read_half + queued.y];
        if (any(isnan(c.rgb)) || any(isinf(c.rgb))) {
            sums.bad++;
        } else {
            clear = c.rgb;
        }
    }

    // The path: scattered at what its segment found, or (ended, or none yet this pass) the
    // slot's next sample started.
    uint s = slice;
    Rng rng = Rng(0u, 0u, 0u);
    PathState path;
    bool alive = false;
    uint shadow_seed = 0u;
    if (status != PT_FRESH) {
        s = state_words[w + 2u].w;
    }
    if (status == PT_SUSPENDED) {
        uvec4 d_pdf = state_words[w];
        uvec4 beta_depth = state_words[w + 1u];
        uvec4 radiance_sample = state_words[w + 2u];
        uvec4 sigma_seed = WF_STATE_SIGMA_SEED ? state_words[w + 4u] : uvec4(0u);
        rng = Rng(rng_queue.x, rng_init_index(pc.sample_base + s), rng_queue.y);
        // The origin is path_scatter's to make (it reads only the hit and the direction).
        path = PathState(vec3(0.0), uintBitsToFloat(d_pdf.xyz), uintBitsToFloat(beta_depth.xyz), uintBitsToFloat(radiance_sample.xyz),
            (beta_depth.w >> 31) != 0u, uintBitsToFloat(d_pdf.w), beta_depth.w & 0x7fffffffu, uintBitsToFloat(sigma_seed.xyz),
            vec3(0.0), 0.0, vec3(0.0), false);
        path.radiance += clear;
        blend_seed = sigma_seed.w;
        GpuHit gh = wf_hits[queued.x];
        uvec2 stats = uvec2(0u);
        alive = path_scatter(path, TraceHit(gh.t, gh.tri, vec2(gh.u, gh.v)), rng, stats);
        shadow_seed = blend_seed; // the shadow ray is this path's, whatever starts next
        if (!alive) {
            add_sample(sums, path.radiance);
            s += slices;
        }
    } else {
        sums.sum += clear; // no path goes on here: the film gets it now
    }
#ifdef PT_WF_FINISH
    // The rest of the slot's samples: each step's shadow ray (with the opacity seed of the path
    // that drew it), then the next segment, or where the path ended the slot's next sample.
    for (;;) {
        if (wf_shadow_pending) {
            uint next_seed = blend_seed;
            blend_seed = shadow_seed;
            uvec2 stats = uvec2(0u);
            if (shadow_ray_clear(wf_shadow, stats)) {
                if (any(isnan(wf_shadow_contrib)) || any(isinf(wf_shadow_contrib))) {
                    sums.bad++;
                } else {
                    sums.sum += wf_shadow_contrib;
                }
            }
            blend_seed = next_seed;
            wf_shadow_pending = false;
        }
        if (!alive) {
            if (status == PT_DONE || s >= pc.spp) {
                break;
            }
            path = sample_start(image_pixel, s, vec2(px), rng);
        }
        uvec2 stats = uvec2(0u);
        TraceHit h = trace_ray(path.o, path.d, 0.0, 3.0e38, false, stats);
        alive = path_scatter(path, h, rng, stats);
        shadow_seed = blend_seed;
        if (!alive) {
            add_sample(sums, path.radiance);
            s += slices;
        }
    }
#else
    if (!alive && status != PT_DONE && s < pc.spp) {
        path = sample_start(image_pixel, s, vec2(px), rng);
        alive = true;
    }
#endif

    // The rays, packed at the front of the queues (a subgroup's together, in lane order).
    uvec4 ext_lanes = subgroupBallot(alive);
    uvec4 shadow_lanes = subgroupBallot(wf_shadow_pending);
    uint ext_count = subgroupBallotBitCount(ext_lanes);
    uint shadow_count = subgroupBallotBitCount(shadow_lanes);
    uvec2 base = uvec2(0u);
    if (subgroupElect()) {
        base.x = ext_count > 0u ? atomicAdd(wf_counts[2u * wpc.launch], ext_count) : 0u;
        base.y = shadow_count > 0u ? atomicAdd(wf_counts[2u * wpc.launch + 1u], shadow_count) : 0u;
    }
    base = subgroupBroadcastFirst(base);
    queued = base + uvec2(subgroupBallotExclusiveBitCount(ext_lanes), subgroupBallotExclusiveBitCount(shadow_lanes));
    if (alive) {
        state_words[w] = uvec4(floatBitsToUint(path.d), floatBitsToUint(path.prev_pdf_w));
        state_words[w + 1u] = uvec4(floatBitsToUint(path.throughput), path.depth | (path.specular ? 1u << 31 : 0u));
        state_words[w + 2u] = uvec4(floatBitsToUint(path.radiance), s);
        state_words[w + 3u] = uvec4(rng.state, rng.dim, queued.x, pt_queue_word(queued.y, wf_shadow_pending, PT_SUSPENDED));
        if (WF_STATE_SIGMA_SEED) {
            state_words[w + 4u] = uvec4(floatBitsToUint(path.sigma_near), blend_seed);
        }
        wf_queue_segment(queued.x, path.o, path.d, blend_seed);
    } else if (status != PT_DONE || pending || wf_shadow_pending) {
        // Done (its samples all ended): what the next launch still has to add, if anything.
        state_words[w + 3u].w = pt_queue_word(queued.y, wf_shadow_pending, PT_DONE);
    }
    if (wf_shadow_pending) {
        wf_queue_shadow(queued.y, wf_shadow.o, wf_shadow.d, wf_shadow.tmax, shadow_seed);
        wf_contrib[write_half + queued.y] = vec4(wf_shadow_contrib, 0.0);
    }

    if (sums.count > 0.0 || any(notEqual(sums.sum, vec3(0.0)))) {
        if (slices == 1u) {
            accum[pixel] += vec4(sums.sum, sums.count);
        } else {
            slices_out[slice * pc.camera.window_size.x * pc.camera.window_size.y + pixel] += vec4(sums.sum, sums.count);
        }
    }
    if (sums.bad > 0u) {
        atomicAdd(render_stats[STAT_NAN_SAMPLES], sums.bad);
    }
}
