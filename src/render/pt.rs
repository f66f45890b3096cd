use super::integrator::{IntegratorKernels, PassInputs};
use super::{film::Film, gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::PtPush, kernels};
use crate::vk::{Bind, Context, Kernel, Recorder, Result, Spec};

/// The megakernel path tracer (`glsl/kernels/pt.comp`), specialised for the scene.
pub struct PathTracer {
    kernel: Kernel,
}

impl PathTracer {
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        nee: bool,
        settings: &super::RenderSettings,
        regenerate: bool,
        one_trace: bool,
    ) -> Result<PathTracer> {
        let sampler = settings.sampler;
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_STATS, value: settings.count_traversal as u32 });
        specs.push(Spec { id: abi::SPEC_NEE, value: nee as u32 });
        specs.push(sampler.spec());
        specs.push(Spec { id: abi::SPEC_PATH_REGENERATION, value: regenerate as u32 });
        specs.push(Spec { id: abi::SPEC_ONE_TRACE, value: one_trace as u32 });
        Ok(PathTracer { kernel: ctx.create_kernel(scene.bvh.kernel(&kernels::PT_FORMS), &specs)? })
    }

    /// Records one pass: `push.spp` samples for every pixel.
    pub fn record(&self, rec: &mut Recorder, scene: &GpuScene, film: &Film, push: &PtPush) -> Result<()> {
        let mut binds = scene.binds();
        binds.push(Bind::buffer(abi::BIND_ACCUM, &film.accum));
        binds.push(Bind::buffer(abi::BIND_RENDER_STATS, &film.stats));
        binds.push(Bind::buffer(abi::BIND_SLICES, film.slices_buffer()));
        let slices = push.slices.max(1);
        let n = crate::gpu_data::tiled_invocations(film.width, film.height) * slices;
        rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(push), [self.kernel.groups_for(n), 1, 1])?;
        film.record_add_slices(rec, slices)
    }
}

impl IntegratorKernels for PathTracer {
    fn kernels(&self) -> Vec<&Kernel> {
        vec![&self.kernel]
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let (s, scene) = (inputs.settings, inputs.scene);
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
        Ok(ctx.submit("render pass", |rec| self.record(rec, scene, inputs.film, &push))?)
    }
}
