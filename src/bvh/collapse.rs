//! The binary tree collapsed to 4-wide nodes at the least surface area cost, found exactly by
//! dynamic programming over the binary tree (the cost-driven collapse of Ylitie, Karras &
//! Laine 2017, "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs",
//! section 3.1, here for four children and our leaves), where `wide4` opens the largest child
//! greedily and keeps obvhs' leaves.
//!
//! The binary tree comes with one triangle per leaf, and the collapse decides both which
//! binary nodes become 4-wide nodes and which subtrees become leaves (of up to the leaf size):
//! a subtree's triangles are contiguous in the binary layout (depth-first leaf order), so a
//! leaf is a range of them and the triangles do not move.
//!
//! For a binary node n with box area A(n) (half the surface area) and T(n) triangles, and
//! F(n, j) the least cost of n's subtree as at most j slots of one 4-wide node:
//! - as a leaf: A(n) · (c_leaf + c_tri · T(n)), where T(n) <= the leaf size;
//! - as a 4-wide node: A(n) · c_node + D(n, 4);
//! - F(n, 1) = the cheaper of the two; F(n, j > 1) = min(F(n, 1), D(n, j));
//! - D(n, j) = min over 0 < k < j of F(left, k) + F(right, j - k): n's two children spread over
//!   j slots.
//!
//! c_node = 1; the root's own visit is left out (every ray pays it), as in `select::sah`.
//! c_leaf prices what a leaf costs beyond its triangles (the traversal loop's switch to its
//! leaf phase).

use super::{
    half_area,
    layout::{leaf_pointer, leaf_range},
    wide4::{self, children, Child},
    Bvh, BvhError,
};
use crate::gpu::abi;

/// Costs of the collapse's surface area model, relative to a 4-wide node's visit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SahCosts {
    /// One triangle test.
    pub tri: f32,
    /// A leaf's visit besides its triangle tests.
    pub leaf: f32,
}

/// How the 4-wide layout groups the binary tree's nodes (`BuildOptions::collapse`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Collapse {
    /// Open the largest inner child until a node holds four; obvhs' leaves (of up to the leaf
    /// size, chosen by its own cost) stay as they are.
    Greedy,
    /// Least surface area cost over all groupings and leaves (`collapse`), from a binary tree
    /// with one triangle per leaf.
    Sah(SahCosts),
}

impl Collapse {
    /// The surface area collapse at the default costs (measured on the NVIDIA H200 with
    /// Sponza: docs/traversal.md, "The 4-wide collapse of least surface area cost").
    pub const SAH: Collapse = Collapse::Sah(SahCosts { tri: 0.5, leaf: 0.5 });
}

impl std::fmt::Display for Collapse {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Collapse::Greedy => write!(f, "greedy"),
            Collapse::Sah(c) => write!(f, "sah:{},{}", c.tri, c.leaf),
        }
    }
}

impl std::str::FromStr for Collapse {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let Collapse::Sah(default) = Collapse::SAH else { unreachable!("the default collapse is sah") };
        let cost = |v: &str, what: &str, positive: bool| match v.parse::<f32>() {
            Ok(c) if c.is_finite() && (c > 0.0 || !positive && c == 0.0) => Ok(c),
            _ => Err(format!(
                "{v:?} is not {what}: expected a {} number, as in sah:0.5,0.5",
                if positive { "positive" } else { "non-negative" }
            )),
        };
        match s.split_once(':') {
            None if s == "greedy" => Ok(Collapse::Greedy),
            None if s == "sah" => Ok(Collapse::SAH),
            Some(("sah", costs)) => {
                let (tri, leaf) = costs.split_once(',').map_or((costs, None), |(t, l)| (t, Some(l)));
                let tri = cost(tri, "a triangle test's cost", true)?;
                let leaf = leaf.map_or(Ok(default.leaf), |l| cost(l, "a leaf's cost", false))?;
                Ok(Collapse::Sah(SahCosts { tri, leaf }))
            }
            _ => Err(format!("unknown collapse {s:?}: expected greedy | sah | sah:TRI_COST[,LEAF_COST]")),
        }
    }
}

/// The dynamic programme's table, per binary inner node.
struct Table {
    /// Triangle entries under the node (pre-split fragments counted each) and the first.
    tris: Vec<usize>,
    first: Vec<usize>,
    /// The node as one slot: as a leaf (infinite above the leaf size), as a 4-wide node.
    as_leaf: Vec<f32>,
    as_node: Vec<f32>,
    /// D(n, j) and its best k (slots for the left child), j = 2..=4 at index j.
    spread: Vec<[(f32, u8); 5]>,
}

impl Table {
    fn one_slot(&self, i: usize) -> f32 {
        self.as_leaf[i].min(self.as_node[i])
    }

    /// F(c, j) for a child pointer with its box.
    fn cost(&self, c: &Child, j: usize, costs: SahCosts) -> f32 {
        if c.ptr < 0 {
            return half_area(c.lo, c.hi) * (costs.leaf + costs.tri * leaf_range(c.ptr).1 as f32);
        }
        let i = c.ptr as usize;
        if j >= 2 {
            self.one_slot(i).min(self.spread[i][j].0)
        } else {
            self.one_slot(i)
        }
    }

    fn new(nodes: &[abi::BvhNode], costs: SahCosts, max_leaf: usize) -> Table {
        let n = nodes.len();
        let mut t = Table {
            tris: vec![0; n],
            first: vec![0; n],
            as_leaf: vec![0.0; n],
            as_node: vec![0.0; n],
            spread: vec![[(f32::INFINITY, 0); 5]; n],
        };
        // Depth-first order: a node's inner children follow it.
        for i in (0..n).rev() {
            let [a, b] = children(nodes, i);
            let range =
                |c: &Child, t: &Table| if c.ptr < 0 { leaf_range(c.ptr) } else { (t.first[c.ptr as usize], t.tris[c.ptr as usize]) };
            let ((first, ta), (_, tb)) = (range(&a, &t), range(&b, &t));
            debug_assert!(a.ptr == b.ptr || range(&b, &t).0 == first + ta, "a subtree's triangles are contiguous");
            // A lone leaf is both children of its root (bvh::layout).
            let tris = if a.ptr == b.ptr { ta } else { ta + tb };
            for j in 2..=4 {
                t.spread[i][j] = (1..j)
                    .map(|k| (t.cost(&a, k, costs) + t.cost(&b, j - k, costs), k as u8))
                    .min_by(|x, y| x.0.total_cmp(&y.0))
                    .expect("a split");
            }
            let area = half_area(a.lo.min(b.lo), a.hi.max(b.hi));
            t.tris[i] = tris;
            t.first[i] = first;
            t.as_leaf[i] = if tris <= max_leaf { area * (costs.leaf + costs.tri * tris as f32) } else { f32::INFINITY };
            t.as_node[i] = area + t.spread[i][4].0;
        }
        t
    }
}

/// The slots child `c` takes in its parent's 4-wide node with at most `j` of them, in the
/// binary tree's left-to-right order.
fn slots(binary: &[abi::BvhNode], t: &Table, c: Child, j: usize, out: &mut Vec<Child>) {
    if c.ptr < 0 {
        out.push(c);
        return;
    }
    let i = c.ptr as usize;
    if j >= 2 && t.spread[i][j].0 < t.one_slot(i) {
        let k = t.spread[i][j].1 as usize;
        let [a, b] = children(binary, i);
        slots(binary, t, a, k, out);
        slots(binary, t, b, j - k, out);
    } else if t.as_leaf[i] <= t.as_node[i] {
        out.push(Child { ptr: leaf_pointer(t.first[i], t.tris[i]), ..c });
    } else {
        out.push(c);
    }
}

/// Converts a binary-layout BVH (`BvhLayout::Bvh2`, best with one triangle per leaf) to the
/// 4-wide layout of least surface area cost, with leaves of up to `max_leaf` triangles.
pub(crate) fn convert(mut bvh: Bvh, costs: SahCosts, max_leaf: u32) -> Result<Bvh, BvhError> {
    let max_leaf = max_leaf.clamp(1, abi::LEAF_MAX_TRIS) as usize;
    let binary = std::mem::take(&mut bvh.nodes);
    let table = Table::new(&binary, costs, max_leaf);
    wide4::emit(bvh, &binary, &mut |i| {
        let [a, b] = children(&binary, i);
        let mut kids = Vec::with_capacity(4);
        if a.ptr == b.ptr {
            // A lone leaf is both children of its root (bvh::layout).
            kids.push(a);
        } else {
            let k = table.spread[i][4].1 as usize;
            slots(&binary, &table, a, k, &mut kids);
            slots(&binary, &table, b, 4 - k, &mut kids);
        }
        kids
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::{select, BuildOptions, BvhLayout};
    use glam::Vec3;

    /// The binary tree with one triangle per leaf that the surface area collapse starts from.
    fn binary(seed: u32, n: u32) -> Bvh {
        let (positions, triangles) = crate::bvh::test_soup(seed, n, 30.0, (0.5, 3.0));
        Bvh::build(&positions, &triangles, &BuildOptions { layout: BvhLayout::Bvh2, max_leaf_tris: 1, ..Default::default() }).unwrap()
    }

    /// The cost of a collapse chosen at random among all the dynamic programme weighs (each
    /// binary node as one slot or spread, at a random split; each subtree a leaf or a node),
    /// priced by the definition in this module's comment, independently of `Table`.
    fn random_cost(nodes: &[abi::BvhNode], c: Child, j: usize, costs: SahCosts, max_leaf: usize, rng: &mut u32) -> f32 {
        let mut next = |m: u32| {
            *rng ^= *rng << 13;
            *rng ^= *rng >> 17;
            *rng ^= *rng << 5;
            *rng % m
        };
        let area = half_area(c.lo, c.hi);
        if c.ptr < 0 {
            return area * (costs.leaf + costs.tri * leaf_range(c.ptr).1 as f32);
        }
        let [a, b] = children(nodes, c.ptr as usize);
        if j >= 2 && next(2) == 0 {
            let k = 1 + next(j as u32 - 1) as usize;
            return random_cost(nodes, a, k, costs, max_leaf, rng) + random_cost(nodes, b, j - k, costs, max_leaf, rng);
        }
        let tris = count(nodes, c.ptr);
        if tris <= max_leaf && next(2) == 0 {
            return area * (costs.leaf + costs.tri * tris as f32);
        }
        let k = 1 + next(3) as usize;
        area + random_cost(nodes, a, k, costs, max_leaf, rng) + random_cost(nodes, b, 4 - k, costs, max_leaf, rng)
    }

    /// The costs of every collapse the dynamic programme weighs, by enumeration.
    fn all_costs(nodes: &[abi::BvhNode], c: Child, j: usize, costs: SahCosts, max_leaf: usize) -> Vec<f32> {
        let area = half_area(c.lo, c.hi);
        if c.ptr < 0 {
            return vec![area * (costs.leaf + costs.tri * leaf_range(c.ptr).1 as f32)];
        }
        let [a, b] = children(nodes, c.ptr as usize);
        let spread = |j: usize| -> Vec<f32> {
            (1..j)
                .flat_map(|k| {
                    let right = all_costs(nodes, b, j - k, costs, max_leaf);
                    all_costs(nodes, a, k, costs, max_leaf).into_iter().flat_map(move |x| right.clone().into_iter().map(move |y| x + y))
                })
                .collect()
        };
        let mut v: Vec<f32> = spread(4).into_iter().map(|x| area + x).collect();
        let tris = count(nodes, c.ptr);
        if tris <= max_leaf {
            v.push(area * (costs.leaf + costs.tri * tris as f32));
        }
        if j >= 2 {
            v.extend(spread(j));
        }
        v
    }

    fn count(nodes: &[abi::BvhNode], ptr: i32) -> usize {
        if ptr < 0 {
            leaf_range(ptr).1
        } else {
            children(nodes, ptr as usize).iter().map(|c| count(nodes, c.ptr)).sum()
        }
    }

    /// The emitted tree costs what the table says it does (`select::sah`, which prices a built
    /// tree at unit costs), no more than the greedy collapse of the same binary tree, and no
    /// random collapse is cheaper.
    #[test]
    fn the_collapse_is_the_cheapest() {
        for (seed, n) in [(3, 40), (7, 700), (19, 3000)] {
            let bin = binary(seed, n);
            // select::sah's costs: a node visit and a triangle test 1, a leaf nothing more.
            let unit = SahCosts { tri: 1.0, leaf: 0.0 };
            let table = Table::new(&bin.nodes, unit, 3);
            let [a, b] = children(&bin.nodes, 0);
            let root = half_area(a.lo.min(b.lo), a.hi.max(b.hi));
            let optimum = table.spread[0][4].0 / root;
            let dp = convert(bin.clone(), unit, 3).unwrap();
            let greedy = wide4::convert(bin.clone()).unwrap();
            let (got, greedy_cost) = (select::sah(&dp), select::sah(&greedy));
            assert!((got - optimum as f64).abs() < 1e-4 * got, "{n} triangles: the tree costs {got}, the table says {optimum}");
            // At 40 triangles the greedy collapse happens to be optimal; above, it is not.
            assert!(
                got <= greedy_cost && (n < 700 || got < greedy_cost),
                "{n} triangles: {got} against the greedy collapse's {greedy_cost}"
            );
            let mut rng = seed * 7919;
            for _ in 0..200 {
                let k = 1 + (rng % 3) as usize;
                let cost = (random_cost(&bin.nodes, a, k, unit, 3, &mut rng) + random_cost(&bin.nodes, b, 4 - k, unit, 3, &mut rng)) / root;
                assert!(cost >= optimum * (1.0 - 1e-5), "{n} triangles: a random collapse costs {cost}, below the optimum {optimum}");
            }
        }
    }

    /// On small trees, the least cost of all collapses, enumerated, is the table's.
    #[test]
    fn no_collapse_is_cheaper_than_the_tables() {
        for (seed, n) in [(2, 9), (23, 12), (29, 14)] {
            for (tri, leaf, max_leaf) in [(1.0, 0.0, 3), (0.5, 0.5, 3), (0.3, 1.0, 8)] {
                let bin = binary(seed, n);
                let costs = SahCosts { tri, leaf };
                let table = Table::new(&bin.nodes, costs, max_leaf);
                let [a, b] = children(&bin.nodes, 0);
                let all: Vec<f32> = (1..4)
                    .flat_map(|k| {
                        let right = all_costs(&bin.nodes, b, 4 - k, costs, max_leaf);
                        all_costs(&bin.nodes, a, k, costs, max_leaf)
                            .into_iter()
                            .flat_map(move |x| right.clone().into_iter().map(move |y| x + y))
                    })
                    .collect();
                let least = all.iter().cloned().fold(f32::INFINITY, f32::min);
                let optimum = table.spread[0][4].0;
                assert!(
                    (least - optimum).abs() <= 1e-5 * optimum,
                    "{n} triangles, {costs:?}, leaves of {max_leaf}: {least} of {} collapses, the table {optimum}",
                    all.len()
                );
            }
        }
    }

    /// Every triangle entry sits in exactly one leaf of at most the leaf size; every node is
    /// the child of exactly one other; the triangles do not move.
    #[test]
    fn leaves_cover_every_triangle_once() {
        for max_leaf in [1, 3, 8] {
            let bin = binary(5, 1500);
            let tris = bin.tris.clone();
            let wide = convert(bin, SahCosts { tri: 0.5, leaf: 0.5 }, max_leaf).unwrap();
            assert_eq!(wide.tris, tris);
            let mut covered = vec![0u32; tris.len()];
            let mut reached = vec![0u32; wide.bvh4_nodes.len()];
            reached[0] = 1;
            let mut leaves = 0;
            for n in &wide.bvh4_nodes {
                let used: Vec<usize> = (0..4).filter(|&s| n.planes[0][s] <= n.planes[1][s]).collect();
                assert!(used.len() >= 2, "a node of {} children", used.len());
                for &s in &used {
                    let p = n.children[s];
                    if p >= 0 {
                        reached[p as usize] += 1;
                        continue;
                    }
                    let (first, count) = leaf_range(p);
                    assert!(count <= max_leaf as usize, "a leaf of {count} triangles, at most {max_leaf} asked for");
                    covered[first..first + count].iter_mut().for_each(|c| *c += 1);
                    leaves += 1;
                }
            }
            assert!(covered.iter().all(|&c| c == 1), "leaf size {max_leaf}: a triangle entry in no leaf or in two");
            assert!(reached.iter().all(|&r| r == 1), "leaf size {max_leaf}: a node reached twice or never");
            assert_eq!(wide.leaves, leaves);
        }
    }

    /// Cheap triangle tests make large leaves and few nodes, dear ones more nodes. A leaf's own
    /// cost lowers the leaves' summed area (the term it multiplies: of two optimal trees at
    /// different costs, the one at the higher cost has no more of it), here strictly.
    #[test]
    fn the_costs_trade_leaves_for_nodes() {
        let build = |tri, leaf| convert(binary(13, 2000), SahCosts { tri, leaf }, 8).unwrap();
        let (cheap, dear) = (build(0.1, 0.0).bvh4_nodes.len(), build(2.0, 0.0).bvh4_nodes.len());
        assert!(cheap < dear, "{cheap} nodes with cheap triangle tests, {dear} with dear ones");
        let leaf_area = |bvh: &Bvh| -> f64 {
            bvh.bvh4_nodes
                .iter()
                .flat_map(|n| (0..4).filter(|&s| n.children[s] < 0 && n.planes[0][s] <= n.planes[1][s]).map(move |s| (n, s)))
                .map(|(n, s)| {
                    let lo = Vec3::new(n.planes[0][s], n.planes[2][s], n.planes[4][s]);
                    let hi = Vec3::new(n.planes[1][s], n.planes[3][s], n.planes[5][s]);
                    half_area(lo, hi) as f64
                })
                .sum()
        };
        let (free, priced) = (leaf_area(&build(0.5, 0.0)), leaf_area(&build(0.5, 1.0)));
        assert!(priced < free, "the leaves' area {priced} with a leaf cost, {free} without");
    }

    #[test]
    fn collapses_parse_and_print() {
        assert_eq!("greedy".parse::<Collapse>(), Ok(Collapse::Greedy));
        assert_eq!("sah".parse::<Collapse>(), Ok(Collapse::SAH));
        assert_eq!("sah:0.25".parse::<Collapse>(), Ok(Collapse::Sah(SahCosts { tri: 0.25, leaf: 0.5 })));
        assert_eq!("sah:0.25,0".parse::<Collapse>(), Ok(Collapse::Sah(SahCosts { tri: 0.25, leaf: 0.0 })));
        assert_eq!(Collapse::Sah(SahCosts { tri: 0.25, leaf: 1.0 }).to_string(), "sah:0.25,1");
        assert_eq!(Collapse::SAH.to_string().parse::<Collapse>(), Ok(Collapse::SAH));
        for bad in ["sah:", "sah:-1", "sah:nan", "sah:0.5,", "sah:0.5,-1", "sah:0,0.5", "optimal", "greedy:1"] {
            let e = bad.parse::<Collapse>().unwrap_err();
            assert!(e.contains("expected"), "{bad}: {e}");
        }
    }
}
