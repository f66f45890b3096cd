//! Ray–triangle tests, CPU twins of `glsl/common/intersect.glsl` (same operations in the same
//! order, and `fma()` rounded as the device rounds it, `Fma`, so both sides agree to the bit
//! where the GPU rounds IEEE).

use crate::gpu::abi::{self, GpuTri};
use glam::{Vec3, Vec4};

/// Which ray–triangle test the triangles are encoded for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriTest {
    /// Woop, Benthin & Wald 2013: shear the triangle into ray space and test edge functions;
    /// rays through shared edges and vertices never slip between triangles.
    Watertight,
    /// Woop's unit-triangle test (thesis eq. 2.29–2.32): one affine map per triangle; fastest
    /// to evaluate, but can leak through shared edges.
    Woop,
}

impl TriTest {
    pub fn spec_value(self) -> u32 {
        match self {
            TriTest::Watertight => abi::TRI_TEST_WATERTIGHT,
            TriTest::Woop => abi::TRI_TEST_WOOP,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            TriTest::Watertight => "watertight",
            TriTest::Woop => "woop",
        }
    }
}

impl std::str::FromStr for TriTest {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "watertight" => Ok(TriTest::Watertight),
            "woop" => Ok(TriTest::Woop),
            _ => Err(format!("unknown triangle test '{s}' (watertight | woop)")),
        }
    }
}

/// Encodes one triangle for `test`.
pub fn encode(test: TriTest, v0: Vec3, v1: Vec3, v2: Vec3) -> GpuTri {
    match test {
        TriTest::Watertight => GpuTri { a: v0.extend(0.0), b: v1.extend(0.0), c: v2.extend(0.0) },
        TriTest::Woop => woop_transform(v0, v1, v2),
    }
}

/// The world-to-unit-triangle map: with `M = [v0 - v2, v1 - v2, n]` (columns) and
/// `n = (v0 - v2) x (v1 - v2)`, a point `p` has unit-space coordinates `M^-1 (p - v2)`: the
/// first two are the barycentrics of v0 and v1, the third is 0 on the plane. Each row r of
/// `M^-1` is stored as (r, -r . v2). Computed in f64 for accuracy.
fn woop_transform(v0: Vec3, v1: Vec3, v2: Vec3) -> GpuTri {
    let (v0, v1, v2) = (v0.as_dvec3(), v1.as_dvec3(), v2.as_dvec3());
    let e0 = v0 - v2;
    let e1 = v1 - v2;
    let n = e0.cross(e1);
    let m = glam::DMat3::from_cols(e0, e1, n);
    let inv = m.inverse();
    let row = |i: usize| {
        let r = inv.row(i);
        Vec4::new(r.x as f32, r.y as f32, r.z as f32, (-r.dot(v2)) as f32)
    };
    GpuTri { a: row(0), b: row(1), c: row(2) }
}

/// How a device evaluates GLSL's `precise fma(a, b, c)`, which the watertight test's shear and
/// distance use. GLSL lets fma() round once or twice, the same way wherever a `precise` value
/// consumes it on one device (GLSL 4.60, section 8.3), so each device's test is watertight either
/// way, but the CPU twin must round as the device does to agree with it bit for bit. NVIDIA's
/// driver fuses (FFMA); lavapipe (Mesa 22.3) splits fma() into a product and a sum.
/// `tests/common/sampling_kernel.rs` asks the device.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Fma {
    /// Rounded once, as `f32::mul_add`.
    #[default]
    Fused,
    /// Rounded twice, as `a * b + c`.
    Separate,
}

impl Fma {
    /// `a b + c` as the device's fma() rounds it.
    pub fn apply(self, a: f32, b: f32, c: f32) -> f32 {
        match self {
            Fma::Fused => a.mul_add(b, c),
            Fma::Separate => a * b + c,
        }
    }
}

/// A ray prepared for intersection (per-ray constants of both tests).
#[derive(Clone, Copy, Debug)]
pub struct PreparedRay {
    pub origin: Vec3,
    pub dir: Vec3,
    pub tmin: f32,
    // Watertight: permutation and shear (Woop, Benthin, Wald 2013, section 3): sx = d_kx / d_kz,
    // sy = d_ky / d_kz, sz = 1 / d_kz.
    kx: usize,
    ky: usize,
    kz: usize,
    sx: f32,
    sy: f32,
    sz: f32,
    /// The device's fma() that the watertight test follows.
    fma: Fma,
}

impl PreparedRay {
    pub fn new(origin: Vec3, dir: Vec3, tmin: f32) -> Self {
        let a = dir.abs();
        let kz = if a.x > a.y {
            if a.x > a.z {
                0
            } else {
                2
            }
        } else if a.y > a.z {
            1
        } else {
            2
        };
        let mut kx = (kz + 1) % 3;
        let mut ky = (kx + 1) % 3;
        if dir[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky); // keep the winding
        }
        let sz = 1.0 / dir[kz];
        PreparedRay { origin, dir, tmin, kx, ky, kz, sx: dir[kx] * sz, sy: dir[ky] * sz, sz, fma: Fma::Fused }
    }

    /// The same ray for a device whose fma() rounds as `fma` says.
    pub fn with_fma(self, fma: Fma) -> Self {
        PreparedRay { fma, ..self }
    }
}

/// A hit: distance and barycentrics of vertices 1 and 2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
}

/// Intersects `tri` (encoded for `test`) in the open interval (tmin, tmax).
pub fn intersect(test: TriTest, ray: &PreparedRay, tri: &GpuTri, tmax: f32) -> Option<TriHit> {
    match test {
        TriTest::Watertight => watertight(ray, tri.a.truncate(), tri.b.truncate(), tri.c.truncate(), tmax),
        TriTest::Woop => woop(ray, tri, tmax),
    }
}

fn woop(ray: &PreparedRay, tri: &GpuTri, tmax: f32) -> Option<TriHit> {
    let (o, d) = (ray.origin, ray.dir);
    // Unit-space z of origin and direction: t where the ray meets the plane.
    let oz = tri.c.w + (tri.c.x * o.x + tri.c.y * o.y + tri.c.z * o.z);
    let dz = tri.c.x * d.x + tri.c.y * d.y + tri.c.z * d.z;
    let t = -oz / dz;
    if !(t > ray.tmin && t < tmax) {
        return None;
    }
    let ox = tri.a.w + (tri.a.x * o.x + tri.a.y * o.y + tri.a.z * o.z);
    let dx = tri.a.x * d.x + tri.a.y * d.y + tri.a.z * d.z;
    let b0 = ox + t * dx; // barycentric of v0
    if b0 < 0.0 {
        return None;
    }
    let oy = tri.b.w + (tri.b.x * o.x + tri.b.y * o.y + tri.b.z * o.z);
    let dy = tri.b.x * d.x + tri.b.y * d.y + tri.b.z * d.z;
    let b1 = oy + t * dy; // barycentric of v1
    if b1 < 0.0 || b0 + b1 > 1.0 {
        return None;
    }
    // Vertex order of the map is (v0, v1, v2) -> (b0, b1, 1 - b0 - b1).
    Some(TriHit { t, u: b1, v: 1.0 - b0 - b1 })
}

fn watertight(ray: &PreparedRay, v0: Vec3, v1: Vec3, v2: Vec3, tmax: f32) -> Option<TriHit> {
    let (kx, ky, kz) = (ray.kx, ray.ky, ray.kz);
    let a = v0 - ray.origin;
    let b = v1 - ray.origin;
    let c = v2 - ray.origin;
    // Shear into ray space (eq. 4 of the paper), each coordinate one fma() rounded as the
    // device rounds it: a vertex shears to the same point in every triangle that shares it.
    let fma = |a: f32, b: f32, c: f32| ray.fma.apply(a, b, c);
    let ax = fma(-ray.sx, a[kz], a[kx]);
    let ay = fma(-ray.sy, a[kz], a[ky]);
    let bx = fma(-ray.sx, b[kz], b[kx]);
    let by = fma(-ray.sy, b[kz], b[ky]);
    let cx = fma(-ray.sx, c[kz], c[kx]);
    let cy = fma(-ray.sy, c[kz], c[ky]);
    // Scaled barycentrics: 2D edge functions (eq. 5). Each is an exact negation of the same
    // edge's function in the neighbouring triangle, hence watertight.
    let u = cx * by - cy * bx;
    let v = ax * cy - ay * cx;
    let w = bx * ay - by * ax;
    if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
        return None;
    }
    let det = u + v + w;
    if det == 0.0 {
        return None;
    }
    // The vertices' kz coordinates interpolated, then scaled once by 1 / d_kz and 1 / det.
    let t_scaled = fma(u, a[kz], fma(v, b[kz], w * c[kz]));
    let inv_det = 1.0 / det;
    let t = t_scaled * (ray.sz * inv_det);
    if !(t > ray.tmin && t < tmax) {
        return None;
    }
    Some(TriHit { t, u: v * inv_det, v: w * inv_det })
}

/// Geometric normal (unnormalised direction) of an encoded triangle, front face = CCW.
pub fn geometric_normal(test: TriTest, tri: &GpuTri) -> Vec3 {
    match test {
        TriTest::Watertight => (tri.b - tri.a).truncate().cross((tri.c - tri.a).truncate()),
        // Row 2 of M^-1 is n / |n|^2 with n = (v0 - v2) x (v1 - v2), which is the CCW normal.
        TriTest::Woop => tri.c.truncate(),
    }
}
