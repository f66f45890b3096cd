//! Where a render's GPU time goes: `bidir bench render` renders the same samples several
//! times with per-kernel GPU timestamps (`vk::Context::set_profiling`) after a warm-up, and
//! reports each kernel's median time per run, its share, and the samples per second of GPU
//! time.

use super::json::Json;
use crate::bvh::BuildOptions;
use crate::render::{RenderError, RenderSettings, Renderer};
use crate::scene::{Camera, Scene};
use crate::vk::Context;
use std::time::Instant;

/// How much to render.
#[derive(Clone, Debug)]
pub struct Options {
    /// Samples per pixel of each timed run.
    pub spp: u32,
    /// Runs before the timed ones (pipelines, caches, the pass model settle).
    pub warmup: usize,
    /// Timed runs; medians are reported.
    pub runs: usize,
    /// Render once more with the kernels counting rays, node visits and triangle tests
    /// (`RenderSettings::count_traversal`; not timed).
    pub count: bool,
}

/// What the integrator kernels traced in the counting render.
#[derive(Clone, Copy, Debug)]
pub struct TraversalCounts {
    /// Samples (pixels x spp) of the counting render.
    pub samples: u64,
    pub rays: u64,
    pub nodes: u64,
    pub tris: u64,
}

/// Most samples a counting render takes (it is untimed, and slower than a plain one).
const COUNT_SAMPLES: u64 = 1 << 21;

/// One kernel's share of a run.
#[derive(Clone, Debug)]
pub struct KernelRow {
    pub name: String,
    /// Median over runs of its GPU milliseconds per run.
    pub ms: f64,
    /// Dispatches per run (the last run's).
    pub dispatches: u64,
}

/// The benchmark's result.
#[derive(Clone, Debug)]
pub struct Report {
    pub device: String,
    pub integrator: String,
    /// The BVH layout and, for pt/pt-nee, path regeneration (`render::kernel_form`).
    pub kernel_form: String,
    pub pixels: u64,
    pub spp: u32,
    /// Median GPU milliseconds of a run (the sum of its dispatches' times).
    pub gpu_ms: f64,
    /// Median wall-clock milliseconds of a run (host work between passes included).
    pub wall_ms: f64,
    pub kernels: Vec<KernelRow>,
    /// Dispatches not timed (more than a submission's timestamps).
    pub untimed: u64,
    pub counts: Option<TraversalCounts>,
    /// Wall-clock milliseconds of the renderer's setup (`Renderer::new`: the BVH, the
    /// scene's buffers and the kernels' pipelines), before the first sample.
    pub setup_ms: f64,
    /// The renderer's kernels and how long the driver took to build each pipeline, in
    /// milliseconds (`vk::Kernel::build_time`), the slowest first.
    pub pipelines: Vec<(String, f64)>,
    /// The BVH the integrator traverses: its build options as resolved (the layout, obvhs'
    /// quality preset, the most triangles a leaf).
    pub bvh: BuildOptions,
}

impl Report {
    /// Samples (pixels x spp) per second of GPU time, in millions.
    pub fn msamples_per_s(&self) -> f64 {
        self.pixels as f64 * self.spp as f64 / (self.gpu_ms * 1e-3) / 1e6
    }

    pub fn print(&self) {
        println!(
            "{} ({}) on {}: {} pixels x {} spp; GPU {:.2} ms ({:.4} Msamples/s), wall {:.2} ms (median of runs)",
            self.integrator,
            self.kernel_form,
            self.device,
            self.pixels,
            self.spp,
            self.gpu_ms,
            self.msamples_per_s(),
            self.wall_ms
        );
        let builds: Vec<String> = self.pipelines.iter().map(|(name, ms)| format!("{name} {ms:.1}")).collect();
        println!(
            "setup {:.1} ms ({} at build quality {}, leaf size {}); the integrator kernels' pipelines built in, ms: {}",
            self.setup_ms,
            self.bvh.layout.name(),
            self.bvh.quality,
            self.bvh.max_leaf_tris,
            builds.join(", ")
        );
        let per_sample_ns = |ms: f64| ms * 1e6 / (self.pixels as f64 * self.spp as f64);
        println!("{:<22} {:>10} {:>7} {:>12} {:>10}", "kernel", "ms/run", "share", "ns/sample", "dispatches");
        for k in &self.kernels {
            println!(
                "{:<22} {:>10.3} {:>6.1}% {:>12.3} {:>10}",
                k.name,
                k.ms,
                100.0 * k.ms / self.gpu_ms.max(1e-12),
                per_sample_ns(k.ms),
                k.dispatches
            );
        }
        if self.untimed > 0 {
            println!("({} dispatches were not timed: a submission held more than the profiler's timestamps)", self.untimed);
        }
        if let Some(c) = self.counts {
            let per_sample = c.rays as f64 / c.samples as f64;
            let samples_per_s = self.msamples_per_s() * 1e6;
            println!(
                "traversal ({} samples counted): {:.2} rays/sample, {:.1} nodes/ray, {:.1} triangles/ray; at the timed rate {:.3} Grays/s, {:.1} G node visits/s",
                c.samples,
                per_sample,
                c.nodes as f64 / c.rays.max(1) as f64,
                c.tris as f64 / c.rays.max(1) as f64,
                per_sample * samples_per_s / 1e9,
                c.nodes as f64 / c.samples as f64 * samples_per_s / 1e9
            );
        }
    }

    pub fn to_json(&self) -> Json {
        Json::obj(vec![
            ("device", Json::Str(self.device.clone())),
            ("integrator", Json::Str(self.integrator.clone())),
            ("kernel_form", Json::Str(self.kernel_form.clone())),
            ("pixels", Json::Int(self.pixels as i64)),
            ("spp", Json::Int(self.spp as i64)),
            ("gpu_ms", Json::Num(self.gpu_ms)),
            ("wall_ms", Json::Num(self.wall_ms)),
            ("msamples_per_s", Json::Num(self.msamples_per_s())),
            ("setup_ms", Json::Num(self.setup_ms)),
            (
                "bvh",
                Json::obj(vec![
                    ("layout", Json::Str(self.bvh.layout.name().to_owned())),
                    ("quality", Json::Int(self.bvh.quality as i64)),
                    ("max_leaf_tris", Json::Int(self.bvh.max_leaf_tris as i64)),
                ]),
            ),
            (
                "pipelines",
                Json::Arr(
                    self.pipelines
                        .iter()
                        .map(|(name, ms)| Json::obj(vec![("name", Json::Str(name.clone())), ("build_ms", Json::Num(*ms))]))
                        .collect(),
                ),
            ),
            (
                "traversal_counts",
                match self.counts {
                    None => Json::Null,
                    Some(c) => Json::obj(vec![
                        ("samples", Json::Int(c.samples as i64)),
                        ("rays", Json::Int(c.rays as i64)),
                        ("nodes", Json::Int(c.nodes as i64)),
                        ("tris", Json::Int(c.tris as i64)),
                    ]),
                },
            ),
            (
                "kernels",
                Json::Arr(
                    self.kernels
                        .iter()
                        .map(|k| {
                            Json::obj(vec![
                                ("name", Json::Str(k.name.clone())),
                                ("ms", Json::Num(k.ms)),
                                ("dispatches", Json::Int(k.dispatches as i64)),
                            ])
                        })
                        .collect(),
                ),
            ),
        ])
    }
}

/// Renders `o.spp` samples per pixel with `settings`: `o.warmup` untimed runs (and more until
/// they have taken WARMUP_TIME, where `o.warmup` > 0), then `o.runs` timed ones, and reports
/// the timed runs' medians. Leaves profiling off.
pub fn run(ctx: &Context, scene: &Scene, camera: &Camera, settings: RenderSettings, o: &Options) -> Result<Report, RenderError> {
    let integrator = settings.integrator.name();
    let count_settings = RenderSettings { count_traversal: true, ..settings.clone() };
    let t_setup = Instant::now();
    let mut r = Renderer::new(ctx, scene, camera, settings)?;
    let setup_ms = t_setup.elapsed().as_secs_f64() * 1e3;
    let mut pipelines: Vec<(String, f64)> = r.kernels().iter().map(|k| (k.name().to_owned(), k.build_time().as_secs_f64() * 1e3)).collect();
    pipelines.sort_by(|a, b| b.1.total_cmp(&a.1));
    let kernel_form = r.kernel_form();
    let bvh = r.settings().bvh;
    let spp = o.spp.max(1);
    let warm_start = Instant::now();
    let mut warm_runs = 0;
    while super::warming_up(warm_runs, o.warmup, warm_start) {
        r.reset(None)?;
        r.render_spp(spp, |_| {})?;
        warm_runs += 1;
    }
    let mut per_kernel: std::collections::BTreeMap<String, (Vec<f64>, u64)> = Default::default();
    let (mut gpu, mut wall, mut untimed) = (Vec::new(), Vec::new(), 0);
    let runs = o.runs.max(1);
    let result = (|| {
        for run in 0..runs {
            r.reset(None)?;
            ctx.set_profiling(true)?;
            let start = Instant::now();
            r.render_spp(spp, |_| {})?;
            wall.push(start.elapsed().as_secs_f64() * 1e3);
            let (times, n) = ctx.take_profile();
            untimed += n;
            gpu.push(times.iter().map(|k| k.ns).sum::<f64>() * 1e-6);
            for k in times {
                let e = per_kernel.entry(k.name).or_insert_with(|| (vec![0.0; runs], 0));
                e.0[run] = k.ns * 1e-6;
                e.1 = k.dispatches;
            }
        }
        Ok::<(), RenderError>(())
    })();
    ctx.set_profiling(false)?;
    result?;
    let mut kernels: Vec<KernelRow> =
        per_kernel.into_iter().map(|(name, (ms, dispatches))| KernelRow { name, ms: super::median(&ms), dispatches }).collect();
    kernels.sort_by(|a, b| b.ms.total_cmp(&a.ms));
    let pixels = camera.width as u64 * camera.height as u64;
    let counts = if o.count {
        drop(r);
        let mut c = Renderer::new(ctx, scene, camera, count_settings)?;
        let count_spp = (COUNT_SAMPLES / pixels.max(1)).clamp(1, spp as u64) as u32;
        // One sample per pixel at a time, the 32-bit counters read after each: their
        // increments stay exact (wrapping differences) unless one pass visits 2^32 nodes.
        let (mut totals, mut last) = ([0u64; 3], [0u32; 3]);
        for total_spp in 1..=count_spp {
            c.render_spp(total_spp, |_| {})?;
            let now = c.traversal_counts()?;
            for k in 0..3 {
                totals[k] += now[k].wrapping_sub(last[k]) as u64;
            }
            last = now;
        }
        let [rays, nodes, tris] = totals;
        Some(TraversalCounts { samples: pixels * count_spp as u64, rays, nodes, tris })
    } else {
        None
    };
    Ok(Report {
        device: ctx.info().name.clone(),
        integrator,
        kernel_form,
        pixels,
        spp,
        gpu_ms: super::median(&gpu),
        wall_ms: super::median(&wall),
        kernels,
        untimed,
        counts,
        setup_ms,
        pipelines,
        bvh,
    })
}
