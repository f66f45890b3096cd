//! A second copy of the 4-wide nodes for any-hit rays, each node's child slots in the order
//! such a ray should visit them.
//!
//! An any-hit (shadow) ray ends at its first hit, so of two children it crosses it should enter
//! first the one likelier to stop it for the work it takes: child A before B when
//! p_A / C_A > p_B / C_B, where p is the probability that a ray crossing the child's box hits
//! a triangle in it and C the expected work of a ray crossing it (visiting A first costs
//! C_A + (1 - p_A) C_B; Ize & Hansen 2011, "RTSAH Traversal Order for Occlusion Rays").
//! Both come from surface areas, as the SAH does: a random line through a convex box of area
//! S crosses a flat triangle of area a inside it with probability 2a / S, so p = min(1, sum of
//! the triangles' areas / the box's half area); C is the subtree's SAH in node visits and
//! triangle tests. The any-hit node step takes the hit slots in slot order
//! (glsl/common/traverse_bvh4_step.glsl).
//!
//! The order lives in its own copy of the nodes because closest-hit rays break ties of entry
//! distance by slot, and the collapse's slot order suits them: with the occlusion order as
//! the one slot order Sponza's shadow rays traced 5-43 % faster on the NVIDIA H200 but its
//! diffuse rays 11 % slower, and a stored permutation decoded in the step cost the shadow rays
//! their gain (docs/traversal.md, "Child slots in occlusion order"). Two copies cost twice the
//! node memory and nothing in the step: any-hit rays start at the copy's root, node 0's
//! `reserved.x`. With the copy, shadow rays trace 10-31 % faster from three of Sponza's four
//! cameras and level from the fourth; other rays are not slower (docs/traversal.md, "Any-hit
//! rays' own copy of the nodes").

use super::layout::leaf_range;
use super::{half_area, Bvh};
use crate::gpu::abi::Bvh4Node;
use glam::Vec3;

/// Adds `bvh4_any_nodes` to a 4-wide tree (`super::wide4::convert`'s): its nodes in occlusion
/// order, their inner pointers moved past the closest-hit nodes, and the copy's root in node
/// 0's `reserved.x`. `positions` and `triangles` are what the tree was built over.
pub(crate) fn add_any_hit_copy(mut bvh: Bvh, positions: &[Vec3], triangles: &[[u32; 3]]) -> Bvh {
    let base = bvh.bvh4_nodes.len();
    let mut copy = bvh.bvh4_nodes.clone();
    let area = |i: usize| {
        let [a, b, c] = triangles[bvh.tri_ids[i] as usize].map(|v| positions[v as usize]);
        0.5 * (b - a).cross(c - a).length()
    };
    order_for_occlusion(&mut copy, area);
    let offset = i32::try_from(base).expect("4-wide node count fits a child pointer");
    for n in &mut copy {
        // Inner pointers move; leaf pointers (< 0) and empty slots' zeros stay.
        for s in 0..4 {
            let used = n.planes[0][s] <= n.planes[1][s];
            if used && n.children[s] >= 0 {
                n.children[s] += offset;
            }
        }
    }
    bvh.bvh4_nodes[0].reserved.x = base as u32;
    bvh.bvh4_any_nodes = copy;
    bvh
}

/// A slot's (lower, upper) bounds; lower.x > upper.x for an empty slot.
fn bounds(n: &Bvh4Node, s: usize) -> (Vec3, Vec3) {
    (Vec3::new(n.planes[0][s], n.planes[2][s], n.planes[4][s]), Vec3::new(n.planes[1][s], n.planes[3][s], n.planes[5][s]))
}

/// What a subtree holds: its triangles' area, and the SAH work of a ray crossing its box.
struct Stats {
    tri_area: f32,
    cost: f32,
}

/// Reorders every node's slots by p / C, highest first (empty slots last); `leaf_tri_area(i)`
/// is the area of the triangle at leaf entry i.
pub(crate) fn order_for_occlusion(nodes: &mut [Bvh4Node], leaf_tri_area: impl Fn(usize) -> f32) {
    if nodes.is_empty() {
        return;
    }
    let mut memo: Vec<Option<Stats>> = (0..nodes.len()).map(|_| None).collect();
    // Children come after their parents (depth first), so a reverse sweep sees them first.
    for i in (0..nodes.len()).rev() {
        let n = nodes[i];
        // (slot, box half area, triangle area, work) of each used slot.
        let used: Vec<(usize, f32, f32, f32)> = (0..4)
            .filter_map(|s| {
                let (l, h) = bounds(&n, s);
                (l.x <= h.x).then_some((s, l, h))
            })
            .map(|(s, l, h)| {
                let p = n.children[s];
                let (tri_area, cost) = if p >= 0 {
                    let st = memo[p as usize].as_ref().expect("children after parents");
                    (st.tri_area, st.cost)
                } else {
                    let (first, count) = leaf_range(p);
                    ((first..first + count).map(&leaf_tri_area).sum(), count as f32)
                };
                (s, half_area(l, h), tri_area, cost)
            })
            .collect();
        let (lo, hi) = used.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &(s, ..)| {
            let (l, h) = bounds(&n, s);
            (lo.min(l), hi.max(h))
        });
        let node_area = half_area(lo, hi).max(f32::MIN_POSITIVE);
        let total_area: f32 = used.iter().map(|u| u.2).sum();
        let cost = 1.0 + used.iter().map(|&(_, box_area, _, c)| box_area / node_area * c).sum::<f32>();
        let mut keyed: Vec<(f32, usize)> = used
            .iter()
            .map(|&(s, box_area, tri_area, c)| {
                let p = if box_area > 0.0 { (tri_area / box_area).min(1.0) } else { 1.0 };
                (p / c.max(f32::MIN_POSITIVE), s)
            })
            .collect();
        memo[i] = Some(Stats { tri_area: total_area, cost });
        // Highest p / C first; ties keep their slot order.
        keyed.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        let mut out = n;
        for (k, &(_, s)) in keyed.iter().enumerate() {
            out.children[k] = n.children[s];
            for plane in 0..6 {
                out.planes[plane][k] = n.planes[plane][s];
            }
        }
        for k in keyed.len()..4 {
            out.children[k] = 0;
            for axis in 0..3 {
                out.planes[2 * axis][k] = f32::INFINITY;
                out.planes[2 * axis + 1][k] = f32::NEG_INFINITY;
            }
        }
        nodes[i] = out;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::{layout::leaf_pointer, BuildOptions, Bvh, BvhLayout};
    use glam::{IVec4, UVec4, Vec4};

    fn node(boxes: &[(Vec3, Vec3, i32)]) -> Bvh4Node {
        let mut planes = [Vec4::splat(f32::INFINITY), Vec4::splat(f32::NEG_INFINITY)].repeat(3);
        let mut children = [0i32; 4];
        for (s, &(lo, hi, p)) in boxes.iter().enumerate() {
            for a in 0..3 {
                planes[2 * a][s] = lo[a];
                planes[2 * a + 1][s] = hi[a];
            }
            children[s] = p;
        }
        Bvh4Node { planes: planes.try_into().unwrap(), children: IVec4::from_array(children), reserved: UVec4::ZERO }
    }

    /// Three leaves of one triangle each in unit boxes: the one whose triangle fills its box
    /// comes first, the one with a sliver last; a leaf of three triangles that fill its box no
    /// more than one does (the same p, thrice the work) after the full one.
    #[test]
    fn the_likeliest_occluder_per_work_comes_first() {
        let unit = |x: f32| (Vec3::new(x, 0.0, 0.0), Vec3::new(x + 1.0, 1.0, 1.0));
        let (a, b, c, d) = (unit(0.0), unit(2.0), unit(4.0), unit(6.0));
        // Leaf entries: 0 sliver, 1 full, 2-4 three that together fill as much as one full.
        let areas = [0.01f32, 3.0, 1.0, 1.0, 1.0];
        let mut nodes = vec![node(&[
            (a.0, a.1, leaf_pointer(0, 1)),
            (b.0, b.1, leaf_pointer(1, 1)),
            (c.0, c.1, leaf_pointer(2, 3)),
            (d.0, d.1, leaf_pointer(0, 1)),
        ])];
        order_for_occlusion(&mut nodes, |i| areas[i]);
        let n = nodes[0];
        assert_eq!(n.children.x, leaf_pointer(1, 1), "the full leaf first");
        assert_eq!(n.children.y, leaf_pointer(2, 3), "then three triangles of the same fill");
        // The boxes moved with their children.
        assert_eq!((n.planes[0].x, n.planes[0].y), (2.0, 4.0));
        assert_eq!((n.planes[1].x, n.planes[1].y), (3.0, 5.0));
    }

    /// The copy permutes each node's (box, child) pairs, inner pointers moved past the
    /// closest-hit nodes, empty slots last, and node 0 says where it starts: the same tree.
    #[test]
    fn the_copy_permutes_slots_and_moves_pointers() {
        let (positions, triangles) = crate::bvh::test_soup(3, 2000, 30.0, (0.2, 3.0));
        let opts = BuildOptions { layout: BvhLayout::Bvh4, ..Default::default() };
        let bvh = Bvh::build(&positions, &triangles, &opts).unwrap();
        let plain = Bvh::build(&positions, &triangles, &BuildOptions { occlusion_copy: false, ..opts }).unwrap();
        let n = bvh.bvh4_nodes.len();
        assert!(n > 100, "a real tree");
        assert_eq!(bvh.bvh4_any_nodes.len(), n);
        assert!(plain.bvh4_any_nodes.is_empty());
        assert_eq!((bvh.bvh4_nodes[0].reserved.x, plain.bvh4_nodes[0].reserved.x), (n as u32, 0));
        let slots = |node: &Bvh4Node, offset: i32| {
            let mut v: Vec<(i32, [u32; 6])> = (0..4)
                .filter(|&s| node.planes[0][s] <= node.planes[1][s])
                .map(|s| {
                    let p = node.children[s];
                    (if p >= 0 { p - offset } else { p }, std::array::from_fn(|k| node.planes[k][s].to_bits()))
                })
                .collect();
            v.sort();
            v
        };
        let mut reordered = 0;
        for (x, y) in bvh.bvh4_nodes.iter().zip(&bvh.bvh4_any_nodes) {
            assert_eq!(slots(x, 0), slots(y, n as i32));
            let used = slots(y, n as i32).len();
            assert!((0..4).all(|s| (y.planes[0][s] <= y.planes[1][s]) == (s < used)), "empty slots last");
            reordered += usize::from(x.children != y.children);
        }
        assert!(reordered * 10 > n, "the order differs from the collapse's in {reordered} of {n} nodes");
        // Apart from node 0's pointer to the copy, the closest-hit nodes are the plain build's.
        let mut first = bvh.bvh4_nodes[0];
        first.reserved.x = 0;
        assert_eq!(bytemuck::bytes_of(&first), bytemuck::bytes_of(&plain.bvh4_nodes[0]));
        assert!(bytemuck::cast_slice::<_, u8>(&bvh.bvh4_nodes[1..]) == bytemuck::cast_slice::<_, u8>(&plain.bvh4_nodes[1..]));
    }
}
