// Random numbers for the integrators, a value per (pixel or path, sample index, dimension):
// - independent (SAMPLER_INDEPENDENT): a PCG-style hash chain, no state in memory;
// - Owen-scrambled Sobol' (SOBOL_DIMS > 0): Burley 2020, "Practical Hash-based Owen
//   Scrambling" — dimensions in groups of four, each group with its own per-pixel index
//   shuffle and value scramble, so every dimension stays uniform (unbiased) and each group
//   keeps Sobol's stratification across a pixel's samples. Each sampling decision (the pixel,
//   a vertex's light sample, its BSDF sample) starts a group of its own (rng_start_group).
//   Sobol' numbers only for the first SOBOL_DIMS dimensions, or with SOBOL_FIRST_VERTEX (the
//   default) for the pixel and the path's first vertex (rng_start_vertex), where
//   stratification lowers the error most; later numbers continue as a hash chain seeded by
//   (pixel, sample index), which costs a fraction of a scrambled Sobol' number
//   (docs/results.md: "Sobol' dimensions", "A group of Sobol' dimensions per sampling
//   decision").
#ifndef BIDIR_RNG_GLSL
#define BIDIR_RNG_GLSL

#include "bidir_sobol.glsl"

layout(constant_id = SPEC_SAMPLER) const uint SOBOL_DIMS = SAMPLER_INDEPENDENT;

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"): one 32-bit LCG step
// and an output permutation.
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

struct Rng {
    uint state;   // hash chain; while dim < SOBOL_DIMS the per-pixel seed
    uint index;   // Sobol: sample index
    uint dim;     // Sobol: next dimension (stops counting past SOBOL_DIMS)
};

// The index rng_init(_, sample_index, _) gives (no draw changes it): a path kept between
// launches need not store it.
uint rng_init_index(uint sample_index) {
    return SOBOL_DIMS > 0u ? sample_index : 0u;
}

Rng rng_init(uint pixel, uint sample_index, uint seed) {
    uint s = pcg_hash(pixel ^ pcg_hash(seed));
    if (SOBOL_DIMS > 0u) {
        return Rng(s, rng_init_index(sample_index), 0u);
    }
    return Rng(pcg_hash(s ^ pcg_hash(sample_index)), 0u, 0u);
}

// Burley's Laine–Karras-style hash: an invertible mixing of the low bits into the high ones.
uint laine_karras_permutation(uint x, uint seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// A random Owen (nested uniform) scramble of the bits of x.
uint nested_uniform_scramble(uint x, uint seed) {
    return bitfieldReverse(laine_karras_permutation(bitfieldReverse(x), seed));
}

// sobol_point(index, dim) comes from the generated bidir_sobol.glsl.

// The next 32 random bits.
uint rng_next_uint(inout Rng r) {
    if (SOBOL_DIMS > 0u && r.dim < SOBOL_DIMS) {
        uint group_seed = pcg_hash(r.state ^ pcg_hash(r.dim / 4u));
        uint shuffled = nested_uniform_scramble(r.index, group_seed);
        uint k = r.dim % 4u;
        r.dim++;
        return nested_uniform_scramble(sobol_point(shuffled, k), pcg_hash(group_seed ^ (k + 1u)));
    }
    if (SOBOL_DIMS > 0u && r.dim == SOBOL_DIMS) {
        // Past the Sobol' dimensions: a hash chain of its own for this pixel and sample.
        r.state = pcg_hash(r.state ^ pcg_hash(r.index ^ 0x5bd1e995u));
        r.dim++;
    }
    r.state = pcg_hash(r.state);
    return r.state;
}

// The next number starts a group of four Sobol' dimensions. Over a pixel's samples a group's
// dimensions 0 and 1, and 1 and 2, are each a (0, 2)-sequence, stratified in 2D at every power
// of two (tests/sampling.rs); dimensions 0 and 2, any pair with 3, and two dimensions of
// different groups are not. So each decision starts a group and draws its 2D numbers first or
// after one other (the padding of pbrt-v4's PaddedSobolSampler, in groups of four). Past the
// Sobol' dimensions nothing changes: the skip stops at SOBOL_DIMS, where rng_next_uint starts
// the sample's hash chain.
void rng_start_group(inout Rng r) {
    if (SOBOL_DIMS > 0u && r.dim < SOBOL_DIMS) {
        r.dim = min((r.dim + 3u) & ~3u, SOBOL_DIMS);
    }
}

// The path reaches its vertex `depth` (1: the first surface it meets). Under
// SOBOL_FIRST_VERTEX the numbers of its second vertex and later come from the hash chain, so a
// sample computes Sobol' numbers for the pixel and its first vertex only, however many
// dimensions that vertex's decisions take (an environment's light sample takes five).
void rng_start_vertex(inout Rng r, uint depth) {
    if (SOBOL_DIMS == SOBOL_FIRST_VERTEX && depth >= 2u && r.dim < SOBOL_DIMS) {
        r.dim = SOBOL_DIMS;
    }
}

// Uniform in [0, 1): the top 24 bits of the next value.
float rng_next(inout Rng r) {
    return float(rng_next_uint(r) >> 8u) * (1.0 / 16777216.0);
}

// An index in [0, n) from 32 uniform bits u, and what is left of u within the index (uniform
// in [0, 1) given the index, in steps of n / 2^32): the high and low words of the 32 x 32-bit
// product u n (Lemire 2019 without the rejection step). Each index takes floor or ceil of
// 2^32 / n of u's values, a relative error below n / 2^32; an index computed from a float in
// [0, 1), whose 24 bits give 2^24 values, misses indices past 2^24 and is off by up to
// n / 2^24 below (tests/sampling.rs, `every_index_below_n_is_drawn_in_proportion`).
uint index_below(uint u, uint n, out float rest) {
    uint hi, lo;
    umulExtended(u, n, hi, lo);
    rest = float(lo >> 8u) * (1.0 / 16777216.0);
    return hi;
}

// The index alone.
uint index_below(uint u, uint n) {
    float rest;
    return index_below(u, n, rest);
}

// Uniform integer in [0, n) (index_below).
uint rng_below(inout Rng r, uint n) {
    return index_below(rng_next_uint(r), n);
}

#endif
