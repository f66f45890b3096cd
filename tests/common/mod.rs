//! Shared helpers for integration tests: a validated Vulkan context, a small RNG, geometry.
#![allow(dead_code)]

pub mod agree;
pub mod geometry;
pub mod gltf_out;
pub mod sampling_kernel;
pub mod scenes;
pub mod sphere;
pub mod stats;

use bidir::vk::{Context, ContextOptions};

/// A context with the Khronos validation layer always on (tests fail if it is missing).
pub fn gpu() -> Context {
    let mut opts = ContextOptions::from_env();
    opts.validation = true;
    Context::new(&opts).unwrap_or_else(|e| panic!("cannot create a Vulkan context: {e}"))
}

/// Destroys the context and fails the test on any validation message (leaks included).
pub fn finish(ctx: Context) {
    let messages = ctx.close().expect("all GPU objects dropped before finish()");
    assert!(messages.is_empty(), "validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n"));
}

/// PCG32 (O'Neill 2014): deterministic random inputs without a dependency.
pub struct Pcg(u64);

impl Pcg {
    pub fn new(seed: u64) -> Self {
        let mut p = Pcg(seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407));
        p.next_u32();
        p
    }
    pub fn next_u32(&mut self) -> u32 {
        let old = self.0;
        self.0 = old.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        xorshifted.rotate_right((old >> 59) as u32)
    }
    /// Uniform in [0, 1).
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 / (1u32 << 24) as f32
    }
    pub fn below(&mut self, n: u32) -> u32 {
        ((self.next_u32() as u64 * n as u64) >> 32) as u32
    }
}
