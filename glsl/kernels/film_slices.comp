#version 460
// Adds the sample slices of a pass (one per group of invocations that rendered some of each
// pixel's samples at once) into the film, always in slice order, so the sum of floats and
// with it the image stays the same for a given seed on a given device.
#include "bidir_abi.glsl"

layout(local_size_x = PT_WG_SIZE) in;
layout(std430, binding = BIND_ACCUM) buffer Accum { vec4 accum[]; };
layout(std430, binding = BIND_SLICES) readonly buffer Slices { vec4 slices[]; };
layout(push_constant) uniform Push { SlicesPush pc; };

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= pc.pixels) {
        return;
    }
    vec4 sum = accum[pixel];
    for (uint j = 0u; j < pc.slices; j++) {
        sum += slices[j * pc.pixels + pixel];
    }
    accum[pixel] = sum;
}
