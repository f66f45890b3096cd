#version 460
// pt and pt-nee, the megakernel (glsl/common/pt_kernel.glsl) with path regeneration: the
// default on CPU devices and for GPUs in most scenes (render::default_path_regeneration).
#include "pt_kernel.glsl"

void main() {
    uint slice, slices, pixel, image_pixel;
    vec2 xy;
    if (!pt_invocation(slice, slices, pixel, image_pixel, xy)) {
        return;
    }
    PixelSums sums = PixelSums(vec3(0.0), 0.0, 0u);
    Rng rng;
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
    pt_store(sums, slice, slices, pixel);
}
