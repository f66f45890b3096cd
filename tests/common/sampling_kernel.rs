//! The sampling test kernel (`glsl/tests/sampling.comp`) with its buffers: each mode writes
//! vec4s per invocation; the inputs a mode does not read are bound to one placeholder.

use bidir::bvh::intersect::Fma;
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

/// How the device rounds `precise fma()` (`SAMPLING_FMA`), for the watertight test's CPU twin
/// (`bidir::bvh::intersect::Fma`). The inputs: a, b in [1, 2) and c = -(a b rounded), where one
/// rounding leaves the product's rounding error and two leave 0, alternating with c that do
/// not cancel. Panics unless every fma() rounds one way, every `precise` a b + c twice, and
/// the inputs tell the two ways apart.
pub fn device_fma(ctx: &Context) -> Fma {
    let s = SamplingKernel::new(ctx);
    let mut pcg = super::Pcg::new(33);
    let mut abc: Vec<Vec4> = Vec::new();
    for i in 0..1024 {
        let a = 1.0 + pcg.next_f32();
        let b = 1.0 + pcg.next_f32();
        let c = if i % 2 == 0 { -(a * b) } else { pcg.next_f32() - 0.5 };
        abc.push(Vec4::new(a, b, c, 0.0));
    }
    let input = ctx.upload_buffer("sampling.fma_inputs", &abc).unwrap();
    let push = abi::SamplingTestPush { mode: abi::SAMPLING_FMA, count: abc.len() as u32, seed: 1, ..Default::default() };
    let out = s.run(push, 1, Some(&input));
    let (mut fused, mut separate, mut differ) = (0, 0, 0);
    for (v, o) in abc.iter().zip(&out) {
        let (f, sep) = (Fma::Fused.apply(v.x, v.y, v.z), Fma::Separate.apply(v.x, v.y, v.z));
        assert_eq!(o.y.to_bits(), sep.to_bits(), "precise {} * {} + {}: device {}, rounded twice {sep}", v.x, v.y, v.z, o.y);
        if f != sep {
            differ += 1;
            fused += (o.x.to_bits() == f.to_bits()) as u32;
            separate += (o.x.to_bits() == sep.to_bits()) as u32;
        } else {
            assert_eq!(o.x.to_bits(), f.to_bits(), "fma({}, {}, {}): device {}, both roundings {f}", v.x, v.y, v.z, o.x);
        }
    }
    assert!(differ > 256, "only {differ} inputs tell one rounding from two");
    match (fused, separate) {
        (n, 0) if n == differ => Fma::Fused,
        (0, n) if n == differ => Fma::Separate,
        _ => panic!("fma() rounds once for {fused} and twice for {separate} of {differ} inputs: one device, two ways"),
    }
}
