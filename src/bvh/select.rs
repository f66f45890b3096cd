//! Build quality 5: several trees built with different PLOC settings, the one of least surface
//! area cost kept.
//!
//! Trees that obvhs builds at one preset with other PLOC search settings have nearly the same
//! SAH (within 1.8 % on Sponza) but trace differently: on the NVIDIA H200, Sponza's sixteen
//! trees of [`CANDIDATES`] spread by 13 % in the time of primary, shadow and diffuse rays summed
//! over four cameras, and by up to 70 % in one ray kind from one camera, each tree's time
//! following the nodes and triangles its rays visit (docs/traversal.md, "The tree lottery").
//! The SAH is a weak but camera-free predictor of that time (correlation 0.49 there): the kept
//! tree is better on average, not on every view.

use super::{half_area, layout::leaf_range, wide4, Bvh, BvhLayout};
use glam::Vec3;

/// PLOC's search distance and the depth below which it searches a single neighbour (obvhs'
/// `ploc_search_distance`, `search_depth_threshold`): every combination of four distances
/// and four depths, obvhs' slowest preset otherwise.
pub(crate) const CANDIDATES: [(u32, usize); 16] = {
    let mut c = [(0u32, 0usize); 16];
    let distances = [6u32, 14, 24, 32];
    let mut i = 0;
    while i < 16 {
        c[i] = (distances[i / 4], i % 4);
        i += 1;
    }
    c
};

/// The tree's surface area cost (MacDonald & Booth 1990), in node visits and triangle tests
/// per ray that crosses the root's box: every inner child's box area and every leaf's box
/// area times its triangles, over the root's area (the root's own visit, 1, left out). Only
/// the binary (`Bvh2`) and 4-wide (`Bvh4`) layouts; a tree's cost compares with trees of the
/// same layout.
pub(crate) fn sah(bvh: &Bvh) -> f64 {
    // (lower, upper, child pointer) of every child slot of every node.
    let slots: Vec<(Vec3, Vec3, i32)> = match bvh.layout {
        BvhLayout::Bvh2 => (0..bvh.nodes.len()).flat_map(|i| wide4::children(&bvh.nodes, i)).map(|c| (c.lo, c.hi, c.ptr)).collect(),
        BvhLayout::Bvh4 => bvh
            .bvh4_nodes
            .iter()
            .flat_map(|n| {
                (0..4).map(move |s| {
                    let lo = Vec3::new(n.planes[0][s], n.planes[2][s], n.planes[4][s]);
                    let hi = Vec3::new(n.planes[1][s], n.planes[3][s], n.planes[5][s]);
                    (lo, hi, n.children[s])
                })
            })
            .collect(),
        other => panic!("sah prices binary and 4-wide trees, not {other:?}"),
    };
    let per_node = if bvh.layout == BvhLayout::Bvh2 { 2 } else { 4 };
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for &(l, h, _) in slots[..per_node].iter().filter(|(l, h, _)| l.x <= h.x) {
        (lo, hi) = (lo.min(l), hi.max(h));
    }
    let root = half_area(lo, hi) as f64;
    let cost: f64 = slots
        .chunks(per_node)
        .flat_map(|node| {
            // An empty slot (bvh4) holds +inf lower and -inf upper bounds; a lone leaf is
            // every child of its root (bvh::layout): counted once.
            node.iter().enumerate().filter(|&(s, &(l, h, p))| l.x <= h.x && node[..s].iter().all(|q| q.2 != p)).map(|(_, c)| *c)
        })
        .map(|(l, h, p)| half_area(l, h) as f64 * if p >= 0 { 1.0 } else { leaf_range(p).1 as f64 })
        .sum();
    if root > 0.0 {
        cost / root
    } else {
        cost
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::BuildOptions;

    /// One triangle costs one test; two far apart, each in a leaf of its own box, cost the
    /// sum of their boxes' areas over the area of the box around both.
    #[test]
    fn leaves_cost_their_triangles_by_area() {
        let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 2.0, 0.0), Vec3::new(10.0, 0.0, 3.0)];
        let (a, b, both) = (
            half_area(Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0)),
            half_area(Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 2.0, 3.0)),
            half_area(Vec3::ZERO, Vec3::new(10.0, 2.0, 3.0)),
        );
        for layout in [BvhLayout::Bvh2, BvhLayout::Bvh4] {
            let opts = BuildOptions { layout, max_leaf_tris: 1, ..Default::default() };
            let one = Bvh::build(&positions, &[[0, 1, 2]], &opts).unwrap();
            assert!((sah(&one) - 1.0).abs() < 1e-9, "{layout:?}: {}", sah(&one));
            let two = Bvh::build(&positions, &[[0, 1, 2], [3, 4, 5]], &opts).unwrap();
            assert_eq!(two.leaves, 2, "{layout:?}");
            let want = (a as f64 + b as f64) / both as f64;
            assert!((sah(&two) - want).abs() < 1e-6 * want, "{layout:?}: {} against {want}", sah(&two));
        }
    }

    #[test]
    fn the_candidates_are_distinct_and_searched() {
        for (i, a) in CANDIDATES.iter().enumerate() {
            assert!(crate::bvh::PLOC_DISTANCES.contains(&a.0), "{a:?}: a distance obvhs offers");
            assert!(CANDIDATES[i + 1..].iter().all(|b| b != a), "{a:?} twice");
        }
    }

    /// Quality 5 keeps the cheapest of the candidate trees, and it is one of them: the same
    /// SAH as one candidate built alone, no more than any.
    #[test]
    fn quality_5_keeps_the_cheapest_candidate() {
        let (positions, triangles) = crate::bvh::test_soup(11, 3000, 40.0, (1.0, 4.0));
        for layout in [BvhLayout::Bvh2, BvhLayout::Bvh4] {
            let best =
                Bvh::build(&positions, &triangles, &BuildOptions { quality: 5, layout, max_leaf_tris: 3, ..Default::default() }).unwrap();
            let costs: Vec<f64> = CANDIDATES
                .iter()
                .map(|&c| {
                    let opts = BuildOptions { quality: 4, layout, max_leaf_tris: 3, ploc: Some(c), ..Default::default() };
                    sah(&Bvh::build(&positions, &triangles, &opts).unwrap())
                })
                .collect();
            let kept = sah(&best);
            assert!(costs.iter().all(|&c| kept <= c), "{layout:?}: kept {kept}, candidates {costs:?}");
            assert!(costs.contains(&kept), "{layout:?}: kept {kept} is no candidate's ({costs:?})");
            let spread = costs.iter().cloned().fold(0.0, f64::max) / kept;
            assert!(spread > 1.0, "{layout:?}: the candidates are different trees");
            if layout == BvhLayout::Bvh4 {
                // The kept tree gets any-hit rays' copy (built for it alone).
                assert_eq!(best.bvh4_any_nodes.len(), best.bvh4_nodes.len());
                assert_eq!(best.bvh4_nodes[0].reserved.x as usize, best.bvh4_nodes.len());
            }
        }
    }
}
