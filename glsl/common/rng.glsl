// Counter-based random numbers: a PCG-style hash of (index, sample, seed), no state in memory.
#ifndef BIDIR_RNG_GLSL
#define BIDIR_RNG_GLSL

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"): one 32-bit LCG step
// and an output permutation.
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

struct Rng {
    uint state;
};

Rng rng_init(uint a, uint b, uint c) {
    return Rng(pcg_hash(a ^ pcg_hash(b ^ pcg_hash(c))));
}

// Uniform in [0, 1): the top 24 bits of the next hash.
float rng_next(inout Rng r) {
    r.state = pcg_hash(r.state);
    return float(r.state >> 8u) * (1.0 / 16777216.0);
}

#endif
