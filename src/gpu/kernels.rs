//! The SPIR-V of every compute kernel, compiled by build.rs from `glsl/` and embedded here.

/// One compiled compute kernel.
#[derive(Clone, Copy, Debug)]
pub struct KernelSource {
    /// File stem, e.g. `reduce_sum`; also its debug name.
    pub name: &'static str,
    /// Source path relative to the crate root.
    pub file: &'static str,
    /// SPIR-V words as bytes (not necessarily 4-byte aligned; use `spirv_words`).
    pub spirv: &'static [u8],
}

impl KernelSource {
    /// The SPIR-V as aligned 32-bit words.
    pub fn spirv_words(&self) -> Vec<u32> {
        self.spirv.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
    }
}

include!(concat!(env!("OUT_DIR"), "/kernels.rs"));
