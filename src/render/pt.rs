use super::integrator::{IntegratorKernels, PassInputs};
use super::shadow_queue::{ShadowQueue, ShadowQueueTracer};
use super::{film::Film, gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::PtPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// Bytes pt-nee's queue needs per invocation besides its slots: the paused path.
pub const PAUSED_PATH_BYTES: u64 = std::mem::size_of::<abi::PtSuspended>() as u64;

/// The path tracers' push constants for samples `first..first + spp` of every pixel, over at
/// most `inputs.slices` sample slices (pt.comp and pt_wavefront.comp).
pub(super) fn pt_push(inputs: &PassInputs, first: u32, spp: u32) -> PtPush {
    let (s, scene) = (inputs.settings, inputs.scene);
    PtPush {
        camera: inputs.camera,
        sample_base: first,
        spp,
        seed: s.seed,
        emitter_count: scene.emitter_count,
        emitter_weight: scene.emitter_weight,
        max_depth: s.max_depth,
        rr_depth: s.rr_depth,
        slices: inputs.slices.min(spp),
    }
}

/// pt-nee's shadow-ray queue: its kernel and slots, its shape, the kernel that pauses paths
/// where the slots are full (with `pause`; else every launch runs `PathTracer::kernel`, which
/// finishes every path), and the paused paths.
struct Queue {
    tracer: ShadowQueueTracer,
    shape: ShadowQueue,
    pause: Option<Kernel>,
    paused: Buffer,
}

/// The megakernel path tracer (`glsl/common/pt_kernel.glsl`: `pt.comp`, `pt_loop.comp` or
/// `pt_queue.comp` by how its samples run), specialised for the scene.
pub struct PathTracer {
    kernel: Kernel,
    queue: Option<Queue>,
}

impl PathTracer {
    /// `queue`: pt-nee's shadow-ray queue for launches of up to `invocations` invocations.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        nee: bool,
        settings: &super::RenderSettings,
        regenerate: bool,
        one_trace: bool,
        queue: Option<ShadowQueue>,
        invocations: u64,
    ) -> std::result::Result<PathTracer, RenderError> {
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_STATS, value: settings.count_traversal as u32 });
        specs.push(Spec { id: abi::SPEC_NEE, value: nee as u32 });
        specs.push(settings.sampler.spec());
        specs.push(Spec { id: abi::SPEC_ONE_TRACE, value: one_trace as u32 });
        let Some(shape) = queue.filter(|_| nee) else {
            // One module per loop form (glsl/common/pt_kernel.glsl).
            let forms = scene.bvh.kernel(if regenerate { &kernels::PT_FORMS } else { &kernels::PT_LOOP_FORMS });
            return Ok(PathTracer { kernel: ctx.create_kernel(forms, &specs)?, queue: None });
        };
        // The queue's launches regenerate paths whatever `regenerate` says.
        let forms = scene.bvh.kernel(&kernels::PT_QUEUE_FORMS);
        let tracer = ShadowQueueTracer::new(ctx, scene, settings.count_traversal, shape.slots, invocations, false)?;
        specs.push(tracer.spec());
        let pause = match shape.pause {
            true => {
                let pause = Spec { id: abi::SPEC_SHADOW_SUSPEND, value: 1 };
                Some(ctx.create_kernel(forms, &specs.iter().copied().chain([pause]).collect::<Vec<_>>())?)
            }
            false => None,
        };
        let paused = ctx.create_buffer("pt.paused_paths", invocations * PAUSED_PATH_BYTES, Memory::Device)?;
        let queue = Queue { tracer, shape, pause, paused };
        Ok(PathTracer { kernel: ctx.create_kernel(forms, &specs)?, queue: Some(queue) })
    }

    /// Records one pass: `push.spp` samples for every pixel.
    fn record(&self, rec: &mut Recorder, scene: &GpuScene, film: &Film, push: &PtPush) -> Result<()> {
        let mut binds = scene.binds();
        binds.push(Bind::buffer(abi::BIND_ACCUM, &film.accum));
        binds.push(Bind::buffer(abi::BIND_RENDER_STATS, &film.stats));
        binds.push(Bind::buffer(abi::BIND_SLICES, film.slices_buffer()));
        let slices = push.slices.max(1);
        let groups = self.kernel.groups_for(crate::gpu_data::tiled_invocations(film.width, film.height) * slices);
        let Some(q) = &self.queue else {
            // Without the queue its bindings hold the film's stats (never read or written).
            binds.extend(ShadowQueueTracer::unused_binds(film));
            binds.push(Bind::buffer(abi::BIND_PT_SUSPENDED, &film.stats));
            rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(push), [groups, 1, 1])?;
            return film.record_add_slices(rec, slices);
        };
        binds.extend(q.tracer.binds());
        binds.push(Bind::buffer(abi::BIND_PT_SUSPENDED, &q.paused));
        // Every path starts fresh; the kernels add into the slices, so they start at zero.
        rec.fill_buffer(&q.paused, 0);
        if slices > 1 {
            rec.fill_buffer(film.slices_buffer(), 0);
        }
        let launches = q.shape.launches(push.spp.div_ceil(slices));
        for launch in 1..=launches + q.shape.pause as u32 {
            // Samples below `spp` of the pass's: `chunk_samples` more per invocation a launch;
            // with `pause` one more that finishes what paused in the last (few lanes).
            let spp = (launch * q.shape.chunk_samples * slices).min(push.spp);
            let kernel = match &q.pause {
                Some(pause) if launch <= launches => pause,
                _ => &self.kernel,
            };
            rec.dispatch(kernel, &binds, bytemuck::bytes_of(&PtPush { spp, ..*push }), [groups, 1, 1])?;
            q.tracer.record(rec, &binds, film, slices, groups)?;
        }
        film.record_add_slices(rec, slices)
    }
}

impl IntegratorKernels for PathTracer {
    fn kernels(&self) -> Vec<&Kernel> {
        match &self.queue {
            Some(q) => q.pause.iter().chain([&self.kernel]).chain(q.tracer.kernels()).collect(),
            None => vec![&self.kernel],
        }
    }

    fn shadow_queue(&self) -> Option<ShadowQueue> {
        self.queue.as_ref().map(|q| q.shape)
    }

    fn storage_bytes(&self) -> u64 {
        self.queue.as_ref().map_or(0, |q| q.tracer.bytes() + q.paused.size())
    }

    /// With the queue: its storage is sized by the film.
    fn sized_by_pixels(&self) -> bool {
        self.queue.is_some()
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let push = pt_push(inputs, first, spp);
        Ok(ctx.submit("render pass", |rec| self.record(rec, inputs.scene, inputs.film, &push))?)
    }
}
