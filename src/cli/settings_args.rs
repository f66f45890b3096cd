//! The render settings that `render`, `view` and `converge` share (one definition of each
//! flag, applied to [`RenderSettings`] in one place).

use anyhow::bail;
use bidir::bvh::TriTest;
use bidir::gpu::abi;
use bidir::render::{Integrator, Join, RenderSettings, Sampler, MAX_CONNECTION_CANDIDATES};

/// Which integrator, for the commands that render with one.
#[derive(clap::Args, Debug)]
pub struct IntegratorArgs {
    /// pt | pt-nee | bdpt (= bdpt:lvc=1) | bdpt:full | bdpt:single | bdpt:k=N | bdpt:lvc | bdpt:lvc=N
    /// | vcm (vertex connection and merging; merging at the first continuous camera vertex) |
    /// vcm:merge-all (merging at every one)
    #[arg(long, default_value = "pt-nee")]
    pub integrator: Integrator,
    /// BDPT join (overrides the one in --integrator): full | single | k=N | lvc | lvc=N.
    #[arg(long)]
    pub join: Option<Join>,
    /// VCM without vertex merging (its connections alone: equals bdpt:lvc).
    #[arg(long)]
    pub no_merge: bool,
    /// VCM without vertex connection: progressive photon mapping (merging alone, unweighted).
    #[arg(long, conflicts_with = "no_merge")]
    pub no_connect: bool,
}

impl IntegratorArgs {
    /// The integrator with `--join` applied.
    pub fn integrator(&self) -> anyhow::Result<Integrator> {
        let integrator = match (self.join, self.integrator) {
            (Some(j), Integrator::Bdpt(_)) => Integrator::Bdpt(j),
            (Some(_), _) => bail!("--join applies to --integrator bdpt only"),
            (None, i) => i,
        };
        match (integrator, self.no_merge || self.no_connect) {
            (Integrator::Vcm(mut m), true) => {
                m.merge &= !self.no_merge;
                m.connect &= !self.no_connect;
                Ok(Integrator::Vcm(m))
            }
            (_, true) => bail!("--no-merge and --no-connect apply to --integrator vcm only"),
            (i, false) => Ok(i),
        }
    }
}

/// How to render, whatever the integrator.
#[derive(clap::Args, Debug)]
pub struct SettingsArgs {
    #[arg(long, default_value_t = 0)]
    pub seed: u32,
    /// Random numbers: sobol (Owen-scrambled Sobol' for the pixel and the path's first vertex,
    /// a group of four dimensions for each sampling decision; hashed after) | sobol:N (the
    /// first N dimensions) | sobol:all | independent.
    #[arg(long, default_value = "sobol")]
    pub sampler: Sampler,
    /// Most path segments (0: unbounded; Russian roulette ends paths).
    #[arg(long, default_value_t = 0)]
    pub max_depth: u32,
    /// First bounce at which Russian roulette may end a path (1 = from the first hit; default
    /// 5 for pt and pt-nee, 3 for bdpt).
    #[arg(long, value_name = "N")]
    pub rr_depth: Option<u32>,
    /// BDPT: light vertices kept per light path (a reservoir over the whole path).
    #[arg(long, default_value_t = 8)]
    pub light_path_len: u32,
    /// BDPT with the light vertex cache: light paths per iteration as a multiple of the pixel
    /// count (more help caustics and light tracing, fewer save time where light paths
    /// rarely matter). The other joins pair one light path with each pixel. Default: 0.4 for
    /// bdpt in scenes with only diffuse surfaces (with its 8 connection candidates), 1
    /// otherwise (docs/results.md, "0.4 light paths per pixel")
    #[arg(long, value_name = "RATIO")]
    pub light_paths: Option<f32>,
    /// Samples of a pixel rendered at once, each by its own GPU thread (0: enough to fill
    /// the GPU, 1 on CPU devices).
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub sample_slices: u32,
    /// Ray-triangle test: watertight | woop.
    #[arg(long, default_value = "watertight")]
    pub tri_test: TriTest,
    /// BVH layout the integrators traverse: auto (the faster one for the device, integrator
    /// and scene: cwbvh on CPU devices such as lavapipe, on GPUs for pt in scenes with only
    /// diffuse surfaces, for pt-nee in scenes without mirrors or glass and for BDPT and VCM
    /// unless --shadow-queue off; bvh2 otherwise) |
    /// bvh2 | cwbvh | bvh4 (4-wide, full-precision boxes).
    #[arg(long, default_value = "auto", value_name = "auto|bvh2|cwbvh|bvh4")]
    pub bvh: String,
    /// BVH build quality, obvhs's preset 0 (fastest build) .. 4 (slowest build, fewest nodes
    /// visited per ray) [default: 4 for bvh4 and, up to 2^20 triangles, for bvh2 and cwbvh; 2
    /// otherwise]; 5 builds sixteen quality-4 trees and keeps the one of least SAH
    /// (sixteen times the build time); the image is the same.
    #[arg(long, value_name = "0..5", value_parser = clap::value_parser!(u32).range(0..=5))]
    pub bvh_quality: Option<u32>,
    /// Most triangles in a BVH leaf (the compressed wide BVH takes at most 3) [default: 3 for
    /// bvh4, 4 otherwise]; the image is the same.
    #[arg(long, value_name = "1..16", value_parser = clap::value_parser!(u32).range(1..=16))]
    pub bvh_leaf_size: Option<u32>,
    /// bvh4: shadow rays traverse the closest-hit nodes instead of their own copy with each
    /// node's children in occlusion order (half the node memory); the image is the same.
    #[arg(long)]
    pub bvh_no_occlusion_copy: bool,
    /// bvh4: how the binary tree's nodes are grouped into 4-wide ones: greedy | sah |
    /// sah:TRI_COST[,LEAF_COST] (`bench traversal --collapse`); the image is the same.
    #[arg(long, value_name = "greedy|sah[:TRI_COST[,LEAF_COST]]", default_value = "sah")]
    pub bvh_collapse: bidir::bvh::Collapse,
    /// Compile the mirror/glass/texture/alpha code in even where the scene has none (measures
    /// what kernel specialisation buys).
    #[arg(long)]
    pub all_features: bool,
    /// pt and pt-nee: start a thread's next sample where its path ends (on), or run a loop of
    /// samples around a loop of bounces (off); the image is the same. auto: on, except on GPUs
    /// for scenes with smooth mirrors or glass (the faster there, measured on the H200).
    #[arg(long, default_value = "auto", value_name = "auto|on|off")]
    pub path_regeneration: String,
    /// pt-nee: trace each light sample's shadow ray in the next step, through the same trace
    /// call as the path's extension rays (on), or where it is drawn (off); the image is the
    /// same. auto: on GPUs, except over the compressed wide BVH in scenes with only diffuse
    /// surfaces (the faster, measured on the H200); off on CPU devices such as lavapipe.
    #[arg(long, default_value = "auto", value_name = "auto|on|off")]
    pub one_trace: String,
    /// pt and pt-nee: the wavefront path tracer (on), whose path kernel leaves each bounce's
    /// segment and shadow ray to the trace kernels (on GPUs over the 4-wide BVH, with their
    /// lockstep loops and dynamic fetch), or the megakernel that traces them itself (off); bdpt
    /// (the light vertex cache with 1 to 3 connections: bdpt, bdpt:lvc=N): its light and camera
    /// passes so.
    /// The image is the same up to the order of float sums. auto: on GPUs where it was measured
    /// faster (`render::default_wavefront`), off on CPU devices such as lavapipe.
    #[arg(long, default_value = "auto", value_name = "auto|on|off")]
    pub wavefront: String,
    /// The wavefront forms (bdpt's passes, pt's and pt-nee's): after N launches (an even
    /// count), or (auto) after as many as the last pass took to leave fewer paths live than a
    /// quarter of what the trace kernels run at once, one launch runs every path still live to
    /// its end (pt and pt-nee: every slot's remaining samples), tracing its own rays, instead
    /// of a launch per bounce down the pass's long tail; off: launches until one queues no ray.
    /// The image is the same up to the order of float sums.
    #[arg(long, default_value = "auto", value_name = "auto|off|N")]
    pub wavefront_finish: String,
    /// BDPT's wavefront passes (with their finishing launch): the camera pass's last N launches
    /// run beside the next iteration's light pass, and its first beside that light pass's tail,
    /// so that neither pass's tail leaves the GPU idle (a second light-vertex store; off where
    /// that does not fit); off: each pass runs alone. The image is the same up to the order of
    /// float sums. auto: 4 (the fastest of 2 to 12 on an H100's Cornell box, session 57).
    #[arg(long, default_value = "auto", value_name = "auto|off|N")]
    pub wavefront_overlap: String,
    /// Queue the shadow rays of pt-nee's kernel and of BDPT's (or VCM's) camera and light
    /// kernels for a kernel of their own that traces them after it, SLOTS per thread; pt-nee
    /// launches its kernel once per SAMPLES samples per thread (default SLOTS / 8). A thread
    /// whose slots are full traces the ray itself, or (pt-nee) with /pause stops its path until
    /// the next launch. The image is the same up to the order of float sums. auto: on GPUs, for
    /// pt-nee where the scene has no mirror or glass (192/24, with /pause where it has glossy
    /// surfaces), for BDPT and VCM 64 slots; off on CPU devices.
    #[arg(long, default_value = "auto", value_name = "auto|off|SLOTS[/SAMPLES][/pause]")]
    pub shadow_queue: String,
    /// BDPT and VCM: keep light tracing as a strategy for direct lighting (light -> surface -> eye).
    /// Off by default: the camera path's light samples and emitter hits, stratified per pixel,
    /// sample it with less noise and no shadow ray per light path's first vertex. Either is
    /// unbiased.
    #[arg(long)]
    pub direct_light_tracing: bool,
    /// BDPT and VCM: how their strategies are weighed (multiple importance sampling): auto |
    /// balance | power (the power heuristic, exponent 2). auto: balance for bdpt in scenes with
    /// only diffuse surfaces, power otherwise (measured: docs/results.md, "BDPT's MIS
    /// heuristic"). Either is unbiased [default: auto]
    #[arg(long, default_value = "auto", value_name = "auto|balance|power")]
    pub mis: String,
    /// BDPT and VCM with the light vertex cache (bdpt, bdpt:lvc=N, vcm): draw each connection's
    /// light vertex from N uniform candidates by resampling, in proportion to what each would
    /// carry if nothing blocked it; one shadow ray per connection either way. 1 draws it
    /// uniformly. The candidates are drawn for a block of 16 x 8 pixels at once and the GPU
    /// subgroup's lanes share their reads where they can, so each costs mostly arithmetic: on an NVIDIA H200, 8
    /// candidates took a Cornell box sample 8 % more time (session 38's form, which took them
    /// from the lanes), for 27 % less variance per sample off the light's edge. Which lanes
    /// connect together changes nothing: parts of a render merge exactly. Default: 8 for bdpt in scenes with only diffuse
    /// surfaces, 1 otherwise (glossy and glass scenes measured level or worse; docs/results.md,
    /// "Candidates shared within the subgroup"). Any N is unbiased
    #[arg(long, value_name = "N")]
    pub connection_candidates: Option<u32>,
    /// VCM: the first iteration's merge radius, a fraction of the scene's bounding-box
    /// diagonal (0.001), or a length in scene units with the suffix u (0.02u).
    #[arg(long, default_value = "0.001", value_name = "R")]
    pub vcm_radius: bidir::render::vcm::VcmRadius,
    /// VCM: radius reduction, r_i = r_1 i^((alpha - 1) / 2) at iteration i (1: fixed radius).
    #[arg(long, default_value_t = 0.75, value_name = "ALPHA")]
    pub vcm_alpha: f32,
}

impl SettingsArgs {
    /// Settings for `integrator` with these flags applied.
    pub fn settings(&self, integrator: Integrator) -> anyhow::Result<RenderSettings> {
        if let Some(ratio) = self.light_paths {
            if !(ratio > 0.0 && ratio.is_finite()) {
                bail!("--light-paths must be a positive multiple of the pixel count");
            }
        }
        let mut s = RenderSettings::new(integrator);
        s.seed = self.seed;
        s.sampler = self.sampler;
        s.max_depth = self.max_depth;
        if let Some(rr) = self.rr_depth {
            if rr == 0 {
                bail!("--rr-depth must be at least 1 (the bounce at which Russian roulette may start)");
            }
            s.rr_depth = rr;
        }
        if self.light_path_len == 0 {
            bail!("--light-path-len must be at least 1 (the light vertices a BDPT light path keeps)");
        }
        s.light_path_len = self.light_path_len;
        s.light_path_ratio = self.light_paths;
        s.sample_slices = self.sample_slices;
        s.bvh.tri_test = self.tri_test;
        s.bvh_quality = self.bvh_quality;
        s.bvh_leaf_size = self.bvh_leaf_size;
        s.bvh.occlusion_copy = !self.bvh_no_occlusion_copy;
        s.bvh.collapse = self.bvh_collapse;
        s.bvh_layout = match self.bvh.as_str() {
            "auto" => None,
            "bvh2" => Some(bidir::bvh::BvhLayout::Bvh2),
            "cwbvh" => Some(bidir::bvh::BvhLayout::Cwbvh),
            "bvh4" => Some(bidir::bvh::BvhLayout::Bvh4),
            other => bail!("--bvh {other}: the integrators traverse auto | bvh2 | cwbvh | bvh4 (bvh2q is for `bidir bench traversal`)"),
        };
        s.all_material_code = self.all_features;
        s.path_regeneration = match self.path_regeneration.as_str() {
            "auto" => None,
            "on" => Some(true),
            "off" => Some(false),
            other => bail!("--path-regeneration {other}: auto | on | off"),
        };
        s.one_trace = match self.one_trace.as_str() {
            "auto" => None,
            "on" => Some(true),
            "off" => Some(false),
            other => bail!("--one-trace {other}: auto | on | off"),
        };
        s.shadow_queue = parse_shadow_queue(&self.shadow_queue)?;
        s.wavefront = match self.wavefront.as_str() {
            "auto" => None,
            "on" => Some(true),
            "off" => Some(false),
            other => bail!("--wavefront {other}: auto | on | off"),
        };
        s.wavefront_finish = self.wavefront_finish.parse().map_err(anyhow::Error::msg)?;
        s.wavefront_overlap = match self.wavefront_overlap.as_str() {
            "off" => None,
            "auto" => Some(bidir::render::DEFAULT_WAVEFRONT_OVERLAP),
            n => match n.parse::<u32>() {
                Ok(n) if (1..abi::WF_MAX_BATCH).contains(&n) => Some(n),
                _ => bail!("--wavefront-overlap {n}: auto | off | a count of launches from 1 to {}", abi::WF_MAX_BATCH - 1),
            },
        };
        s.direct_light_tracing = self.direct_light_tracing;
        s.mis = match self.mis.as_str() {
            "auto" => None,
            other => Some(other.parse().map_err(|_| anyhow::anyhow!("--mis {other}: auto | balance | power"))?),
        };
        if let Some(n) = self.connection_candidates {
            if !(1..=MAX_CONNECTION_CANDIDATES).contains(&n) {
                bail!("--connection-candidates {n}: a whole number from 1 to {MAX_CONNECTION_CANDIDATES}");
            }
        }
        s.connection_candidates = self.connection_candidates;
        if self.connection_candidates.is_some_and(|n| n > 1) && !matches!(integrator, Integrator::Bdpt(Join::Lvc(_)) | Integrator::Vcm(_)) {
            bail!(
                "--connection-candidates resamples the light vertex cache's connections (bdpt, bdpt:lvc=N, vcm), not {}'s",
                integrator.name()
            );
        }
        s.vcm_radius = self.vcm_radius;
        s.vcm_alpha = bidir::render::vcm::check_alpha(self.vcm_alpha).map_err(anyhow::Error::msg)?;
        Ok(s)
    }
}

/// `--shadow-queue auto|off|SLOTS[/SAMPLES][/pause]`.
pub(crate) fn parse_shadow_queue(v: &str) -> anyhow::Result<Option<Option<bidir::render::ShadowQueue>>> {
    let bad = || {
        anyhow::anyhow!(
            "--shadow-queue {v}: auto | off | SLOTS[/SAMPLES][/pause] (queue slots per thread, samples per thread in a launch, \
             paths pause where the slots are full; e.g. 128/16/pause)"
        )
    };
    Ok(match v {
        "auto" => None,
        "off" => Some(None),
        _ => {
            let (v, pause) = match v.strip_suffix("/pause") {
                Some(rest) => (rest, true),
                None => (v, false),
            };
            let (slots, samples) = match v.split_once('/') {
                Some((a, b)) => (a.parse::<u32>().map_err(|_| bad())?, Some(b.parse::<u32>().map_err(|_| bad())?)),
                None => (v.parse::<u32>().map_err(|_| bad())?, None),
            };
            let chunk_samples = samples.unwrap_or((slots / 8).max(1));
            if slots == 0 || chunk_samples == 0 {
                return Err(bad());
            }
            Some(Some(bidir::render::ShadowQueue { slots, chunk_samples, pause }))
        }
    })
}
