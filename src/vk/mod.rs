//! The Vulkan backend. Every `unsafe` ash call in bidir lives below this module; what it
//! exports is safe: a [`Context`] (instance, device, queue, allocator), [`Buffer`]s and
//! [`Image`]s that free themselves, [`Kernel`]s whose bindings are reflected from their
//! SPIR-V, [`Context::submit`] to record and run work with a timeout, and a [`Swapchain`]
//! that shows an image in a window.
//!
//! ```no_run
//! use bidir::{gpu::{abi, kernels}, vk::{Bind, Context, ContextOptions, Memory}};
//! let ctx = Context::new(&ContextOptions::from_env())?;
//! let input = ctx.upload_buffer("values", &[1u32, 2, 3])?;
//! let sum = ctx.create_buffer("sum", 4, Memory::Device)?;
//! let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[])?;
//! let push = abi::ScanPush { count: 3, ..Default::default() };
//! ctx.submit("sum", |rec| {
//!     rec.fill_buffer(&sum, 0);
//!     rec.dispatch(&k, &[Bind::buffer(abi::REDUCE_BIND_INPUT, &input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &sum)],
//!                  bytemuck::bytes_of(&push), [1, 1, 1])
//! })?;
//! assert_eq!(ctx.read_buffer::<u32>(&sum)?, vec![6]);
//! # Ok::<(), bidir::vk::VkError>(())
//! ```

// The one layer allowed `unsafe` (the crate root denies it everywhere else); every unsafe
// block says why it is sound.
#![allow(unsafe_code)]
#![deny(clippy::undocumented_unsafe_blocks)]

mod commands;
mod context;
mod error;
mod instance;
mod kernel;
mod memory;
mod profile;
pub mod reflect;
mod rt;
mod submit;
mod swapchain;

pub use ash::vk::{Format, PhysicalDeviceType};
pub use commands::{Bind, Recorder, Resource, Timer};
pub use context::{Context, ContextOptions};
pub use error::{Result, VkError};
pub use instance::{choose_device, list_devices, DeviceInfo, MemoryHeap, SubgroupOps};
pub use kernel::{Kernel, KernelSource, KernelStatistic, Spec};
pub use memory::{Buffer, Image, Memory};
pub use profile::KernelTime;
pub use rt::{DriverTracer, RtShaders};
pub use submit::{InFlight, Recorded};
pub use swapchain::{surface_extensions, Presented, Swapchain, Vsync, SWAPCHAIN_EXTENSION};
