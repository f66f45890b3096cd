#version 460
// pt and pt-nee, the megakernel (glsl/common/pt_kernel.glsl) without path regeneration: the
// default on GPUs in scenes with smooth mirrors or glass (render::default_path_regeneration).
#include "pt_kernel.glsl"

void main() {
    uint slice, slices, pixel, image_pixel;
    vec2 xy;
    if (!pt_invocation(slice, slices, pixel, image_pixel, xy)) {
        return;
    }
    PixelSums sums = PixelSums(vec3(0.0), 0.0, 0u);
    Rng rng;
    // A loop of samples around a loop of bounces: fewer values live across the trace.
    for (uint s = slice; s < pc.spp; s += slices) {
        PathState path = sample_start(image_pixel, s, xy, rng);
        while (path_bounce(path, rng)) {
        }
        add_sample(sums, path.radiance);
    }
    pt_store(sums, slice, slices, pixel);
}
