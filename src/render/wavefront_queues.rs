//! What the wavefront integrators share (pt_wavefront.rs, bdpt_wavefront.rs): the ray queues
//! between a path kernel and the trace kernels of `crate::trace`, the lists of live slots each
//! launch runs (glsl/common/wf_active.glsl), and the batches of launches (path kernel,
//! closest-hit trace of the segments, any-hit trace of the shadow rays) that end in a read of
//! how many rays each launch queued.

use super::{gpu_scene::GpuScene, RenderError};
use crate::gpu::abi;
use crate::trace::{RayCounters, TraceOptions, Tracer};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};
use std::rc::Rc;

/// Dynamic fetch's refill (`TraceOptions::refill_lanes`) of the wavefront integrators' 4-wide
/// trace kernels on GPUs with subgroups of 32 lanes or more. NVIDIA H200, ms per run with a
/// launch's two traces running at once (session 21, measured 12 / 16 / 20 / 24 / 28 / 32):
/// textured Sponza pt-nee 55.1 / **54.7** / 54.7 / 54.8 / 55.4 / 56.9, bdpt 72.3 / **72.0** /
/// 72.3 / 72.7 / 73.2 / 74.5; DamagedHelmet bdpt 170.0 / **170.1** / 170.8 / - / 172.2 / -
/// (docs/results.md). `bench traversal`'s secondary rays alone prefer 28.
const REFILL_LANES: u32 = 16;

/// How the trace kernels of the wavefront integrators run: over the scene's BVH (on GPUs the
/// 4-wide one, `wavefront_bvh_layout`) with the lockstep loops, the ray count read from the
/// queue's counter; over the 4-wide BVH on GPUs (`on_cpu` false, `subgroup_size` 32 or more)
/// as persistent threads with dynamic fetch, refilled at 16 lanes (`REFILL_LANES`). NVIDIA
/// H200, ms per run against one invocation per ray (session 18, refilled at 28): textured
/// Sponza pt-nee 58.2 against 60.3, pt 44.0 against 45.9, DamagedHelmet pt-nee 25.1 against
/// 24.6 (docs/results.md, "A wavefront path tracer"). `alpha`: where the scene has alpha-tested or
/// blended triangles (trace_alpha*.comp), each ray carrying its path's stochastic-opacity seed.
pub fn trace_options(scene: &GpuScene, on_cpu: bool, subgroup_size: u32, alpha: bool) -> TraceOptions {
    let mut opts = TraceOptions::new(scene.bvh.tri_test);
    opts.layout = scene.bvh.layout;
    opts.alpha = alpha.then_some(scene.features);
    opts.ray_seed = alpha;
    opts.count_buffer = true;
    opts.any_hit_words = true;
    opts.ray_words = ray_words(alpha);
    if scene.bvh.layout == crate::bvh::BvhLayout::Bvh4 && !on_cpu && subgroup_size >= 32 {
        opts.persistent = Some(0);
        opts.refill_lanes = REFILL_LANES;
    }
    opts
}

/// The forms of the segments and of the shadow rays the wavefront passes queue (the path
/// kernels' SPEC_WF_SEGMENT_WORDS and SPEC_WF_SHADOW_WORDS, the trace kernels'
/// `TraceOptions::ray_words`): whole `GpuRay`s where the scene has alpha (each ray carries its
/// path's opacity seed), else the compact forms of glsl/common/ray_words.glsl, 24 and 28 bytes
/// of memory traffic a ray instead of 32.
pub fn ray_words(alpha: bool) -> [u32; 2] {
    match alpha {
        true => [abi::RAY_WORDS_FULL; 2],
        false => [abi::RAY_WORDS_SEGMENT, abi::RAY_WORDS_BOUNDED],
    }
}

/// The queues of a wavefront pass of up to `slots` slots, each queueing one segment and up to
/// `shadow` shadow rays a launch, and the trace kernels that trace them.
pub struct Queues {
    tracer: Rc<Tracer>,
    /// Queues that share another's tracer (`sharing`) take their rays with their own
    /// persistent counters, so that both may trace at once.
    counters: Option<[Buffer; 2]>,
    rays: Buffer,
    hits: Buffer,
    shadow_rays: Buffer,
    shadow_hits: Buffer,
    /// Per launch of a batch, the segments and shadow rays it queued; copied to one of
    /// `counts_read` at its end (the batch's `readback`: BDPT's two passes each have their own,
    /// so that one pass may run while the host reads what the other queued).
    counts: Buffer,
    counts_read: [Buffer; 2],
    /// The trace kernels' node and triangle counters (unused: not counted).
    trace_stats: Buffer,
    /// Where each launch runs only the slots the launch before listed (BDPT's passes).
    live: Option<LiveSlots>,
    slots: u32,
    shadow: u32,
    /// Invocations the device runs at once (`trace::default_persistent_groups` workgroups), for
    /// `finish_below` where the traces are not persistent; None on CPU devices.
    device_resident: Option<u32>,
}

/// Bytes per slot of `Queues` with `shadow` shadow rays: the segment and its hit (a `GpuHit`),
/// the shadow rays and theirs (one word each, `TraceOptions::any_hit_words`).
pub const fn queue_bytes(shadow: u32) -> u64 {
    32 + 16 + shadow as u64 * (32 + 4)
}

/// Bytes of a slot's path between launches (the path tracer's and BDPT's passes): the most
/// 16-byte words its stored form takes (WF_STATE_WORDS; one fewer in scenes without a medium or
/// alpha, where the kernels use a shorter stride).
pub const STATE_BYTES: u64 = abi::WF_STATE_WORDS as u64 * 16;

/// Bytes per slot of the lists of live slots (`Queues::new` with `live`): its places in both.
pub const LIVE_SLOT_BYTES: u64 = 2 * 4;

/// The lists of live slots: the launches' indirect dispatches (the path kernel's and its two
/// traces', which each launch's last workgroup sizes) and the slots each runs (BIND_WF_ACTIVE;
/// glsl/common/wf_active.glsl).
struct LiveSlots {
    active: Buffer,
}

/// Launches of a batch: `n`, at least 4 and at most `WF_MAX_BATCH`, rounded up to an even
/// number so that every batch starts at an even launch: the lists of live slots (and BDPT's
/// shadow-ray contributions) alternate between two halves with the launch's parity within the
/// pass. (The path tracer's first version of the lists took batches of odd length: a batch's
/// first launch then ran a stale list, 3 of 1152 values off in the test against the megakernel.)
pub fn even_batch(n: u32) -> u32 {
    const _: () = assert!(abi::WF_MAX_BATCH % 2 == 0);
    (n.clamp(4, abi::WF_MAX_BATCH) + 1) & !1
}

/// Bytes of BIND_WF_ACTIVE's indirect dispatches (the path kernel's, then the trace kernels'),
/// before its slot lists.
const DISPATCH_BYTES: u64 = (abi::WF_DISPATCH_ENTRIES + abi::WF_TRACE_DISPATCH_ENTRIES) as u64 * 16;

/// Byte offset in BIND_WF_ACTIVE of launch `l`'s closest-hit (`any_hit` false) or any-hit
/// trace's indirect dispatch.
fn trace_dispatch_offset(l: u32, any_hit: bool) -> u64 {
    (abi::WF_DISPATCH_ENTRIES + 2 * l + any_hit as u32) as u64 * 16
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
    // Whole 16-byte words: the any-hit kernels write one-word hits as parts of `uvec4`s.
    ctx.create_buffer(name, (slots * bytes).next_multiple_of(16), Memory::Device).map_err(|e| {
        RenderError::Memory(format!(
            "{what}'s {slots} slots ({} MiB) do not fit ({e}): lower --sample-slices or the image size, or add --wavefront off",
            (slots * slot_bytes) >> 20
        ))
    })
}

/// A step of a batch of launches (`steps`): commands that may run at once, recorded behind one
/// barrier; BDPT records two passes' steps side by side (bdpt_wavefront.rs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// The fills of the launches' counts and dispatches.
    Fills,
    /// The path kernel's launch `l` of the batch.
    Launch(u32),
    /// The traces of the segments and shadow rays launch `l` queued.
    Traces(u32),
    /// The finishing launch (after the batch's last launch's traces).
    Finish,
    /// The copies after the batch: its last dispatch, its counts to the host's buffer.
    Readback,
}

/// The steps of a batch of `launches` launches, with its finishing launch where `finish`.
pub fn steps(launches: u32, finish: bool) -> Vec<Step> {
    let mut s = vec![Step::Fills];
    for l in 0..launches {
        s.extend([Step::Launch(l), Step::Traces(l)]);
    }
    if finish {
        s.push(Step::Finish);
    }
    s.push(Step::Readback);
    s
}

/// The path kernel's push word for launch `l` of a batch: WF_ALL_SLOTS for a pass's first
/// (`start`).
pub fn launch_word(l: u32, start: bool) -> u32 {
    if start && l == 0 {
        l | abi::WF_ALL_SLOTS
    } else {
        l
    }
}

impl Queues {
    /// `what` names the integrator in errors (as `slot_buffer`), `prefix` its buffers. `live`:
    /// each launch after a pass's first runs only the slots that queued a ray in the launch
    /// before, from lists the path kernel writes (wf_active.glsl). BDPT's passes take them
    /// (their light paths' long tails); the path tracer does not: on the H200 they sped its
    /// 64-spp passes up 2-8 % but slowed its 1 s renders of the textured Sponza 2 % and the
    /// Cornell box's passes 12 % (a global atomic per subgroup and launch for paths that
    /// regenerate and so stay live; docs/results.md, "BDPT's light pass as a wavefront").
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        (what, prefix): (&str, &str),
        slots: u64,
        shadow: u32,
        slot_bytes: u64,
        live: bool,
    ) -> std::result::Result<Self, RenderError> {
        let opts = trace_options(scene, super::on_cpu(ctx), ctx.info().subgroup_size, scene.features.alpha);
        let tracer = Rc::new(Tracer::with_options(ctx, &opts)?);
        Queues::with_tracer(ctx, (tracer, None), (what, prefix), slots, shadow, slot_bytes, live)
    }

    /// Queues of their own (`new`'s) that trace with this one's kernels, taking their rays with
    /// their own counters: the two may trace at once (BDPT's passes side by side).
    pub fn sharing(
        &self,
        ctx: &Context,
        (what, prefix): (&str, &str),
        slots: u64,
        shadow: u32,
        slot_bytes: u64,
    ) -> std::result::Result<Self, RenderError> {
        let counters = self.tracer.create_counters(ctx, prefix)?;
        Queues::with_tracer(ctx, (self.tracer.clone(), Some(counters)), (what, prefix), slots, shadow, slot_bytes, self.live.is_some())
    }

    #[allow(clippy::too_many_arguments)]
    fn with_tracer(
        ctx: &Context,
        (tracer, counters): (Rc<Tracer>, Option<[Buffer; 2]>),
        (what, prefix): (&str, &str),
        slots: u64,
        shadow: u32,
        slot_bytes: u64,
        live: bool,
    ) -> std::result::Result<Self, RenderError> {
        let buffer = |name: &str, bytes: u64| slot_buffer(ctx, what, &format!("{prefix}.{name}"), slots, bytes, slot_bytes);
        let batch_bytes = abi::WF_MAX_BATCH as u64 * 8;
        Ok(Queues {
            tracer,
            counters,
            rays: buffer("rays", 32)?,
            hits: buffer("hits", 16)?,
            shadow_rays: buffer("shadow_rays", 32 * shadow as u64)?,
            shadow_hits: buffer("shadow_hits", 4 * shadow as u64)?,
            counts: ctx.create_buffer(&format!("{prefix}.counts"), batch_bytes, Memory::Device)?,
            counts_read: [
                ctx.create_buffer(&format!("{prefix}.counts_read0"), batch_bytes, Memory::Readback)?,
                ctx.create_buffer(&format!("{prefix}.counts_read1"), batch_bytes, Memory::Readback)?,
            ],
            trace_stats: ctx.create_buffer(&format!("{prefix}.trace_stats"), 8, Memory::Device)?,
            live: match live {
                true => Some(LiveSlots {
                    active: ctx.create_indirect_buffer(&format!("{prefix}.active"), DISPATCH_BYTES + slots * LIVE_SLOT_BYTES).map_err(
                        |e| {
                            RenderError::Memory(format!(
                                "{what}'s {slots} slots ({} MiB) do not fit ({e}): lower --sample-slices or the image size, or add --wavefront off",
                                (slots * slot_bytes) >> 20
                            ))
                        },
                    )?,
                }),
                false => None,
            },
            slots: u32::try_from(slots).map_err(|_| RenderError::Memory(format!("{what}: {slots} slots are too many")))?,
            shadow,
            device_resident: (!super::on_cpu(ctx))
                .then(|| crate::trace::default_persistent_groups(ctx.info()).saturating_mul(abi::TRACE_WG_SIZE)),
        })
    }

    /// Shadow rays a slot queues a launch at most.
    pub fn shadow(&self) -> u32 {
        self.shadow
    }

    /// The kernels besides the path kernel: the trace kernels (closest hit, any hit).
    pub fn kernels(&self) -> Vec<&Kernel> {
        self.tracer.trace_kernels().to_vec()
    }

    /// With the lists of live slots: the path kernel's specialisation constant that bounds the
    /// workgroups of the traces it sizes (SPEC_WF_TRACE_GROUPS): what a direct launch over the
    /// most rays a launch may queue takes.
    pub fn trace_groups_spec(&self) -> Spec {
        let t = &self.tracer;
        let most = t.queued_groups(self.slots).max(t.queued_groups(self.slots.saturating_mul(self.shadow)));
        Spec { id: abi::SPEC_WF_TRACE_GROUPS, value: most }
    }

    /// The path kernel's specialisation constants for the forms of the rays it queues (as the
    /// trace kernels read them: `ray_words`).
    pub fn ray_specs(&self) -> [Spec; 2] {
        let [segment, shadow] = self.tracer.options().ray_words;
        [Spec { id: abi::SPEC_WF_SEGMENT_WORDS, value: segment }, Spec { id: abi::SPEC_WF_SHADOW_WORDS, value: shadow }]
    }

    /// The queues' bindings for the path kernel.
    pub fn binds(&self) -> Vec<Bind<'_>> {
        let mut b = vec![
            Bind::buffer(abi::BIND_WF_RAYS, &self.rays),
            Bind::buffer(abi::BIND_WF_HITS, &self.hits),
            Bind::buffer(abi::BIND_WF_SHADOW_RAYS, &self.shadow_rays),
            Bind::buffer(abi::BIND_WF_SHADOW_HITS, &self.shadow_hits),
            Bind::buffer(abi::BIND_WF_COUNTS, &self.counts),
        ];
        b.extend(self.live.as_ref().map(|l| Bind::buffer(abi::BIND_WF_ACTIVE, &l.active)));
        b
    }

    /// Records the path kernel's launch `word` (its launch in the batch, with WF_ALL_SLOTS for
    /// a pass's first): over all `slots` slots, or with the lists of live slots (after a pass's
    /// first launch) over the slots the launch before listed, from the indirect dispatch sized
    /// after it.
    pub fn dispatch_path(&self, rec: &mut Recorder, kernel: &Kernel, binds: &[Bind], push: &[u8], slots: u32, word: u32) -> Result<()> {
        match &self.live {
            Some(l) if word & abi::WF_ALL_SLOTS == 0 => rec.dispatch_indirect(kernel, binds, push, &l.active, word as u64 * 16),
            _ => rec.dispatch(kernel, binds, push, [kernel.groups_for(slots), 1, 1]),
        }
    }

    /// Records `launches` launches over `slots` slots: `launch(rec, word)` records the path
    /// kernel's launch (`dispatch_path`; `word` is the launch in the batch, with WF_ALL_SLOTS
    /// for a pass's first where `start`; with the lists of live slots its last workgroup sizes
    /// the next launch's dispatch and its traces'), then the segments and shadow rays it queued
    /// are traced; the last launch's dispatch moves to entry 0 for the next batch, and the ray
    /// counts are read back at the end (`first_idle_launch`). Each step of `steps` behind a
    /// barrier.
    pub fn record_batch(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        slots: u32,
        (launches, readback): (u32, usize),
        start: bool,
        mut launch: impl FnMut(&mut Recorder, u32) -> Result<()>,
    ) -> Result<()> {
        for step in steps(launches, false) {
            rec.concurrent(|rec| match step {
                Step::Launch(l) => launch(rec, launch_word(l, start)),
                step => self.record_step(rec, geometry, slots, (launches, readback), step),
            })?;
        }
        Ok(())
    }

    /// Records `step` of a batch of `launches` over `slots` slots read back into
    /// `counts_read[readback]` (`steps`), without a barrier (inside `Recorder::concurrent`): the
    /// fills before it, a launch's traces, or the read-back after it. A path kernel's launch
    /// (`Step::Launch`, `Step::Finish`) is the integrator's (`dispatch_path`).
    pub fn record_step(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        slots: u32,
        (launches, readback): (u32, usize),
        step: Step,
    ) -> Result<()> {
        assert!(slots <= self.slots, "a pass of {slots} slots on storage for {}", self.slots);
        assert!(launches <= abi::WF_MAX_BATCH && launches % 2 == 0, "a batch of {launches} launches (even_batch)");
        match step {
            // Three fills of disjoint ranges.
            Step::Fills => {
                rec.fill_buffer(&self.counts, 0);
                if let Some(live) = &self.live {
                    // The launches' dispatches (entry 0 holds the first's) and their traces'.
                    rec.fill_buffer_range(&live.active, 16, launches as u64 * 16, 0);
                    rec.fill_buffer_range(&live.active, trace_dispatch_offset(0, false), 2 * launches as u64 * 16, 0);
                }
            }
            Step::Traces(l) => self.record_traces(rec, geometry, slots, l)?,
            Step::Readback => {
                // Two copies of disjoint ranges: the last launch's dispatch to entry 0 (where a
                // batch after this one starts), the counts to the host's buffer.
                if let Some(live) = &self.live {
                    rec.copy_buffer_range(&live.active, launches as u64 * 16, &live.active, 0, 16);
                }
                rec.copy_buffer(&self.counts, &self.counts_read[readback], self.counts.size());
            }
            Step::Launch(_) | Step::Finish => unreachable!("a path kernel's launch is the integrator's to record"),
        }
        Ok(())
    }

    /// Records the traces of launch `l` of a batch over `slots` slots: its segments' and its
    /// shadow rays'. With the lists, the path kernel has sized them. The two share no ray, hit
    /// or counter (their node and triangle counters, `trace_stats`, take atomics only, and only
    /// where traversal is counted, which the wavefront forms refuse): inside
    /// `Recorder::concurrent` the GPU may run them at once.
    fn record_traces(&self, rec: &mut Recorder, geometry: &[Bind], slots: u32, l: u32) -> Result<()> {
        let (t, stats) = (&self.tracer, &self.trace_stats);
        let (ext, shadow) = (Some((&self.counts, 2 * l)), Some((&self.counts, 2 * l + 1)));
        let sized = |any_hit| self.live.as_ref().map(|live| (&live.active, trace_dispatch_offset(l, any_hit)));
        let c = self.counters.as_ref().map_or_else(|| t.counters(), |[closest, any]| RayCounters { closest, any });
        t.record_trace_counted(rec, geometry, (&self.rays, &self.hits, stats), slots, ext, false, sized(false), c)?;
        let (rays, hits) = (&self.shadow_rays, &self.shadow_hits);
        t.record_trace_counted(rec, geometry, (rays, hits, stats), slots * self.shadow, shadow, true, sized(true), c)
    }

    /// After a batch of `launches` (read back into `counts_read[readback]`): the segments and
    /// shadow rays each launch queued. With `BIDIR_WF_LOG` set, prints them to stderr.
    pub fn queued(&self, launches: u32, readback: usize) -> Result<Vec<[u32; 2]>> {
        let counts: Vec<u32> = self.counts_read[readback].read()?;
        let queued: Vec<[u32; 2]> = counts.chunks(2).take(launches as usize).map(|c| [c[0], c[1]]).collect();
        if std::env::var_os("BIDIR_WF_LOG").is_some() {
            let rays: Vec<String> = queued.iter().map(|c| format!("{}+{}", c[0], c[1])).collect();
            eprintln!("wavefront batch of {launches} launches, segments+shadow rays queued: {}", rays.join(" "));
        }
        Ok(queued)
    }

    /// The first of `queued`'s launches that queued no ray (the pass is over after it), if one
    /// did.
    pub fn first_idle_launch(queued: &[[u32; 2]]) -> Option<u32> {
        queued.iter().position(|c| c[0] + c[1] == 0).map(|l| l as u32)
    }

    /// Live paths below which a pass's tail is left to its finishing launch
    /// (`WavefrontFinish::Auto`): a quarter of the rays the trace kernels run at once
    /// (`resident_rays`).
    pub fn finish_below(&self) -> u32 {
        let persistent = self.tracer.options().persistent.is_some();
        let launched = self.tracer.queued_groups(self.slots).saturating_mul(abi::TRACE_WG_SIZE);
        (resident_rays(persistent, launched, self.device_resident, self.slots) / 4).max(1)
    }
}

/// Rays the trace kernels of a pass over `slots` slots run at once: a persistent kernel's
/// resident invocations (`launched`, the workgroups it launches); else, on a GPU, the
/// invocations the device keeps resident (`device`), and on a CPU device the slots. The queues'
/// slots alone made the finishing threshold a quarter of the pass on GPUs whose traces are not
/// persistent (`--bvh cwbvh` or `bvh2`): an NVIDIA H100's Cornell box bdpt then took 153.90 ms
/// per 1024 spp over cwbvh and 156.51 over bvh2, against 115.41 and 124.28 without a finishing
/// launch (session 55; docs/results.md, "Rays in 24 and 28 bytes").
pub fn resident_rays(persistent: bool, launched: u32, device: Option<u32>, slots: u32) -> u32 {
    match (persistent, device) {
        (true, _) => launched,
        (false, Some(d)) => d,
        (false, None) => slots,
    }
    .min(slots)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn traces_run_at_once_what_the_device_keeps_resident() {
        // Persistent: the launched workgroups' invocations, at most the slots.
        assert_eq!(resident_rays(true, 270_336, Some(270_336), 16 << 20), 270_336);
        assert_eq!(resident_rays(true, 4_096, Some(270_336), 1_000), 1_000);
        // Not persistent: on a GPU what the device keeps resident, not the slots.
        assert_eq!(resident_rays(false, 1 << 18, Some(65_536), 16 << 20), 65_536);
        assert_eq!(resident_rays(false, 1 << 18, Some(65_536), 1_152), 1_152);
        // On a CPU device: the slots.
        assert_eq!(resident_rays(false, 1 << 18, None, 16 << 20), 16 << 20);
    }

    #[test]
    fn batches_are_even() {
        assert_eq!(even_batch(0), 4);
        assert_eq!(even_batch(5), 6);
        assert_eq!(even_batch(14), 14);
        assert_eq!(even_batch(1000), abi::WF_MAX_BATCH);
    }
}
