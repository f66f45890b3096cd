// Lanes of a subgroup ballot (the uvec4 of subgroupBallot) by rank; no subgroup operations
// here, so tests can run them on any ballot (glsl/tests/sampling.comp, SAMPLING_BALLOT_NTH).
#ifndef BIDIR_BALLOT_GLSL
#define BIDIR_BALLOT_GLSL

// The lane whose bit is the n-th (from 0) set bit of the ballot `b`, for n below its count:
// the lane that subgroupBallotExclusiveBitCount ranks n. Branch-free: past the words that
// hold n set bits or fewer, then a binary search within the word (halves of 16, 8, 4, 2, 1).
uint ballot_nth(uvec4 b, uint n) {
    uint word = b.x;
    uint lane = 0u;
    for (uint w = 0u; w < 3u; w++) {
        uint c = bitCount(word);
        bool past = n >= c;
        n = past ? n - c : n;
        lane = past ? lane + 32u : lane;
        word = past ? b[w + 1u] : word;
    }
    for (uint width = 16u; width > 0u; width >>= 1u) {
        uint low = bitCount(word & ((1u << width) - 1u));
        bool skip = n >= low;
        n = skip ? n - low : n;
        word = skip ? word >> width : word;
        lane = skip ? lane + width : lane;
    }
    return lane;
}

#endif
