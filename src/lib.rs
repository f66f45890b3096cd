//! bidir: a bidirectional path tracer that runs entirely on the GPU through Vulkan compute.
//!
//! Layers, from the bottom (see docs/architecture.md):
//! - [`vk`]: the only place with `unsafe` Vulkan: context, memory, kernels, submission.
//! - [`gpu`]: the ABI shared with GLSL (structs, bindings, workgroup sizes) and the SPIR-V.
//! - [`compute`]: small reusable GPU algorithms (reduction, prefix sum).

pub mod compute;
pub mod bench;
pub mod bvh;
pub mod film;
pub mod gpu;
pub mod render;
pub mod scene;
pub mod trace;
pub mod vk;
