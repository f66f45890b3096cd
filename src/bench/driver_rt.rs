//! `bench traversal --driver-rt`: the same rays traced through the driver's own ray-tracing
//! pipeline (VK_KHR_ray_tracing_pipeline, over acceleration structures the driver builds from
//! the scene's triangles), timed the same way, and its hits compared with bidir's.

use crate::gpu::abi::{self, GpuHit, NO_HIT};
use crate::gpu::kernels;
use crate::vk::{Buffer, Context, DriverTracer, RtShaders, Timer, VkError};

/// The driver's pipeline over one scene.
pub struct Driver {
    tracer: DriverTracer,
    pub build_ms: f64,
    pub bytes: u64,
}

/// How the driver's hits compare with bidir's, ray by ray.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Agreement {
    pub rays: u64,
    /// Same verdict and, for closest hits, the same triangle or one at the same distance
    /// (a ray through a shared edge or vertex may report either triangle).
    pub agree: u64,
    /// bidir found a hit where the driver found none, and the other way round.
    pub only_bidir: u64,
    pub only_driver: u64,
    /// Both hit, different triangles at different distances; in how many of those bidir's
    /// hit is the nearer.
    pub different: u64,
    pub bidir_nearer: u64,
    /// The first few disagreeing rays (indices into the ray buffer), to look at.
    pub examples: Vec<u32>,
}

/// Disagreeing rays `compare` keeps as examples.
pub const EXAMPLES: usize = 4;

impl Agreement {
    pub fn fraction(&self) -> f64 {
        if self.rays == 0 {
            1.0
        } else {
            self.agree as f64 / self.rays as f64
        }
    }
}

/// Relative distance within which two different triangles count as the same hit.
pub const SAME_DISTANCE: f32 = 1e-4;

/// Compares hit for hit: `ours` in leaf order (`tri_ids` maps it to the scene's triangle
/// index), `theirs` in the scene's order. Any-hit queries compare the verdict alone.
pub fn compare(ours: &[GpuHit], theirs: &[GpuHit], tri_ids: &[u32], any_hit: bool) -> Agreement {
    let mut a = Agreement { rays: ours.len().min(theirs.len()) as u64, ..Default::default() };
    for (i, (o, t)) in ours.iter().zip(theirs).enumerate() {
        let agree = match (o.tri != NO_HIT, t.tri != NO_HIT) {
            (false, false) => true,
            (true, false) => {
                a.only_bidir += 1;
                false
            }
            (false, true) => {
                a.only_driver += 1;
                false
            }
            (true, true) if any_hit => true,
            (true, true) => {
                let same_tri = tri_ids.get(o.tri as usize) == Some(&t.tri);
                let close = (o.t - t.t).abs() <= SAME_DISTANCE * o.t.abs().max(t.t.abs()).max(1e-3);
                if !(same_tri || close) {
                    a.different += 1;
                    a.bidir_nearer += (o.t < t.t) as u64;
                }
                same_tri || close
            }
        };
        if agree {
            a.agree += 1;
        } else if a.examples.len() < EXAMPLES {
            a.examples.push(i as u32);
        }
    }
    a
}

impl Driver {
    /// Builds the driver's acceleration structures over the scene's triangles and its pipeline.
    pub fn new(ctx: &Context, positions: &[glam::Vec3], triangles: &[[u32; 3]]) -> Result<Driver, VkError> {
        let shaders = RtShaders {
            raygen: &kernels::RT_TRACE_RGEN,
            miss: &kernels::RT_TRACE_RMISS,
            closest_hit: &kernels::RT_TRACE_RCHIT,
            tlas_binding: abi::RT_BIND_TLAS,
            rays_binding: abi::BIND_RAYS,
            hits_binding: abi::BIND_HITS,
            push_size: std::mem::size_of::<abi::RtTracePush>() as u32,
        };
        let points: Vec<[f32; 3]> = positions.iter().map(|p| p.to_array()).collect();
        let tracer = ctx.create_driver_tracer(&shaders, &points, triangles)?;
        Ok(Driver { build_ms: tracer.blas_build_ms(), bytes: tracer.blas_bytes(), tracer })
    }

    /// Traces `count` rays `reps` times after `warmup` untimed runs; the trace's GPU times (ms).
    #[allow(clippy::too_many_arguments)]
    pub fn time(
        &self,
        ctx: &Context,
        timer: &Timer,
        rays: &Buffer,
        hits: &Buffer,
        count: u32,
        any_hit: bool,
        warmup: usize,
        reps: usize,
    ) -> Result<Vec<f64>, VkError> {
        let push = abi::RtTracePush { count, any_hit: any_hit as u32, ..Default::default() };
        let mut times = Vec::new();
        for rep in 0..warmup + reps {
            ctx.submit("driver trace", |rec| {
                rec.reset_timer(timer);
                rec.timestamp(timer, 1);
                rec.trace_rays_driver(&self.tracer, rays, hits, bytemuck::bytes_of(&push), count)?;
                rec.timestamp(timer, 2);
                Ok(())
            })?;
            if rep >= warmup {
                times.push(timer.elapsed_ns(1, 2)? * 1e-6);
            }
        }
        Ok(times)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hit(t: f32, tri: u32) -> GpuHit {
        GpuHit { t, tri, u: 0.0, v: 0.0 }
    }

    #[test]
    fn hits_compare_by_triangle_or_distance() {
        // Leaf order 0, 1, 2 holds the scene's triangles 7, 3, 5.
        let ids = [7, 3, 5];
        let ours = [hit(1.0, 0), hit(2.0, 1), hit(3.0, 2), hit(4.0, NO_HIT), hit(5.0, 0), hit(6.0, NO_HIT), hit(7.0, 1)];
        let theirs = [
            hit(1.0, 7),        // same triangle
            hit(2.0 + 1e-5, 9), // another triangle at the same distance: a shared edge
            hit(3.5, 1),        // another triangle farther away
            hit(4.0, NO_HIT),   // both miss
            hit(5.0, NO_HIT),   // only bidir hits
            hit(6.0, 2),        // only the driver hits
            hit(7.0, 3),
        ];
        let a = compare(&ours, &theirs, &ids, false);
        assert_eq!(
            a,
            Agreement { rays: 7, agree: 4, only_bidir: 1, only_driver: 1, different: 1, bidir_nearer: 1, examples: vec![2, 4, 5] }
        );
        // Any-hit queries: only the verdict counts.
        let a = compare(&ours, &theirs, &ids, true);
        assert_eq!(a, Agreement { rays: 7, agree: 5, only_bidir: 1, only_driver: 1, different: 0, bidir_nearer: 0, examples: vec![4, 5] });
        assert!((a.fraction() - 5.0 / 7.0).abs() < 1e-12);
    }
}
