// Ray–triangle tests. CPU twins: src/bvh/intersect.rs (same operations, same order). Every
// value is `precise` so the compiler neither fuses multiply-adds of its own nor reassociates:
// the watertight test relies on a shared edge's function being the exact negation in the two
// triangles, and the tests rely on GPU and CPU agreeing. The multiply-adds the watertight test
// does fuse are written as fma(): a device rounds it once (NVIDIA) or twice (lavapipe), the same
// way in every triangle (GLSL 4.60, 8.3), and the CPU twin asks which (Fma in intersect.rs).
#ifndef BIDIR_INTERSECT_GLSL
#define BIDIR_INTERSECT_GLSL

layout(constant_id = SPEC_TRI_TEST) const uint TRI_TEST = TRI_TEST_WATERTIGHT;

// v[k] for k in 0..2 as two selects. (Indexing a vector with a run-time k, `v[k]`, compiles
// on NVIDIA's driver to a chain of address compares and predicated moves per use: the
// watertight test's nine picks ran ~40 instructions more per triangle, seen in the machine
// code, scripts/device/sass.py.)
float pick3(vec3 v, uint k) {
    return k == 0u ? v.x : (k == 1u ? v.y : v.z);
}

// Per-ray constants.
struct PreparedRay {
    vec3 o;
    vec3 d;
    float tmin;
    // Watertight (Woop, Benthin, Wald 2013, section 3): axis permutation and shear (sx = d_kx /
    // d_kz, sy = d_ky / d_kz, sz = 1 / d_kz).
    uint kx, ky, kz;
    float sx, sy, sz;
};

PreparedRay prepare_ray(vec3 o, vec3 d, float tmin) {
    PreparedRay r;
    r.o = o;
    r.d = d;
    r.tmin = tmin;
    vec3 a = abs(d);
    r.kz = a.x > a.y ? (a.x > a.z ? 0u : 2u) : (a.y > a.z ? 1u : 2u);
    r.kx = r.kz == 2u ? 0u : r.kz + 1u;
    r.ky = r.kx == 2u ? 0u : r.kx + 1u;
    if (d[r.kz] < 0.0) { // keep the winding
        uint t = r.kx;
        r.kx = r.ky;
        r.ky = t;
    }
    precise float sz = 1.0 / d[r.kz];
    precise float sx = d[r.kx] * sz;
    precise float sy = d[r.ky] * sz;
    r.sx = sx;
    r.sy = sy;
    r.sz = sz;
    return r;
}

// Woop's unit-triangle test (thesis eq. 2.29–2.32). Rows a, b, c of the world-to-unit map;
// the hit is where unit z = 0; unit x, y are the barycentrics of v0, v1.
bool intersect_woop(PreparedRay r, GpuTri tri, float tmax, out float t, out vec2 bary) {
    precise float oz = tri.c.w + (tri.c.x * r.o.x + tri.c.y * r.o.y + tri.c.z * r.o.z);
    precise float dz = tri.c.x * r.d.x + tri.c.y * r.d.y + tri.c.z * r.d.z;
    precise float tt = -oz / dz;
    t = tt;
    bary = vec2(0.0);
    if (!(tt > r.tmin && tt < tmax)) {
        return false;
    }
    precise float ox = tri.a.w + (tri.a.x * r.o.x + tri.a.y * r.o.y + tri.a.z * r.o.z);
    precise float dx = tri.a.x * r.d.x + tri.a.y * r.d.y + tri.a.z * r.d.z;
    precise float b0 = ox + tt * dx;
    if (b0 < 0.0) {
        return false;
    }
    precise float oy = tri.b.w + (tri.b.x * r.o.x + tri.b.y * r.o.y + tri.b.z * r.o.z);
    precise float dy = tri.b.x * r.d.x + tri.b.y * r.d.y + tri.b.z * r.d.z;
    precise float b1 = oy + tt * dy;
    precise float b01 = b0 + b1;
    if (b1 < 0.0 || b01 > 1.0) {
        return false;
    }
    precise float b2 = 1.0 - b0 - b1;
    bary = vec2(b1, b2);
    return true;
}

// Watertight test (Woop, Benthin, Wald 2013): shear into ray space, 2D edge functions.
bool intersect_watertight(PreparedRay r, vec3 v0, vec3 v1, vec3 v2, float tmax, out float t, out vec2 bary) {
    t = 0.0;
    bary = vec2(0.0);
    precise vec3 a = v0 - r.o;
    precise vec3 b = v1 - r.o;
    precise vec3 c = v2 - r.o;
    float akz = pick3(a, r.kz);
    float bkz = pick3(b, r.kz);
    float ckz = pick3(c, r.kz);
    // Sheared vertices (eq. 4 of the paper), each coordinate a_kx - (d_kx / d_kz) a_kz as one
    // fma(). A vertex shears to the same point in every triangle that shares it, however the
    // device rounds fma(), which is all that watertightness asks of this step (H200, Sponza
    // CameraMain: primary rays 0.8-1.1 % faster than as a product and a difference, session 33;
    // with the slopes stored negated, two instructions fewer, they were not: the compiler's
    // schedule, docs/traversal.md).
    precise float ax = fma(-r.sx, akz, pick3(a, r.kx));
    precise float ay = fma(-r.sy, akz, pick3(a, r.ky));
    precise float bx = fma(-r.sx, bkz, pick3(b, r.kx));
    precise float by = fma(-r.sy, bkz, pick3(b, r.ky));
    precise float cx = fma(-r.sx, ckz, pick3(c, r.kx));
    precise float cy = fma(-r.sy, ckz, pick3(c, r.ky));
    precise float u = cx * by - cy * bx;
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) {
        return false;
    }
    precise float det = u + v + w;
    if (det == 0.0) {
        return false;
    }
    // The hit's distance: the vertices' kz coordinates (relative to the origin) interpolated,
    // u a_kz + v b_kz + w c_kz, then scaled once by 1 / d_kz and 1 / det (the paper scales each
    // vertex's by 1 / d_kz first).
    precise float ts = fma(u, akz, fma(v, bkz, w * ckz));
    precise float inv_det = 1.0 / det;
    precise float tt = ts * (r.sz * inv_det);
    if (!(tt > r.tmin && tt < tmax)) {
        return false;
    }
    t = tt;
    bary = vec2(v * inv_det, w * inv_det);
    return true;
}

bool intersect_tri(PreparedRay r, GpuTri tri, float tmax, out float t, out vec2 bary) {
    if (TRI_TEST == TRI_TEST_WOOP) {
        return intersect_woop(r, tri, tmax, t, bary);
    }
    return intersect_watertight(r, tri.a.xyz, tri.b.xyz, tri.c.xyz, tmax, t, bary);
}

// Unnormalised geometric normal, CCW front face (row 2 of the Woop map is n / |n|^2).
vec3 tri_geometric_normal(GpuTri tri) {
    if (TRI_TEST == TRI_TEST_WOOP) {
        return tri.c.xyz;
    }
    return cross(tri.b.xyz - tri.a.xyz, tri.c.xyz - tri.a.xyz);
}

#endif
