//! The SPIR-V of every compute kernel, compiled by build.rs from `glsl/` and embedded here.

pub use crate::vk::KernelSource;

include!(concat!(env!("OUT_DIR"), "/kernels.rs"));
