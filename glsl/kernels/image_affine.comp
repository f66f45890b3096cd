#version 460
// dst = src * scale + offset on RGBA32F storage images (image plumbing test and a template
// for image passes).
#include "bidir_abi.glsl"

layout(local_size_x = IMAGE_WG_SIZE, local_size_y = IMAGE_WG_SIZE) in;
layout(binding = IMAGE_AFFINE_BIND_SRC, rgba32f) uniform readonly image2D src;
layout(binding = IMAGE_AFFINE_BIND_DST, rgba32f) uniform writeonly image2D dst;
layout(push_constant) uniform Push { ImageAffinePush pc; };

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(p, pc.size.xy))) {
        return;
    }
    imageStore(dst, ivec2(p), imageLoad(src, ivec2(p)) * pc.scale + pc.offset);
}
