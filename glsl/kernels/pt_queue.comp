#version 460
// pt-nee, the megakernel (glsl/common/pt_kernel.glsl) with the shadow-ray queue
// (shadow_queue.glsl; render::default_shadow_queue): its paths regenerate, their light samples'
// shadow rays are left to shadow_queue.comp between launches.
#include "pt_kernel.glsl"

void main() {
    uint slice, slices, pixel, image_pixel;
    vec2 xy;
    if (!pt_invocation(slice, slices, pixel, image_pixel, xy)) {
        return;
    }
    PixelSums sums = PixelSums(vec3(0.0), 0.0, 0u);
    Rng rng;
    // The shadow-ray queue: a pass is several launches, the host running shadow_queue.comp
    // after each. Launch c renders the invocation's samples below pc.spp (the host raises
    // it launch by launch, the last one to the pass's count), regenerating as pt.comp does, from
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
    pt_store_counts(sums);
}
