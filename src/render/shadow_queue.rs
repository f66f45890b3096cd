//! The shadow-ray queue of the megakernels (`--shadow-queue`; docs/integrators.md, "Shadow-ray
//! queue"): pt-nee's kernel and BDPT's camera pass queue their shadow rays with what each adds
//! if clear (`glsl/common/shadow_queue.glsl`), and `shadow_queue.comp` traces them after the
//! launch and adds the clear ones to the same pixel sums; BDPT's light pass queues its joins to
//! the camera, which `shadow_queue_splat.comp` traces and splats.

use super::{film::Film, gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// The queue's shape (`--shadow-queue SLOTS[/SAMPLES][/pause]`). `slots` per megakernel
/// invocation. pt-nee renders a pass in launches of `chunk_samples` samples per invocation,
/// each followed by the queue's kernel; where an invocation's slots are full it traces the
/// shadow ray itself (a second traversal in the kernel), or with `pause` stops before its next
/// bounce for the next launch to resume its path (the kernel then holds no shadow-ray
/// traversal), one more launch finishing the paths still paused. BDPT's camera pass (one
/// camera path per invocation) uses `slots` only and traces what does not fit itself.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShadowQueue {
    /// Queue slots per invocation (the kernels' SPEC_SHADOW_QUEUE).
    pub slots: u32,
    /// pt-nee: samples per invocation a launch adds.
    pub chunk_samples: u32,
    /// pt-nee: a path whose invocation's slots are full pauses until the next launch.
    pub pause: bool,
}

impl std::fmt::Display for ShadowQueue {
    /// `--shadow-queue`'s form (for BDPT's camera pass only its slots count).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}{}", self.slots, self.chunk_samples, if self.pause { "/pause" } else { "" })
    }
}

/// Bytes of a queue slot.
const SLOT_BYTES: u64 = std::mem::size_of::<abi::QueuedShadow>() as u64;
/// Bytes of an invocation's count of queued rays (`ShadowQueueTracer`'s counts).
const COUNT_BYTES: u64 = 4;

/// Queue memory an invocation with `slots` slots takes, with `fixed` more bytes of its own.
pub fn invocation_bytes(slots: u64, fixed: u64) -> u64 {
    slots * SLOT_BYTES + COUNT_BYTES + fixed
}

impl ShadowQueue {
    /// The queue for `invocations` megakernel invocations that need `fixed` more bytes each,
    /// within `budget` bytes: `slots` as asked where they fit, else fewer, `None` where fewer
    /// than `MIN_SLOTS` would.
    pub fn fit(self, invocations: u64, fixed: u64, budget: u64) -> Option<ShadowQueue> {
        const MIN_SLOTS: u32 = 4;
        let fit = (budget / invocations.max(1)).saturating_sub(invocation_bytes(0, fixed)) / SLOT_BYTES;
        let slots = self.slots.min(fit.min(u32::MAX as u64) as u32);
        (slots >= MIN_SLOTS).then_some(ShadowQueue { slots, ..self })
    }

    /// pt-nee: launches of a pass of `samples` samples per invocation.
    pub fn launches(self, samples: u32) -> u32 {
        samples.div_ceil(self.chunk_samples.max(1)).max(1)
    }
}

/// GPU memory the shadow-ray queue may take on `ctx`: a sixteenth of its largest device-local
/// heap, within one storage buffer's range.
pub fn budget(ctx: &Context) -> u64 {
    (ctx.info().device_local_bytes() / 16).min(ctx.info().max_storage_buffer_range as u64)
}

/// Invocations of a megakernel launch over a `width` x `height` film in `slices` slices (whole
/// workgroups).
pub fn invocations(width: u32, height: u32, slices: u32) -> u64 {
    let n = crate::gpu_data::tiled_invocations(width, height) as u64 * slices.max(1) as u64;
    n.next_multiple_of(abi::PT_WG_SIZE as u64)
}

/// The queue's kernels and storage for megakernel launches of up to `invocations` invocations.
pub struct ShadowQueueTracer {
    trace: Kernel,
    /// BDPT's light pass: the kernel that splats the clear joins to the camera.
    splat: Option<Kernel>,
    slots: u32,
    queue: Buffer,
    counts: Buffer,
}

impl ShadowQueueTracer {
    /// `splats`: also the kernel for BDPT's light pass (`record_splats`).
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        count_traversal: bool,
        slots: u32,
        invocations: u64,
        splats: bool,
    ) -> Result<ShadowQueueTracer, RenderError> {
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_STATS, value: count_traversal as u32 });
        specs.push(Spec { id: abi::SPEC_SHADOW_QUEUE, value: slots });
        let bytes = invocations * slots as u64 * SLOT_BYTES;
        let mem = |e| {
            RenderError::Memory(format!(
                "the shadow-ray queue ({} MiB) does not fit on the GPU ({e}): --shadow-queue off, or fewer slots",
                bytes >> 20
            ))
        };
        Ok(ShadowQueueTracer {
            trace: ctx.create_kernel(scene.bvh.kernel(&kernels::SHADOW_QUEUE_FORMS), &specs)?,
            splat: if splats { Some(ctx.create_kernel(scene.bvh.kernel(&kernels::SHADOW_QUEUE_SPLAT_FORMS), &specs)?) } else { None },
            slots,
            queue: ctx.create_buffer("shadow_queue.rays", bytes, Memory::Device).map_err(mem)?,
            counts: ctx.create_buffer("shadow_queue.counts", invocations * COUNT_BYTES, Memory::Device).map_err(mem)?,
        })
    }

    /// The megakernels' specialisation: this queue's slots.
    pub fn spec(&self) -> Spec {
        Spec { id: abi::SPEC_SHADOW_QUEUE, value: self.slots }
    }

    /// The queue's kernels (the splatting one where made).
    pub fn kernels(&self) -> impl Iterator<Item = &Kernel> {
        std::iter::once(&self.trace).chain(self.splat.as_ref())
    }

    pub fn bytes(&self) -> u64 {
        self.queue.size() + self.counts.size()
    }

    /// The queue's bindings for the megakernel and the queue's kernel.
    pub fn binds(&self) -> [Bind<'_>; 2] {
        [Bind::buffer(abi::BIND_SHADOW_QUEUE, &self.queue), Bind::buffer(abi::BIND_SHADOW_COUNTS, &self.counts)]
    }

    /// Bindings for a megakernel without the queue (it declares them, never touches them).
    pub fn unused_binds(film: &Film) -> [Bind<'_>; 2] {
        [Bind::buffer(abi::BIND_SHADOW_QUEUE, &film.stats), Bind::buffer(abi::BIND_SHADOW_COUNTS, &film.stats)]
    }

    /// Records the queue's kernel after a megakernel launch of `groups` workgroups over `film`
    /// in `slices` slices (`binds`: the megakernel's, with the queue's).
    pub fn record(&self, rec: &mut Recorder, binds: &[Bind], film: &Film, slices: u32, groups: u32) -> Result<()> {
        let push = abi::ShadowQueuePush { width: film.width, height: film.height, slices: slices.max(1), pad: 0 };
        rec.dispatch(&self.trace, binds, bytemuck::bytes_of(&push), [groups, 1, 1])
    }

    /// Records the splatting kernel after a BDPT light pass of `paths` light paths in `groups`
    /// workgroups (`binds`: the light pass's, with the queue's and the splat buffer).
    pub fn record_splats(&self, rec: &mut Recorder, binds: &[Bind], paths: u32, groups: u32) -> Result<()> {
        let splat = self.splat.as_ref().expect("the queue was made without its splatting kernel");
        let push = abi::ShadowQueuePush { width: paths, height: 1, slices: 1, pad: 0 };
        rec.dispatch(splat, binds, bytemuck::bytes_of(&push), [groups, 1, 1])
    }
}
