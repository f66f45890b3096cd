#version 460
// Camera rays through pixel centres (row 0 on top), one per pixel, in 8x8-tile order
// (see tiled_pixel); rays of edge-tile pixels outside the image get tmax = -1.
#include "bidir_abi.glsl"
#include "ray.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(std430, binding = BIND_RAYS_OUT) writeonly buffer Rays { GpuRay rays[]; };
layout(push_constant) uniform Push { GpuCamera cam; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    bool valid;
    uvec2 px = tiled_pixel(i, cam.size.xy, valid);
    vec2 p = vec2(px) + 0.5;
    rays[i] = GpuRay(vec4(cam.eye.xyz, 0.0), vec4(camera_direction(cam, p), valid ? 3.0e38 : -1.0));
}
