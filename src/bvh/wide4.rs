//! The binary layout collapsed into a 4-wide one with full-precision boxes (`Bvh4Node`; a ray
//! visits about half as many nodes, each one a single 128-byte line with no decoding): the
//! nodes' emission, which `collapse` (the default, least surface area cost) shares, and the
//! greedy collapse (`Collapse::Greedy`): each 4-wide node takes its binary node's two children
//! and repeatedly opens the inner child of largest surface area until it holds four (the usual
//! collapse, e.g. Wald et al. 2008, "Getting Rid of Packets"). Its leaves and triangles stay
//! exactly the binary layout's, so the same rays hit the same triangles.

use super::{layout::leaf_range, Bvh, BvhError, BvhLayout};
use crate::gpu::abi::{self, Bvh4Node, BvhNode};
use glam::{IVec4, UVec4, Vec3, Vec4};

/// A child of a node being collapsed: its box and its binary-layout pointer.
#[derive(Clone, Copy)]
pub(super) struct Child {
    pub(super) lo: Vec3,
    pub(super) hi: Vec3,
    pub(super) ptr: i32,
}

impl Child {
    fn half_area(&self) -> f32 {
        super::half_area(self.lo, self.hi)
    }
}

/// The two children of binary node `i`.
pub(super) fn children(nodes: &[BvhNode], i: usize) -> [Child; 2] {
    let n = &nodes[i];
    [
        Child { lo: Vec3::new(n.c0_xy.x, n.c0_xy.z, n.c01_z.x), hi: Vec3::new(n.c0_xy.y, n.c0_xy.w, n.c01_z.y), ptr: n.children.x },
        Child { lo: Vec3::new(n.c1_xy.x, n.c1_xy.z, n.c01_z.z), hi: Vec3::new(n.c1_xy.y, n.c1_xy.w, n.c01_z.w), ptr: n.children.y },
    ]
}

/// The 4-wide node of up to four children (boxes from `kids`, pointers `ptrs`); unused slots
/// hold an inverted box (+inf lower, -inf upper bounds) that no ray enters.
fn wide_node(kids: &[Child], ptrs: [i32; 4]) -> Bvh4Node {
    let mut planes = [Vec4::splat(f32::INFINITY), Vec4::splat(f32::NEG_INFINITY)].repeat(3);
    for (slot, c) in kids.iter().enumerate() {
        for axis in 0..3 {
            planes[2 * axis][slot] = c.lo[axis];
            planes[2 * axis + 1][slot] = c.hi[axis];
        }
    }
    Bvh4Node { planes: planes.try_into().expect("six planes"), children: IVec4::from_array(ptrs), reserved: UVec4::ZERO }
}

/// Emits a collapse's 4-wide nodes depth first (an inner node's first inner child follows
/// it), the children of binary inner node i's 4-wide node chosen by `slots(i)`.
struct Emit<'a> {
    slots: &'a mut dyn FnMut(usize) -> Vec<Child>,
    out: Vec<Bvh4Node>,
    leaves: usize,
}

impl Emit<'_> {
    /// Emits the 4-wide node for binary inner node `i` and its subtree; returns (its index,
    /// its depth, the most stack entries a traversal below it pushes).
    fn node(&mut self, i: usize) -> (i32, usize, usize) {
        let kids = (self.slots)(i);
        debug_assert!((1..=4).contains(&kids.len()));
        let index = self.out.len();
        self.out.push(Bvh4Node::default());
        let (mut depth, mut below) = (0, 0);
        let mut ptrs = [0i32; 4];
        for (slot, c) in kids.iter().enumerate() {
            ptrs[slot] = if c.ptr >= 0 {
                let (p, d, s) = self.node(c.ptr as usize);
                depth = depth.max(d + 1);
                below = below.max(s);
                p
            } else {
                self.leaves += 1;
                depth = depth.max(1);
                c.ptr
            };
        }
        self.out[index] = wide_node(&kids, ptrs);
        // Visiting this node pushes all hit children but the nearest.
        (index as i32, depth, below + kids.len() - 1)
    }
}

/// The binary-layout BVH (`BvhLayout::Bvh2`, its `binary` nodes taken out of it) as a 4-wide
/// one whose node for binary inner node i has the children `slots(i)` (binary inner nodes, each
/// the root of a 4-wide node of its own, and leaves), from the root, node 0.
pub(super) fn emit(mut bvh: Bvh, binary: &[BvhNode], slots: &mut dyn FnMut(usize) -> Vec<Child>) -> Result<Bvh, BvhError> {
    debug_assert_eq!(bvh.layout, BvhLayout::Bvh2);
    let mut e = Emit { slots, out: Vec::with_capacity(binary.len() / 2 + 1), leaves: 0 };
    let (_, depth, stack) = e.node(0);
    let (nodes, leaves) = (e.out, e.leaves);
    // The stack holds the sentinel below the pushed entries.
    if stack + 1 > abi::TRAVERSAL_STACK_SIZE as usize {
        return Err(BvhError::TooDeep { depth, max: abi::TRAVERSAL_STACK_SIZE });
    }
    debug_assert!(nodes.iter().flat_map(|n| n.children.to_array()).all(|p| p >= 0 || leaf_range(p).0 + leaf_range(p).1 <= bvh.tris.len()));
    bvh.layout = BvhLayout::Bvh4;
    bvh.nodes = Vec::new();
    bvh.bvh4_nodes = nodes;
    bvh.depth = depth;
    bvh.leaves = leaves;
    Ok(bvh)
}

/// Converts a binary-layout BVH (`BvhLayout::Bvh2`) to the 4-wide one by the greedy collapse.
pub(crate) fn convert(mut bvh: Bvh) -> Result<Bvh, BvhError> {
    let binary = std::mem::take(&mut bvh.nodes);
    emit(bvh, &binary, &mut |i| {
        let mut kids: Vec<Child> = children(&binary, i).to_vec();
        // A lone leaf is both children of its root (bvh::layout).
        kids.dedup_by_key(|c| c.ptr);
        while kids.len() < 4 {
            let open = kids
                .iter()
                .enumerate()
                .filter(|(_, c)| c.ptr >= 0)
                .max_by(|(_, a), (_, b)| a.half_area().total_cmp(&b.half_area()))
                .map(|(k, _)| k);
            let Some(k) = open else { break };
            let c = kids.remove(k);
            kids.extend(children(&binary, c.ptr as usize));
        }
        kids
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::BuildOptions;

    fn soup(n: u32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let mut positions = Vec::new();
        let mut tris = Vec::new();
        for i in 0..n {
            let o = Vec3::new((i % 13) as f32, (i / 13 % 11) as f32 * 0.7, (i / 143) as f32 * 1.3);
            positions.extend([o, o + Vec3::new(0.6, 0.1, 0.0), o + Vec3::new(0.0, 0.5, 0.4)]);
            tris.push([3 * i, 3 * i + 1, 3 * i + 2]);
        }
        (positions, tris)
    }

    /// Every leaf of the binary tree is a child of exactly one 4-wide node, with the box its
    /// binary parent gave it; every inner node is reached once; no node has fewer than two
    /// children, and only nodes whose children are all leaves have fewer than four.
    #[test]
    fn collapse_keeps_every_leaf_and_box() {
        let (positions, tris) = soup(2000);
        let binary = Bvh::build(&positions, &tris, &BuildOptions::default()).unwrap();
        let greedy = BuildOptions { layout: BvhLayout::Bvh4, collapse: crate::bvh::Collapse::Greedy, ..Default::default() };
        let wide = Bvh::build(&positions, &tris, &greedy).unwrap();
        assert_eq!(wide.tris, binary.tris);
        let mut binary_leaves: Vec<(i32, [f32; 6])> = Vec::new();
        for i in 0..binary.nodes.len() {
            for c in children(&binary.nodes, i) {
                if c.ptr < 0 {
                    binary_leaves.push((c.ptr, [c.lo.x, c.lo.y, c.lo.z, c.hi.x, c.hi.y, c.hi.z]));
                }
            }
        }
        let mut wide_leaves = Vec::new();
        let mut reached = vec![0u32; wide.bvh4_nodes.len()];
        reached[0] = 1;
        for n in &wide.bvh4_nodes {
            let used: Vec<usize> = (0..4).filter(|&s| n.planes[0][s] <= n.planes[1][s]).collect();
            assert!(used.len() >= 2);
            assert!(used.len() == 4 || used.iter().all(|&s| n.children[s] < 0), "a node with an inner child is not full");
            for s in 0..4 {
                if !used.contains(&s) {
                    assert!(n.planes.iter().step_by(2).all(|p| p[s] == f32::INFINITY));
                    assert!(n.planes.iter().skip(1).step_by(2).all(|p| p[s] == f32::NEG_INFINITY));
                    continue;
                }
                let p = n.children[s];
                if p < 0 {
                    let b = [n.planes[0][s], n.planes[2][s], n.planes[4][s], n.planes[1][s], n.planes[3][s], n.planes[5][s]];
                    wide_leaves.push((p, b));
                } else {
                    reached[p as usize] += 1;
                }
            }
        }
        assert!(reached.iter().all(|&r| r == 1), "every 4-wide node is the child of exactly one other (the root of none)");
        let key = |a: &(i32, [f32; 6])| (a.0, a.1.map(f32::to_bits));
        binary_leaves.sort_by_key(key);
        wide_leaves.sort_by_key(key);
        assert_eq!(binary_leaves, wide_leaves);
        assert!(
            wide.bvh4_nodes.len() * 2 < binary.nodes.len() + 2,
            "{} wide nodes for {} binary ones",
            wide.bvh4_nodes.len(),
            binary.nodes.len()
        );
        assert!(wide.depth < binary.depth);
    }

    /// A lone triangle, with either collapse: one node of one leaf slot (the binary layout's
    /// root holds the leaf twice), the other slots empty.
    #[test]
    fn a_single_leaf_collapses_to_one_node() {
        let positions = [Vec3::ZERO, Vec3::X, Vec3::Y];
        for collapse in [crate::bvh::Collapse::Greedy, crate::bvh::Collapse::SAH] {
            let opts = BuildOptions { layout: BvhLayout::Bvh4, collapse, ..Default::default() };
            let wide = Bvh::build(&positions, &[[0, 1, 2]], &opts).unwrap();
            assert_eq!(wide.bvh4_nodes.len(), 1, "{collapse}");
            let root = &wide.bvh4_nodes[0];
            assert_eq!(leaf_range(root.children.x), (0, 1), "{collapse}");
            assert!((1..4).all(|s| root.planes[0][s] == f32::INFINITY), "{collapse}: one slot used");
            assert_eq!(wide.leaves, 1, "{collapse}");
        }
    }
}
