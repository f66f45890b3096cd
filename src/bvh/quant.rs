//! The binary layout quantised to 32-byte nodes (`QuantNode`, half a `BvhNode`): the same
//! tree, leaves and triangle order as `layout::convert`, each node's two child boxes stored
//! in 8 bits per plane on a grid over the node's own box (origin its lower corner, a
//! power-of-two cell per axis, as the compressed wide BVH of Ylitie et al. 2017 does for eight
//! children), and one child pointer instead of two.
//!
//! Child pointers: inner nodes are in depth-first order, so an inner child 0 is the next
//! node; a node with one leaf child stores it as child 1; with two leaves, child 0's
//! triangles end where child 1's begin (leaf order), so its count alone locates it.
//!
//! Conservative rounding: the GPU decodes a plane as `origin + q * 2^(e - 127)`, where the
//! product is exact (an 8-bit integer times a power of two no smaller than the least normal
//! float) and the sum is rounded once (Vulkan rounds `+` and `*` correctly, and a fused
//! multiply-add rounds the same exact sum once too). The builder computes exactly that value
//! in f32 and moves every lower plane down and every upper plane up until the decoded box
//! encloses the child, also where a device flushes a subnormal result to zero. The decoded
//! boxes then enter the binary kernel's slab test unchanged, with its exit-distance slack,
//! so the quantised tree loses no hit the exact one finds.

use super::layout::{leaf_pointer, leaf_range};
use super::{Bvh, BvhError, BvhLayout};
use crate::gpu::abi::{self, BvhNode, QuantNode};

/// The plane `origin + q 2^(e - 127)` as the GPU computes it, and as a device that flushes
/// subnormal results to zero would.
fn decoded(origin: f32, q: u32, e: u32) -> [f32; 2] {
    let cell = f32::from_bits(e << 23);
    let v = origin + q as f32 * cell;
    [v, if v.is_subnormal() { 0.0 } else { v }]
}

/// Grid of one axis over the node's extent [lo, hi]: (origin, biased exponent of the cell).
/// The origin is `lo`, or the nearest normal-or-zero value below it (a subnormal origin could
/// be flushed upwards); the cell is the smallest power of two whose 255 steps reach `hi`.
fn grid(lo: f32, hi: f32) -> Option<(f32, u32)> {
    let origin = match lo {
        x if x.is_subnormal() && x > 0.0 => 0.0,
        x if x.is_subnormal() => -f32::MIN_POSITIVE,
        x => x,
    };
    let extent = (hi as f64 - origin as f64) / 255.0;
    // A first guess a little below the answer, then up one exponent at a time.
    let guess = if extent > 0.0 { (extent.log2().floor() as i64 + 127 - 1).clamp(1, 254) as u32 } else { 1 };
    (guess..=254).find(|&e| decoded(origin, 255, e).iter().all(|&v| v >= hi)).map(|e| (origin, e))
}

/// The tightest codes (lo, hi) of the interval [lo, hi] on grid (origin, e) that still
/// enclose it when decoded.
fn quantize(origin: f32, e: u32, lo: f32, hi: f32) -> (u32, u32) {
    let cell = f32::from_bits(e << 23) as f64;
    let mut qlo = ((lo as f64 - origin as f64) / cell).floor().clamp(0.0, 255.0) as u32;
    while qlo > 0 && decoded(origin, qlo, e).iter().any(|&v| v > lo) {
        qlo -= 1;
    }
    while qlo < 255 && decoded(origin, qlo + 1, e).iter().all(|&v| v <= lo) {
        qlo += 1;
    }
    let mut qhi = ((hi as f64 - origin as f64) / cell).ceil().clamp(0.0, 255.0) as u32;
    while qhi < 255 && decoded(origin, qhi, e).iter().any(|&v| v < hi) {
        qhi += 1;
    }
    while qhi > 0 && decoded(origin, qhi - 1, e).iter().all(|&v| v >= hi) {
        qhi -= 1;
    }
    (qlo, qhi)
}

/// A child box: (lo, hi) per axis.
type Box3 = [[f32; 2]; 3];

fn child_boxes(n: &BvhNode) -> [Box3; 2] {
    [
        [[n.c0_xy.x, n.c0_xy.y], [n.c0_xy.z, n.c0_xy.w], [n.c01_z.x, n.c01_z.y]],
        [[n.c1_xy.x, n.c1_xy.y], [n.c1_xy.z, n.c1_xy.w], [n.c01_z.z, n.c01_z.w]],
    ]
}

/// Quantises node `index`'s boxes (child 0, child 1 in the order given).
fn quant_node(index: usize, boxes: [Box3; 2], left_count: u32, child1: i32) -> Result<QuantNode, BvhError> {
    let mut origin = [0f32; 3];
    let mut exps = 0u32;
    let mut codes = [0u32; 3];
    for axis in 0..3 {
        let (lo, hi) = (boxes[0][axis][0].min(boxes[1][axis][0]), boxes[0][axis][1].max(boxes[1][axis][1]));
        let (o, e) = grid(lo, hi).ok_or(BvhError::Quantize(index))?;
        origin[axis] = o;
        exps |= e << (8 * axis);
        let (a_lo, a_hi) = quantize(o, e, boxes[0][axis][0], boxes[0][axis][1]);
        let (b_lo, b_hi) = quantize(o, e, boxes[1][axis][0], boxes[1][axis][1]);
        codes[axis] = a_lo | a_hi << 8 | b_lo << 16 | b_hi << 24;
    }
    Ok(QuantNode {
        origin: origin.into(),
        exps_left: exps | left_count << abi::QUANT_LEFT_SHIFT,
        qx: codes[0],
        qy: codes[1],
        qz: codes[2],
        child1,
    })
}

/// Converts a binary-layout BVH (`BvhLayout::Bvh2`) to the quantised one.
pub(crate) fn convert(mut bvh: Bvh) -> Result<Bvh, BvhError> {
    debug_assert_eq!(bvh.layout, BvhLayout::Bvh2);
    let mut quant = Vec::with_capacity(bvh.nodes.len());
    for (i, n) in bvh.nodes.iter().enumerate() {
        let [b0, b1] = child_boxes(n);
        let (c0, c1) = (n.children.x, n.children.y);
        let node = match (c0 < 0, c1 < 0) {
            (false, _) => {
                assert_eq!(c0 as usize, i + 1, "binary layout: an inner child 0 follows its parent");
                quant_node(i, [b0, b1], 0, c1)?
            }
            (true, false) => {
                assert_eq!(c1 as usize, i + 1, "binary layout: a lone inner child follows its parent");
                quant_node(i, [b1, b0], 0, c0)?
            }
            (true, true) if c0 == c1 => {
                // The root of a one-leaf tree (both children the same leaf): its triangles are
                // stored twice so that child 0 is a leaf ending where child 1 begins.
                let (first, count) = leaf_range(c0);
                debug_assert!(first == 0 && count == bvh.tris.len());
                bvh.tris.extend_from_within(..);
                bvh.tri_ids.extend_from_within(..);
                quant_node(i, [b0, b1], count as u32, leaf_pointer(count, count))?
            }
            (true, true) => {
                let ((f0, k0), (f1, _)) = (leaf_range(c0), leaf_range(c1));
                assert_eq!(f0 + k0, f1, "binary layout: a node's two leaves are adjacent in leaf order");
                quant_node(i, [b0, b1], k0 as u32, c1)?
            }
        };
        quant.push(node);
    }
    bvh.layout = BvhLayout::Bvh2q;
    bvh.quant_nodes = quant;
    bvh.nodes = Vec::new();
    Ok(bvh)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::BuildOptions;
    use glam::Vec3;

    /// Decodes node `n`'s child boxes as traverse_bvh2q.glsl does.
    fn decode(n: &QuantNode) -> [Box3; 2] {
        let mut b = [[[0f32; 2]; 3]; 2];
        for (axis, q) in [n.qx, n.qy, n.qz].into_iter().enumerate() {
            let e = (n.exps_left >> (8 * axis)) & 0xff;
            for (k, v) in (0..4).map(|k| (k, decoded(n.origin[axis], (q >> (8 * k)) & 0xff, e)[0])) {
                b[k / 2][axis][k % 2] = v;
            }
        }
        b
    }

    #[test]
    fn decoded_planes_enclose_awkward_intervals() {
        let cases = [
            (-1.0e-40f32, 3.0e-39f32),
            (-1.0, 1.0),
            (1.0e6, 1.0e6 + 0.0625),
            (-3.0e30, 2.0e35),
            (0.1, 0.1),
            (-7.3, -7.299999),
            (f32::MIN_POSITIVE, 1.0e-30),
        ];
        for (lo, hi) in cases {
            let (o, e) = grid(lo, hi).unwrap();
            for (a, b) in [(lo, hi), (lo, lo), (hi, hi), (lo + (hi - lo) * 0.37, lo + (hi - lo) * 0.41)] {
                let (qa, qb) = quantize(o, e, a, b);
                // Codes can cross where the grid is finer than the floats (a, b one ulp apart):
                // the planes never do.
                assert!(qa.max(qb) <= 255 && decoded(o, qa, e)[0] <= decoded(o, qb, e)[0], "[{a}, {b}] on ({o}, {e}): codes {qa} {qb}");
                assert!(decoded(o, qa, e).iter().all(|&v| v <= a), "[{a}, {b}]: lower plane {:?}", decoded(o, qa, e));
                assert!(decoded(o, qb, e).iter().all(|&v| v >= b), "[{a}, {b}]: upper plane {:?}", decoded(o, qb, e));
            }
        }
    }

    #[test]
    fn quantised_boxes_enclose_the_exact_ones() {
        let mut positions = Vec::new();
        let mut tris = Vec::new();
        let mut x = 12345u32;
        let mut next = || {
            x = x.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (x >> 8) as f32 / (1 << 24) as f32
        };
        for i in 0..2000u32 {
            let o = Vec3::new(next() * 100.0 - 50.0, next() * 3.0, next() * 1.0e4);
            positions.extend([o, o + Vec3::new(next(), next(), next()) * 0.3, o + Vec3::new(next(), 0.0, next()) * 0.2]);
            tris.push([3 * i, 3 * i + 1, 3 * i + 2]);
        }
        let exact = Bvh::build(&positions, &tris, &BuildOptions::default()).unwrap();
        let q = Bvh::build(&positions, &tris, &BuildOptions { layout: BvhLayout::Bvh2q, ..Default::default() }).unwrap();
        assert_eq!(q.quant_nodes.len(), exact.nodes.len());
        assert_eq!(q.tri_ids, exact.tri_ids);
        let mut tighter = 0.0;
        for (i, (n, e)) in q.quant_nodes.iter().zip(&exact.nodes).enumerate() {
            let got = decode(n);
            let mut want = child_boxes(e);
            if n.child1 != e.children.y {
                want.swap(0, 1);
            }
            for (g, w) in got.iter().zip(&want) {
                for axis in 0..3 {
                    assert!(g[axis][0] <= w[axis][0] && g[axis][1] >= w[axis][1], "node {i} axis {axis}: {g:?} vs {w:?}");
                    tighter += ((w[axis][1] - w[axis][0]) / (g[axis][1] - g[axis][0]).max(1e-30)) as f64;
                }
            }
        }
        // Quantisation loosens the boxes only a little (an 8-bit grid over the parent).
        let mean = tighter / (6 * q.quant_nodes.len()) as f64;
        assert!(mean > 0.8, "mean exact / quantised extent {mean}");
    }

    #[test]
    fn a_single_leaf_tree_is_stored_twice() {
        let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
        let q = Bvh::build(&positions, &[[0, 1, 2]], &BuildOptions { layout: BvhLayout::Bvh2q, ..Default::default() }).unwrap();
        assert_eq!(q.quant_nodes.len(), 1);
        assert_eq!(q.tri_ids, vec![0, 0]);
        assert_eq!(q.quant_nodes[0].exps_left >> abi::QUANT_LEFT_SHIFT, 1);
        assert_eq!(leaf_range(q.quant_nodes[0].child1), (1, 1));
    }
}
