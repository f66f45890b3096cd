use std::cell::RefCell;

use super::integrator::{IntegratorKernels, PassInputs};
use super::{film::Film, gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::PtPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// pt-nee's shadow-ray queue (`--shadow-queue`): the megakernel queues each light sample's
/// shadow ray with what it adds, `slots` per invocation, and `shadow_queue.comp` traces them
/// after it. A pass is several launches of the megakernel, each followed by the queue's
/// kernel, each rendering `chunk_samples` more samples per invocation. Where an invocation's
/// slots are full, it traces the shadow ray itself (a second traversal in the kernel), or with
/// `pause` stops before its next bounce for the next launch to resume its path (the kernel
/// then holds no shadow-ray traversal), one more launch finishing the paths still paused.
/// docs/integrators.md, "Shadow-ray queue".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShadowQueue {
    /// Queue slots per invocation (the kernels' SPEC_SHADOW_QUEUE).
    pub slots: u32,
    /// Samples per invocation a launch adds.
    pub chunk_samples: u32,
    /// A path whose invocation's slots are full pauses until the next launch.
    pub pause: bool,
}

impl std::fmt::Display for ShadowQueue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}{}", self.slots, self.chunk_samples, if self.pause { "/pause" } else { "" })
    }
}

impl ShadowQueue {
    /// Bytes of queue, counts and suspended path one invocation needs.
    fn bytes_per_invocation(self) -> u64 {
        self.slots as u64 * std::mem::size_of::<abi::QueuedShadow>() as u64 + 4 + std::mem::size_of::<abi::PtSuspended>() as u64
    }

    /// The queue for `invocations` megakernel invocations within `budget` bytes: `slots` as
    /// asked where they fit, else fewer, `None` where fewer than `MIN_SLOTS` would.
    pub fn fit(self, invocations: u64, budget: u64) -> Option<ShadowQueue> {
        const MIN_SLOTS: u32 = 4;
        let per_slot = std::mem::size_of::<abi::QueuedShadow>() as u64;
        let fixed = self.bytes_per_invocation() - self.slots as u64 * per_slot;
        let fit = (budget / invocations.max(1)).saturating_sub(fixed) / per_slot;
        let slots = self.slots.min(fit.min(u32::MAX as u64) as u32);
        (slots >= MIN_SLOTS).then_some(ShadowQueue { slots, ..self })
    }

    /// Launches of a pass of `samples` samples per invocation.
    fn launches(self, samples: u32) -> u32 {
        samples.div_ceil(self.chunk_samples.max(1)).max(1)
    }
}

/// GPU memory the shadow-ray queue may take on `ctx`: a sixteenth of its largest
/// device-local heap, within one storage buffer's range.
pub fn shadow_queue_budget(ctx: &Context) -> u64 {
    (ctx.info().device_local_bytes() / 16).min(ctx.info().max_storage_buffer_range as u64)
}

struct QueueBuffers {
    queue: Buffer,
    counts: Buffer,
    suspended: Buffer,
    invocations: u64,
}

/// The queue's kernels: with `pause` the megakernel that stops where the slots are full (else
/// every launch runs `PathTracer::kernel`, which finishes every path), and the queue's own.
struct QueueKernels {
    pause: Option<Kernel>,
    trace: Kernel,
}

/// The megakernel path tracer (`glsl/kernels/pt.comp`), specialised for the scene.
pub struct PathTracer {
    kernel: Kernel,
    /// With the shadow-ray queue: its kernel, its shape and its buffers (made by the first pass
    /// and grown when a pass needs more invocations).
    queue: Option<(QueueKernels, ShadowQueue, RefCell<Option<QueueBuffers>>)>,
}

impl PathTracer {
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        nee: bool,
        settings: &super::RenderSettings,
        regenerate: bool,
        one_trace: bool,
        queue: Option<ShadowQueue>,
    ) -> Result<PathTracer> {
        let sampler = settings.sampler;
        let queue = queue.filter(|_| nee);
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_STATS, value: settings.count_traversal as u32 });
        let shared = specs.clone();
        specs.push(Spec { id: abi::SPEC_NEE, value: nee as u32 });
        specs.push(sampler.spec());
        specs.push(Spec { id: abi::SPEC_PATH_REGENERATION, value: regenerate as u32 });
        specs.push(Spec { id: abi::SPEC_ONE_TRACE, value: one_trace as u32 });
        let slots = Spec { id: abi::SPEC_SHADOW_QUEUE, value: queue.map_or(0, |q| q.slots) };
        let with = |extra: &[Spec]| specs.iter().chain(extra).copied().collect::<Vec<_>>();
        let forms = scene.bvh.kernel(&kernels::PT_FORMS);
        let kernel = ctx.create_kernel(forms, &with(&[slots]))?;
        let queue = match queue {
            Some(q) => {
                let pause = Spec { id: abi::SPEC_SHADOW_SUSPEND, value: 1 };
                let trace_specs: Vec<Spec> = shared.iter().copied().chain([slots]).collect();
                let k = QueueKernels {
                    pause: q.pause.then(|| ctx.create_kernel(forms, &with(&[slots, pause]))).transpose()?,
                    trace: ctx.create_kernel(scene.bvh.kernel(&kernels::SHADOW_QUEUE_FORMS), &trace_specs)?,
                };
                Some((k, q, RefCell::new(None)))
            }
            None => None,
        };
        Ok(PathTracer { kernel, queue })
    }

    /// The shadow-ray queue in use, if any.
    pub fn shadow_queue(&self) -> Option<ShadowQueue> {
        self.queue.as_ref().map(|q| q.1)
    }

    /// Records one pass: `push.spp` samples for every pixel.
    fn record(&self, rec: &mut Recorder, scene: &GpuScene, film: &Film, push: &PtPush, buffers: Option<&QueueBuffers>) -> Result<()> {
        let mut binds = scene.binds();
        binds.push(Bind::buffer(abi::BIND_ACCUM, &film.accum));
        binds.push(Bind::buffer(abi::BIND_RENDER_STATS, &film.stats));
        binds.push(Bind::buffer(abi::BIND_SLICES, film.slices_buffer()));
        let tiles = crate::gpu_data::tiled_invocations(film.width, film.height);
        let (Some((k, q, _)), Some(b)) = (&self.queue, buffers) else {
            // Without the queue its bindings hold the film's stats (never read or written).
            binds.push(Bind::buffer(abi::BIND_SHADOW_QUEUE, &film.stats));
            binds.push(Bind::buffer(abi::BIND_SHADOW_COUNTS, &film.stats));
            binds.push(Bind::buffer(abi::BIND_PT_SUSPENDED, &film.stats));
            let slices = push.slices.max(1);
            rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(push), [self.kernel.groups_for(tiles * slices), 1, 1])?;
            return film.record_add_slices(rec, slices);
        };
        binds.push(Bind::buffer(abi::BIND_SHADOW_QUEUE, &b.queue));
        binds.push(Bind::buffer(abi::BIND_SHADOW_COUNTS, &b.counts));
        binds.push(Bind::buffer(abi::BIND_PT_SUSPENDED, &b.suspended));
        // Every path starts fresh; the kernels add into the slices, so they start at zero.
        let slices = push.slices.max(1);
        rec.fill_buffer(&b.suspended, 0);
        if slices > 1 {
            rec.fill_buffer(film.slices_buffer(), 0);
        }
        let groups = [self.kernel.groups_for(tiles * slices), 1, 1];
        let samples = push.spp.div_ceil(slices);
        let launches = q.launches(samples);
        for launch in 1..=launches + q.pause as u32 {
            // Samples below `spp` of the pass's: `chunk_samples` more per invocation a launch;
            // with `pause` one more that finishes what paused in the last (few lanes).
            let spp = (launch * q.chunk_samples * slices).min(push.spp);
            let kernel = match &k.pause {
                Some(pause) if launch <= launches => pause,
                _ => &self.kernel,
            };
            let p = PtPush { spp, ..*push };
            rec.dispatch(kernel, &binds, bytemuck::bytes_of(&p), groups)?;
            rec.dispatch(&k.trace, &binds, bytemuck::bytes_of(&p), groups)?;
        }
        film.record_add_slices(rec, slices)
    }

    /// The queue's buffers for `invocations` invocations (made or grown here).
    fn queue_buffers(&self, ctx: &Context, invocations: u64) -> std::result::Result<(), RenderError> {
        let Some((_, q, cell)) = &self.queue else { return Ok(()) };
        if cell.borrow().as_ref().is_some_and(|b| b.invocations >= invocations) {
            return Ok(());
        }
        cell.replace(None);
        let bytes = invocations * q.slots as u64 * std::mem::size_of::<abi::QueuedShadow>() as u64;
        let mem = |e| {
            RenderError::Memory(format!(
                "the shadow-ray queue ({} MiB) does not fit on the GPU ({e}): --shadow-queue off, or fewer slots",
                bytes >> 20
            ))
        };
        let queue = ctx.create_buffer("pt.shadow_queue", bytes, Memory::Device).map_err(mem)?;
        let counts = ctx.create_buffer("pt.shadow_counts", invocations * 4, Memory::Device).map_err(mem)?;
        let suspended_bytes = invocations * std::mem::size_of::<abi::PtSuspended>() as u64;
        let suspended = ctx.create_buffer("pt.suspended", suspended_bytes, Memory::Device).map_err(mem)?;
        cell.replace(Some(QueueBuffers { queue, counts, suspended, invocations }));
        Ok(())
    }
}

impl IntegratorKernels for PathTracer {
    fn kernels(&self) -> Vec<&Kernel> {
        match &self.queue {
            Some((k, _, _)) => k.pause.iter().chain([&self.kernel, &k.trace]).collect(),
            None => vec![&self.kernel],
        }
    }

    fn storage_bytes(&self) -> u64 {
        self.queue.as_ref().and_then(|(_, q, cell)| cell.borrow().as_ref().map(|b| b.invocations * q.bytes_per_invocation())).unwrap_or(0)
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let (s, scene, film) = (inputs.settings, inputs.scene, inputs.film);
        let push = PtPush {
            camera: inputs.camera,
            sample_base: first,
            spp,
            seed: s.seed,
            emitter_count: scene.emitter_count,
            emitter_weight: scene.emitter_weight,
            max_depth: s.max_depth,
            rr_depth: s.rr_depth,
            slices: inputs.slices.min(spp),
        };
        let invocations = self.kernel.groups_for(crate::gpu_data::tiled_invocations(film.width, film.height) * push.slices.max(1)) as u64
            * abi::PT_WG_SIZE as u64;
        self.queue_buffers(ctx, invocations)?;
        let buffers = self.queue.as_ref().map(|q| q.2.borrow());
        let buffers = buffers.as_ref().and_then(|b| b.as_ref());
        Ok(ctx.submit("render pass", |rec| self.record(rec, scene, film, &push, buffers))?)
    }
}
