// Light sampling: an emissive triangle chosen in proportion to its power (luminance(Le) *
// area) through Walker's alias table, then a uniform point on it.
#ifndef BIDIR_LIGHTS_GLSL
#define BIDIR_LIGHTS_GLSL

layout(std430, binding = BIND_EMITTERS) readonly buffer Emitters { GpuEmitter emitters[]; };
layout(std430, binding = BIND_ALIAS) readonly buffer Alias { GpuAlias alias_table[]; };

struct LightSample {
    vec3 p;         // point on the emitter
    vec3 n;         // its unit front normal
    vec3 le;        // emitted radiance
    float pick;     // probability of having chosen this emitter
    float area;     // its area
    uint emitter;   // index of the emitter chosen
    vec2 bary;      // barycentric weights of its vertices 1 and 2 at p
};

// O(1) alias-table choice from 32 uniform bits: the cell from the high word of u count, the
// choice within it from the low word (index_below; a float's 24 bits would give the cells
// unequal shares, and the choice within a cell few steps, once there are many emitters).
uint choose_emitter(uint u, uint count) {
    float rest;
    uint i = index_below(u, count, rest);
    GpuAlias a = alias_table[i];
    return rest < a.prob ? i : a.alias;
}

// Uniform point on the chosen triangle by the square-root warp (Turk, "Generating Random
// Points in Triangles", Graphics Gems, 1990): (1 - su, u2 su, su (1 - u2)) is uniform over
// the barycentric simplex for su = sqrt(u1); any permutation of it is too.
LightSample sample_emitter(uint count, uint u0, float u1, float u2) {
    uint index = choose_emitter(u0, count);
    GpuEmitter e = emitters[index];
    float su = sqrt(u1);
    float b1 = u2 * su;        // weight of v1
    float b2 = 1.0 - su;       // weight of v2 (v0 gets su (1 - u2))
    LightSample s;
    s.p = e.v0 + b1 * e.e1 + b2 * e.e2;
    s.n = normalize(cross(e.e1, e.e2));
    s.le = e.radiance;
    s.pick = e.pick;
    s.area = e.area;
    s.emitter = index;
    s.bary = vec2(b1, b2);
    return s;
}

// Area pdf of light sampling at a point of an emitter with emission luminance `lum`:
// (lum * area / total) * (1 / area).
float light_pdf_a(float lum, float total_weight) {
    return lum / total_weight;
}

#endif
