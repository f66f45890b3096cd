//! Ray queries on the GPU: the BVH uploaded, closest-hit and any-hit traversal over ray
//! buffers, and ray generation (primary, shadow, diffuse) with compaction. Integrators call
//! the same GLSL traversal inline; this module serves the tests and the benchmark.

mod camera;

pub use camera::gpu_camera;

use crate::bvh::{Bvh, TriTest};
use crate::compute::Scan;
use crate::gpu::{
    abi::{self, GpuCamera, GpuHit, GpuRay, SecondaryPush, TracePush},
    kernels,
};
use crate::render::SceneFeatures;
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// Invocations that cover a `width` x `height` image in whole 8x8 tiles (the order of
/// `tiled_pixel` in glsl/common/ray.glsl).
pub fn tiled_invocations(width: u32, height: u32) -> u32 {
    width.div_ceil(8) * 8 * height.div_ceil(8) * 8
}

/// A BVH in GPU memory.
pub struct GpuBvh {
    pub nodes: Buffer,
    pub tris: Buffer,
    pub tri_test: TriTest,
    pub bytes: u64,
}

impl GpuBvh {
    pub fn upload(ctx: &Context, bvh: &Bvh) -> Result<GpuBvh> {
        Ok(GpuBvh {
            nodes: ctx.upload_buffer("bvh.nodes", &bvh.nodes)?,
            tris: ctx.upload_buffer("bvh.tris", &bvh.tris)?,
            tri_test: bvh.tri_test,
            bytes: (std::mem::size_of_val(bvh.nodes.as_slice()) + std::mem::size_of_val(bvh.tris.as_slice())) as u64,
        })
    }

    /// Bindings of the BVH buffers (glsl/common/traverse.glsl).
    pub fn binds(&self) -> Vec<Bind<'_>> {
        vec![Bind::buffer(abi::BIND_NODES, &self.nodes), Bind::buffer(abi::BIND_TRIS, &self.tris)]
    }
}

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
}

impl TraceOptions {
    pub fn new(tri_test: TriTest) -> Self {
        TraceOptions { tri_test, stats: false, alpha: None }
    }
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
}

impl Tracer {
    /// `stats`: count nodes and triangles tested (slower; for reports, not timing).
    pub fn new(ctx: &Context, tri_test: TriTest, stats: bool) -> Result<Tracer> {
        Tracer::with_options(ctx, &TraceOptions { stats, ..TraceOptions::new(tri_test) })
    }

    pub fn with_options(ctx: &Context, opts: &TraceOptions) -> Result<Tracer> {
        let base = [Spec { id: abi::SPEC_TRI_TEST, value: opts.tri_test.spec_value() }, Spec { id: abi::SPEC_STATS, value: opts.stats as u32 }];
        let mut trace_specs = base.to_vec();
        let source = match &opts.alpha {
            Some(features) => {
                trace_specs.extend(features.specs());
                &kernels::TRACE_ALPHA
            }
            None => &kernels::TRACE,
        };
        let with = |id, value| {
            let mut s = trace_specs.clone();
            s.push(Spec { id, value });
            s
        };
        Ok(Tracer {
            closest: ctx.create_kernel(source, &with(abi::SPEC_ANY_HIT, 0))?,
            any: ctx.create_kernel(source, &with(abi::SPEC_ANY_HIT, 1))?,
            gen_primary: ctx.create_kernel(&kernels::GEN_PRIMARY, &[])?,
            gen_shadow: ctx.create_kernel(&kernels::GEN_SECONDARY, &[base[0], Spec { id: abi::SPEC_SECONDARY_KIND, value: 0 }])?,
            gen_diffuse: ctx.create_kernel(&kernels::GEN_SECONDARY, &[base[0], Spec { id: abi::SPEC_SECONDARY_KIND, value: 1 }])?,
            compact: ctx.create_kernel(&kernels::COMPACT_RAYS, &[])?,
            scan: Scan::new(ctx)?,
            opts: *opts,
        })
    }

    pub fn tri_test(&self) -> TriTest {
        self.opts.tri_test
    }

    pub fn options(&self) -> &TraceOptions {
        &self.opts
    }

    /// Records a trace of `count` rays into `hits` (one `GpuHit` each). `geometry`: the BVH's
    /// bindings (`GpuBvh::binds`), or the whole scene's (`GpuScene::binds`) for a tracer with
    /// `alpha`. `stats` receives two u32 counters (nodes, triangles) when the tracer counts
    /// them.
    #[allow(clippy::too_many_arguments)]
    pub fn record_trace(&self, rec: &mut Recorder, geometry: &[Bind], rays: &Buffer, hits: &Buffer, stats: &Buffer, count: u32, any_hit: bool) -> Result<()> {
        let k = if any_hit { &self.any } else { &self.closest };
        let push = TracePush { count, ..Default::default() };
        let mut binds = geometry.to_vec();
        binds.extend([Bind::buffer(abi::BIND_RAYS, rays), Bind::buffer(abi::BIND_HITS, hits), Bind::buffer(abi::BIND_STATS, stats)]);
        rec.dispatch(k, &binds, bytemuck::bytes_of(&push), [k.groups_for(count), 1, 1])
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
        let n = tiled_invocations(cam.size.x, cam.size.y);
        rec.dispatch(&self.gen_primary, &[Bind::buffer(abi::BIND_RAYS_OUT, rays)], bytemuck::bytes_of(cam), [self.gen_primary.groups_for(n), 1, 1])
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
