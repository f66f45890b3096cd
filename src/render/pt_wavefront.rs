//! The wavefront path tracer (`--wavefront`, `glsl/kernels/pt_wavefront.comp`): pt.comp's
//! paths with their traversal in the trace kernels of `crate::trace` (Laine, Karras & Aila
//! 2013). A pass is a loop of launches: the path kernel (scatter at the hits, start samples,
//! leave the next segment and shadow ray per slot), the closest-hit trace of the segments, the
//! any-hit trace of the shadow rays; recorded in batches, each ending in a read of how many
//! rays each launch queued, until a launch queues none.

use std::cell::Cell;

use super::integrator::{IntegratorKernels, PassInputs};
use super::{gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::PtPush, abi::PtWavefrontPush, kernels};
use crate::trace::{TraceOptions, Tracer};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// Bytes per slot: the path (`PtSuspended`), two rays, two hits, the pending contribution and
/// where its rays went in the queues.
pub const SLOT_BYTES: u64 = std::mem::size_of::<abi::PtSuspended>() as u64 + 2 * 32 + 2 * 16 + 16 + 8;

/// Slots the wavefront tracer's passes aim for on GPUs (sample slices enough for about this
/// many): fewer leave its trace kernels' launches too short to fill the GPU. NVIDIA H200,
/// `bench render`, Sponza 640 x 360 pt-nee, 64 spp: 201 ms at 2 slices (0.46 million slots),
/// 147 at 8 and 16 (1.8 and 3.7 million), 153 at 32; Cornell box 256 x 256, 1024 spp: 91 ms at
/// 16 slices (1 million), 78 at 64 (4.2 million) (docs/results.md, "A wavefront path tracer").
pub const TARGET_SLOTS: u64 = 1 << 22;

/// Dynamic fetch's refill (`TraceOptions::refill_lanes`) of the wavefront tracer's 4-wide
/// trace kernels on GPUs with subgroups of 32 lanes or more.
const REFILL_LANES: u32 = 28;

/// How the trace kernels of the wavefront tracer run: over the scene's BVH (on GPUs the 4-wide
/// one, `wavefront_bvh_layout`) with the lockstep loops, the ray count read from the queue's
/// counter; over the 4-wide BVH on GPUs (`on_cpu` false, `subgroup_size` 32 or more) as
/// persistent threads with dynamic fetch, refilled at 28 lanes as for `bench traversal`'s
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

/// The wavefront path tracer's kernels and per-slot storage for passes of up to `slots` slots.
pub struct WavefrontPathTracer {
    kernel: Kernel,
    tracer: Tracer,
    state: Buffer,
    rays: Buffer,
    hits: Buffer,
    shadow_rays: Buffer,
    shadow_hits: Buffer,
    contrib: Buffer,
    index: Buffer,
    /// Per launch of a batch, the segments and shadow rays it queued; copied to `counts_read`
    /// at its end.
    counts: Buffer,
    counts_read: Buffer,
    /// The trace kernels' node and triangle counters (unused: not counted).
    trace_stats: Buffer,
    slots: u64,
    /// Launches a pass took per sample of a slot, learnt from the last pass: sizes the first
    /// batch of the next.
    launches_per_sample: Cell<f64>,
}

impl WavefrontPathTracer {
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        nee: bool,
        settings: &super::RenderSettings,
        slots: u64,
    ) -> std::result::Result<Self, RenderError> {
        if settings.count_traversal {
            return Err(RenderError::Unsupported(
                "counting traversal (`bench render --count`) is for the megakernels: add --wavefront off".into(),
            ));
        }
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_NEE, value: nee as u32 });
        specs.push(settings.sampler.spec());
        let kernel = ctx.create_kernel(&kernels::PT_WAVEFRONT, &specs)?;
        let opts = trace_options(scene, super::on_cpu(ctx), ctx.info().subgroup_size, scene.features.alpha);
        let tracer = Tracer::with_options(ctx, &opts)?;
        let buffer = |name: &str, bytes: u64| {
            ctx.create_buffer(name, slots * bytes, Memory::Device).map_err(|e| {
                RenderError::Memory(format!(
                    "the wavefront path tracer's {slots} slots ({} MiB) do not fit ({e}): lower --sample-slices or the image size, or add --wavefront off",
                    (slots * SLOT_BYTES) >> 20
                ))
            })
        };
        let state = buffer("pt_wavefront.state", std::mem::size_of::<abi::PtSuspended>() as u64)?;
        let rays = buffer("pt_wavefront.rays", 32)?;
        let hits = buffer("pt_wavefront.hits", 16)?;
        let shadow_rays = buffer("pt_wavefront.shadow_rays", 32)?;
        let shadow_hits = buffer("pt_wavefront.shadow_hits", 16)?;
        let contrib = buffer("pt_wavefront.contrib", 16)?;
        let index = buffer("pt_wavefront.queue_index", 8)?;
        let batch_bytes = abi::WF_MAX_BATCH as u64 * 8;
        Ok(WavefrontPathTracer {
            kernel,
            tracer,
            state,
            rays,
            hits,
            shadow_rays,
            shadow_hits,
            contrib,
            index,
            counts: ctx.create_buffer("pt_wavefront.counts", batch_bytes, Memory::Device)?,
            counts_read: ctx.create_buffer("pt_wavefront.counts_read", batch_bytes, Memory::Readback)?,
            trace_stats: ctx.create_buffer("pt_wavefront.trace_stats", 8, Memory::Device)?,
            slots,
            launches_per_sample: Cell::new(8.0),
        })
    }

    /// Records `launches` launches of the path kernel, each followed by the two traces.
    fn record_batch(
        &self,
        rec: &mut Recorder,
        binds: &[Bind],
        geometry: &[Bind],
        push: &PtWavefrontPush,
        slots: u32,
        launches: u32,
    ) -> Result<()> {
        rec.fill_buffer(&self.counts, 0);
        let groups = self.kernel.groups_for(slots);
        for launch in 0..launches {
            rec.dispatch(&self.kernel, binds, bytemuck::bytes_of(&PtWavefrontPush { launch, ..*push }), [groups, 1, 1])?;
            let (ext, shadow) = (Some((&self.counts, 2 * launch)), Some((&self.counts, 2 * launch + 1)));
            self.tracer.record_trace_queued(rec, geometry, &self.rays, &self.hits, &self.trace_stats, slots, ext, false)?;
            self.tracer.record_trace_queued(rec, geometry, &self.shadow_rays, &self.shadow_hits, &self.trace_stats, slots, shadow, true)?;
        }
        rec.copy_buffer(&self.counts, &self.counts_read, self.counts.size());
        Ok(())
    }
}

/// Launches of the next batch: the first of a pass sized by what the last pass took per
/// sample of a slot (a few more, so most passes take one batch), later ones a quarter of the
/// launches so far (the tail of the longest paths).
fn batch_launches(first: bool, samples_per_slot: u32, launches_per_sample: f64, done: u32) -> u32 {
    let n = match first {
        true => (samples_per_slot as f64 * launches_per_sample * 1.1).ceil() as u32 + 2,
        false => done / 4,
    };
    n.clamp(4, abi::WF_MAX_BATCH)
}

impl IntegratorKernels for WavefrontPathTracer {
    fn kernels(&self) -> Vec<&Kernel> {
        let [closest, any] = self.tracer.trace_kernels();
        vec![&self.kernel, closest, any]
    }

    fn storage_bytes(&self) -> u64 {
        self.slots * SLOT_BYTES
    }

    fn sized_by_pixels(&self) -> bool {
        true
    }

    fn wavefront(&self) -> bool {
        true
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let (scene, film) = (inputs.scene, inputs.film);
        let pt = super::pt::pt_push(inputs, first, spp);
        let slices = pt.slices.max(1);
        let push = PtWavefrontPush { pt: PtPush { slices, ..pt }, ..Default::default() };
        let slots = crate::gpu_data::tiled_invocations(film.width, film.height) * slices;
        assert!(slots as u64 <= self.slots, "a pass of {slots} slots on storage for {}", self.slots);
        let geometry = scene.binds();
        let mut binds = geometry.clone();
        binds.extend([
            Bind::buffer(abi::BIND_ACCUM, &film.accum),
            Bind::buffer(abi::BIND_RENDER_STATS, &film.stats),
            Bind::buffer(abi::BIND_SLICES, film.slices_buffer()),
            Bind::buffer(abi::BIND_PT_SUSPENDED, &self.state),
            Bind::buffer(abi::BIND_WF_RAYS, &self.rays),
            Bind::buffer(abi::BIND_WF_HITS, &self.hits),
            Bind::buffer(abi::BIND_WF_SHADOW_RAYS, &self.shadow_rays),
            Bind::buffer(abi::BIND_WF_SHADOW_HITS, &self.shadow_hits),
            Bind::buffer(abi::BIND_WF_CONTRIB, &self.contrib),
            Bind::buffer(abi::BIND_WF_INDEX, &self.index),
            Bind::buffer(abi::BIND_WF_COUNTS, &self.counts),
        ]);
        let samples_per_slot = spp.div_ceil(slices);
        let mut done = 0u32;
        loop {
            let launches = batch_launches(done == 0, samples_per_slot, self.launches_per_sample.get(), done);
            ctx.submit("wavefront path tracing", |rec| {
                if done == 0 {
                    // Every slot starts its pass fresh with nothing pending; slices sum from 0.
                    rec.fill_buffer(&self.state, 0);
                    rec.fill_buffer(&self.contrib, 0);
                    if slices > 1 {
                        rec.fill_buffer(film.slices_buffer(), 0);
                    }
                }
                self.record_batch(rec, &binds, &geometry, &push, slots, launches)
            })?;
            let counts: Vec<u32> = self.counts_read.read()?;
            let queued: Vec<u32> = counts.chunks(2).take(launches as usize).map(|c| c[0] + c[1]).collect();
            // The first launch that queued no ray ends the pass (the rest found nothing to do).
            match queued.iter().position(|&n| n == 0) {
                Some(last) => {
                    done += last as u32 + 1;
                    break;
                }
                None => done += launches,
            }
        }
        self.launches_per_sample.set(done as f64 / samples_per_slot as f64);
        if slices > 1 {
            ctx.submit("wavefront film", |rec| film.record_add_slices(rec, slices))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batches_cover_the_pass_and_stay_bounded() {
        // The first batch of a pass: the last pass's launches per sample, 10 % and 2 more.
        assert_eq!(batch_launches(true, 8, 6.0, 0), 55);
        assert_eq!(batch_launches(true, 1, 1.0, 0), 4);
        assert_eq!(batch_launches(true, 1000, 8.0, 0), abi::WF_MAX_BATCH);
        // Later ones: a quarter of the launches so far, at least 4.
        assert_eq!(batch_launches(false, 8, 6.0, 55), 13);
        assert_eq!(batch_launches(false, 8, 6.0, 5), 4);
    }
}
