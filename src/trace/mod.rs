//! Ray queries on the GPU: the BVH uploaded, closest-hit and any-hit traversal over ray
//! buffers, and ray generation (primary, shadow, diffuse) with compaction. The megakernel
//! integrators call the same GLSL traversal inline; this module serves the tests, the
//! benchmark and the wavefront path tracer (`render::pt_wavefront`).

pub mod ray_forms;
pub mod sort;
pub use sort::RaySorter;

use crate::bvh::{BvhLayout, TriTest};
use crate::compute::Scan;
use crate::gpu::{
    abi::{self, GpuCamera, GpuHit, GpuRay, SecondaryPush, TracePush},
    kernels,
};
use crate::gpu_data::{GpuBvh, SceneFeatures};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// Which secondary rays to spawn from hits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Secondary {
    /// Toward a point light.
    Shadow,
    /// Cosine-distributed about the geometric normal.
    Diffuse,
}

/// What the trace kernels are specialised for.
#[derive(Clone, Copy, Debug)]
pub struct TraceOptions {
    pub tri_test: TriTest,
    /// Count nodes and triangles tested (slower; for reports, not timing).
    pub stats: bool,
    /// Skip alpha-masked triangles where their alpha texture is below the cutoff, as the
    /// integrators do (trace_alpha.comp, through glsl/common/scene.glsl): the features of the
    /// scene whose buffers (`GpuScene::binds`) are then given to `record_trace`.
    pub alpha: Option<SceneFeatures>,
    /// Persistent threads (Aila & Laine 2009, section 3): launch this many workgroups, whose
    /// subgroups fetch batches of rays from a global counter until none are left; 0: the
    /// device's default (`default_persistent_groups`). `None`: one invocation per ray.
    pub persistent: Option<u32>,
    /// Node layout of the BVHs traced (must match `GpuBvh::layout`).
    pub layout: BvhLayout,
    /// Binary layout: speculative while-while traversal (Aila & Laine 2009), the default;
    /// false: plain while-while (see SPEC_SPECULATIVE).
    pub speculative: bool,
    /// Binary and 4-wide layouts, speculative: the traversal's loops in lockstep over the
    /// subgroup (SPEC_LOCKSTEP), the default; false: each lane leaves them on its own, as in
    /// the integrators.
    pub lockstep: bool,
    /// 4-wide layout, persistent, lockstep: refill a subgroup's done lanes with new rays as
    /// soon as this many are done (SPEC_REFILL_LANES, dynamic fetch); 0 (default): a batch
    /// when all are.
    pub refill_lanes: u32,
    /// 4-wide layout, speculative lockstep loops (one ray per invocation, or dynamic fetch), no
    /// alpha masks: the leaf phase's triangle tests shared among the subgroup's lanes, the lanes
    /// without a leaf testing the next triangles of those with one (trace_bvh4_share.comp;
    /// glsl/common/traverse.glsl, TRAVERSAL_LEAVES_SHARED). Off by default.
    pub share_leaves: bool,
    /// 4-wide layout, one ray per invocation, speculative lockstep loops, no alpha masks: the
    /// subgroup's rays traverse as one packet, a node at a time (trace_bvh4_packet.comp;
    /// glsl/common/traverse_bvh4_packet.glsl). Off by default: NVIDIA H100, Sponza, camera rays
    /// 2.4 % slower than the lockstep loops, shadow rays 22 %, diffuse rays 3.4x (session 62).
    pub packet: bool,
    /// 4-wide layout, one ray per invocation in lockstep loops (not persistent, no alpha masks):
    /// the kernel that keeps each ray's origin in shared memory for its leaf tests
    /// (trace_bvh4_lockstep.comp; glsl/common/traverse.glsl, TRACE_LOCKSTEP_KERNEL). None (the
    /// default): on GPUs, where it is faster (H200: primary rays +3-4 %, session 29), not on CPU
    /// devices (llvmpipe: 10-20 % slower).
    pub shared_origin: Option<bool>,
    /// Compressed wide layout: triangle postponing (see SPEC_CWBVH_POSTPONE).
    pub postpone: bool,
    /// Binary layouts, geometry only: the stack's top four entries in registers, the rest in
    /// workgroup shared memory (glsl/common/traverse_short_stack.glsl) instead of local memory.
    pub short_stack: bool,
    /// The slab tests' minima and maxima on the distances' bits as integers (SPEC_INT_SLABS;
    /// the default), or as floats.
    pub int_slabs: bool,
    /// Rays each invocation traces (not persistent; 1 by default): SPEC_RAYS_PER_INVOCATION.
    pub rays_per_invocation: u32,
    /// Invocations per workgroup: TRACE_WG_SIZE (default), or 32, 128, 256 for the plain
    /// binary kernel (trace_wg*.comp: bvh2, geometry only, not persistent, local stack).
    pub workgroup_size: u32,
    /// With `alpha`: each ray's tmin slot holds its path's stochastic-opacity seed and the ray
    /// starts at 0 (SPEC_RAY_SEED; the wavefront path tracer's rays).
    pub ray_seed: bool,
    /// The ray count is read from a buffer a kernel before filled (SPEC_RAY_COUNT_BUFFER;
    /// `Tracer::record_trace_queued`).
    pub count_buffer: bool,
    /// The any-hit kernel writes one word per ray, NO_HIT where the segment is clear
    /// (SPEC_HIT_WORDS), instead of a `GpuHit`: a quarter of the bytes, for the wavefront passes.
    pub any_hit_words: bool,
    /// The form of the rays the closest-hit and the any-hit kernel read (SPEC_RAY_WORDS):
    /// `abi::RAY_WORDS_FULL` (`GpuRay`s) for both by default; the wavefront passes' compact
    /// forms (`abi::RAY_WORDS_SEGMENT`, `abi::RAY_WORDS_BOUNDED`; glsl/common/ray_words.glsl) where
    /// their rays carry no opacity seed (`render::wavefront_queues::ray_words`).
    pub ray_words: [u32; 2],
}

impl TraceOptions {
    pub fn new(tri_test: TriTest) -> Self {
        TraceOptions {
            tri_test,
            stats: false,
            alpha: None,
            persistent: None,
            layout: BvhLayout::Bvh2,
            speculative: true,
            lockstep: true,
            refill_lanes: 0,
            share_leaves: false,
            packet: false,
            shared_origin: None,
            postpone: false,
            short_stack: false,
            int_slabs: true,
            rays_per_invocation: 1,
            workgroup_size: abi::TRACE_WG_SIZE,
            ray_seed: false,
            count_buffer: false,
            any_hit_words: false,
            ray_words: [abi::RAY_WORDS_FULL; 2],
        }
    }
}

/// Workgroups a persistent trace kernel launches by default. Where the device reports its
/// streaming multiprocessors (VK_NV_shader_sm_builtins: the H100 has 132, each keeping up to
/// 64 warps resident), enough to fill every one at full occupancy: SMs × resident warps × 32
/// lanes / TRACE_WG_SIZE (H100: 4224). That is an upper bound — registers may allow fewer
/// resident — but a harmless one: groups beyond those resident start only as others finish,
/// i.e. when the ray queue is (nearly) empty, and leave at once. Elsewhere 1024 groups (65,536
/// invocations; lavapipe runs them on its few CPU threads).
pub fn default_persistent_groups(info: &crate::vk::DeviceInfo) -> u32 {
    if info.sm_count > 0 && info.warps_per_sm > 0 {
        (info.sm_count * info.warps_per_sm * info.subgroup_size.max(1) / abi::TRACE_WG_SIZE).max(1)
    } else {
        1024
    }
}

/// Most ray batches one subgroup of a persistent kernel may fetch on `info`'s device: no limit
/// on GPUs; 32 on CPU devices. llvmpipe (lavapipe) gives each invocation a budget of 65,535
/// loop iterations in all (gallivm's loop limiter, meant to stop infinite loops) and then
/// silently leaves every loop; its few threads run the first workgroups to the end, so one
/// subgroup would fetch hundreds of batches (measured: rays lost after ~1,200 batches of the
/// Cornell box, wrong hits before that). 32 batches of ≤ 8 rays stay far below the budget.
pub fn persistent_batch_cap(info: &crate::vk::DeviceInfo) -> u32 {
    if info.is_cpu() {
        32
    } else {
        u32::MAX
    }
}

/// (workgroups, batches per subgroup) of a persistent launch over `count` rays: `groups`
/// workgroups, or more where `max_batches` batches of each subgroup could not cover every
/// ray, and never more than one invocation per ray needs. `rays_per_batch`: the fewest rays
/// one batch of a workgroup's subgroups takes together (TRACE_WG_SIZE where each subgroup
/// fetches whole batches of its size; fewer with dynamic fetch, `refill_rays_per_batch`).
pub fn persistent_launch(count: u32, groups: u32, max_batches: u32, rays_per_batch: u32) -> (u32, u32) {
    let per_ray = count.div_ceil(abi::TRACE_WG_SIZE);
    let per_group = rays_per_batch.clamp(1, abi::TRACE_WG_SIZE) as u64;
    let needed = (count as u64).div_ceil(per_group * max_batches.max(1) as u64).min(u32::MAX as u64) as u32;
    (groups.max(needed).min(per_ray), max_batches.max(1))
}

/// The fewest rays a workgroup's subgroups take in one round of dynamic fetch: each refills
/// at least min(`refill_lanes`, its lanes) (glsl/common/trace_kernel.glsl, trace_dynamic).
pub fn refill_rays_per_batch(refill_lanes: u32, subgroup_size: u32) -> u32 {
    let lanes = subgroup_size.clamp(1, abi::TRACE_WG_SIZE);
    (abi::TRACE_WG_SIZE / lanes) * refill_lanes.clamp(1, lanes)
}

/// A persistent trace kernel's ray counter (`RayCounter` in glsl/common/trace_kernel.glsl: the
/// next ray, the finished workgroups), zeroed.
fn zeroed(ctx: &Context, name: &str) -> Result<Buffer> {
    let counter = ctx.create_buffer(name, 8, Memory::Device)?;
    ctx.submit(name, |rec| {
        rec.fill_buffer(&counter, 0);
        Ok(())
    })?;
    Ok(counter)
}

/// The ray counters a persistent trace takes its rays with: the closest-hit kernel's and the
/// any-hit kernel's (`Tracer::create_counters`).
#[derive(Clone, Copy)]
pub struct RayCounters<'a> {
    pub closest: &'a Buffer,
    pub any: &'a Buffer,
}

/// Trace and ray-generation kernels specialised for one triangle test.
pub struct Tracer {
    closest: Kernel,
    any: Kernel,
    gen_primary: Kernel,
    gen_shadow: Kernel,
    gen_diffuse: Kernel,
    compact: Kernel,
    scan: Scan,
    opts: TraceOptions,
    /// Persistent kernels: workgroups launched.
    persistent: Option<u32>,
    /// Their ray counters (bound to every trace kernel, which declares one): the closest-hit
    /// kernel's and the any-hit kernel's, so that the two may run at once. Zeroed when made;
    /// each persistent launch's last workgroup leaves its counter at 0 again
    /// (glsl/common/trace_kernel.glsl), so a launch needs no fill before it.
    counter: Buffer,
    counter_any: Buffer,
    /// Most ray batches one subgroup of a persistent kernel fetches.
    max_batches: u32,
    /// The device's subgroup size (dynamic fetch's launch).
    subgroup_size: u32,
}

impl Tracer {
    /// `stats`: count nodes and triangles tested (slower; for reports, not timing).
    pub fn new(ctx: &Context, tri_test: TriTest, stats: bool) -> Result<Tracer> {
        Tracer::with_options(ctx, &TraceOptions { stats, ..TraceOptions::new(tri_test) })
    }

    pub fn with_options(ctx: &Context, opts: &TraceOptions) -> Result<Tracer> {
        let base =
            [Spec { id: abi::SPEC_TRI_TEST, value: opts.tri_test.spec_value() }, Spec { id: abi::SPEC_STATS, value: opts.stats as u32 }];
        let mut trace_specs = base.to_vec();
        trace_specs.push(Spec { id: abi::SPEC_PERSISTENT, value: opts.persistent.is_some() as u32 });
        match opts.layout {
            BvhLayout::Bvh2 | BvhLayout::Bvh2q | BvhLayout::Bvh4 => {
                trace_specs.push(Spec { id: abi::SPEC_SPECULATIVE, value: opts.speculative as u32 });
                // Lockstep loops are the speculative traversal's (trace_ray_lockstep).
                trace_specs.push(Spec { id: abi::SPEC_LOCKSTEP, value: (opts.lockstep && opts.speculative) as u32 });
            }
            BvhLayout::Cwbvh => trace_specs.push(Spec { id: abi::SPEC_CWBVH_POSTPONE, value: opts.postpone as u32 }),
        }
        if opts.refill_lanes > 0 {
            if opts.layout != BvhLayout::Bvh4 || opts.persistent.is_none() || !opts.speculative || !opts.lockstep {
                let msg = format!(
                    "dynamic fetch ({} lanes) needs the 4-wide layout, persistent threads and the speculative lockstep loops",
                    opts.refill_lanes
                );
                return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
            }
            trace_specs.push(Spec { id: abi::SPEC_REFILL_LANES, value: opts.refill_lanes });
        }
        // Shared leaf tests: the lockstep loops of one ray per invocation or of dynamic fetch
        // (the batches of plain persistent threads run divergent per-ray calls).
        let lockstep_loops = opts.lockstep && opts.speculative && (opts.persistent.is_none() || opts.refill_lanes > 0);
        if opts.share_leaves
            && (opts.layout != BvhLayout::Bvh4
                || !lockstep_loops
                || opts.alpha.is_some()
                || opts.short_stack
                || opts.workgroup_size != abi::TRACE_WG_SIZE)
        {
            let msg = "shared leaf tests need the 4-wide layout's speculative lockstep loops (one ray per invocation or dynamic fetch), without alpha masks".to_string();
            return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
        }
        if opts.packet
            && (opts.layout != BvhLayout::Bvh4
                || opts.persistent.is_some()
                || !opts.lockstep
                || !opts.speculative
                || opts.share_leaves
                || opts.alpha.is_some()
                || opts.workgroup_size != abi::TRACE_WG_SIZE)
        {
            let msg = "packet traversal needs the 4-wide layout, one ray per invocation and the speculative lockstep loops, without alpha masks or shared leaf tests".to_string();
            return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
        }
        trace_specs.push(Spec { id: abi::SPEC_INT_SLABS, value: opts.int_slabs as u32 });
        trace_specs.push(Spec { id: abi::SPEC_RAY_COUNT_BUFFER, value: opts.count_buffer as u32 });
        if opts.rays_per_invocation != 1 {
            if opts.persistent.is_some() || opts.rays_per_invocation == 0 {
                let msg = format!("{} rays per invocation: 1 with persistent threads, at least 1 otherwise", opts.rays_per_invocation);
                return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
            }
            trace_specs.push(Spec { id: abi::SPEC_RAYS_PER_INVOCATION, value: opts.rays_per_invocation });
        }
        let persistent = opts.persistent.map(|g| if g == 0 { default_persistent_groups(ctx.info()) } else { g });
        let shared_origin = opts.shared_origin.unwrap_or(!ctx.info().is_cpu());
        let plain = opts.alpha.is_none() && opts.layout == BvhLayout::Bvh2 && !opts.short_stack && opts.persistent.is_none();
        let source = match (&opts.alpha, opts.layout) {
            _ if opts.workgroup_size != abi::TRACE_WG_SIZE => match opts.workgroup_size {
                32 if plain => &kernels::TRACE_WG32,
                128 if plain => &kernels::TRACE_WG128,
                256 if plain => &kernels::TRACE_WG256,
                size => {
                    let msg = format!(
                        "workgroups of {size}: {} (default) for every kernel; 32, 128 or 256 for bvh2 without alpha masks, short stack or persistent threads",
                        abi::TRACE_WG_SIZE
                    );
                    return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
                }
            },
            _ if opts.short_stack => match (&opts.alpha, opts.layout) {
                (None, BvhLayout::Bvh2) => &kernels::TRACE_SHORT_STACK,
                (None, BvhLayout::Bvh2q) => &kernels::TRACE_SHORT_STACK_BVH2Q,
                _ => {
                    let msg = format!("the short stack is built for the binary layouts without alpha masks, not {}", opts.layout.name());
                    return Err(crate::vk::VkError::Kernel { kernel: "trace_short_stack".into(), msg });
                }
            },
            (Some(features), layout) => {
                trace_specs.extend(features.specs());
                trace_specs.push(Spec { id: abi::SPEC_RAY_SEED, value: opts.ray_seed as u32 });
                match layout {
                    BvhLayout::Bvh2 => &kernels::TRACE_ALPHA,
                    BvhLayout::Cwbvh => &kernels::TRACE_ALPHA_CWBVH,
                    BvhLayout::Bvh2q => &kernels::TRACE_ALPHA_BVH2Q,
                    BvhLayout::Bvh4 => &kernels::TRACE_ALPHA_BVH4,
                }
            }
            (None, BvhLayout::Bvh2) => &kernels::TRACE,
            (None, BvhLayout::Cwbvh) => &kernels::TRACE_CWBVH,
            (None, BvhLayout::Bvh2q) => &kernels::TRACE_BVH2Q,
            // Leaf tests shared among the lanes, per ray or with dynamic fetch (validated above).
            (None, BvhLayout::Bvh4) if opts.share_leaves => &kernels::TRACE_BVH4_SHARE,
            // The subgroup's rays as one packet (validated above).
            (None, BvhLayout::Bvh4) if opts.packet => &kernels::TRACE_BVH4_PACKET,
            // One ray per invocation in lockstep loops: the kernel whose leaf tests read the
            // origin from shared memory (glsl/common/traverse.glsl, TRACE_LOCKSTEP_KERNEL).
            (None, BvhLayout::Bvh4) if opts.persistent.is_none() && opts.lockstep && opts.speculative && shared_origin => {
                &kernels::TRACE_BVH4_LOCKSTEP
            }
            (None, BvhLayout::Bvh4) => &kernels::TRACE_BVH4,
        };
        let [closest_words, any_words] = opts.ray_words;
        let compact = [closest_words, any_words] != [abi::RAY_WORDS_FULL; 2];
        let forms_ok = matches!(closest_words, abi::RAY_WORDS_FULL | abi::RAY_WORDS_SEGMENT)
            && matches!(any_words, abi::RAY_WORDS_FULL | abi::RAY_WORDS_BOUNDED);
        if !forms_ok || (compact && opts.ray_seed) {
            let msg = format!(
                "rays of {closest_words} and {any_words} words: closest-hit rays take {} or {}, any-hit rays {} or {}, and rays that carry an opacity seed take {}",
                abi::RAY_WORDS_FULL,
                abi::RAY_WORDS_SEGMENT,
                abi::RAY_WORDS_FULL,
                abi::RAY_WORDS_BOUNDED,
                abi::RAY_WORDS_FULL
            );
            return Err(crate::vk::VkError::Kernel { kernel: "trace".into(), msg });
        }
        let with = |any_hit: bool, extra: &[Spec]| {
            let mut s = trace_specs.clone();
            s.push(Spec { id: abi::SPEC_ANY_HIT, value: any_hit as u32 });
            s.push(Spec { id: abi::SPEC_RAY_WORDS, value: opts.ray_words[any_hit as usize] });
            s.extend_from_slice(extra);
            s
        };
        Ok(Tracer {
            closest: ctx.create_kernel(source, &with(false, &[]))?,
            any: ctx.create_kernel(source, &with(true, &[Spec { id: abi::SPEC_HIT_WORDS, value: opts.any_hit_words as u32 }]))?,
            gen_primary: ctx.create_kernel(&kernels::GEN_PRIMARY, &[])?,
            gen_shadow: ctx.create_kernel(&kernels::GEN_SECONDARY, &[base[0], Spec { id: abi::SPEC_SECONDARY_KIND, value: 0 }])?,
            gen_diffuse: ctx.create_kernel(&kernels::GEN_SECONDARY, &[base[0], Spec { id: abi::SPEC_SECONDARY_KIND, value: 1 }])?,
            compact: ctx.create_kernel(&kernels::COMPACT_RAYS, &[])?,
            scan: Scan::new(ctx)?,
            opts: *opts,
            persistent,
            counter: zeroed(ctx, "trace.ray_counter")?,
            counter_any: zeroed(ctx, "trace.ray_counter_any")?,
            max_batches: persistent_batch_cap(ctx.info()),
            subgroup_size: ctx.info().subgroup_size,
        })
    }

    /// The closest-hit and any-hit trace kernels (for their compile statistics).
    pub fn trace_kernels(&self) -> [&Kernel; 2] {
        [&self.closest, &self.any]
    }

    pub fn tri_test(&self) -> TriTest {
        self.opts.tri_test
    }

    pub fn options(&self) -> &TraceOptions {
        &self.opts
    }

    /// Workgroups a persistent tracer launches (None: not persistent).
    pub fn persistent_groups(&self) -> Option<u32> {
        self.persistent
    }

    /// Records a trace of `count` rays into `hits` (one `GpuHit` each). `geometry`: the BVH's
    /// bindings (`GpuBvh::binds`), or the whole scene's (`GpuScene::binds`) for a tracer with
    /// `alpha`. `stats` receives two u32 counters (nodes, triangles) when the tracer counts
    /// them.
    #[allow(clippy::too_many_arguments)]
    pub fn record_trace(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        rays: &Buffer,
        hits: &Buffer,
        stats: &Buffer,
        count: u32,
        any_hit: bool,
    ) -> Result<()> {
        self.record_trace_queued(rec, geometry, rays, hits, stats, count, None, any_hit, None)
    }

    /// `record_trace` of rays a kernel recorded before queued: with `counts` = (buffer, i) the
    /// first `buffer[i]` of them, at most `count` (a tracer with `count_buffer`). `indirect`: the
    /// workgroups come from that indirect dispatch
    /// (`VkDispatchIndirectCommand` at the byte offset), which a kernel before sized for the
    /// queued rays: one workgroup per TRACE_WG_SIZE of them, at most `queued_groups(count)`
    /// (wf_active.glsl, wf_end_launch).
    #[allow(clippy::too_many_arguments)]
    pub fn record_trace_queued(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        rays: &Buffer,
        hits: &Buffer,
        stats: &Buffer,
        count: u32,
        counts: Option<(&Buffer, u32)>,
        any_hit: bool,
        indirect: Option<(&Buffer, u64)>,
    ) -> Result<()> {
        self.record_trace_counted(rec, geometry, (rays, hits, stats), count, counts, any_hit, indirect, self.counters())
    }

    /// The tracer's own ray counters.
    pub fn counters(&self) -> RayCounters<'_> {
        RayCounters { closest: &self.counter, any: &self.counter_any }
    }

    /// Two persistent ray counters (closest hit, any hit) beside the tracer's own, zeroed, for
    /// `record_trace_counted`: traces that may run at once with the tracer's others (another
    /// queue's, in the same group of `Recorder::concurrent`) each need their own.
    pub fn create_counters(&self, ctx: &Context, prefix: &str) -> Result<[Buffer; 2]> {
        Ok([zeroed(ctx, &format!("{prefix}.ray_counter"))?, zeroed(ctx, &format!("{prefix}.ray_counter_any"))?])
    }

    /// `record_trace_queued` with the ray counters `counters` (`create_counters`'s, or the
    /// tracer's own).
    #[allow(clippy::too_many_arguments)]
    pub fn record_trace_counted(
        &self,
        rec: &mut Recorder,
        geometry: &[Bind],
        (rays, hits, stats): (&Buffer, &Buffer, &Buffer),
        count: u32,
        counts: Option<(&Buffer, u32)>,
        any_hit: bool,
        indirect: Option<(&Buffer, u64)>,
        counters: RayCounters,
    ) -> Result<()> {
        let k = if any_hit { &self.any } else { &self.closest };
        let counter = if any_hit { counters.any } else { counters.closest };
        assert_eq!(counts.is_some(), self.opts.count_buffer, "queued rays need a tracer with count_buffer, and only they");
        let mut push = TracePush { count, count_index: counts.map_or(0, |c| c.1), ..Default::default() };
        let mut binds = geometry.to_vec();
        binds.extend([Bind::buffer(abi::BIND_RAYS, rays), Bind::buffer(abi::BIND_HITS, hits), Bind::buffer(abi::BIND_STATS, stats)]);
        binds.push(Bind::buffer(abi::BIND_RAY_COUNTER, counter));
        // (Read only with SPEC_RAY_COUNT_BUFFER; the counter stands in elsewhere.)
        binds.push(Bind::buffer(abi::BIND_RAY_COUNTS, counts.map_or(counter, |c| c.0)));
        let groups;
        (groups, push.max_batches) = self.launch(count);
        match indirect {
            Some((buffer, offset)) => {
                assert!(self.sized_launch_covers(), "an indirect trace whose groups for the queued rays may not cover them");
                rec.dispatch_indirect(k, &binds, bytemuck::bytes_of(&push), buffer, offset)
            }
            None => rec.dispatch(k, &binds, bytemuck::bytes_of(&push), [groups, 1, 1]),
        }
    }

    /// Workgroups and `TracePush::max_batches` of a direct launch over `count` rays.
    fn launch(&self, count: u32) -> (u32, u32) {
        match self.persistent {
            Some(persistent_groups) => persistent_launch(count, persistent_groups, self.max_batches, self.rays_per_batch()),
            None => (self.closest.groups_for(count.div_ceil(self.opts.rays_per_invocation.max(1))), 0),
        }
    }

    /// The fewest rays a persistent workgroup takes in one round of fetches.
    fn rays_per_batch(&self) -> u32 {
        match self.opts.refill_lanes {
            0 => abi::TRACE_WG_SIZE,
            n => refill_rays_per_batch(n, self.subgroup_size),
        }
    }

    /// The workgroups `record_trace_queued` launches over `count` rays without `indirect`: the
    /// most an indirect dispatch of it may ask for.
    pub fn queued_groups(&self, count: u32) -> u32 {
        self.launch(count).0
    }

    /// Whether an indirect launch of one workgroup per TRACE_WG_SIZE queued rays (at most
    /// `queued_groups`) traces every one of them (a persistent kernel's
    /// subgroups may fetch only `max_batches` times: llvmpipe's loop limiter).
    fn sized_launch_covers(&self) -> bool {
        self.persistent.is_none() || self.rays_per_batch() as u64 * self.max_batches as u64 >= abi::TRACE_WG_SIZE as u64
    }

    /// Traces host rays and returns their hits (for tests and tools).
    pub fn trace(&self, ctx: &Context, bvh: &GpuBvh, rays: &[GpuRay], any_hit: bool) -> Result<Vec<GpuHit>> {
        self.trace_with(ctx, &bvh.binds(), rays, any_hit)
    }

    /// As `trace`, with the given geometry bindings (see `record_trace`).
    pub fn trace_with(&self, ctx: &Context, geometry: &[Bind], rays: &[GpuRay], any_hit: bool) -> Result<Vec<GpuHit>> {
        let count = rays.len() as u32;
        let ray_buf = ctx.upload_buffer("trace.rays", rays)?;
        let hits = ctx.create_buffer("trace.hits", rays.len() as u64 * 16, Memory::Device)?;
        let stats = ctx.create_buffer("trace.stats", 8, Memory::Device)?;
        ctx.submit("trace", |rec| {
            rec.fill_buffer(&stats, 0);
            self.record_trace(rec, geometry, &ray_buf, &hits, &stats, count, any_hit)
        })?;
        ctx.read_buffer(&hits)
    }

    /// Records camera rays through pixel centres into `rays`, in 8x8-tile order
    /// (`tiled_invocations` of them; those outside the image have tmax < 0).
    pub fn record_primary(&self, rec: &mut Recorder, cam: &GpuCamera, rays: &Buffer) -> Result<()> {
        let n = crate::gpu_data::tiled_invocations(cam.size.x, cam.size.y);
        rec.dispatch(
            &self.gen_primary,
            &[Bind::buffer(abi::BIND_RAYS_OUT, rays)],
            bytemuck::bytes_of(cam),
            [self.gen_primary.groups_for(n), 1, 1],
        )
    }

    /// Spawns secondary rays from `hits` of `rays` and compacts the valid ones to the front
    /// of `out`; returns how many there are. `scratch` needs `count` rays, `flags` count + 1
    /// u32s.
    #[allow(clippy::too_many_arguments)]
    pub fn secondary(
        &self,
        ctx: &Context,
        bvh: &GpuBvh,
        kind: Secondary,
        light: glam::Vec3,
        seed: u32,
        rays: &Buffer,
        hits: &Buffer,
        count: u32,
        scratch: &Buffer,
        flags: &Buffer,
        out: &Buffer,
    ) -> Result<u32> {
        let k = match kind {
            Secondary::Shadow => &self.gen_shadow,
            Secondary::Diffuse => &self.gen_diffuse,
        };
        let push = SecondaryPush { light: light.extend(0.0), count, seed, ..Default::default() };
        ctx.submit("secondary rays", |rec| {
            rec.fill_buffer(flags, 0);
            rec.dispatch(
                k,
                &[
                    Bind::buffer(abi::BIND_TRIS, &bvh.tris),
                    Bind::buffer(abi::BIND_RAYS, rays),
                    Bind::buffer(abi::BIND_HITS, hits),
                    Bind::buffer(abi::BIND_RAYS_OUT, scratch),
                    Bind::buffer(abi::BIND_FLAGS, flags),
                ],
                bytemuck::bytes_of(&push),
                [k.groups_for(count), 1, 1],
            )
        })?;
        self.scan.exclusive_scan(ctx, flags, count + 1)?;
        let push = TracePush { count, ..Default::default() };
        ctx.submit("compact rays", |rec| {
            rec.dispatch(
                &self.compact,
                &[Bind::buffer(abi::BIND_RAYS, scratch), Bind::buffer(abi::BIND_FLAGS, flags), Bind::buffer(abi::BIND_RAYS_OUT, out)],
                bytemuck::bytes_of(&push),
                [self.compact.groups_for(count), 1, 1],
            )
        })?;
        let offsets: Vec<u32> = ctx.read_buffer(flags)?;
        Ok(offsets[count as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn persistent_launch_covers_every_ray() {
        let wg = abi::TRACE_WG_SIZE;
        for count in [1u32, 63, 64, 65, 90_000, 2_073_600] {
            for groups in [1u32, 3, 1024, 4224] {
                for cap in [1u32, 32, u32::MAX] {
                    let (g, b) = persistent_launch(count, groups, cap, wg);
                    assert!(g >= 1 && g <= count.div_ceil(wg), "{count} {groups} {cap}: {g} groups");
                    assert!(g as u64 * wg as u64 * b as u64 >= count as u64, "{count} {groups} {cap}: {g} x {b} batches");
                    assert!(g >= groups.min(count.div_ceil(wg)));
                }
                // Dynamic fetch: refills of as few as 1 or 3 of 8 lanes, 4 of 32, with the CPU's
                // cap or none.
                for (refill, sg, cap) in [(1u32, 8u32, 32u32), (3, 8, 32), (1, 8, u32::MAX), (4, 32, 32)] {
                    let per_group = refill_rays_per_batch(refill, sg);
                    assert_eq!(per_group, wg / sg * refill);
                    let (g, b) = persistent_launch(count, groups, cap, per_group);
                    assert!(g >= 1 && g <= count.div_ceil(wg), "{count} {groups} {cap} {refill}/{sg}: {g} groups");
                    assert!(
                        g as u64 * per_group as u64 * b as u64 >= count as u64,
                        "{count} {groups} {cap} {refill}/{sg}: {g} x {b} batches"
                    );
                }
            }
        }
    }
}
