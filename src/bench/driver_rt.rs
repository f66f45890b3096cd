//! `bench traversal --driver-rt`: the same rays traced through the driver's own ray-tracing
//! pipeline (VK_KHR_ray_tracing_pipeline, over acceleration structures the driver builds from
//! the scene's triangles), timed the same way, and its hits compared with bidir's.

use super::json::Json;
use crate::gpu::abi::{self, GpuHit, GpuRay, NO_HIT};
use crate::gpu::kernels;
use crate::vk::{Buffer, Context, DriverTracer, Memory, RtShaders, Timer, VkError};

/// The driver's pipeline over one scene, with its own hit buffer and timer.
pub struct Driver {
    tracer: DriverTracer,
    hits: Buffer,
    timer: Timer,
    /// GPU time of the bottom-level build (ms) and its bytes.
    pub build_ms: f64,
    pub bytes: u64,
}

/// One ray kind through the driver's ray-tracing pipeline.
#[derive(Clone, Debug)]
pub struct DriverKindResult {
    pub times_ms: Vec<f64>,
    pub median_ms: f64,
    pub mrays_per_s: f64,
    pub hit_fraction: f64,
    pub agreement: Agreement,
    /// The example disagreeing rays of `agreement`: the ray, bidir's hit (triangle as the
    /// scene numbers it) and the driver's.
    pub examples: Vec<(GpuRay, GpuHit, GpuHit)>,
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
    /// Builds the driver's acceleration structures over the scene's triangles and its
    /// pipeline, for launches of up to `max_rays` rays.
    pub fn new(ctx: &Context, positions: &[glam::Vec3], triangles: &[[u32; 3]], max_rays: u32) -> Result<Driver, VkError> {
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
        let hits = ctx.create_buffer("bench.driver_hits", max_rays as u64 * std::mem::size_of::<GpuHit>() as u64, Memory::Device)?;
        let timer = ctx.create_timer("bench.driver_timer", 2)?;
        Ok(Driver { build_ms: tracer.blas_build_ms(), bytes: tracer.blas_bytes(), tracer, hits, timer })
    }

    /// Traces the first `count` rays of `rays` `reps` times after `warmup` untimed runs (GPU
    /// timestamps around each launch) and compares the hits with `ours` (bidir's, leaf order:
    /// `tri_ids` maps them to the scene's triangles); `real` rays count for the rate.
    #[allow(clippy::too_many_arguments)]
    pub fn measure(
        &self,
        ctx: &Context,
        rays: &Buffer,
        count: u32,
        real: u32,
        any_hit: bool,
        ours: &[GpuHit],
        tri_ids: &[u32],
        warmup: usize,
        reps: usize,
    ) -> Result<DriverKindResult, VkError> {
        let push = abi::RtTracePush { count, any_hit: any_hit as u32, ..Default::default() };
        let mut times = Vec::new();
        for rep in 0..warmup + reps {
            ctx.submit("driver trace", |rec| {
                rec.reset_timer(&self.timer);
                rec.timestamp(&self.timer, 0);
                rec.trace_rays_driver(&self.tracer, rays, &self.hits, bytemuck::bytes_of(&push), count)?;
                rec.timestamp(&self.timer, 1);
                Ok(())
            })?;
            if rep >= warmup {
                times.push(self.timer.elapsed_ns(0, 1)? * 1e-6);
            }
        }
        let theirs: Vec<GpuHit> = ctx.read_buffer(&self.hits)?;
        let (ours, theirs) = (&ours[..count as usize], &theirs[..count as usize]);
        let agreement = compare(ours, theirs, tri_ids, any_hit);
        let mut examples = Vec::new();
        if !agreement.examples.is_empty() {
            let all: Vec<GpuRay> = ctx.read_buffer(rays)?;
            for &i in &agreement.examples {
                let mut mine = ours[i as usize];
                if let Some(&id) = tri_ids.get(mine.tri as usize) {
                    mine.tri = id;
                }
                examples.push((all[i as usize], mine, theirs[i as usize]));
            }
        }
        let median_ms = super::median(&times);
        Ok(DriverKindResult {
            median_ms,
            mrays_per_s: real as f64 / (median_ms * 1e-3) / 1e6,
            hit_fraction: theirs.iter().filter(|x| x.tri != NO_HIT).count() as f64 / real as f64,
            agreement,
            examples,
            times_ms: times,
        })
    }
}

impl DriverKindResult {
    pub fn to_json(&self) -> Json {
        let a = &self.agreement;
        Json::obj(vec![
            ("median_ms", Json::Num(self.median_ms)),
            ("mrays_per_s", Json::Num(self.mrays_per_s)),
            ("hit_fraction", Json::Num(self.hit_fraction)),
            ("agree_fraction", Json::Num(a.fraction())),
            ("only_bidir", Json::Int(a.only_bidir as i64)),
            ("only_driver", Json::Int(a.only_driver as i64)),
            ("different", Json::Int(a.different as i64)),
            ("bidir_nearer", Json::Int(a.bidir_nearer as i64)),
            ("times_ms", Json::Arr(self.times_ms.iter().map(|&t| Json::Num(t)).collect())),
        ])
    }

    /// The row of one ray kind (`bidir_mrays_per_s`: bidir's rate for the ratio), then the
    /// disagreements and their example rays, if any.
    pub fn print(&self, kind: &str, rays: u32, bidir_mrays_per_s: f64) {
        println!(
            "{:<8} {:>10} {:>10.3} {:>12.1} {:>18.2} {:>6.1} {:>9.3}",
            kind,
            rays,
            self.median_ms,
            self.mrays_per_s,
            bidir_mrays_per_s / self.mrays_per_s,
            100.0 * self.hit_fraction,
            100.0 * self.agreement.fraction()
        );
        let a = &self.agreement;
        if a.agree == a.rays {
            return;
        }
        println!(
            "         disagreements: {} hit by bidir only, {} by the driver only, {} different triangles at different distances ({} of them nearer for bidir)",
            a.only_bidir, a.only_driver, a.different, a.bidir_nearer
        );
        let tri = |h: &GpuHit| if h.tri == NO_HIT { "none".to_string() } else { format!("{} at t {:e}", h.tri, h.t) };
        for (ray, ours, theirs) in &self.examples {
            let (o, d) = (ray.origin, ray.dir);
            println!(
                "         ray o ({:e}, {:e}, {:e}) d ({:e}, {:e}, {:e}) t ({:e}, {:e}): bidir {}, driver {}",
                o.x,
                o.y,
                o.z,
                d.x,
                d.y,
                d.z,
                o.w,
                d.w,
                tri(ours),
                tri(theirs)
            );
        }
    }
}

/// The header of the driver's rows: its build, then the columns.
pub fn print_header(build_ms: f64, bytes: u64) {
    println!(
        "driver's ray-tracing pipeline (VK_KHR_ray_tracing_pipeline): acceleration structure built in {build_ms:.1} ms (GPU), {:.1} MiB",
        bytes as f64 / (1 << 20) as f64
    );
    println!(
        "{:<8} {:>10} {:>10} {:>12} {:>18} {:>6} {:>9}",
        "rays", "count", "median ms", "Mrays/s", "bidir / driver", "hit %", "agree %"
    );
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
