//! What the wavefront integrators share (pt_wavefront.rs, bdpt_wavefront.rs): the ray queues
//! between a path kernel and the trace kernels of `crate::trace`, and the batches of launches
//! (path kernel, closest-hit trace of the segments, any-hit trace of the shadow rays) that end
//! in a read of how many rays each launch queued.

use super::{gpu_scene::GpuScene, RenderError};
use crate::gpu::abi;
use crate::trace::{TraceOptions, Tracer};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result};

/// Dynamic fetch's refill (`TraceOptions::refill_lanes`) of the wavefront integrators' 4-wide
/// trace kernels on GPUs with subgroups of 32 lanes or more.
const REFILL_LANES: u32 = 28;

/// How the trace kernels of the wavefront integrators run: over the scene's BVH (on GPUs the
/// 4-wide one, `wavefront_bvh_layout`) with the lockstep loops, the ray count read from the
/// queue's counter; over the 4-wide BVH on GPUs (`on_cpu` false, `subgroup_size` 32 or more)
/// as persistent threads with dynamic fetch, refilled at 28 lanes as for `bench traversal`'s
/// secondary rays. NVIDIA H200, ms per run against one invocation per ray: textured Sponza
/// pt-nee 58.2 against 60.3, pt 44.0 against 45.9, DamagedHelmet pt-nee 25.1 against 24.6
/// (docs/results.md, "A wavefront path tracer"). `alpha`: where the scene has alpha-tested or
/// blended triangles (trace_alpha*.comp), each ray carrying its path's stochastic-opacity seed.
pub fn trace_options(scene: &GpuScene, on_cpu: bool, subgroup_size: u32, alpha: bool) -> TraceOptions {
    let mut opts = TraceOptions::new(scene.bvh.tri_test);
    opts.layout = scene.bvh.layout;
    opts.alpha = alpha.then_some(scene.features);
    opts.ray_seed = alpha;
    opts.count_buffer = true;
    if scene.bvh.layout == crate::bvh::BvhLayout::Bvh4 && !on_cpu && subgroup_size >= 32 {
        opts.persistent = Some(0);
        opts.refill_lanes = REFILL_LANES;
    }
    opts
}

/// The queues of a wavefront pass of up to `slots` slots, each queueing one segment and up to
/// `shadow` shadow rays a launch, and the trace kernels that trace them.
pub struct Queues {
    tracer: Tracer,
    rays: Buffer,
    hits: Buffer,
    shadow_rays: Buffer,
    shadow_hits: Buffer,
    /// Per launch of a batch, the segments and shadow rays it queued; copied to `counts_read`
    /// at its end.
    counts: Buffer,
    counts_read: Buffer,
    /// The trace kernels' node and triangle counters (unused: not counted).
    trace_stats: Buffer,
    slots: u32,
    shadow: u32,
}

/// Bytes per slot of `Queues` with `shadow` shadow rays: the segment and its hit, the shadow
/// rays and theirs.
pub const fn queue_bytes(shadow: u32) -> u64 {
    (1 + shadow as u64) * (32 + 16)
}

/// A buffer of `bytes` per slot for `slots` slots, named `name`; where it does not fit, an
/// error that says how much the `what`'s slots take in all (`slot_bytes` each) and what to do.
pub fn slot_buffer(
    ctx: &Context,
    what: &str,
    name: &str,
    slots: u64,
    bytes: u64,
    slot_bytes: u64,
) -> std::result::Result<Buffer, RenderError> {
    ctx.create_buffer(name, slots * bytes, Memory::Device).map_err(|e| {
        RenderError::Memory(format!(
            "{what}'s {slots} slots ({} MiB) do not fit ({e}): lower --sample-slices or the image size, or add --wavefront off",
            (slots * slot_bytes) >> 20
        ))
    })
}

impl Queues {
    /// `what` names the integrator in errors (as `slot_buffer`), `prefix` its buffers.
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        (what, prefix): (&str, &str),
        slots: u64,
        shadow: u32,
        slot_bytes: u64,
    ) -> std::result::Result<Self, RenderError> {
        let opts = trace_options(scene, super::on_cpu(ctx), ctx.info().subgroup_size, scene.features.alpha);
        let buffer = |name: &str, bytes: u64| slot_buffer(ctx, what, &format!("{prefix}.{name}"), slots, bytes, slot_bytes);
        let batch_bytes = abi::WF_MAX_BATCH as u64 * 8;
        Ok(Queues {
            tracer: Tracer::with_options(ctx, &opts)?,
            rays: buffer("rays", 32)?,
            hits: buffer("hits", 16)?,
            shadow_rays: buffer("shadow_rays", 32 * shadow as u64)?,
            shadow_hits: buffer("shadow_hits", 16 * shadow as u64)?,
            counts: ctx.create_buffer(&format!("{prefix}.counts"), batch_bytes, Memory::Device)?,
            counts_read: ctx.create_buffer(&format!("{prefix}.counts_read"), batch_bytes, Memory::Readback)?,
            trace_stats: ctx.create_buffer(&format!("{prefix}.trace_stats"), 8, Memory::Device)?,
            slots: u32::try_from(slots).map_err(|_| RenderError::Memory(format!("{what}: {slots} slots are too many")))?,
            shadow,
        })
    }

    /// The trace kernels (closest hit, any hit).
    pub fn kernels(&self) -> [&Kernel; 2] {
        self.tracer.trace_kernels()
    }

    /// The queues' bindings for the path kernel.
    pub fn binds(&self) -> [Bind<'_>; 5] {
        [
            Bind::buffer(abi::BIND_WF_RAYS, &self.rays),
            Bind::buffer(abi::BIND_WF_HITS, &self.hits),
            Bind::buffer(abi::BIND_WF_SHADOW_RAYS, &self.shadow_rays),
            Bind::buffer(abi::BIND_WF_SHADOW_HITS, &self.shadow_hits),
            Bind::buffer(abi::BIND_WF_COUNTS, &self.counts),
        ]
    }

    /// Records `launches` launches over `slots` slots: `launch(rec, l)` records the path kernel's
    /// launch l of the batch, then the segments and shadow rays it queued are traced; the ray
    /// counts are read back at the end (`queued`).
    pub fn record_batch(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        slots: u32,
        launches: u32,
        mut launch: impl FnMut(&mut Recorder, u32) -> Result<()>,
    ) -> Result<()> {
        assert!(slots <= self.slots, "a pass of {slots} slots on storage for {}", self.slots);
        assert!(launches <= abi::WF_MAX_BATCH);
        rec.fill_buffer(&self.counts, 0);
        for l in 0..launches {
            launch(rec, l)?;
            let (ext, shadow) = (Some((&self.counts, 2 * l)), Some((&self.counts, 2 * l + 1)));
            self.tracer.record_trace_queued(rec, geometry, &self.rays, &self.hits, &self.trace_stats, slots, ext, false)?;
            let shadow_slots = slots * self.shadow;
            self.tracer.record_trace_queued(
                rec,
                geometry,
                &self.shadow_rays,
                &self.shadow_hits,
                &self.trace_stats,
                shadow_slots,
                shadow,
                true,
            )?;
        }
        rec.copy_buffer(&self.counts, &self.counts_read, self.counts.size());
        Ok(())
    }

    /// After a batch of `launches`: the first launch that queued no ray (the pass is over after
    /// it), if one did.
    pub fn first_idle_launch(&self, launches: u32) -> Result<Option<u32>> {
        let counts: Vec<u32> = self.counts_read.read()?;
        let queued = counts.chunks(2).take(launches as usize).map(|c| c[0] + c[1]);
        Ok(queued.enumerate().find(|&(_, n)| n == 0).map(|(l, _)| l as u32))
    }
}
