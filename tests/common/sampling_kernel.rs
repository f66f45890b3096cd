//! The sampling test kernel (`glsl/tests/sampling.comp`) with its buffers: each mode writes
//! vec4s per invocation; the inputs a mode does not read are bound to one placeholder.

use bidir::gpu::{abi, kernels};
use bidir::vk::{Bind, Buffer, Context, Kernel, Memory, Spec};
use glam::Vec4;

pub struct SamplingKernel<'a> {
    pub ctx: &'a Context,
    kernel: Kernel,
    /// As large as the largest struct read from an unused binding.
    placeholder: Buffer,
}

impl<'a> SamplingKernel<'a> {
    pub fn new(ctx: &'a Context) -> Self {
        Self::with_specs(ctx, &[])
    }

    /// The kernel with specialisation constants, e.g. a sampler (`SPEC_SAMPLER`).
    pub fn with_specs(ctx: &'a Context, specs: &[Spec]) -> Self {
        let kernel = ctx.create_kernel(&kernels::SAMPLING, specs).unwrap();
        let placeholder = ctx.create_buffer("sampling.placeholder", 128, Memory::Device).unwrap();
        SamplingKernel { ctx, kernel, placeholder }
    }

    /// Runs `push.count` invocations and returns `per_sample` vec4s for each.
    pub fn run(&self, push: abi::SamplingTestPush, per_sample: u64, input: Option<&Buffer>) -> Vec<Vec4> {
        self.run_env(push, per_sample, input, None, None)
    }

    /// As `run`, with the emitters' (GpuEmitter, alias) buffers where given.
    pub fn run_lights(
        &self,
        push: abi::SamplingTestPush,
        per_sample: u64,
        input: Option<&Buffer>,
        lights: Option<(&Buffer, &Buffer)>,
    ) -> Vec<Vec4> {
        self.run_env(push, per_sample, input, lights, None)
    }

    /// As `run_lights`, with the environment's (GpuEnv, texels, alias) buffers where given.
    pub fn run_env(
        &self,
        push: abi::SamplingTestPush,
        per_sample: u64,
        input: Option<&Buffer>,
        lights: Option<(&Buffer, &Buffer)>,
        env: Option<[&Buffer; 3]>,
    ) -> Vec<Vec4> {
        let out = self.ctx.create_buffer("sampling.out", push.count as u64 * per_sample * 16, Memory::Device).unwrap();
        let (emitters, alias) = lights.unwrap_or((&self.placeholder, &self.placeholder));
        let [env, env_texels, env_alias] = env.unwrap_or([&self.placeholder; 3]);
        let binds = [
            Bind::buffer(abi::SAMPLING_BIND_OUT, &out),
            Bind::buffer(abi::SAMPLING_BIND_IN, input.unwrap_or(&self.placeholder)),
            Bind::buffer(abi::BIND_EMITTERS, emitters),
            Bind::buffer(abi::BIND_ALIAS, alias),
            Bind::buffer(abi::BIND_ENV, env),
            Bind::buffer(abi::BIND_ENV_TEXELS, env_texels),
            Bind::buffer(abi::BIND_ENV_ALIAS, env_alias),
        ];
        let groups = self.kernel.groups_for(push.count);
        self.ctx.submit("sampling", |rec| rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(&push), [groups, 1, 1])).unwrap();
        self.ctx.read_buffer(&out).unwrap()
    }
}
