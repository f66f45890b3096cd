// Lanes of a subgroup ballot (the uvec4 of subgroupBallot, lane l at bit l % 32 of word l / 32);
// no subgroup operations here, so tests can run them on any ballot (glsl/tests/sampling.comp,
// SAMPLING_BALLOT_CURSOR).
#ifndef BIDIR_BALLOT_GLSL
#define BIDIR_BALLOT_GLSL

// The ballot `b` without its lanes below `start` (0 to 128).
uvec4 ballot_from(uvec4 b, uint start) {
    for (uint w = 0u; w < 4u; w++) {
        uint below = start >= 32u * (w + 1u) ? 0xffffffffu : (start > 32u * w ? (1u << (start - 32u * w)) - 1u : 0u);
        b[w] &= ~below;
    }
    return b;
}

// The lowest lane of the ballot `b` (not empty), taken out of it.
uint ballot_take_lowest(inout uvec4 b) {
    uint w = 0u;
    for (uint j = 4u; j > 0u; j--) {
        w = b[j - 1u] != 0u ? j - 1u : w;
    }
    uint lane = 32u * w + uint(findLSB(b[w]));
    for (uint j = 0u; j < 4u; j++) {
        b[j] &= j == w ? b[j] - 1u : 0xffffffffu;
    }
    return lane;
}

#endif
