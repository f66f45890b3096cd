//! The BVH in GPU memory, bound the same way by the integrators and the trace kernels.

use crate::bvh::{Bvh, BvhLayout, TriTest};
use crate::gpu::abi::{self, Bvh4Node, GpuTri};
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
    /// Whether any-hit rays traverse their own copy of the nodes (4-wide layout;
    /// `Bvh::bvh4_any_nodes`, uploaded where it fits).
    pub any_hit_copy: bool,
}

impl GpuBvh {
    pub fn upload(ctx: &Context, bvh: &Bvh) -> Result<GpuBvh> {
        GpuBvh::upload_with_tris(ctx, bvh, &bvh.tris)
    }

    /// As `upload`, with `tris` (`bvh.tris` re-encoded, e.g. `Bvh::alpha_marked_tris`) in
    /// place of `bvh.tris`.
    pub fn upload_with_tris(ctx: &Context, bvh: &Bvh, tris: &[GpuTri]) -> Result<GpuBvh> {
        assert_eq!(tris.len(), bvh.tris.len(), "one GPU triangle per leaf triangle");
        let mut any_hit_copy = false;
        let nodes = match bvh.layout {
            BvhLayout::Bvh2 => ctx.upload_buffer("bvh.nodes", &bvh.nodes)?,
            BvhLayout::Cwbvh => ctx.upload_buffer("bvh.wide_nodes", &bvh.wide_nodes)?,
            BvhLayout::Bvh2q => ctx.upload_buffer("bvh.quant_nodes", &bvh.quant_nodes)?,
            BvhLayout::Bvh4 => {
                let data = bvh4_node_data(bvh, ctx.info().max_storage_buffer_range as usize);
                any_hit_copy = data.len() > bvh.bvh4_nodes.len();
                ctx.upload_buffer("bvh.bvh4_nodes", &data)?
            }
        };
        let bytes = nodes.size() + std::mem::size_of_val(bvh.tris.as_slice()) as u64;
        let tris = ctx.upload_buffer("bvh.tris", tris)?;
        Ok(GpuBvh { nodes, tris, tri_test: bvh.tri_test, layout: bvh.layout, bytes, any_hit_copy })
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

/// The 4-wide node buffer's contents: the closest-hit nodes, then any-hit rays' copy
/// (`Bvh::bvh4_any_nodes`, its pointers counting from there), unless the two exceed `limit`
/// bytes (the device's largest storage buffer) where the nodes alone do not: then the nodes
/// alone, node 0 naming no copy, and any-hit rays traverse the closest-hit tree.
fn bvh4_node_data(bvh: &Bvh, limit: usize) -> Vec<Bvh4Node> {
    let both = std::mem::size_of_val(bvh.bvh4_nodes.as_slice()) + std::mem::size_of_val(bvh.bvh4_any_nodes.as_slice());
    if both <= limit || bvh.bvh4_any_nodes.is_empty() {
        return [bvh.bvh4_nodes.as_slice(), &bvh.bvh4_any_nodes].concat();
    }
    let mut nodes = bvh.bvh4_nodes.clone();
    nodes[0].reserved.x = 0;
    nodes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::BuildOptions;

    /// The copy follows the nodes where both fit one storage buffer; where they do not, the
    /// nodes go alone and node 0 sends any-hit rays to their own root.
    #[test]
    fn the_any_hit_copy_is_left_out_where_it_does_not_fit() {
        let (positions, triangles) = crate::bvh::test_soup(5, 500, 10.0, (0.2, 0.5));
        let bvh = Bvh::build(&positions, &triangles, &BuildOptions { layout: BvhLayout::Bvh4, ..Default::default() }).unwrap();
        let n = bvh.bvh4_nodes.len();
        let one = n * std::mem::size_of::<Bvh4Node>();
        let both = bvh4_node_data(&bvh, 2 * one);
        assert_eq!((both.len(), both[0].reserved.x), (2 * n, n as u32));
        let alone = bvh4_node_data(&bvh, 2 * one - 1);
        assert_eq!((alone.len(), alone[0].reserved.x), (n, 0));
        assert!(bytemuck::cast_slice::<_, u8>(&alone[1..]) == bytemuck::cast_slice::<_, u8>(&bvh.bvh4_nodes[1..]));
    }
}
