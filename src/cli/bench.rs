//! `bidir bench traversal` and `bidir bench render`.

use super::scene_args::SceneArgs;
use anyhow::Context as _;
use bidir::bench::traversal::{self, RayKind};
use bidir::bvh::TriTest;
use bidir::vk::{Context, ContextOptions};
use std::path::PathBuf;

#[derive(clap::Subcommand, Debug)]
pub enum BenchCommand {
    /// Traversal speed: primary, shadow and diffuse rays, GPU-timed.
    Traversal(Box<TraversalArgs>),
    /// Where a render's GPU time goes: per-kernel GPU timestamps over repeated renders.
    Render(Box<RenderBenchArgs>),
}

#[derive(clap::Args, Debug)]
pub struct RenderBenchArgs {
    #[command(flatten)]
    pub scene: super::scene_args::SceneArgs,
    #[command(flatten)]
    pub integrator: super::settings_args::IntegratorArgs,
    #[command(flatten)]
    pub settings: super::settings_args::SettingsArgs,
    /// Samples per pixel of each run.
    #[arg(long, default_value_t = 256)]
    pub spp: u32,
    /// Untimed runs first; when not 0, they also last at least 1 s, so that a GPU left idle is
    /// back at its clock.
    #[arg(long, default_value_t = 2)]
    pub warmup: usize,
    /// Timed runs (the median is reported).
    #[arg(long, default_value_t = 5)]
    pub runs: usize,
    /// Then render once more (untimed, at most 2^21 samples) with the kernels counting the rays
    /// they trace, their node visits and triangle tests, and print them per sample and at the
    /// timed rate.
    #[arg(long)]
    pub count: bool,
    /// Also run the first-hit pass that writing an EXR adds: `alpha` (the EXR's alpha alone),
    /// or alpha and the AOVs named, as `--aov` takes them (`albedo,normal,depth`).
    #[arg(long, value_name = "alpha|AOVS")]
    pub first_hit: Option<String>,
    /// Write the report as JSON.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

#[derive(clap::Args, Debug)]
pub struct TraversalArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// primary | shadow | diffuse | all
    #[arg(long, default_value = "all")]
    pub rays: String,
    /// Ray-triangle test: watertight | woop.
    #[arg(long, default_value = "watertight")]
    pub tri_test: TriTest,
    /// Timed repetitions (at least 5); the median is reported.
    #[arg(long, default_value_t = 9)]
    pub reps: usize,
    /// Untimed runs of each ray kind before the timed ones; when not 0, they also last at
    /// least 1 s, so that a GPU left idle during the build is back at its clock.
    #[arg(long, default_value_t = 3)]
    pub warmup: usize,
    /// obvhs build quality 0 (fastest) .. 4 (slowest, best); 5: sixteen quality-4 builds with
    /// different PLOC searches, the one of least SAH kept (docs/traversal.md, "The tree lottery").
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u32).range(0..=5))]
    pub quality: u32,
    /// BVH node layout: bvh2 (binary, Aila & Laine) | cwbvh (compressed 8-wide, Ylitie et al.
    /// 2017; leaves of at most 3 triangles) | bvh2q (binary, 32-byte quantised nodes) | bvh4
    /// (the binary tree collapsed to 4-wide nodes of full-precision boxes).
    #[arg(long, default_value = "bvh2")]
    pub bvh: bidir::bvh::BvhLayout,
    /// Most triangles per leaf (1..=16; 1..=3 with --bvh cwbvh) [default: 4; 3 with cwbvh].
    #[arg(long)]
    pub leaf_size: Option<u32>,
    /// Disable spatial pre-splits.
    #[arg(long)]
    pub no_pre_split: bool,
    /// bvh4: shadow rays traverse the closest-hit nodes instead of their own copy with each
    /// node's children in occlusion order (half the node memory).
    #[arg(long)]
    pub no_occlusion_copy: bool,
    /// bvh4: how the binary tree's nodes are grouped into 4-wide ones: greedy (open the largest
    /// child; obvhs' leaves) | sah (least surface area cost, leaves formed from single
    /// triangles; a triangle test and a leaf's visit costing 0.5 node visits each) |
    /// sah:TRI_COST[,LEAF_COST].
    #[arg(long, default_value = "sah")]
    pub collapse: bidir::bvh::Collapse,
    /// PLOC's search distance (1, 2, 6, 14, 24 or 32) and the depth below which it searches one
    /// neighbour, in place of the quality preset's (below quality 5): another of the trees of
    /// nearly equal SAH that trace differently (docs/traversal.md, "The tree lottery").
    #[arg(long, value_name = "DISTANCE,DEPTH")]
    pub ploc: Option<String>,
    /// Honour alpha masks as the integrators do (skip triangles where their alpha texture is
    /// below the cutoff); default: geometry only.
    #[arg(long)]
    pub alpha: bool,
    /// Persistent threads (Aila & Laine 2009): launch only enough workgroups to fill the GPU;
    /// subgroups fetch batches of rays from a global counter.
    #[arg(long)]
    pub persistent: bool,
    /// Workgroups of the persistent kernel (implies --persistent) [default: SMs × resident
    /// warps per SM × 32 / 64 where the driver reports SMs (NVIDIA: 4224 on an H100), else 1024].
    #[arg(long, value_name = "N")]
    pub persistent_groups: Option<u32>,
    /// Binary BVH: plain while-while traversal, each lane testing its leaf at once, instead of
    /// the speculative one (Aila & Laine 2009).
    #[arg(long)]
    pub no_speculative: bool,
    /// Binary and 4-wide BVHs: let each lane leave the traversal's loops on its own, as the
    /// integrators do, instead of running them in lockstep over the subgroup until every lane
    /// is done (the default: its speculative vote is cheaper).
    #[arg(long)]
    pub divergent_loops: bool,
    /// 4-wide BVH, persistent threads (implies --persistent): refill a subgroup's done lanes
    /// with new rays as soon as N of them are done (dynamic fetch) instead of fetching a batch
    /// when all are.
    #[arg(long, value_name = "N")]
    pub refill: Option<u32>,
    /// 4-wide BVH, lockstep loops (one ray per invocation, or --refill): share the leaf phase's
    /// triangle tests among the subgroup's lanes (the lanes without a leaf test the next
    /// triangles of those with one)
    #[arg(long)]
    pub share_leaves: bool,
    /// 4-wide BVH, one ray per invocation: the subgroup's rays traverse as one packet, a node
    /// at a time (glsl/common/traverse_bvh4_packet.glsl; for coherent rays)
    #[arg(long)]
    pub packet: bool,
    /// Compressed wide BVH: postpone triangle tests while few lanes have any (Ylitie et al.
    /// 2017, section 4).
    #[arg(long)]
    pub postpone: bool,
    /// Binary layouts: keep the traversal stack's top four entries in registers and the rest
    /// in workgroup shared memory instead of local memory.
    #[arg(long)]
    pub short_stack: bool,
    /// Take the slab tests' minima and maxima as floats instead of on the distances' bits as
    /// signed integers (the default; the same boxes are hit either way).
    #[arg(long)]
    pub float_slabs: bool,
    /// Rays each invocation traces, strided by the launch size (not with --persistent).
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub rays_per_invocation: u32,
    /// Sort shadow and diffuse rays by direction octant and origin cell (a counting sort on
    /// the GPU) before tracing; the sort's time is reported beside the trace's.
    #[arg(long, conflicts_with = "sort_local")]
    pub sort: bool,
    /// Sort shadow and diffuse rays locally before tracing: blocks of BLOCK consecutive rays
    /// (pixel-tile order, so nearby origins), each by its rays' direction cells on a GRID x
    /// GRID octahedral grid (one pass on the GPU); the sort's time is reported beside the
    /// trace's.
    #[arg(long, value_name = "GRID,BLOCK", value_parser = parse_local_sort)]
    pub sort_local: Option<bidir::trace::sort::SortKind>,
    /// Invocations per workgroup of the trace kernel: 64 (default; every variant), or 32, 128,
    /// 256 (bvh2 without --alpha, --short-stack or --persistent).
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub workgroup_size: u32,
    /// Also trace the same rays through the driver's own ray-tracing pipeline
    /// (VK_KHR_ray_tracing_pipeline, over acceleration structures the driver builds), timed the
    /// same way, its hits compared with bidir's: the yardstick. Geometry only (not with
    /// --alpha); the device must offer the extension (lavapipe does not).
    #[arg(long)]
    pub driver_rt: bool,
    /// Write the report as JSON.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

pub fn run(cmd: &BenchCommand, opts: &ContextOptions) -> anyhow::Result<()> {
    match cmd {
        BenchCommand::Traversal(a) => traversal_cmd(a, opts),
        BenchCommand::Render(a) => render_cmd(a, opts),
    }
}

fn render_cmd(a: &RenderBenchArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    if a.spp == 0 || a.runs == 0 {
        anyhow::bail!("bench render: --spp and --runs must be at least 1 (got --spp {} --runs {})", a.spp, a.runs);
    }
    if let Some(path) = &a.json {
        bidir::imaging::check_writable(path)?;
    }
    let mut settings = a.settings.settings(a.integrator.integrator()?)?;
    settings.first_hit = match a.first_hit.as_deref() {
        None => None,
        Some("alpha") => Some(bidir::imaging::aov::Aovs::default()),
        Some(list) => Some(list.parse().map_err(|e: String| anyhow::anyhow!("--first-hit {list}: {e}"))?),
    };
    super::signals::on_interrupt(super::signals::FirstInterrupt::Abort)?;
    let loaded = a.scene.load()?;
    let ctx = Context::new(opts).context("cannot start Vulkan")?;
    let o = bidir::bench::render::Options { spp: a.spp, warmup: a.warmup, runs: a.runs, count: a.count };
    let report = bidir::bench::render::run(&ctx, &loaded.scene, &loaded.camera, settings, &o)?;
    report.print();
    if let Some(path) = &a.json {
        let json = report.to_json().to_pretty();
        bidir::imaging::write_atomically(path, |tmp| std::fs::write(tmp, json).map_err(|e| e.to_string()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

fn traversal_cmd(a: &TraversalArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    let kinds = match a.rays.as_str() {
        "all" => RayKind::ALL.to_vec(),
        "primary" => vec![RayKind::Primary],
        "shadow" => vec![RayKind::Shadow],
        "diffuse" => vec![RayKind::Diffuse],
        other => anyhow::bail!("--rays {other}: expected primary | shadow | diffuse | all"),
    };
    let (most, default) = if a.bvh == bidir::bvh::BvhLayout::Cwbvh { (3, 3) } else { (16, 4) };
    let leaf_size = a.leaf_size.unwrap_or(default);
    if !(1..=most).contains(&leaf_size) {
        anyhow::bail!("--leaf-size {leaf_size}: must be in 1..={most} (with --bvh {})", a.bvh.name());
    }
    if a.short_stack && (a.alpha || !matches!(a.bvh, bidir::bvh::BvhLayout::Bvh2 | bidir::bvh::BvhLayout::Bvh2q)) {
        anyhow::bail!("--short-stack: only with the binary layouts (--bvh bvh2 | bvh2q) and without --alpha");
    }
    if !(1..=64).contains(&a.rays_per_invocation) || (a.rays_per_invocation > 1 && (a.persistent || a.persistent_groups.is_some())) {
        anyhow::bail!("--rays-per-invocation {}: must be in 1..=64, and 1 with --persistent", a.rays_per_invocation);
    }
    if a.workgroup_size != 64
        && (![32, 128, 256].contains(&a.workgroup_size)
            || a.bvh != bidir::bvh::BvhLayout::Bvh2
            || a.alpha
            || a.short_stack
            || a.persistent
            || a.persistent_groups.is_some())
    {
        anyhow::bail!("--workgroup-size {}: 64 with every variant; 32, 128 or 256 only with --bvh bvh2 and without --alpha, --short-stack, --persistent", a.workgroup_size);
    }
    if a.driver_rt && a.alpha {
        anyhow::bail!("--driver-rt traces the geometry alone: leave out --alpha");
    }
    let ploc = a.ploc.as_deref().map(parse_ploc).transpose()?;
    if ploc.is_some() && a.quality >= bidir::bvh::BEST_OF_QUALITY {
        anyhow::bail!("--ploc sets the search of one tree; quality {} builds its own candidates: leave out one of them", a.quality);
    }
    let mut o = traversal::Options { kinds, warmup: a.warmup, repetitions: a.reps.max(5), ..Default::default() };
    o.build.tri_test = a.tri_test;
    o.build.quality = a.quality;
    o.build.max_leaf_tris = leaf_size;
    o.build.pre_split = !a.no_pre_split;
    o.build.occlusion_copy = !a.no_occlusion_copy;
    o.build.collapse = a.collapse;
    o.build.layout = a.bvh;
    o.build.ploc = ploc;
    o.alpha = a.alpha;
    o.sort = if a.sort { Some(bidir::trace::sort::SortKind::Cells) } else { a.sort_local };
    o.driver_rt = a.driver_rt;
    let t = &mut o.trace;
    t.speculative = !a.no_speculative;
    t.lockstep = !a.divergent_loops;
    t.postpone = a.postpone;
    t.short_stack = a.short_stack;
    t.int_slabs = !a.float_slabs;
    t.rays_per_invocation = a.rays_per_invocation;
    t.workgroup_size = a.workgroup_size;
    t.persistent = match (a.persistent || a.refill.is_some(), a.persistent_groups) {
        (_, Some(0)) => anyhow::bail!("--persistent-groups must be at least 1"),
        (_, Some(n)) => Some(n),
        (true, None) => Some(0),
        (false, None) => None,
    };
    if let Some(n) = a.refill {
        if !(1..=128).contains(&n) || a.bvh != bidir::bvh::BvhLayout::Bvh4 || a.no_speculative || a.divergent_loops {
            anyhow::bail!("--refill {n}: 1 to 128 lanes, with --bvh bvh4 and its speculative lockstep loops (not --no-speculative or --divergent-loops)");
        }
        t.refill_lanes = n;
    }
    if a.share_leaves
        && (a.bvh != bidir::bvh::BvhLayout::Bvh4
            || a.no_speculative
            || a.divergent_loops
            || a.alpha
            || ((a.persistent || a.persistent_groups.is_some()) && a.refill.is_none()))
    {
        anyhow::bail!("--share-leaves: with --bvh bvh4 and its speculative lockstep loops, one ray per invocation or --refill N (not --persistent alone, --alpha, --no-speculative or --divergent-loops)");
    }
    t.share_leaves = a.share_leaves;
    if a.packet
        && (a.bvh != bidir::bvh::BvhLayout::Bvh4
            || a.no_speculative
            || a.divergent_loops
            || a.alpha
            || a.share_leaves
            || a.persistent
            || a.persistent_groups.is_some()
            || a.refill.is_some())
    {
        anyhow::bail!("--packet: with --bvh bvh4, one ray per invocation (not --persistent, --refill, --alpha, --share-leaves, --no-speculative or --divergent-loops)");
    }
    t.packet = a.packet;
    if let Some(path) = &a.json {
        bidir::imaging::check_writable(path)?;
    }
    super::signals::on_interrupt(super::signals::FirstInterrupt::Abort)?;
    let loaded = a.scene.load()?;
    // The driver's registers, spills and shared memory of the timed kernels, where it reports
    // them (printed with the timings).
    let opts = ContextOptions { kernel_statistics: true, ray_tracing: a.driver_rt, ..opts.clone() };
    let ctx = Context::new(&opts).context("cannot start Vulkan")?;
    let cam = bidir::gpu_data::gpu_camera(&loaded.camera);
    let report = traversal::run(&ctx, &loaded.scene, &cam, &o)?;
    report.print();
    if let Some(path) = &a.json {
        let json = report.to_json().to_pretty();
        bidir::imaging::write_atomically(path, |tmp| std::fs::write(tmp, json).map_err(|e| e.to_string()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// `--sort-local GRID,BLOCK`.
fn parse_local_sort(v: &str) -> Result<bidir::trace::sort::SortKind, String> {
    let (g, b) = v.split_once(',').ok_or_else(|| format!("`{v}`: expected GRID,BLOCK, e.g. 4,1024"))?;
    let num = |x: &str| x.trim().parse::<u32>().map_err(|e| format!("`{x}` in `{v}`: {e}"));
    bidir::trace::sort::SortKind::local(num(g)?, num(b)?)
}

/// `--ploc DISTANCE,DEPTH`.
fn parse_ploc(s: &str) -> anyhow::Result<(u32, usize)> {
    let parsed = s.split_once(',').and_then(|(d, k)| Some((d.trim().parse::<u32>().ok()?, k.trim().parse::<usize>().ok()?)));
    match parsed {
        Some((d, k)) if bidir::bvh::PLOC_DISTANCES.contains(&d) && k <= 64 => Ok((d, k)),
        _ => anyhow::bail!("--ploc {s}: expected DISTANCE,DEPTH with DISTANCE one of 1, 2, 6, 14, 24, 32 and DEPTH at most 64"),
    }
}
