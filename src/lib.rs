//! bidir: a bidirectional path tracer that runs entirely on the GPU through Vulkan compute.
//!
//! Layers, from the bottom (see docs/architecture.md):
//! - [`vk`]: the only place with `unsafe` Vulkan: context, memory, kernels, submission.
//! - [`gpu`]: the ABI shared with GLSL (structs, bindings, workgroup sizes) and the SPIR-V.
//! - [`compute`]: small reusable GPU algorithms (reduction, prefix sum).
//! - [`scene`]: the CPU scene: OBJ+MTL and glTF loaders, textures, cameras, the built-in
//!   Cornell box, derived data (emitters, bounds, sizes). Needs no GPU.
//! - [`render`]: integrators on the GPU, the progressive film, the display tonemap.
//! - [`viewer`]: `bidir view`, the film live in a window with a fly camera.
//! - [`text`]: untrusted text (file contents, flag values) made safe to print.
//! - [`limits`]: scene, texture, film and image size limits, checked before allocating.

#![deny(unsafe_code)]

pub mod bench;
pub mod bvh;
pub mod compute;
pub mod gpu;
pub mod gpu_data;
pub mod imaging;
pub mod limits;
pub mod render;
pub mod scene;
pub mod text;
pub mod trace;
pub mod viewer;
pub mod vk;
