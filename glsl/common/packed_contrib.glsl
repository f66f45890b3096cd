// A shadow ray's contribution in 8 bytes: BDPT's wavefront camera pass keeps each queued shadow
// ray's contribution between its launches in this form (BIND_WF_CONTRIB as uvec2), half the
// 16 bytes of a vec4. Each channel's float is rounded to the nearest with 13 (red, green) or 14
// (blue) bits of mantissa and no sign bit: 21 + 21 + 22 bits, a relative error of at most 2^-14
// per channel, as likely up as down (tests/sampling.rs). With the light vertex cache's join both
// forms of the camera pass round their shadow rays' contributions so (camera_shadow_clear), so
// that the wavefront form's image stays the megakernels' value for value. On an H100 the 8
// bytes took the camera kernel from 47.7 to 45.8 ms per 1024 spp on the Cornell box 256², BDPT
// 2 % (12 bytes, exact: 0.3 %; docs/results.md, "Shadow-ray contributions in 8 bytes").
// A negative or non-finite channel packs as a NaN, which the reader counts as a bad
// contribution (contributions are never negative; contrib_round leaves such a channel as it is).
#ifndef BIDIR_PACKED_CONTRIB_GLSL
#define BIDIR_PACKED_CONTRIB_GLSL

// `c` as the packed form holds it: each channel's magnitude rounded to the nearest float with
// 13, 13 and 14 bits of mantissa (adding half of the dropped bits' unit; a carry moves into the
// exponent, as it should), the sign kept, an infinite or NaN channel left as it is (rounding
// could carry a NaN's mantissa away). Branch-free integer steps, which the megakernels run
// where the wavefront form packs; a negative or non-finite channel, which the packed form
// counts as bad, stays what it is here.
vec3 contrib_round(vec3 c) {
    uvec3 b = floatBitsToUint(c);
    uvec3 m = b & 0x7fffffffu;
    uvec3 r = (m + uvec3(0x200u, 0x200u, 0x100u)) & ~uvec3(0x3ffu, 0x3ffu, 0x1ffu);
    r = mix(r, m, greaterThanEqual(m, uvec3(0x7f800000u)));
    return uintBitsToFloat(r | (b & 0x80000000u));
}

// contrib_round's value in two words: the rounded magnitudes' bits without the dropped ones
// (a zero of either sign packs as +0). A negative, infinite or NaN channel (or one that
// rounds up to infinity) packs as a NaN.
uvec2 contrib_pack(vec3 c) {
    uvec3 b = floatBitsToUint(contrib_round(c));
    uvec3 m = b & 0x7fffffffu;
    uint r = m.x >> 10u;
    uint g = m.y >> 10u;
    uint bl = m.z >> 9u;
    if (any(greaterThanEqual(m, uvec3(0x7f800000u))) || any(greaterThan(b, uvec3(0x80000000u)))) {
        r = 0x1fffffu; // all exponent bits and a mantissa: NaN
    }
    return uvec2(r | (g << 21u), (g >> 11u) | (bl << 10u));
}

vec3 contrib_unpack(uvec2 w) {
    uint r = w.x & 0x1fffffu;
    uint g = (w.x >> 21u) | ((w.y & 0x3ffu) << 11u);
    uint bl = w.y >> 10u;
    return uintBitsToFloat(uvec3(r << 10u, g << 10u, bl << 9u));
}

#endif
