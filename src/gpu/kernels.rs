//! The SPIR-V of every compute kernel, compiled by build.rs from `glsl/` and embedded here.

pub use crate::vk::KernelSource;

/// One integrator kernel built for each BVH layout the integrators traverse (build.rs,
/// `WIDE_VARIANTS`); `GpuBvh::kernel` picks the one of the bound BVH.
pub struct LayoutForms {
    pub bvh2: &'static KernelSource,
    pub cwbvh: &'static KernelSource,
    pub bvh4: &'static KernelSource,
}

include!(concat!(env!("OUT_DIR"), "/kernels.rs"));
