//! `bidir bench traversal`: rays generated on the GPU (primary through pixel centres; shadow
//! from each primary hit toward a point light high above the scene's centre; diffuse,
//! cosine-distributed about the geometric normal at each primary hit), then only the
//! traversal kernel timed with GPU timestamps: warm-up runs, then repetitions, median.

use super::driver_rt::Driver;
use super::median;
use crate::bvh::BvhError;
use crate::bvh::{BuildOptions, Bvh, BvhLayout};
use crate::gpu::abi::GpuCamera;
use crate::gpu_data::{GpuBvh, SceneFeatures};
use crate::render::GpuScene;
use crate::scene::Scene;
use crate::trace::sort::SortKind;
use crate::trace::{RaySorter, Secondary, TraceOptions, Tracer};
use crate::vk::{Bind, Buffer, Context, Memory, VkError};
use glam::Vec3;
use std::time::Instant;

mod report;
pub use report::{KindResult, Report};

/// The ray sets the benchmark can time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    Primary,
    Shadow,
    Diffuse,
}

impl RayKind {
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Primary => "primary",
            RayKind::Shadow => "shadow",
            RayKind::Diffuse => "diffuse",
        }
    }
    pub const ALL: [RayKind; 3] = [RayKind::Primary, RayKind::Shadow, RayKind::Diffuse];
}

/// Benchmark settings.
#[derive(Clone, Debug)]
pub struct Options {
    pub kinds: Vec<RayKind>,
    pub warmup: usize,
    pub repetitions: usize,
    pub build: BuildOptions,
    /// Point light for shadow rays; default: above the centre of the bounds by their height.
    pub light: Option<Vec3>,
    /// Skip alpha-masked triangles where their texture is transparent, as the integrators do
    /// (trace_alpha.comp with the scene's materials, UVs and textures); default: geometry only.
    pub alpha: bool,
    /// The trace kernels' variant: persistent threads, lockstep loops, dynamic fetch, shared
    /// leaves, packets, the stack, the launch shape (`TraceOptions`, whose defaults are the
    /// fastest kernels'). `run` takes its layout and triangle test from `build`, its alpha
    /// masks from `alpha`.
    pub trace: TraceOptions,
    /// Sort shadow and diffuse rays before tracing (`trace::RaySorter`: globally by
    /// direction octant and origin cell, or locally by direction); the sort is timed apart.
    pub sort: Option<SortKind>,
    /// Trace the same rays through the driver's ray-tracing pipeline too (`driver_rt.rs`);
    /// the context must have been created with `ContextOptions::ray_tracing`.
    pub driver_rt: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            kinds: RayKind::ALL.to_vec(),
            warmup: 3,
            repetitions: 9,
            build: BuildOptions::default(),
            light: None,
            alpha: false,
            trace: TraceOptions::new(BuildOptions::default().tri_test),
            sort: None,
            driver_rt: false,
        }
    }
}

/// Why the benchmark could not run.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    Bvh(#[from] BvhError),
    #[error(transparent)]
    Vk(#[from] VkError),
    #[error("no {0} rays: the camera sees no geometry (check --camera / --eye / --target)")]
    NoRays(&'static str),
}

/// Warps of a kernel an NVIDIA Hopper SM (H100, H200) keeps resident, in whole workgroups of
/// `wg` invocations: `registers` per invocation from a register file of 65,536 allocated per
/// warp in units of 256, `shared` bytes per workgroup from 228 KiB (plus 1 KiB the driver
/// reserves per workgroup), at most `max_warps` (64). An estimate from the CUDA occupancy
/// rules (the driver's own limits may differ), for reading `bench traversal`'s statistics.
pub fn hopper_resident_warps(registers: u64, shared: u64, wg: u64, max_warps: u64) -> u64 {
    let warps_per_group = wg.div_ceil(32).max(1);
    let per_warp = (registers * 32).div_ceil(256) * 256;
    let by_registers = 65_536u64.checked_div(per_warp).map_or(u64::MAX, |warps| warps / warps_per_group);
    let by_shared = if shared == 0 { u64::MAX } else { (228 * 1024) / (shared + 1024) };
    let by_warps = max_warps / warps_per_group;
    by_registers.min(by_shared).min(by_warps) * warps_per_group
}

/// Runs the benchmark on a scene seen through `camera` (only its triangles, unless
/// `opts.alpha`).
pub fn run(ctx: &Context, scene: &Scene, camera: &GpuCamera, opts: &Options) -> Result<Report, BenchError> {
    let (positions, triangles) = (&scene.positions[..], &scene.triangles[..]);
    let t0 = Instant::now();
    let bvh = Bvh::build(positions, triangles, &opts.build)?;
    let build_ms = t0.elapsed().as_secs_f64() * 1e3;
    let gbvh = GpuBvh::upload(ctx, &bvh)?;
    // With alpha, the whole scene as the integrators see it (its BVH buffers included).
    let gscene = if opts.alpha { Some(GpuScene::upload(ctx, scene, &bvh)?) } else { None };
    let geometry: Vec<Bind> = match &gscene {
        Some(s) => s.binds(),
        None => gbvh.binds(),
    };
    let trace_opts = TraceOptions {
        tri_test: opts.build.tri_test,
        layout: opts.build.layout,
        alpha: opts.alpha.then(|| SceneFeatures::of(scene)),
        ..opts.trace
    };
    let timing = Tracer::with_options(ctx, &trace_opts)?;
    let counting = Tracer::with_options(ctx, &TraceOptions { stats: true, ..trace_opts })?;
    let mut kernel_stats = Vec::new();
    for k in timing.trace_kernels() {
        let stats = k.statistics()?;
        let mut line: Vec<String> = stats.iter().map(|s| format!("{} {}", s.name, s.value)).collect();
        let number = |pred: &dyn Fn(&str) -> bool| stats.iter().find(|s| pred(&s.name)).and_then(|s| s.value.trim().parse::<u64>().ok());
        let warps_per_sm = ctx.info().warps_per_sm;
        if let (Some(registers), true) = (number(&|n| n == "Register Count"), warps_per_sm > 0) {
            let shared = number(&|n| n.contains("Shared Memory")).unwrap_or(0);
            let resident = hopper_resident_warps(registers, shared, k.local_size()[0] as u64, warps_per_sm as u64);
            line.push(format!("resident warps per SM (Hopper estimate) {resident} of {warps_per_sm}"));
        }
        if !line.is_empty() {
            kernel_stats.push((k.name().to_string(), line.join("; ")));
        }
    }

    let (lo, hi) = positions.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let light = opts.light.unwrap_or(Vec3::new((lo.x + hi.x) * 0.5, hi.y + (hi.y - lo.y), (lo.z + hi.z) * 0.5));

    let n = crate::gpu_data::tiled_invocations(camera.size.x, camera.size.y);
    let pixels = camera.size.x * camera.size.y;
    let ray_bytes = n as u64 * 32;
    let primary = ctx.create_buffer("bench.primary_rays", ray_bytes, Memory::Device)?;
    let primary_hits = ctx.create_buffer("bench.primary_hits", n as u64 * 16, Memory::Device)?;
    let secondary = ctx.create_buffer("bench.secondary_rays", ray_bytes, Memory::Device)?;
    let scratch = ctx.create_buffer("bench.scratch_rays", ray_bytes, Memory::Device)?;
    let flags = ctx.create_buffer("bench.flags", (n as u64 + 1) * 4, Memory::Device)?;
    let hits = ctx.create_buffer("bench.hits", n as u64 * 16, Memory::Device)?;
    let stats = ctx.create_buffer("bench.stats", 8, Memory::Device)?;
    let timer = ctx.create_timer("bench.timer", 3)?;
    let sorter = if opts.sort.is_some() { Some(RaySorter::new(ctx, n)?) } else { None };
    let driver = if opts.driver_rt { Some(Driver::new(ctx, positions, triangles, n)?) } else { None };
    let sorted = ctx.create_buffer("bench.sorted_rays", if opts.sort.is_some() { ray_bytes } else { 32 }, Memory::Device)?;
    let order = ctx.create_buffer("bench.sort_order", if opts.sort.is_some() { n as u64 * 4 } else { 4 }, Memory::Device)?;

    // Primary rays and their hits (the origin of the secondary rays).
    ctx.submit("bench primary", |rec| {
        timing.record_primary(rec, camera, &primary)?;
        rec.fill_buffer(&stats, 0);
        timing.record_trace(rec, &geometry, &primary, &primary_hits, &stats, n, false)
    })?;

    let mut results = Vec::new();
    for &kind in &opts.kinds {
        let (rays, count, any_hit): (&Buffer, u32, bool) = match kind {
            RayKind::Primary => (&primary, n, false),
            RayKind::Shadow => {
                let c =
                    timing.secondary(ctx, &gbvh, Secondary::Shadow, light, 1, &primary, &primary_hits, n, &scratch, &flags, &secondary)?;
                (&secondary, c, true)
            }
            RayKind::Diffuse => {
                let c =
                    timing.secondary(ctx, &gbvh, Secondary::Diffuse, light, 2, &primary, &primary_hits, n, &scratch, &flags, &secondary)?;
                (&secondary, c, false)
            }
        };
        if count == 0 {
            return Err(BenchError::NoRays(kind.name()));
        }
        // Secondary rays sorted first (timed apart) where asked.
        let sort = sorter.as_ref().filter(|_| kind != RayKind::Primary);
        let rays = if sort.is_some() { &sorted } else { rays };
        let (mut times, mut sort_times) = (Vec::new(), Vec::new());
        // Warm-up: `warmup` runs and, where there are any, at least WARMUP_TIME of them. A GPU
        // left idle (a slow BVH build: quality 5 takes seconds) drops to its idle clock and
        // three runs of a millisecond do not raise it again: the H200 then timed every kind
        // 5.5x slower, and after 0.25 s of runs still some (session 26, docs/traversal.md).
        let warm_start = std::time::Instant::now();
        let mut warm_runs = 0;
        while times.len() < opts.repetitions {
            ctx.submit("bench trace", |rec| {
                rec.reset_timer(&timer);
                rec.timestamp(&timer, 0);
                if let Some(sorter) = sort {
                    sorter.record_kind(rec, opts.sort.expect("a sorter only with a sort"), &secondary, &sorted, &order, count, lo, hi)?;
                }
                rec.timestamp(&timer, 1);
                timing.record_trace(rec, &geometry, rays, &hits, &stats, count, any_hit)?;
                rec.timestamp(&timer, 2);
                Ok(())
            })?;
            if super::warming_up(warm_runs, opts.warmup, warm_start) {
                warm_runs += 1;
            } else {
                sort_times.push(timer.elapsed_ns(0, 1)? * 1e-6);
                times.push(timer.elapsed_ns(1, 2)? * 1e-6);
            }
        }
        // One more pass with counters for node/triangle tests per ray.
        ctx.submit("bench count", |rec| {
            rec.fill_buffer(&stats, 0);
            counting.record_trace(rec, &geometry, rays, &hits, &stats, count, any_hit)
        })?;
        let s: Vec<u32> = ctx.read_buffer(&stats)?;
        let h: Vec<crate::gpu::abi::GpuHit> = ctx.read_buffer(&hits)?;
        let hit_count = h[..count as usize].iter().filter(|x| x.tri != crate::gpu::abi::NO_HIT).count();
        let med = median(&times);
        // Primary rays of edge tiles outside the image (none at 1920x1080) are not counted.
        let real = if kind == RayKind::Primary { pixels } else { count };
        let driver = match &driver {
            Some(d) => Some(d.measure(ctx, rays, count, real, any_hit, &h, &bvh.tri_ids, opts.warmup, opts.repetitions)?),
            None => None,
        };
        results.push(KindResult {
            kind,
            rays: real,
            median_ms: med,
            sort_median_ms: sort.map(|_| median(&sort_times)),
            mrays_per_s: real as f64 / (med * 1e-3) / 1e6,
            times_ms: times,
            nodes_per_ray: s[0] as f64 / real as f64,
            node_bytes_per_ray: s[0] as f64 * opts.build.layout.node_size() as f64 / real as f64,
            tris_per_ray: s[1] as f64 / real as f64,
            hit_fraction: hit_count as f64 / real as f64,
            driver,
        });
    }
    Ok(Report {
        device: ctx.info().name.clone(),
        triangles: triangles.len(),
        // The kernels as they ran: what does not apply to the layout or the launch off.
        trace: TraceOptions {
            persistent: timing.persistent_groups(),
            speculative: trace_opts.speculative && trace_opts.layout != BvhLayout::Cwbvh,
            lockstep: trace_opts.lockstep && trace_opts.speculative && trace_opts.layout != BvhLayout::Cwbvh,
            refill_lanes: if trace_opts.persistent.is_some() { trace_opts.refill_lanes } else { 0 },
            postpone: trace_opts.postpone && trace_opts.layout == BvhLayout::Cwbvh,
            ..trace_opts
        },
        alpha_materials: scene.materials.iter().filter(|m| m.alpha.is_some()).count(),
        sort: opts.sort,
        kernel_stats,
        bvh_build_ms: build_ms,
        bvh_nodes: bvh.node_count(),
        bvh_leaves: bvh.leaves,
        bvh_depth: bvh.depth,
        bvh_bytes: gbvh.bytes,
        bvh_sah: bvh.sah_cost(),
        quality: opts.build.quality,
        ploc: opts.build.ploc,
        any_hit_copy: gbvh.any_hit_copy,
        collapse: (opts.build.layout == BvhLayout::Bvh4).then_some(opts.build.collapse),
        width: camera.size.x,
        height: camera.size.y,
        light,
        results,
        driver_build: driver.as_ref().map(|d| (d.build_ms, d.bytes)),
    })
}

#[cfg(test)]
mod tests {
    use super::hopper_resident_warps;

    #[test]
    fn hopper_occupancy_follows_the_cuda_rules() {
        // docs/results.md: 72 registers leave 28 of 64 warps, 96 registers 21 (here in whole
        // workgroups of two warps: 20).
        assert_eq!(hopper_resident_warps(72, 0, 64, 64), 28);
        assert_eq!(hopper_resident_warps(96, 0, 64, 64), 20);
        assert_eq!(hopper_resident_warps(32, 0, 64, 64), 64);
        // The short stack's 15 KiB per 64 invocations: 14 workgroups of 16 KiB fit 228 KiB.
        assert_eq!(hopper_resident_warps(32, 15 * 1024, 64, 64), 28);
    }
}
