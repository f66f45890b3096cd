//! The GPU ABI (shared with GLSL) and the embedded SPIR-V of every kernel.

pub mod abi;
pub mod kernels;
pub mod sobol;
// build.rs's step for SPIR-V that shaderc's optimiser skipped; here only for its tests.
#[cfg(test)]
mod spirv_post;

pub use abi::{FieldLayout, GpuStruct};
