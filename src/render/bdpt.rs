use super::bdpt_wavefront::{Batch, Pass, Run, WavefrontPasses};
use super::integrator::{IntegratorKernels, PassInputs};
use super::{film::Film, gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::BdptPush, abi::LightVertex, kernels};
use crate::vk::{Bind, Buffer, Context, InFlight, Kernel, Memory, Recorder, Result, Spec, VkError};

/// How camera vertices are joined to the light subpath.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Join {
    /// Every stored light vertex.
    Full,
    /// `k` stored light vertices chosen uniformly (with replacement) per camera vertex.
    K(u32),
    /// The light vertex cache of Davidovič et al. 2014: `k` vertices drawn uniformly from the
    /// vertices of every light path of the iteration (0: as many as a light path stores on
    /// average, so the work matches the full join's but is the same for every thread).
    Lvc(u32),
}

impl Join {
    /// `--integrator bdpt` and VCM's connections: the light vertex cache with one connection
    /// per camera vertex. Against as many as a light path stores (`lvc`, about 2 on the
    /// Cornell box), measured at equal time on the H200 (docs/results.md, "Connections per
    /// camera vertex"): Cornell box MSE -20 %, caustic scene within 1 %, and on lavapipe 4 %
    /// more variance per sample where the light hides behind a panel for 11 % less time.
    pub const DEFAULT: Join = Join::Lvc(1);

    /// The name `from_str` reads back (k = 1 is `single`).
    pub fn name(self) -> String {
        match self {
            Join::Full => "full".into(),
            Join::K(1) => "single".into(),
            Join::K(k) => format!("k={k}"),
            Join::Lvc(0) => "lvc".into(),
            Join::Lvc(k) => format!("lvc={k}"),
        }
    }
}

impl std::str::FromStr for Join {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "full" => Ok(Join::Full),
            "single" => Ok(Join::K(1)),
            "lvc" => Ok(Join::Lvc(0)),
            _ => match (s.strip_prefix("k=").map(str::parse::<u32>), s.strip_prefix("lvc=").map(str::parse::<u32>)) {
                (Some(Ok(k)), _) if k >= 1 => Ok(Join::K(k)),
                (_, Some(Ok(k))) if k >= 1 => Ok(Join::Lvc(k)),
                _ => Err(format!("unknown join '{s}' (full | single | k=N | lvc | lvc=N, with N >= 1)")),
            },
        }
    }
}

/// Light paths per camera sample for a film of `pixels` pixels (`--light-paths RATIO`).
fn light_paths_per_sample(pixels: u32, ratio: f32) -> u32 {
    ((pixels as f64 * ratio as f64).round() as u64).clamp(1, u32::MAX as u64 / 2) as u32
}

/// Bytes of the light-vertex store per camera sample of a film of `pixels` pixels: its light
/// paths times `light_path_len` vertices of `light_vertex_words` words. The one count behind
/// the store `Bdpt::new` allocates and the sample slices `render::slices::sample_slices` fits to a
/// buffer's range (which counted 96-byte vertices and truncated paths until session 51).
pub(super) fn store_bytes_per_sample(
    pixels: u32,
    ratio: f32,
    light_path_len: u32,
    features: &crate::gpu_data::SceneFeatures,
    merges: bool,
) -> u64 {
    light_paths_per_sample(pixels, ratio) as u64 * light_path_len.max(1) as u64 * light_vertex_words(features, merges) as u64 * 16
}

/// Invocations of a light pass of `paths` light paths (whole workgroups).
fn light_invocations(paths: u32) -> u64 {
    (paths as u64).next_multiple_of(abi::PT_WG_SIZE as u64)
}

/// Invocations the shadow-ray queue serves for a film of `pixels` pixels (the full image's)
/// whose camera pass launches `camera_invocations`: the light pass queues its joins to the
/// camera in the same storage, a light path per invocation (`--light-paths RATIO` per pixel and
/// camera sample, `slices` camera samples an iteration).
pub fn queue_invocations(camera_invocations: u64, pixels: u32, ratio: f32, slices: u32) -> u64 {
    camera_invocations.max(light_invocations(light_paths_per_sample(pixels, ratio).saturating_mul(slices.max(1))))
}

/// Bytes of a light vertex cache entry (`BIND_LVC_INDEX`, glsl/common/lvc_entry.glsl): the slot
/// and the inverse of its path's reservoir probability, so a connection reads the entry and the
/// vertex and not the path's counts too; where connections are resampled from several
/// candidates, a 16-byte preview of the vertex beside it: 32 bytes a candidate, read once for
/// the lanes of a subgroup that connect for one block of pixels where they can serve all its
/// blocks (else by each lane).
fn lvc_entry_bytes(connection_candidates: u32) -> u64 {
    16 * if connection_candidates > 1 { abi::LVC_ENTRY_WORDS_RESAMPLED } else { abi::LVC_ENTRY_WORDS_UNIFORM } as u64
}

/// What the light vertex cache adds to the megakernel: a scan of the stored counts and a
/// pass that lists every stored slot densely.
struct Lvc {
    scan: crate::compute::Scan,
    plan: crate::compute::ScanPlan,
    compact: Kernel,
    /// `compact` runs an invocation per slot of the store, not per light path
    /// ([`super::default_lvc_listing_per_slot`]).
    per_slot: bool,
}

/// An iteration's light-vertex store and its cache: the stored vertices, each light path's
/// counts, its stored count then (scanned) its first cache entry, and (`Join::Lvc`) the cache's
/// entries and length. Two where the wavefront passes run side by side: the next iteration's
/// light pass fills one while this one's camera pass reads the other.
struct Store {
    vertices: Buffer,
    counts: Buffer,
    lvc_offsets: Buffer,
    /// The cache's listing and its length (only for `Join::Lvc`).
    cache: Option<(Buffer, Buffer)>,
}

impl Store {
    /// `i`: the store's index, in its buffers' names.
    fn new(ctx: &Context, i: usize, bytes: u64, paths: u32, cache_bytes: Option<u64>) -> Result<Store, RenderError> {
        let name = |n: &str| if i == 0 { format!("bdpt.{n}") } else { format!("bdpt.{n}{i}") };
        let vertices = ctx.create_buffer(&name("light_vertices"), bytes, Memory::Device).map_err(|e| match e {
            VkError::Alloc { bytes, .. } => {
                RenderError::Memory(format!("BDPT light vertices: {bytes} bytes could not be allocated on the GPU; lower --light-path-len"))
            }
            e => e.into(),
        })?;
        Ok(Store {
            vertices,
            counts: ctx.create_buffer(&name("light_counts"), paths as u64 * 8, Memory::Device)?,
            lvc_offsets: ctx.create_buffer(&name("lvc_offsets"), paths as u64 * 4, Memory::Device)?,
            cache: match cache_bytes {
                Some(b) => Some((
                    ctx.create_buffer(&name("lvc_index"), b, Memory::Device)?,
                    ctx.create_buffer(&name("lvc_total"), 16, Memory::Device)?,
                )),
                None => None,
            },
        })
    }
}

/// BDPT: a light-subpath pass and a camera-subpath pass per iteration (with
/// the light vertex cache, a scan and a listing pass between them).
pub struct Bdpt {
    passes: Passes,
    /// The light-vertex stores: one, or two where the wavefront passes run side by side
    /// (`iterate_side_by_side`).
    stores: Vec<Store>,
    /// The light vertex cache's scan and listing (only for `Join::Lvc`).
    lvc: Option<Lvc>,
    /// With two stores: the camera pass's launches that run beside the next light pass
    /// (`RenderSettings::wavefront_overlap`).
    overlap: Option<u32>,
    /// VCM's merge grid (only for `--integrator vcm` with merging).
    grid: Option<super::vcm::MergeGrid>,
    pub join: Join,
    pub light_path_len: u32,
    /// Light paths per camera sample.
    pub light_paths: u32,
    /// Most camera samples per pixel in one iteration (the store holds light_paths x this).
    pub max_camera_samples: u32,
    /// Bytes of light-vertex storage (vertices, per-path counts, the cache's list, VCM's
    /// merge grid).
    pub vertex_bytes: u64,
    /// The megakernels' shadow-ray queue of the camera pass and of the light pass's joins to
    /// the camera (`--shadow-queue`), if any (none with the wavefront passes).
    queue: Option<(super::shadow_queue::ShadowQueueTracer, super::ShadowQueue)>,
}

/// How the subpaths run: the megakernels (bdpt_light.comp, bdpt_camera.comp, which trace their
/// own rays and queue their shadow rays), or as wavefronts (`--wavefront`; bdpt_wavefront.rs).
enum Passes {
    Megakernels { light: Kernel, camera: Kernel },
    Wavefront(Box<WavefrontPasses>),
}

/// What `--integrator vcm` adds to BDPT with the light vertex cache.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VcmConfig {
    pub mode: super::vcm::VcmMode,
    /// First iteration's merge radius in scene units.
    pub radius: f32,
    /// Radius reduction exponent.
    pub alpha: f32,
}

/// 16-byte words per light-vertex slot (`SPEC_LIGHT_VERTEX_WORDS`): a whole `LightVertex` (6)
/// where the kernels read its GGX, volume or merging fields (a scene with glossy surfaces or
/// volumes, or VCM that merges), else its compact form of 4 (glsl/common/bdpt.glsl). The
/// store is written once and read about once per vertex: on the Cornell box its 96-byte
/// stores were 14.5 of the light pass's 67 ms per 1024 spp (docs/results.md).
pub fn light_vertex_words(features: &crate::gpu_data::SceneFeatures, merges: bool) -> u32 {
    const _: () = assert!(std::mem::size_of::<LightVertex>() == 6 * 16);
    if features.glossy || features.volume || merges {
        6
    } else {
        4
    }
}

impl Bdpt {
    /// BDPT kernels and light-vertex storage for a film of `pixels` pixels.
    /// `camera_samples`: most camera samples per pixel one iteration runs at once (their light
    /// paths are traced together). `vcm`: vertex connection and merging (the light vertex
    /// cache's join). `queue`: the camera and light passes' shadow-ray queue, for launches of up
    /// to `invocations` invocations (`queue_invocations`). `wavefront`: the passes as wavefronts
    /// (bdpt_wavefront.rs) whose camera pass takes up to this many slots, instead of the
    /// megakernels (the queue is then unused).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        pixels: u32,
        settings: &super::RenderSettings,
        join: Join,
        camera_samples: u32,
        vcm: Option<VcmConfig>,
        queue: Option<super::ShadowQueue>,
        invocations: u64,
        wavefront: Option<u64>,
    ) -> Result<Bdpt, RenderError> {
        let (light_path_len, sampler) = (settings.light_path_len, settings.sampler);
        let ratio = settings.light_path_ratio_for(&scene.estimator_features);
        if !(ratio > 0.0 && ratio.is_finite()) {
            return Err(RenderError::Unsupported(format!("light paths per pixel must be a positive number, not {ratio}")));
        }
        if ratio != 1.0 && !matches!(join, Join::Lvc(_)) {
            return Err(RenderError::Unsupported(format!(
                "the {} join pairs one light path with each pixel; a light-path ratio other than 1 needs the light vertex cache (bdpt:lvc)",
                join.name()
            )));
        }
        let per_sample = light_paths_per_sample(pixels, ratio);
        let camera_samples = camera_samples.max(1);
        let paths = per_sample.saturating_mul(camera_samples);
        let info = ctx.info();
        if !info.atomic_float_add {
            return Err(RenderError::Unsupported(format!(
                "{} lacks atomic float add (VK_EXT_shader_atomic_float), which BDPT's light tracing needs",
                info.name
            )));
        }
        let light_path_len = light_path_len.max(1);
        let merges = vcm.is_some_and(|v| v.mode.merge);
        let words = light_vertex_words(&scene.features, merges);
        let vertex_size = words as u64 * 16;
        let bytes = store_bytes_per_sample(pixels, ratio, light_path_len, &scene.features, merges) * camera_samples as u64;
        if bytes > info.max_storage_buffer_range as u64 {
            return Err(RenderError::Memory(format!(
                "BDPT light vertices need {:.1} MiB ({paths} paths x {light_path_len} vertices x {} bytes), over the device's {} MiB storage-buffer limit: lower --light-path-len, --light-paths, --sample-slices or the resolution",
                bytes as f64 / (1u64 << 20) as f64,
                vertex_size,
                info.max_storage_buffer_range >> 20
            )));
        }
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_STATS, value: settings.count_traversal as u32 });
        specs.push(sampler.spec());
        specs.push(Spec { id: abi::SPEC_DIRECT_LIGHT_TRACING, value: settings.direct_light_tracing as u32 });
        specs.push(Spec { id: abi::SPEC_MIS_BALANCE, value: (settings.mis_for(&scene.estimator_features) == super::Mis::Balance) as u32 });
        specs.push(Spec { id: abi::SPEC_LIGHT_VERTEX_WORDS, value: words });
        let candidates = settings.connection_candidates_for(&scene.estimator_features);
        if !(1..=super::MAX_CONNECTION_CANDIDATES).contains(&candidates) {
            return Err(RenderError::Unsupported(format!(
                "connection candidates: {candidates} (1 to {})",
                super::MAX_CONNECTION_CANDIDATES
            )));
        }
        specs.push(Spec { id: abi::SPEC_LVC_CANDIDATES, value: candidates });
        let capacity = paths.saturating_mul(light_path_len);
        let wavefront = match wavefront {
            Some(_) if vcm.is_some() => return Err(RenderError::Unsupported("VCM has no wavefront form: add --wavefront off".into())),
            // A slot per light path in the light pass, per pixel and camera sample in the other.
            Some(slots) => Some(WavefrontPasses::new(ctx, scene, &specs, settings, join, slots, paths as u64)?),
            None => None,
        };
        let queue = if wavefront.is_some() { None } else { queue };
        if let Some(v) = vcm {
            if !matches!(join, Join::Lvc(_)) {
                return Err(RenderError::Unsupported("VCM merges over the light vertex cache (join lvc)".into()));
            }
            if !(v.radius > 0.0 && v.radius.is_finite()) {
                return Err(RenderError::Unsupported(format!("the VCM merge radius must be positive, not {}", v.radius)));
            }
            super::vcm::check_alpha(v.alpha).map_err(RenderError::Unsupported)?;
            specs.extend(super::vcm::specs(v.mode, scene.features.mixed_lobes, v.radius, v.alpha, super::vcm::grid_bits(capacity)));
        }
        let cache_bytes = matches!(join, Join::Lvc(_)).then(|| paths as u64 * light_path_len as u64 * lvc_entry_bytes(candidates));
        let mut stores = vec![Store::new(ctx, 0, bytes, paths, cache_bytes)?];
        // A second store lets the wavefront passes run side by side; where it does not fit,
        // they run one after the other.
        if wavefront.is_some() && settings.wavefront_overlap.is_some() && settings.wavefront_finish != super::WavefrontFinish::Off {
            match Store::new(ctx, 1, bytes, paths, cache_bytes) {
                Ok(second) => stores.push(second),
                Err(RenderError::Memory(_) | RenderError::Vk(VkError::Alloc { .. })) => {}
                Err(e) => return Err(e),
            }
        }
        let per_slot =
            settings.lvc_listing_per_slot.unwrap_or_else(|| super::default_lvc_listing_per_slot(super::defaults::on_cpu(ctx), candidates));
        let lvc = match join {
            Join::Lvc(_) => Some(Lvc {
                scan: crate::compute::Scan::new(ctx)?,
                plan: crate::compute::ScanPlan::new(ctx, paths)?,
                compact: ctx.create_kernel(
                    &kernels::LVC_COMPACT,
                    &[specs.as_slice(), &[Spec { id: abi::SPEC_LVC_LIST_PER_SLOT, value: per_slot as u32 }]].concat(),
                )?,
                per_slot,
            }),
            _ => None,
        };
        let grid = match vcm {
            Some(v) if v.mode.merge => {
                let queries = if v.mode.merges_apart(scene.features.mixed_lobes) { pixels.saturating_mul(camera_samples) } else { 0 };
                let query_bytes = queries as u64 * std::mem::size_of::<abi::MergeQuery>() as u64;
                if query_bytes > info.max_storage_buffer_range as u64 {
                    return Err(RenderError::Memory(format!(
                        "VCM's merge queries need {:.1} MiB ({queries} camera samples x {} bytes), over the device's {} MiB storage-buffer limit: lower --sample-slices or the resolution",
                        query_bytes as f64 / (1u64 << 20) as f64,
                        std::mem::size_of::<abi::MergeQuery>(),
                        info.max_storage_buffer_range >> 20
                    )));
                }
                Some(super::vcm::MergeGrid::new(ctx, &specs, capacity, super::vcm::grid_bits(capacity), queries)?)
            }
            _ => None,
        };
        let store_bytes = bytes + paths as u64 * 12 + cache_bytes.map_or(0, |b| b + 16);
        let vertex_bytes = store_bytes * stores.len() as u64 + grid.as_ref().map_or(0, |g| g.bytes);
        // `queue_invocations` counted the light pass's invocations too.
        assert!(queue.is_none() || invocations >= light_invocations(paths), "the shadow-ray queue is smaller than the light pass");
        let queue = queue
            .map(|q| {
                let tracer = super::shadow_queue::ShadowQueueTracer::new(ctx, scene, settings.count_traversal, q.slots, invocations, true)?;
                Ok::<_, RenderError>((tracer, q))
            })
            .transpose()?;
        specs.extend(queue.as_ref().map(|q| q.0.spec()));
        Ok(Bdpt {
            overlap: settings.wavefront_overlap.filter(|_| stores.len() == 2),
            stores,
            lvc,
            grid,
            passes: match wavefront {
                Some(w) => Passes::Wavefront(Box::new(w)),
                None => Passes::Megakernels {
                    light: ctx.create_kernel(scene.bvh.kernel(&kernels::BDPT_LIGHT_FORMS), &specs)?,
                    camera: ctx.create_kernel(scene.bvh.kernel(&kernels::BDPT_CAMERA_FORMS), &specs)?,
                },
            },
            join,
            light_path_len,
            light_paths: per_sample,
            max_camera_samples: camera_samples,
            vertex_bytes,
            queue,
        })
    }

    /// The buffers an iteration's kernels bind: with light-vertex store `store`, and with the
    /// wavefront passes `pass`'s slots.
    fn binds<'a>(&'a self, scene: &'a GpuScene, film: &'a Film, store: usize, pass: Pass) -> Vec<Bind<'a>> {
        let st = &self.stores[store];
        let mut binds = scene.binds();
        binds.push(Bind::buffer(abi::BIND_LIGHT_VERTICES, &st.vertices));
        binds.push(Bind::buffer(abi::BIND_LIGHT_COUNTS, &st.counts));
        binds.push(Bind::buffer(abi::BIND_RENDER_STATS, &film.stats));
        binds.push(Bind::buffer(abi::BIND_SPLAT, film.splat.as_ref().expect("BDPT films have a splat buffer")));
        binds.push(Bind::buffer(abi::BIND_ACCUM, &film.accum));
        binds.push(Bind::buffer(abi::BIND_LVC_OFFSETS, &st.lvc_offsets));
        binds.push(Bind::buffer(abi::BIND_SLICES, film.slices_buffer()));
        match &st.cache {
            Some((index, total)) => {
                binds.push(Bind::buffer(abi::BIND_LVC_INDEX, index));
                binds.push(Bind::buffer(abi::BIND_LVC_TOTAL, total));
            }
            None => {
                // The camera kernel declares the cache; the megakernel joins never read it.
                binds.push(Bind::buffer(abi::BIND_LVC_INDEX, &st.lvc_offsets));
                binds.push(Bind::buffer(abi::BIND_LVC_TOTAL, &st.lvc_offsets));
            }
        }
        match &self.grid {
            Some(g) => binds.extend(g.binds()),
            None => {
                // The camera kernel declares the merge grid; BDPT never reads it.
                binds.push(Bind::buffer(abi::BIND_MERGE_CELLS, &st.lvc_offsets));
                binds.push(Bind::buffer(abi::BIND_MERGE_ITEMS, &st.lvc_offsets));
                binds.push(Bind::buffer(abi::BIND_MERGE_QUERIES, &st.lvc_offsets));
            }
        }
        match &self.queue {
            Some((tracer, _)) => binds.extend(tracer.binds()),
            None => binds.extend(super::shadow_queue::ShadowQueueTracer::unused_binds(film)),
        }
        if let Passes::Wavefront(w) = &self.passes {
            binds.extend(w.binds(pass));
        }
        binds
    }

    /// Records an iteration's light pass with the megakernel: all light subpaths and their
    /// joins to the camera, then the light vertex cache's listing (and VCM's grid).
    fn record_light(&self, rec: &mut Recorder, light: &Kernel, binds: &[Bind], push: &BdptPush) -> Result<()> {
        let total = push.light_path_total;
        assert!(total <= self.light_paths * self.max_camera_samples, "more light paths than the store holds");
        rec.dispatch(light, binds, bytemuck::bytes_of(push), [light.groups_for(total), 1, 1])?;
        if let Some((tracer, _)) = &self.queue {
            tracer.record_splats(rec, binds, total, light.groups_for(total))?;
        }
        self.record_cache(rec, binds, push, 0)
    }

    /// Records the light vertex cache's listing of the stored vertices (and VCM's grid) of
    /// store `store` (whose buffers `binds` binds).
    fn record_cache(&self, rec: &mut Recorder, binds: &[Bind], push: &BdptPush, store: usize) -> Result<()> {
        let total = push.light_path_total;
        if let Some(lvc) = &self.lvc {
            lvc.scan.record(rec, &lvc.plan, &self.stores[store].lvc_offsets, total)?;
            let groups = if lvc.per_slot {
                // At most the 65,535 workgroups every device takes (4 M invocations fill any GPU;
                // the kernel's grid-stride loop covers the rest).
                lvc.compact.groups_for(total.saturating_mul(push.light_path_len)).min(65_535)
            } else {
                lvc.compact.groups_for(total)
            };
            rec.dispatch(&lvc.compact, binds, bytemuck::bytes_of(push), [groups, 1, 1])?;
        }
        if let Some(grid) = &self.grid {
            grid.record(rec, binds, push)?;
        }
        Ok(())
    }

    /// Records one iteration with the megakernels: all light subpaths, then all camera
    /// subpaths.
    fn record(&self, rec: &mut Recorder, [light, camera]: [&Kernel; 2], scene: &GpuScene, film: &Film, push: &BdptPush) -> Result<()> {
        let binds = self.binds(scene, film, 0, Pass::Camera);
        self.record_light(rec, light, &binds, push)?;
        let samples = push.camera_samples.max(1);
        let n = crate::gpu_data::tiled_invocations(film.width, film.height) * samples;
        rec.dispatch(camera, &binds, bytemuck::bytes_of(push), [camera.groups_for(n), 1, 1])?;
        if let Some((tracer, _)) = &self.queue {
            tracer.record(rec, &binds, film, samples, camera.groups_for(n))?;
        }
        if let Some(grid) = &self.grid {
            grid.record_merge(rec, &binds, push, film.width * film.height * samples)?;
        }
        film.record_add_slices(rec, samples)
    }

    /// Iterations with the wavefront passes: each iteration the light pass's batches until a
    /// launch queues no ray, then the light vertex cache's listing and the camera pass's batches
    /// likewise, then the slices' sum. Each pass's first batch is recorded while the GPU runs
    /// the submission before it (the camera pass's during the light pass; the next iteration's
    /// light pass, after this one's slices, during the camera pass): the host's recording of
    /// tens of launches then costs the GPU no idle time. Where that submission's first batch
    /// ends its pass (the finishing launch, the default), the next is submitted before the host
    /// waits for it (`follow`), so the GPU does not idle between passes either. With two
    /// light-vertex stores the passes run side by side instead (`iterate_side_by_side`).
    fn iterate_wavefront(
        &self,
        ctx: &Context,
        w: &WavefrontPasses,
        scene: &GpuScene,
        film: &Film,
        pushes: &[BdptPush],
    ) -> std::result::Result<(), RenderError> {
        if let Some(overlap) = self.overlap {
            return self.iterate_side_by_side(ctx, w, scene, film, pushes, overlap);
        }
        let light_binds = self.binds(scene, film, 0, Pass::Light);
        let camera_binds = self.binds(scene, film, 0, Pass::Camera);
        let geometry = scene.binds();
        let geometry = &geometry[..];
        let binds_of = |pass| match pass {
            Pass::Light => &light_binds[..],
            Pass::Camera => &camera_binds[..],
        };
        let slots = |pass, push: &BdptPush| WavefrontPasses::slots_for(pass, push, film.width, film.height);
        let run = |pass, push, batch, start| Run { pass, binds: binds_of(pass), push, batch, start, readback: 0 };
        // The first batch of iteration i's light pass (the slices of iteration i - 1 summed
        // first).
        let record_light = |i: usize| {
            let (push, before) = (&pushes[i], i.checked_sub(1).map(|b| &pushes[b]));
            assert!(push.light_path_total <= self.light_paths * self.max_camera_samples, "more light paths than the store holds");
            let batch = w.first_batch(Pass::Light, slots(Pass::Light, push));
            let recorded = ctx.record("bdpt wavefront light pass", move |rec| {
                if let Some(before) = before.filter(|b| b.camera_samples > 1) {
                    film.record_add_slices(rec, before.camera_samples)?;
                }
                if push.camera_samples > 1 {
                    // The camera pass adds into the slices as its contributions arise.
                    rec.fill_buffer(film.slices_buffer(), 0);
                }
                w.record_batch(rec, geometry, &run(Pass::Light, push, batch, true))
            });
            recorded.map(|r| (r, batch))
        };
        let record_camera = |i: usize| {
            let push = &pushes[i];
            let batch = w.first_batch(Pass::Camera, slots(Pass::Camera, push));
            let recorded = ctx.record("bdpt wavefront camera pass", move |rec| {
                self.record_cache(rec, binds_of(Pass::Camera), push, 0)?;
                w.record_batch(rec, geometry, &run(Pass::Camera, push, batch, true))
            });
            recorded.map(|r| (r, batch))
        };
        // Batches after the first until the pass is over.
        let later_batches = |pass, push: &BdptPush, mut batch: Batch| -> std::result::Result<(), RenderError> {
            let mut done = 0;
            while let Some(next) = w.after_batch(pass, done, batch, 0)? {
                done += batch.launches;
                batch = next;
                let name = format!("bdpt wavefront {pass:?} pass");
                let run = Run { pass, binds: binds_of(pass), push, batch, start: false, readback: 0 };
                ctx.submit(&name, |rec| w.record_batch(rec, geometry, &run))?;
            }
            Ok(())
        };
        // Runs `ahead` (recorded, not yet submitted) after the pass `running` (submitted, its
        // first batch `batch`): where that batch ends the pass (its finishing launch), `ahead` is
        // submitted at once, queued behind it, and only then does the host wait for the pass and
        // read what it queued, so that the GPU does not idle through the host's wake-up, read-back
        // and submission between the passes (on an H100's Cornell box `bench render`'s wall time
        // ran 4.2 ms per 1024 spp above its GPU time, session 56); else the host waits, records
        // the pass's further batches, then submits.
        let follow = |running: InFlight<'_>, pass, push: &BdptPush, batch: Batch, ahead| -> std::result::Result<_, RenderError> {
            if batch.finish {
                let next = ctx.start(ahead)?;
                running.wait()?;
                later_batches(pass, push, batch)?;
                return Ok(next);
            }
            running.wait()?;
            later_batches(pass, push, batch)?;
            Ok(ctx.start(ahead)?)
        };
        if pushes.is_empty() {
            return Ok(());
        }
        let (recorded, batch) = record_light(0)?;
        let mut light = Some((ctx.start(recorded)?, batch));
        for (i, push) in pushes.iter().enumerate() {
            let (running, light_batch) = light.take().expect("submitted while the camera pass before ran");
            // Recorded while the light pass runs.
            let (recorded, camera_batch) = record_camera(i)?;
            let camera = follow(running, Pass::Light, push, light_batch, recorded)?;
            match (i + 1 < pushes.len()).then(|| record_light(i + 1)).transpose()? {
                Some((recorded, batch)) => light = Some((follow(camera, Pass::Camera, push, camera_batch, recorded)?, batch)),
                None => {
                    camera.wait()?;
                    later_batches(Pass::Camera, push, camera_batch)?;
                    if push.camera_samples > 1 {
                        ctx.submit("bdpt film", |rec| film.record_add_slices(rec, push.camera_samples))?;
                    }
                }
            }
        }
        Ok(())
    }

    /// Iterations with the wavefront passes side by side, over two light-vertex stores
    /// (iteration i's light pass fills store i % 2, its camera pass reads it): each submission
    /// runs iteration i - 1's camera pass from its second launch on, iteration i's light pass
    /// beside its last `overlap` launches, and iteration i's first camera launch and its trace
    /// (which read no light vertex) beside that light pass's tail, then the slices' sum and the
    /// listing of store i % 2. The passes' tails, launches over a few live paths on a mostly idle
    /// GPU (13 % of BDPT's time on an H100's Cornell box, session 56), then run beside the other
    /// pass's work. Every pass is one batch ending in its finishing launch. Each submission is
    /// recorded while the one before runs and queued behind it before the host waits for that
    /// one and reads what its passes queued (each pass reads back into its buffer of the
    /// iteration's parity, so the one running does not overwrite it).
    #[allow(clippy::too_many_arguments)]
    fn iterate_side_by_side(
        &self,
        ctx: &Context,
        w: &WavefrontPasses,
        scene: &GpuScene,
        film: &Film,
        pushes: &[BdptPush],
        overlap: u32,
    ) -> std::result::Result<(), RenderError> {
        use super::wavefront_queues::Step;
        if pushes.is_empty() {
            return Ok(());
        }
        let geometry = scene.binds();
        let geometry = &geometry[..];
        let binds: [[Vec<Bind>; 2]; 2] = [0, 1].map(|s| [Pass::Light, Pass::Camera].map(|p| self.binds(scene, film, s, p)));
        let binds = &binds;
        let slots = |pass, push: &BdptPush| WavefrontPasses::slots_for(pass, push, film.width, film.height);
        let batch = |pass, i: usize| {
            let b = w.first_batch(pass, slots(pass, &pushes[i]));
            assert!(b.finish, "passes side by side end in their finishing launch");
            b
        };
        // Iteration i's run of `pass`.
        let run = |pass, i: usize, batch| Run {
            pass,
            binds: &binds[i % 2][pass as usize],
            push: &pushes[i],
            batch,
            start: true,
            readback: i % 2,
        };
        // A camera pass's head: its fills, first launch and that launch's trace.
        const HEAD: usize = 3;
        // Submission i: iteration i - 1's camera pass after its head (`camera`: its batch), and
        // for i < n iteration i's light pass and camera head (`next`: their batches).
        let record = |i: usize, camera: Option<Batch>, next: Option<(Batch, Batch)>| {
            ctx.record("bdpt wavefront passes", move |rec| {
                let rest = camera.map(|cb| {
                    let steps = w.steps(cb);
                    assert_eq!(steps[..HEAD], [Step::Fills, Step::Launch(0), Step::Traces(0)], "a camera pass's head");
                    steps[HEAD..].to_vec()
                });
                // The light pass's fills beside the trace of the launch before the first of the
                // camera pass's last `overlap` launches (beside its first step where that trace
                // is in the head).
                let light_start = match (camera, &rest) {
                    (Some(cb), Some(rest)) => {
                        let first_beside = cb.launches.saturating_sub(overlap).max(1);
                        rest.iter().position(|&s| s == Step::Traces(first_beside - 1)).unwrap_or(0)
                    }
                    _ => 0,
                };
                let light = next.map(|(lb, _)| w.steps(lb));
                let head = next.map(|(_, nb)| w.steps(nb)[..HEAD].to_vec());
                let mut lanes = Vec::new();
                if let (Some(cb), Some(rest)) = (camera, &rest) {
                    lanes.push((run(Pass::Camera, i - 1, cb), &rest[..], 0));
                }
                if let (Some((lb, nb)), Some(light), Some(head)) = (next, &light, &head) {
                    assert!(
                        pushes[i].light_path_total <= self.light_paths * self.max_camera_samples,
                        "more light paths than the store holds"
                    );
                    lanes.push((run(Pass::Light, i, lb), &light[..], light_start));
                    // The next camera pass's head after this one's end (its readback): its fills
                    // and first launch beside the light pass's first launch left then (in the
                    // first submission, none: beside its last), and the launch's trace beside the
                    // light pass's finishing launch where that is later.
                    let finish = light_start + light.iter().position(|&s| s == Step::Finish).expect("a finishing batch");
                    let after_camera = rest.as_ref().map_or(0, |r| r.len());
                    let from = if camera.is_some() { after_camera + 1 } else { finish.saturating_sub(1) };
                    let launch_at = (from..finish).find(|&g| matches!(light[g - light_start], Step::Launch(_)));
                    let (fills_at, trace_at) = match launch_at {
                        Some(g) => (g - 1, finish.max(g + 1)),
                        None => {
                            let at = after_camera.max(finish.saturating_sub(HEAD - 1));
                            (at, at + 2)
                        }
                    };
                    // (It reads no light vertex: bound to the other store, which the light pass
                    // beside it does not write.)
                    let head_run = Run { binds: &binds[(i + 1) % 2][Pass::Camera as usize], ..run(Pass::Camera, i, nb) };
                    lanes.push((head_run, &head[..HEAD - 1], fills_at));
                    lanes.push((head_run, &head[HEAD - 1..], trace_at));
                }
                w.record_side_by_side(rec, geometry, &lanes)?;
                if let Some(before) = camera.and(i.checked_sub(1)).map(|b| &pushes[b]).filter(|b| b.camera_samples > 1) {
                    film.record_add_slices(rec, before.camera_samples)?;
                }
                if next.is_some() {
                    if pushes[i].camera_samples > 1 {
                        // The camera pass adds into the slices as its contributions arise (from
                        // its second launch on).
                        rec.fill_buffer(film.slices_buffer(), 0);
                    }
                    self.record_cache(rec, &binds[i % 2][Pass::Camera as usize], &pushes[i], i % 2)?;
                }
                Ok(())
            })
        };
        // Each iteration's light and camera batches, decided when its submission is recorded.
        let n = pushes.len();
        let mut batches = vec![(batch(Pass::Light, 0), batch(Pass::Camera, 0))];
        let mut running = ctx.start(record(0, None, Some(batches[0]))?)?;
        for i in 1..=n {
            if i < n {
                batches.push((batch(Pass::Light, i), batch(Pass::Camera, i)));
            }
            let submitted = ctx.start(record(i, Some(batches[i - 1].1), batches.get(i).copied())?)?;
            running.wait()?;
            // Submission i - 1 ran iteration i - 1's light pass and (from i = 2) the rest of
            // iteration i - 2's camera pass: what they queued, for the next passes' finishing
            // launches.
            w.after_batch(Pass::Light, 0, batches[i - 1].0, (i - 1) % 2)?;
            if i >= 2 {
                w.after_batch(Pass::Camera, 0, batches[i - 2].1, (i - 2) % 2)?;
            }
            running = submitted;
        }
        running.wait()?;
        w.after_batch(Pass::Camera, 0, batches[n - 1].1, (n - 1) % 2)?;
        Ok(())
    }
}

impl IntegratorKernels for Bdpt {
    /// The kernels an iteration runs (the light-vertex cache's scan kernels are shared
    /// utilities, `compute::Scan`).
    fn kernels(&self) -> Vec<&Kernel> {
        let mut k = match &self.passes {
            Passes::Megakernels { light, camera } => {
                let mut k = vec![light, camera];
                k.extend(self.queue.iter().flat_map(|q| q.0.kernels()));
                k
            }
            Passes::Wavefront(w) => w.kernels(),
        };
        if let Some(g) = &self.grid {
            k.extend(g.kernels());
        }
        k
    }

    fn storage_bytes(&self) -> u64 {
        let wavefront = match &self.passes {
            Passes::Wavefront(w) => w.bytes(),
            Passes::Megakernels { .. } => 0,
        };
        self.vertex_bytes + self.queue.as_ref().map_or(0, |q| q.0.bytes()) + wavefront
    }

    fn wavefront(&self) -> bool {
        matches!(self.passes, Passes::Wavefront(_))
    }

    fn shadow_queue(&self) -> Option<super::ShadowQueue> {
        self.queue.as_ref().map(|q| q.1)
    }

    fn splats(&self) -> bool {
        true
    }

    fn sized_by_pixels(&self) -> bool {
        true
    }

    fn slice_aligned(&self) -> bool {
        true
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let (s, scene, slices) = (inputs.settings, inputs.scene, inputs.slices);
        let (join, join_k) = match self.join {
            Join::Full => (abi::JOIN_FULL, 0),
            Join::K(k) => (abi::JOIN_K, k),
            Join::Lvc(k) => (abi::JOIN_LVC, k),
        };
        // Iterations of up to `slices` camera samples per pixel, their light paths traced
        // together. Iterations start at multiples of `slices` whatever the pass sizes, so the
        // light paths (and the light vertex cache) of a sample depend on its index only:
        // passes, sample ranges and devices split one render exactly.
        let mut pushes = Vec::new();
        let mut done = 0;
        while done < spp {
            let base = first + done;
            let samples = (slices - base % slices).min(spp - done);
            pushes.push(BdptPush {
                camera: inputs.camera,
                sample_base: base,
                seed: s.seed,
                emitter_count: scene.emitter_count,
                emitter_weight: scene.emitter_weight,
                max_depth: s.max_depth,
                rr_depth: s.rr_depth,
                light_path_len: self.light_path_len,
                join,
                join_k,
                light_paths: self.light_paths,
                camera_samples: samples,
                light_path_total: self.light_paths * samples,
            });
            done += samples;
        }
        match &self.passes {
            Passes::Wavefront(w) => self.iterate_wavefront(ctx, w, scene, inputs.film, &pushes),
            Passes::Megakernels { light, camera } => Ok(ctx.submit("bdpt pass", |rec| {
                pushes.iter().try_for_each(|push| self.record(rec, [light, camera], scene, inputs.film, push))
            })?),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn joins_parse() {
        assert_eq!("full".parse::<Join>().unwrap(), Join::Full);
        assert_eq!("single".parse::<Join>().unwrap(), Join::K(1));
        assert_eq!("k=4".parse::<Join>().unwrap(), Join::K(4));
        assert!("k=0".parse::<Join>().is_err());
        assert!("k=x".parse::<Join>().is_err());
        assert_eq!("lvc".parse::<Join>().unwrap(), Join::Lvc(0));
        assert_eq!("lvc=3".parse::<Join>().unwrap(), Join::Lvc(3));
        assert!("lvc=0".parse::<Join>().is_err());
        for j in [Join::Full, Join::K(1), Join::K(4), Join::Lvc(0), Join::Lvc(2)] {
            assert_eq!(j.name().parse::<Join>().unwrap(), j);
        }
    }
}
