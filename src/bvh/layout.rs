//! obvhs' BVH2 to the GPU layout: inner nodes in depth-first order holding both child boxes,
//! leaves folded into their parent's child pointer, triangles copied into leaf order.

use super::{intersect, Bvh, BvhError, BvhLayout, TriTest};
use crate::gpu::abi::{self, BvhNode, CwbvhNode, GpuTri};
use glam::{IVec4, Vec3, Vec4};
use obvhs::{aabb::Aabb, bvh2::Bvh2};

use std::time::Duration;

/// A leaf child pointer: bit 31 set, count - 1 in bits 27..31, first triangle in bits 0..27.
pub(crate) fn leaf_pointer(first: usize, count: usize) -> i32 {
    debug_assert!(count >= 1 && count as u32 <= abi::LEAF_MAX_TRIS && first < 1 << abi::LEAF_FIRST_BITS);
    ((1u32 << 31) | (((count - 1) as u32) << abi::LEAF_FIRST_BITS) | first as u32) as i32
}

/// (first, count) of a leaf pointer.
pub(crate) fn leaf_range(ptr: i32) -> (usize, usize) {
    let p = ptr as u32;
    ((p & ((1 << abi::LEAF_FIRST_BITS) - 1)) as usize, (((p >> abi::LEAF_FIRST_BITS) & 0xf) + 1) as usize)
}

struct Builder<'a> {
    src: &'a Bvh2,
    positions: &'a [Vec3],
    triangles: &'a [[u32; 3]],
    test: TriTest,
    nodes: Vec<BvhNode>,
    tris: Vec<GpuTri>,
    tri_ids: Vec<u32>,
    leaves: usize,
}

impl Builder<'_> {
    /// Child pointer for obvhs node `i`, emitting its subtree.
    fn child(&mut self, i: usize, depth: usize, max_depth: &mut usize) -> Result<i32, BvhError> {
        let n = &self.src.nodes[i];
        if n.prim_count > 0 {
            *max_depth = (*max_depth).max(depth);
            let first = self.tris.len();
            let count = n.prim_count as usize;
            for k in 0..count {
                let id = self.src.primitive_indices[n.first_index as usize + k];
                let t = self.triangles[id as usize];
                let [v0, v1, v2] = t.map(|v| self.positions[v as usize]);
                self.tris.push(intersect::encode(self.test, v0, v1, v2));
                self.tri_ids.push(id);
            }
            self.leaves += 1;
            return Ok(leaf_pointer(first, count));
        }
        let index = self.nodes.len();
        self.nodes.push(BvhNode::default());
        let (a, b) = (n.first_index as usize, n.first_index as usize + 1);
        let ca = self.child(a, depth + 1, max_depth)?;
        let cb = self.child(b, depth + 1, max_depth)?;
        self.nodes[index] = node(self.src.nodes[a].aabb(), self.src.nodes[b].aabb(), ca, cb);
        Ok(index as i32)
    }
}

fn node(a: &Aabb, b: &Aabb, ca: i32, cb: i32) -> BvhNode {
    BvhNode {
        c0_xy: Vec4::new(a.min.x, a.max.x, a.min.y, a.max.y),
        c1_xy: Vec4::new(b.min.x, b.max.x, b.min.y, b.max.y),
        c01_z: Vec4::new(a.min.z, a.max.z, b.min.z, b.max.z),
        children: IVec4::new(ca, cb, 0, 0),
    }
}

pub(crate) fn convert(src: Bvh2, positions: &[Vec3], triangles: &[[u32; 3]], test: TriTest) -> Result<Bvh, BvhError> {
    let mut b = Builder {
        src: &src,
        positions,
        triangles,
        test,
        nodes: Vec::with_capacity(src.nodes.len() / 2 + 1),
        tris: Vec::with_capacity(src.primitive_indices.len()),
        tri_ids: Vec::with_capacity(src.primitive_indices.len()),
        leaves: 0,
    };
    let mut depth = 0;
    let root = &src.nodes[0];
    if root.prim_count > 0 {
        // A single leaf: give it an inner root with that leaf as both children (an inverted
        // "empty" box would read as an infinite slab in the min/max box test).
        b.nodes.push(BvhNode::default());
        let leaf = b.child(0, 1, &mut depth)?;
        b.nodes[0] = node(root.aabb(), root.aabb(), leaf, leaf);
    } else {
        b.child(0, 0, &mut depth)?;
    }
    if depth + 1 > abi::TRAVERSAL_STACK_SIZE as usize {
        return Err(BvhError::TooDeep { depth, max: abi::TRAVERSAL_STACK_SIZE });
    }
    let (nodes, tris, tri_ids, leaves) = (b.nodes, b.tris, b.tri_ids, b.leaves);
    Ok(Bvh {
        layout: BvhLayout::Bvh2,
        nodes,
        wide_nodes: Vec::new(),
        quant_nodes: Vec::new(),
        bvh4_nodes: Vec::new(),
        bvh4_any_nodes: Vec::new(),
        tris,
        tri_ids,
        tri_test: test,
        depth,
        leaves,
        build_time: Duration::ZERO,
        source: src,
    })
}

/// obvhs' BVH2 (one triangle per leaf) to its compressed 8-wide BVH (leaves of up to
/// `max_leaf_tris` <= 3 triangles, children ordered for the ray octant), nodes copied byte
/// for byte, triangles in its primitive order.
pub(crate) fn convert_wide(
    src: Bvh2,
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    test: TriTest,
    max_leaf_tris: u32,
) -> Result<Bvh, BvhError> {
    let wide = obvhs::cwbvh::bvh2_to_cwbvh::bvh2_to_cwbvh(&src, max_leaf_tris.clamp(1, 3), true, false);
    let wide_nodes: Vec<CwbvhNode> = wide.nodes.iter().map(|n| bytemuck::cast::<obvhs::cwbvh::node::CwBvhNode, CwbvhNode>(*n)).collect();
    let tri_ids = wide.primitive_indices.clone();
    let tris = tri_ids
        .iter()
        .map(|&id| {
            let [v0, v1, v2] = triangles[id as usize].map(|v| positions[v as usize]);
            intersect::encode(test, v0, v1, v2)
        })
        .collect();
    // Depth (levels of wide nodes below the root) and leaves, by an explicit walk.
    let (mut depth, mut leaves) = (0usize, 0usize);
    let mut todo = vec![(0usize, 0usize)];
    while let Some((i, d)) = todo.pop() {
        depth = depth.max(d);
        let n = &wide.nodes[i];
        let mut inner = 0;
        for slot in 0..8 {
            if n.child_meta[slot] == 0 {
                continue;
            }
            if n.imask & (1 << slot) != 0 {
                todo.push((n.child_base_idx as usize + inner, d + 1));
                inner += 1;
            } else {
                leaves += 1;
            }
        }
    }
    // Each level holds at most one pending node group and one postponed triangle group on the
    // stack.
    if 2 * (depth + 1) > abi::CWBVH_STACK_SIZE as usize {
        return Err(BvhError::TooDeep { depth, max: abi::CWBVH_STACK_SIZE });
    }
    Ok(Bvh {
        layout: BvhLayout::Cwbvh,
        nodes: Vec::new(),
        wide_nodes,
        quant_nodes: Vec::new(),
        bvh4_nodes: Vec::new(),
        bvh4_any_nodes: Vec::new(),
        tris,
        tri_ids,
        tri_test: test,
        depth,
        leaves,
        build_time: Duration::ZERO,
        source: src,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn leaf_pointers_round_trip() {
        for (first, count) in [(0, 1), (5, 16), ((1 << 27) - 1, 3)] {
            let p = leaf_pointer(first, count);
            assert!(p < 0);
            assert_eq!(leaf_range(p), (first, count));
        }
    }

    #[test]
    fn every_triangle_reachable_once_without_splits() {
        let mut positions = Vec::new();
        let mut tris = Vec::new();
        for i in 0..500u32 {
            let o = Vec3::new((i % 10) as f32, (i / 10 % 10) as f32, (i / 100) as f32);
            positions.extend([o, o + Vec3::X * 0.5, o + Vec3::Y * 0.5]);
            tris.push([3 * i, 3 * i + 1, 3 * i + 2]);
        }
        let opts = crate::bvh::BuildOptions { pre_split: false, ..Default::default() };
        let bvh = Bvh::build(&positions, &tris, &opts).unwrap();
        let mut seen = bvh.tri_ids.clone();
        seen.sort();
        assert_eq!(seen, (0..500).collect::<Vec<_>>());
        // Every leaf range lies inside `tris`, every inner pointer inside `nodes`.
        for n in &bvh.nodes {
            for c in [n.children.x, n.children.y] {
                if c < 0 {
                    let (f, k) = leaf_range(c);
                    assert!(f + k <= bvh.tris.len());
                } else {
                    assert!((c as usize) < bvh.nodes.len() && c > 0);
                }
            }
        }
    }
}
