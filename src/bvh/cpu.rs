//! The CPU reference traversal: obvhs' own BVH2 traversal (independent of the GPU layout and
//! kernels) with the same triangle tests as the GPU. Tests compare the GPU against it.

use super::{
    intersect::{self, Fma, PreparedRay, TriHit, TriTest},
    Bvh,
};
use crate::gpu::abi::GpuTri;
use glam::Vec3;
use obvhs::ray::{Ray, RayHit};

/// Closest-hit and any-hit queries on the CPU.
pub struct CpuTracer<'a> {
    bvh: &'a Bvh,
    /// Encoded triangles by original index.
    tris: Vec<GpuTri>,
    test: TriTest,
    fma: Fma,
}

impl<'a> CpuTracer<'a> {
    pub fn new(bvh: &'a Bvh, positions: &[Vec3], triangles: &[[u32; 3]]) -> Self {
        let tris = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| positions[v as usize]);
                intersect::encode(bvh.tri_test, a, b, c)
            })
            .collect();
        CpuTracer { bvh, tris, test: bvh.tri_test, fma: Fma::Fused }
    }

    /// The same tracer rounding the watertight test's fma() as a device does (see `Fma`).
    pub fn with_fma(self, fma: Fma) -> Self {
        CpuTracer { fma, ..self }
    }

    /// Closest hit in (tmin, tmax): original triangle index and hit.
    pub fn closest(&self, origin: Vec3, dir: Vec3, tmin: f32, tmax: f32) -> Option<(u32, TriHit)> {
        self.closest_where(origin, dir, tmin, tmax, |_, _| true)
    }

    /// Whether anything is hit in (tmin, tmax).
    pub fn any(&self, origin: Vec3, dir: Vec3, tmin: f32, tmax: f32) -> bool {
        self.any_where(origin, dir, tmin, tmax, |_, _| true)
    }

    /// As `closest`, counting only hits `accept(original triangle, hit)` keeps (alpha masks:
    /// false where the texture is transparent); a rejected hit neither shortens the ray nor
    /// ends the search.
    pub fn closest_where(
        &self,
        origin: Vec3,
        dir: Vec3,
        tmin: f32,
        tmax: f32,
        accept: impl Fn(u32, &TriHit) -> bool,
    ) -> Option<(u32, TriHit)> {
        let pr = PreparedRay::new(origin, dir, tmin).with_fma(self.fma);
        let ray = Ray::new(origin.into(), dir.into(), tmin, tmax);
        let mut best: Option<(u32, TriHit)> = None;
        let mut hit = RayHit::none();
        let src = &self.bvh.source;
        src.ray_traverse(ray, &mut hit, |r, id| {
            let orig = src.primitive_indices[id];
            match intersect::intersect(self.test, &pr, &self.tris[orig as usize], r.tmax).filter(|h| accept(orig, h)) {
                Some(h) => {
                    if best.is_none_or(|(_, b)| h.t < b.t) {
                        best = Some((orig, h));
                    }
                    h.t
                }
                None => f32::INFINITY,
            }
        });
        best
    }

    /// As `any`, counting only hits `accept` keeps (see `closest_where`).
    pub fn any_where(&self, origin: Vec3, dir: Vec3, tmin: f32, tmax: f32, accept: impl Fn(u32, &TriHit) -> bool) -> bool {
        let pr = PreparedRay::new(origin, dir, tmin).with_fma(self.fma);
        let ray = Ray::new(origin.into(), dir.into(), tmin, tmax);
        let src = &self.bvh.source;
        !src.ray_traverse_miss(ray, |r, id| {
            let orig = src.primitive_indices[id];
            intersect::intersect(self.test, &pr, &self.tris[orig as usize], r.tmax)
                .filter(|h| accept(orig, h))
                .map_or(f32::INFINITY, |h| h.t)
        })
    }
}
