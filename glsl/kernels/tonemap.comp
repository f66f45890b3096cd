#version 460
// The progressive film as display bytes: per pixel the film's estimate exactly as
// Film::resolve computes it (rgb sum / max(count, 1), plus splats / iterations for BDPT),
// times 2^exposure, non-finite values as 0, clamped to [0, 1], sRGB-encoded (the same
// mapping as the PNG writer), into an RGBA8 storage image in RGBA or BGRA byte order.
#include "bidir_abi.glsl"

layout(local_size_x = IMAGE_WG_SIZE, local_size_y = IMAGE_WG_SIZE) in;
layout(std430, binding = TONEMAP_BIND_ACCUM) readonly buffer Accum { vec4 accum[]; };
layout(std430, binding = TONEMAP_BIND_SPLAT) readonly buffer Splat { float splat[]; };
layout(binding = TONEMAP_BIND_OUT, rgba8) uniform writeonly image2D display;
layout(push_constant) uniform Push { TonemapPush pc; };

// IEC 61966-2-1, as film::linear_to_srgb.
float linear_to_srgb(float x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

float display_value(float v) {
    v = (isnan(v) || isinf(v)) ? 0.0 : v * pc.scale;
    return linear_to_srgb(clamp(v, 0.0, 1.0));
}

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.width || p.y >= pc.height) {
        return;
    }
    uint i = p.y * pc.width + p.x;
    vec4 a = accum[i];
    float n = max(a.w, 1.0);
    vec3 c = vec3(a.x / n, a.y / n, a.z / n);
    if (pc.has_splat != 0u) {
        c += vec3(splat[3u * i], splat[3u * i + 1u], splat[3u * i + 2u]) * pc.inv_iterations;
    }
    vec3 s = vec3(display_value(c.r), display_value(c.g), display_value(c.b));
    imageStore(display, ivec2(p), vec4(pc.bgra != 0u ? s.bgr : s, 1.0));
}
