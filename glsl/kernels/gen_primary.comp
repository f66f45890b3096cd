#version 460
// Camera rays through pixel centres (row 0 on top), one per pixel, row-major.
#include "bidir_abi.glsl"
#include "ray.glsl"

layout(local_size_x = TRACE_WG_SIZE) in;
layout(std430, binding = BIND_RAYS_OUT) writeonly buffer Rays { GpuRay rays[]; };
layout(push_constant) uniform Push { GpuCamera cam; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    uint w = cam.size.x;
    if (i >= w * cam.size.y) {
        return;
    }
    vec2 p = vec2(float(i % w) + 0.5, float(i / w) + 0.5);
    rays[i] = GpuRay(vec4(cam.eye.xyz, 0.0), vec4(camera_direction(cam, p), 3.0e38));
}
