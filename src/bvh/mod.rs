//! The bounding volume hierarchy: built on the CPU with obvhs (PLOC + reinsertion, optional
//! spatial pre-splits), converted to the GPU layout of Aila & Laine (2009) — each inner node
//! holds both children's boxes — with triangles stored in leaf order for the chosen
//! intersection test.
//!
//! ```
//! use bidir::bvh::{Bvh, BuildOptions};
//! use glam::Vec3;
//! let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
//! let bvh = Bvh::build(&positions, &[[0, 1, 2]], &BuildOptions::default()).unwrap();
//! assert_eq!(bvh.tri_ids, vec![0]);
//! ```

mod collapse;
mod cpu;
pub mod intersect;
mod layout;
mod occlusion;
mod quant;
mod select;
mod wide4;

pub use collapse::{Collapse, SahCosts};
pub use cpu::CpuTracer;
pub use intersect::TriTest;

use crate::gpu::abi::{self, Bvh4Node, BvhNode, CwbvhNode, GpuTri, QuantNode};

/// The node layout the GPU traverses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BvhLayout {
    /// Binary, both children's boxes in each node (Aila & Laine 2009), leaves of up to
    /// `max_leaf_tris` triangles.
    Bvh2,
    /// Compressed 8-wide (Ylitie, Karras & Laine 2017), built by obvhs from the same binary
    /// tree (with one triangle per leaf); leaves of up to min(`max_leaf_tris`, 3) triangles.
    Cwbvh,
    /// The binary layout with each node quantised to 32 bytes (`QuantNode`: child boxes in 8
    /// bits per plane relative to the node's box), same tree and leaves as `Bvh2`.
    Bvh2q,
    /// The binary tree collapsed to 4 children per node (`Bvh4Node`: full-precision boxes,
    /// 128 bytes): by default at the least surface area cost, leaves formed from a binary
    /// tree of single triangles (`Collapse::Sah`); with `Collapse::Greedy`, the same leaves and
    /// triangles as `Bvh2`.
    Bvh4,
}

impl BvhLayout {
    pub fn name(self) -> &'static str {
        match self {
            BvhLayout::Bvh2 => "bvh2",
            BvhLayout::Cwbvh => "cwbvh",
            BvhLayout::Bvh2q => "bvh2q",
            BvhLayout::Bvh4 => "bvh4",
        }
    }

    /// Bytes of one node of the layout (a binary node holds two child boxes, a wide one eight).
    pub fn node_size(self) -> usize {
        match self {
            BvhLayout::Bvh2 => std::mem::size_of::<BvhNode>(),
            BvhLayout::Cwbvh => std::mem::size_of::<CwbvhNode>(),
            BvhLayout::Bvh2q => std::mem::size_of::<QuantNode>(),
            BvhLayout::Bvh4 => std::mem::size_of::<Bvh4Node>(),
        }
    }
}

impl std::str::FromStr for BvhLayout {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "bvh2" => Ok(BvhLayout::Bvh2),
            "cwbvh" => Ok(BvhLayout::Cwbvh),
            "bvh2q" => Ok(BvhLayout::Bvh2q),
            "bvh4" => Ok(BvhLayout::Bvh4),
            _ => Err(format!("unknown BVH layout {s:?}: expected bvh2 | cwbvh | bvh2q | bvh4")),
        }
    }
}
use glam::Vec3;
use std::time::{Duration, Instant};

/// The PLOC search distances obvhs offers (`BuildOptions::ploc`).
pub const PLOC_DISTANCES: [u32; 6] = [1, 2, 6, 14, 24, 32];

/// The build quality that builds several trees and keeps the cheapest (`BuildOptions::quality`).
pub const BEST_OF_QUALITY: u32 = 5;

/// How to build.
#[derive(Clone, Copy, Debug)]
pub struct BuildOptions {
    /// Intersection test the triangles are encoded for.
    pub tri_test: TriTest,
    /// obvhs quality preset: 0 fastest .. 4 very slow; 5 builds sixteen trees at 4's
    /// settings with different PLOC searches and keeps the one of least SAH (`select`).
    pub quality: u32,
    /// Split large triangles' boxes before building (the role the thesis' SBVH spatial splits
    /// play); a triangle can then sit in several leaves.
    pub pre_split: bool,
    /// Most triangles in a leaf (1..=16; 1..=3 for the compressed wide BVH).
    pub max_leaf_tris: u32,
    pub layout: BvhLayout,
    /// PLOC's search distance (1, 2, 6, 14, 24 or 32 neighbours) and the depth below which it
    /// searches one neighbour, in place of the quality preset's (below quality 5): trees of
    /// nearly equal SAH that trace differently (docs/traversal.md, "The tree lottery").
    pub ploc: Option<(u32, usize)>,
    /// 4-wide layout only: a second copy of the nodes for any-hit (shadow) rays, each node's
    /// slots in occlusion order (`occlusion`), stored after the closest-hit nodes on the GPU.
    /// Twice the node memory; the hits are the same either way.
    pub occlusion_copy: bool,
    /// 4-wide layout only: how the binary tree's nodes are grouped into 4-wide ones and its
    /// leaves formed (`Collapse::Sah` builds the binary tree with one triangle per leaf).
    pub collapse: Collapse,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            tri_test: TriTest::Watertight,
            quality: 2,
            pre_split: true,
            max_leaf_tris: 4,
            layout: BvhLayout::Bvh2,
            ploc: None,
            occlusion_copy: true,
            collapse: Collapse::SAH,
        }
    }
}

/// Why a BVH could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BvhError {
    #[error("the scene has no triangles")]
    Empty,
    #[error("triangle {tri} indexes vertex {index}, but there are only {count} vertices")]
    BadIndex { tri: usize, index: u32, count: usize },
    #[error("the BVH is {depth} levels deep, the GPU traversal stack holds {max}: the scene is degenerate (many coincident triangles?)")]
    TooDeep { depth: usize, max: u32 },
    #[error("node {0}'s box cannot be quantised (coordinates not finite?)")]
    Quantize(usize),
    #[error("a PLOC search distance of {0} neighbours: obvhs searches 1, 2, 6, 14, 24 or 32")]
    PlocDistance(u32),
    #[error("{0} triangles exceed what the GPU layout can address (2^27)")]
    TooMany(usize),
}

/// A BVH in GPU layout.
#[derive(Clone)]
pub struct Bvh {
    pub layout: BvhLayout,
    /// Inner nodes of the binary layout; the root is node 0 (empty for `BvhLayout::Cwbvh`).
    pub nodes: Vec<BvhNode>,
    /// Nodes of the compressed wide layout; the root is node 0 (empty for other layouts).
    pub wide_nodes: Vec<CwbvhNode>,
    /// Nodes of the quantised binary layout; the root is node 0 (empty for other layouts).
    pub quant_nodes: Vec<QuantNode>,
    /// Nodes of the 4-wide layout; the root is node 0 (empty for other layouts). Node 0's
    /// `reserved.x` is where any-hit rays start: `bvh4_nodes.len()`, the root of
    /// `bvh4_any_nodes`, or 0 (this tree) without them.
    pub bvh4_nodes: Vec<Bvh4Node>,
    /// The 4-wide nodes again for any-hit rays (`BuildOptions::occlusion_copy`; else empty),
    /// indexed as the GPU stores them, after `bvh4_nodes`: node i here is node
    /// `bvh4_nodes.len() + i` there, and so are its inner children's pointers.
    pub bvh4_any_nodes: Vec<Bvh4Node>,
    /// Triangles in leaf order.
    pub tris: Vec<GpuTri>,
    /// Original triangle index of each entry of `tris`.
    pub tri_ids: Vec<u32>,
    pub tri_test: TriTest,
    /// Longest root-to-leaf path (edges).
    pub depth: usize,
    pub leaves: usize,
    pub build_time: Duration,
    /// The obvhs tree it came from (the CPU reference traverses it).
    pub(crate) source: obvhs::bvh2::Bvh2,
}

impl Bvh {
    /// Builds over indexed triangles.
    pub fn build(positions: &[Vec3], triangles: &[[u32; 3]], opts: &BuildOptions) -> Result<Bvh, BvhError> {
        if opts.quality < BEST_OF_QUALITY {
            return Self::build_one(positions, triangles, opts);
        }
        // Quality 5: the candidates at quality 4's settings, priced in the layout itself where
        // `select::sah` can (binary, 4-wide), else in the binary layout and the cheapest built
        // again in the one asked for.
        let start = Instant::now();
        let scored = match opts.layout {
            BvhLayout::Bvh2 | BvhLayout::Bvh4 => *opts,
            BvhLayout::Bvh2q => BuildOptions { layout: BvhLayout::Bvh2, ..*opts },
            BvhLayout::Cwbvh => BuildOptions { layout: BvhLayout::Bvh2, max_leaf_tris: 1, ..*opts },
        };
        // The any-hit copy (4-wide) is added to the chosen tree alone.
        let quality4 = BuildOptions { quality: 4, occlusion_copy: false, ..scored };
        let mut best: Option<(f64, (u32, usize), Bvh)> = None;
        for c in select::CANDIDATES {
            let bvh = Self::build_one(positions, triangles, &BuildOptions { ploc: Some(c), ..quality4 })?;
            let cost = select::sah(&bvh);
            if best.as_ref().is_none_or(|b| cost < b.0) {
                best = Some((cost, c, bvh));
            }
        }
        let (_, chosen, mut bvh) = best.expect("candidates");
        if scored.layout != opts.layout {
            bvh = Self::build_one(positions, triangles, &BuildOptions { quality: 4, ploc: Some(chosen), ..*opts })?;
        } else if opts.layout == BvhLayout::Bvh4 && opts.occlusion_copy {
            bvh = occlusion::add_any_hit_copy(bvh, positions, triangles);
        }
        bvh.build_time = start.elapsed();
        Ok(bvh)
    }

    /// One tree (`build` below quality 5).
    fn build_one(positions: &[Vec3], triangles: &[[u32; 3]], opts: &BuildOptions) -> Result<Bvh, BvhError> {
        if triangles.is_empty() {
            return Err(BvhError::Empty);
        }
        if triangles.len() >= 1 << crate::gpu::abi::LEAF_FIRST_BITS {
            return Err(BvhError::TooMany(triangles.len()));
        }
        for (tri, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= positions.len()) {
                return Err(BvhError::BadIndex { tri, index, count: positions.len() });
            }
        }
        let start = Instant::now();
        let obvhs_tris: Vec<obvhs::triangle::Triangle> = triangles
            .iter()
            .map(|t| obvhs::triangle::Triangle {
                v0: positions[t[0] as usize].into(),
                v1: positions[t[1] as usize].into(),
                v2: positions[t[2] as usize].into(),
            })
            .collect();
        let mut params = match opts.quality {
            0 => obvhs::BvhBuildParams::fastest_build(),
            1 => obvhs::BvhBuildParams::fast_build(),
            2 => obvhs::BvhBuildParams::medium_build(),
            3 => obvhs::BvhBuildParams::slow_build(),
            _ => obvhs::BvhBuildParams::very_slow_build(),
        };
        params.pre_split = opts.pre_split;
        if let Some((distance, depth)) = opts.ploc {
            if !PLOC_DISTANCES.contains(&distance) {
                return Err(BvhError::PlocDistance(distance));
            }
            params.ploc_search_distance = distance.into();
            params.search_depth_threshold = depth;
        }
        params.max_prims_per_leaf = match opts.layout {
            // The surface area collapse forms its own leaves from single-triangle ones.
            BvhLayout::Bvh4 if matches!(opts.collapse, Collapse::Sah(_)) => 1,
            BvhLayout::Bvh2 | BvhLayout::Bvh2q | BvhLayout::Bvh4 => opts.max_leaf_tris.clamp(1, abi::LEAF_MAX_TRIS),
            // The wide conversion chooses its own leaves (SAH) from single-triangle ones.
            BvhLayout::Cwbvh => 1,
        };
        let mut core = Duration::ZERO;
        let bvh2 = obvhs::bvh2::builder::build_bvh2_from_tris(&obvhs_tris, params, &mut core);
        let mut bvh = match opts.layout {
            BvhLayout::Bvh2 => layout::convert(bvh2, positions, triangles, opts.tri_test)?,
            BvhLayout::Cwbvh => layout::convert_wide(bvh2, positions, triangles, opts.tri_test, opts.max_leaf_tris.clamp(1, 3))?,
            BvhLayout::Bvh2q => quant::convert(layout::convert(bvh2, positions, triangles, opts.tri_test)?)?,
            BvhLayout::Bvh4 => {
                let binary = layout::convert(bvh2, positions, triangles, opts.tri_test)?;
                let bvh = match opts.collapse {
                    Collapse::Greedy => wide4::convert(binary)?,
                    Collapse::Sah(costs) => collapse::convert(binary, costs, opts.max_leaf_tris)?,
                };
                if opts.occlusion_copy {
                    occlusion::add_any_hit_copy(bvh, positions, triangles)
                } else {
                    bvh
                }
            }
        };
        bvh.build_time = start.elapsed();
        Ok(bvh)
    }

    /// The tree's surface area cost in node visits and triangle tests per ray through the
    /// root's box (what build quality 5 minimises); binary and 4-wide layouts only.
    pub fn sah_cost(&self) -> Option<f64> {
        matches!(self.layout, BvhLayout::Bvh2 | BvhLayout::Bvh4).then(|| select::sah(self))
    }

    /// Bytes the BVH takes on the GPU (nodes, triangles, index map).
    pub fn gpu_bytes(&self) -> u64 {
        (self.node_bytes() + self.tris.len() * std::mem::size_of::<GpuTri>() + self.tri_ids.len() * 4) as u64
    }

    /// Bytes of the node buffer (either layout).
    pub fn node_bytes(&self) -> usize {
        std::mem::size_of_val(self.nodes.as_slice())
            + std::mem::size_of_val(self.wide_nodes.as_slice())
            + std::mem::size_of_val(self.quant_nodes.as_slice())
            + std::mem::size_of_val(self.bvh4_nodes.as_slice())
            + std::mem::size_of_val(self.bvh4_any_nodes.as_slice())
    }

    /// The triangles as the GPU stores them, each watertight one whose original triangle
    /// `may_reject` (its material's alpha mask or opacity can turn a hit away) marked with
    /// `a.w` = 1 instead of 0: the alpha-tested kernels look up the material of marked
    /// triangles only (glsl/common/traverse.glsl, `test_leaf_triangle`). Woop's triangles
    /// use `w` and come back as they are (their kernels look up every hit's material).
    pub fn alpha_marked_tris(&self, may_reject: impl Fn(u32) -> bool) -> Vec<GpuTri> {
        let mut tris = self.tris.clone();
        if self.tri_test == TriTest::Watertight {
            for (tri, &id) in tris.iter_mut().zip(&self.tri_ids) {
                tri.a.w = if may_reject(id) { 1.0 } else { 0.0 };
            }
        }
        tris
    }

    /// Nodes of the layout built (the closest-hit tree's; `bvh4_any_nodes` not counted).
    pub fn node_count(&self) -> usize {
        self.nodes.len() + self.wide_nodes.len() + self.quant_nodes.len() + self.bvh4_nodes.len()
    }
}

/// Half the surface area of the box `lo`..`hi` (0 for an empty or inverted one): what the
/// surface area heuristic weighs a box by.
pub(crate) fn half_area(lo: Vec3, hi: Vec3) -> f32 {
    let e = (hi - lo).max(Vec3::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// A soup of `n` random triangles for the module's tests: corners within `size.0 + size.1 x
/// u` (u uniform in [0, 1), drawn per corner) of a random point in a cube of side `spread`, from
/// an xorshift generator seeded with `seed` (not 0): the same soup on every machine.
#[cfg(test)]
pub(crate) fn test_soup(seed: u32, n: u32, spread: f32, size: (f32, f32)) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let mut state = seed;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state as f32 / u32::MAX as f32
    };
    let (mut positions, mut triangles) = (Vec::new(), Vec::new());
    for i in 0..n {
        let o = Vec3::new(next(), next(), next()) * spread;
        for _ in 0..3 {
            positions.push(o + Vec3::new(next(), next(), next()) * (size.0 + size.1 * next()));
        }
        triangles.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    (positions, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// obvhs builds in parallel (rayon); the tree, and so every image, must not depend on how
    /// many threads build it (the same seed gives the same image on any machine).
    #[test]
    fn the_tree_does_not_depend_on_the_thread_count() {
        // A soup large enough for obvhs's parallel paths (reinsertion batches, radix sorts).
        let (positions, triangles) = test_soup(7, 60_000, 100.0, (1.0, 0.0));
        for (quality, layout) in [(2, BvhLayout::Bvh2), (4, BvhLayout::Bvh4), (3, BvhLayout::Cwbvh)] {
            let opts = BuildOptions { quality, layout, max_leaf_tris: 3, ..Default::default() };
            let build = |threads: usize| {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("a thread pool");
                pool.install(|| Bvh::build(&positions, &triangles, &opts).expect("the soup builds"))
            };
            let (one, four) = (build(1), build(4));
            let bytes = |b: &Bvh| {
                let mut v: Vec<u8> = bytemuck::cast_slice(&b.nodes).to_vec();
                v.extend_from_slice(bytemuck::cast_slice(&b.wide_nodes));
                v.extend_from_slice(bytemuck::cast_slice(&b.bvh4_nodes));
                v.extend_from_slice(bytemuck::cast_slice(&b.bvh4_any_nodes));
                v.extend_from_slice(bytemuck::cast_slice(&b.tri_ids));
                v
            };
            assert!(one.node_count() > 1000, "{layout:?}: a real tree");
            assert!(bytes(&one) == bytes(&four), "{layout:?} at quality {quality}: 1 and 4 threads built different trees");
        }
    }
}
