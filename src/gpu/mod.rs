//! The GPU ABI (shared with GLSL) and the embedded SPIR-V of every kernel.

pub mod abi;
pub mod kernels;
pub mod sobol;

pub use abi::{FieldLayout, GpuStruct};
