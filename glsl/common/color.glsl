// Small colour helpers every kernel shares (one definition, included through ray.glsl).
#ifndef BIDIR_COLOR_GLSL
#define BIDIR_COLOR_GLSL

// Largest channel (Russian roulette, "is anything left" tests).
float max3(vec3 v) {
    return max(v.x, max(v.y, v.z));
}

// Luminance of linear Rec. 709 RGB (ITU-R BT.709 weights), the same weights as
// `scene::luminance` on the host.
float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

#endif
