//! What every integrator implements: its kernels, its GPU storage and its whole pass.
//!
//! Adding an integrator touches its own file (kernels, storage, push constants, dispatches)
//! plus its registration: a variant of [`super::Integrator`] and an arm of
//! [`super::build_kernels`].

use super::{film::Film, gpu_scene::GpuScene, RenderError, RenderSettings};
use crate::gpu::abi::GpuCamera;
use crate::vk::{Context, Kernel};

/// What a pass reads from the renderer.
pub struct PassInputs<'a> {
    pub scene: &'a GpuScene,
    pub film: &'a Film,
    /// The camera, windowed to the film (`gpu_data::gpu_camera_window`).
    pub camera: GpuCamera,
    pub settings: &'a RenderSettings,
    /// Most samples of a pixel one pass renders at once (the storage is sized for it).
    pub slices: u32,
}

/// An integrator's kernels and storage, specialised for one scene and film size.
pub trait IntegratorKernels {
    /// The kernels a pass runs (for their compile statistics, `Kernel::statistics`).
    fn kernels(&self) -> Vec<&Kernel>;
    /// Bytes of integrator-specific GPU memory (e.g. BDPT's light vertices).
    fn storage_bytes(&self) -> u64 {
        0
    }
    /// Whether the film needs a splat buffer (light tracing writes to any pixel).
    fn splats(&self) -> bool {
        false
    }
    /// Whether the storage is sized by the image's pixel count (then a camera with another
    /// image size needs new kernels).
    fn sized_by_pixels(&self) -> bool {
        false
    }
    /// Whether its iterations start at multiples of the sample slices (then passes should end
    /// on one: a shorter iteration traces fewer light paths for the same work).
    fn slice_aligned(&self) -> bool {
        false
    }
    /// Whether it runs as a wavefront (its paths' rays traced by the trace kernels between its
    /// launches; for logs and image metadata).
    fn wavefront(&self) -> bool {
        false
    }
    /// The shadow-ray queue its megakernel uses, if any.
    fn shadow_queue(&self) -> Option<super::ShadowQueue> {
        None
    }
    /// Records and submits samples `first..first + spp` of every pixel, added to the film.
    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> Result<(), RenderError>;
}
