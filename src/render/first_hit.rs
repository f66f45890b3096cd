//! The first-hit pass (`glsl/kernels/first_hit.comp`): alpha and the AOVs, for every
//! integrator alike. One shared pass rather than code in each integrator's camera kernel:
//! what a camera ray finds does not depend on the estimator, the integrators' kernels stay as
//! they are (and cost nothing more) when nothing is asked for, and the sums are added per
//! pixel in sample order (deterministic) whatever the integrator's sample slices. Its cost is
//! one camera ray per sample (more through mirrors and glass), paid only when asked for.

use super::gpu_scene::GpuScene;
use crate::gpu::abi::{self, FirstHitPush, FirstHitSums, GpuCamera};
use crate::gpu::kernels;
use crate::imaging::aov::{Aovs, FirstHit};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// The first-hit kernel and its per-pixel sums for a film of `width` x `height` pixels.
pub struct FirstHitPass {
    kernel: Kernel,
    sums: Buffer,
    width: u32,
    height: u32,
    aovs: Aovs,
}

impl FirstHitPass {
    pub fn new(ctx: &Context, scene: &GpuScene, sampler: super::Sampler, width: u32, height: u32, aovs: Aovs) -> Result<FirstHitPass> {
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(sampler.spec());
        let any_aov = aovs.albedo || aovs.normal || aovs.depth;
        specs.push(Spec { id: abi::SPEC_FIRST_HIT_AOVS, value: any_aov as u32 });
        let kernel = ctx.create_kernel(scene.bvh.kernel(&kernels::FIRST_HIT_FORMS), &specs)?;
        let pass = FirstHitPass { kernel, sums: Self::sums_buffer(ctx, width, height)?, width, height, aovs };
        pass.clear(ctx)?;
        Ok(pass)
    }

    /// A sums buffer for a film of `width` x `height` pixels (for [`FirstHitPass::resize`]).
    pub fn sums_buffer(ctx: &Context, width: u32, height: u32) -> Result<Buffer> {
        let bytes = width as u64 * height as u64 * std::mem::size_of::<FirstHitSums>() as u64;
        ctx.create_buffer("first_hit.sums", bytes, Memory::Device)
    }

    /// Follows a film of another size with `sums` from [`FirstHitPass::sums_buffer`] (cleared).
    pub fn resize(&mut self, ctx: &Context, sums: Buffer, width: u32, height: u32) -> Result<()> {
        (self.sums, self.width, self.height) = (sums, width, height);
        self.clear(ctx)
    }

    pub fn clear(&self, ctx: &Context) -> Result<()> {
        ctx.submit("first-hit clear", |rec| {
            rec.fill_buffer(&self.sums, 0);
            Ok(())
        })
    }

    /// Records samples `first..first + spp` of every pixel of the camera's window.
    pub fn record(&self, rec: &mut Recorder, scene: &GpuScene, camera: GpuCamera, first: u32, spp: u32, seed: u32) -> Result<()> {
        let push = FirstHitPush { camera, sample_base: first, spp, seed, ..Default::default() };
        let mut binds = scene.binds();
        binds.push(Bind::buffer(abi::BIND_FIRST_HIT, &self.sums));
        let n = crate::gpu_data::tiled_invocations(self.width, self.height);
        rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(&push), [self.kernel.groups_for(n), 1, 1])
    }

    /// The sums so far (over every sample rendered since the last clear).
    pub fn read(&self, ctx: &Context) -> Result<FirstHit> {
        let raw: Vec<FirstHitSums> = ctx.read_buffer(&self.sums)?;
        let n = (self.width * self.height) as usize;
        let sums = raw
            .iter()
            .take(n)
            .map(|s| {
                let (a, nr) = (s.albedo.as_dvec3(), s.normal.as_dvec3());
                [s.hits as f64, a.x, a.y, a.z, nr.x, nr.y, nr.z, s.depth as f64]
            })
            .collect();
        Ok(FirstHit { sums, aovs: self.aovs })
    }
}
