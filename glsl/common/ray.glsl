// Ray helpers shared by every kernel that spawns rays.
#ifndef BIDIR_RAY_GLSL
#define BIDIR_RAY_GLSL

#include "color.glsl"

const float PI = 3.14159265358979323846;

// Moves a surface point off its surface along the geometric normal `n` (pointing to the side
// the new ray leaves on), by a few ulps of each coordinate that is large next to the point's
// largest, and by a fixed fraction of that largest coordinate for the others: no scene-scale
// epsilon. After Wächter & Binder, "A Fast and
// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems (2019), ch. 6.
//
// "Near the origin" is relative to the point's largest coordinate (at least 1): a triangle
// test's rounding error grows with the coordinates of the triangle and the ray, not with one
// small coordinate of the point, so a point on the plane x = 0 of a box 500 units wide needs
// an offset of the box's scale in x, not 1/65536 (found with the compressed wide BVH, whose
// looser boxes let a ray leaving that wall be tested against it: the test put the wall
// 2e-5 in front of the ray; tests/traversal.rs, shadow_rays_to_the_light). For points within
// 1 of the origin this is the chapter's method unchanged.
vec3 offset_ray_origin(vec3 p, vec3 n) {
    const float int_scale = 256.0;
    float scale = max(max(abs(p.x), abs(p.y)), max(abs(p.z), 1.0));
    float near_origin = scale * (1.0 / 32.0);
    float float_scale = scale * (1.0 / 65536.0);
    ivec3 of_i = ivec3(int_scale * n);
    vec3 p_i = intBitsToFloat(floatBitsToInt(p) + ivec3(p.x < 0.0 ? -of_i.x : of_i.x,
                                                       p.y < 0.0 ? -of_i.y : of_i.y,
                                                       p.z < 0.0 ? -of_i.z : of_i.z));
    return vec3(abs(p.x) < near_origin ? p.x + float_scale * n.x : p_i.x,
                abs(p.y) < near_origin ? p.y + float_scale * n.y : p_i.y,
                abs(p.z) < near_origin ? p.z + float_scale * n.z : p_i.z);
}

// Orthonormal basis around a unit vector (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited", listing 3).
void onb(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction about unit `n` (Malley's method): pdf_w = cos(theta) / pi.
vec3 sample_cosine_hemisphere(vec3 n, float u1, float u2) {
    float r = sqrt(u1);
    float phi = 2.0 * PI * u2;
    vec3 t, b;
    onb(n, t, b);
    return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u1)) * n);
}

// Solid-angle pdf of sample_cosine_hemisphere for a direction at cos(theta) to its normal:
// cos(theta) / pi above the surface, 0 below (pbrt-v4 section A.5.3).
float cosine_hemisphere_pdf(float cos_theta) {
    return max(cos_theta, 0.0) / PI;
}

// Invocation index -> pixel, in TILE_SIZE x TILE_SIZE tiles (row-major tiles, row-major
// within a tile), so a subgroup covers a compact block: neighbouring lanes trace neighbouring
// rays, which keeps traversal coherent. Dispatch tiled_invocations(size) invocations; `valid`
// is false for the parts of edge tiles outside the image.
uvec2 tiled_pixel(uint i, uvec2 size, out bool valid) {
    const uint T = TILE_SIZE;
    uint tiles_x = (size.x + T - 1u) / T;
    uint tile = i / (T * T);
    uint within = i % (T * T);
    uvec2 p = uvec2((tile % tiles_x) * T + within % T, (tile / tiles_x) * T + within / T);
    valid = p.x < size.x && p.y < size.y;
    return p;
}

// Invocations tiled_pixel covers for an image of `size` (whole tiles).
uint tiled_count(uvec2 size) {
    return ((size.x + TILE_SIZE - 1u) / TILE_SIZE) * ((size.y + TILE_SIZE - 1u) / TILE_SIZE) * TILE_SIZE * TILE_SIZE;
}

// Primary ray direction through image position `p` (pixels, row 0 on top) of camera `cam`.
vec3 camera_direction(GpuCamera cam, vec2 p) {
    vec2 ndc = vec2(2.0 * p.x / float(cam.size.x) - 1.0, 1.0 - 2.0 * p.y / float(cam.size.y));
    return normalize(cam.forward.xyz + ndc.x * cam.right.xyz + ndc.y * cam.up.xyz);
}

#endif
