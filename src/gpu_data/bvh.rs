//! The BVH in GPU memory, bound the same way by the integrators and the trace kernels.

use crate::bvh::{Bvh, BvhLayout, TriTest};
use crate::gpu::abi::{self, GpuTri};
use crate::gpu::kernels::LayoutForms;
use crate::vk::{Bind, Buffer, Context, KernelSource, Result};

/// A BVH in GPU memory.
pub struct GpuBvh {
    /// `BvhNode`s, `CwbvhNode`s, `QuantNode`s or `Bvh4Node`s, as `layout` says.
    pub nodes: Buffer,
    pub tris: Buffer,
    pub tri_test: TriTest,
    pub layout: BvhLayout,
    pub bytes: u64,
}

impl GpuBvh {
    pub fn upload(ctx: &Context, bvh: &Bvh) -> Result<GpuBvh> {
        GpuBvh::upload_with_tris(ctx, bvh, &bvh.tris)
    }

    /// As `upload`, with `tris` (`bvh.tris` re-encoded, e.g. `Bvh::alpha_marked_tris`) in
    /// place of `bvh.tris`.
    pub fn upload_with_tris(ctx: &Context, bvh: &Bvh, tris: &[GpuTri]) -> Result<GpuBvh> {
        assert_eq!(tris.len(), bvh.tris.len(), "one GPU triangle per leaf triangle");
        let nodes = match bvh.layout {
            BvhLayout::Bvh2 => ctx.upload_buffer("bvh.nodes", &bvh.nodes)?,
            BvhLayout::Cwbvh => ctx.upload_buffer("bvh.wide_nodes", &bvh.wide_nodes)?,
            BvhLayout::Bvh2q => ctx.upload_buffer("bvh.quant_nodes", &bvh.quant_nodes)?,
            // Any-hit rays' copy after the closest-hit nodes (its pointers count from there).
            BvhLayout::Bvh4 => ctx.upload_buffer("bvh.bvh4_nodes", &[bvh.bvh4_nodes.as_slice(), &bvh.bvh4_any_nodes].concat())?,
        };
        Ok(GpuBvh {
            nodes,
            tris: ctx.upload_buffer("bvh.tris", tris)?,
            tri_test: bvh.tri_test,
            layout: bvh.layout,
            bytes: (bvh.node_bytes() + std::mem::size_of_val(bvh.tris.as_slice())) as u64,
        })
    }

    /// The form of an integrator kernel that traverses this BVH's layout: `bvh2` is built
    /// from the kernel's source as it is, `cwbvh` with `TRAVERSE_CWBVH`, `bvh4` with
    /// `TRAVERSE_BVH4` (build.rs). The renderer builds only these three layouts
    /// (`render::check_layout`).
    pub fn kernel(&self, forms: &LayoutForms) -> &'static KernelSource {
        match self.layout {
            BvhLayout::Cwbvh => forms.cwbvh,
            BvhLayout::Bvh4 => forms.bvh4,
            BvhLayout::Bvh2 | BvhLayout::Bvh2q => forms.bvh2,
        }
    }

    /// Bindings of the BVH buffers (glsl/common/traverse.glsl).
    pub fn binds(&self) -> Vec<Bind<'_>> {
        vec![Bind::buffer(abi::BIND_NODES, &self.nodes), Bind::buffer(abi::BIND_TRIS, &self.tris)]
    }
}
