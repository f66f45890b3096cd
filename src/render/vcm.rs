//! Vertex connection and merging (`--integrator vcm`; Georgiev, Křivánek, Davidovič and
//! Slusallek 2012): BDPT with the light vertex cache plus vertex merging, both weighted
//! together by the recursive dVCM/dVC/dVM quantities of Georgiev's technical report. The
//! kernels are BDPT's, specialised (`SPEC_VCM`); this module holds the options and the merge
//! grid, a hash grid over the cached light vertices rebuilt on the GPU every iteration.

use crate::gpu::{abi, abi::BdptPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result, Spec};

/// Which VCM strategies run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VcmMode {
    /// Vertex merging (density estimation at camera vertices).
    pub merge: bool,
    /// Vertex connection: BDPT's strategies (light sampling, connections, light tracing).
    pub connect: bool,
    /// Merging at every continuous camera vertex (Georgiev et al. 2012) rather than at the
    /// first one only, after delta scatterings (`vcm:merge-all`; glsl/common/vcm.glsl).
    /// Only meaningful with both strategies: photon mapping merges at the first vertex anyway.
    pub merge_all: bool,
}

impl VcmMode {
    /// `vcm`: both strategies, merging at the first continuous camera vertex.
    pub const FULL: VcmMode = VcmMode { merge: true, connect: true, merge_all: false };
    /// `vcm:merge-all`: both strategies, merging at every continuous camera vertex.
    pub const MERGE_ALL: VcmMode = VcmMode { merge: true, connect: true, merge_all: true };
    /// `vcm:no-merge`: the connections alone (BDPT's image).
    pub const NO_MERGE: VcmMode = VcmMode { merge: false, connect: true, merge_all: false };
    /// `vcm:no-connect`: progressive photon mapping.
    pub const NO_CONNECT: VcmMode = VcmMode { merge: true, connect: false, merge_all: false };

    /// The same mode with `merge_all` cleared where it changes nothing (one name, one
    /// specialisation per distinct estimator).
    pub fn normalized(self) -> VcmMode {
        VcmMode { merge_all: self.merge_all && self.merge && self.connect, ..self }
    }

    /// Whether merging runs in its own pass after the camera pass (vcm_merge.comp): full VCM
    /// merging at the first continuous camera vertex in a scene where no material mixes a
    /// continuous lobe with a delta one (`mixed_lobes`, `SceneFeatures::mixed_lobes`), so that
    /// a camera sample merges at most once.
    pub fn merges_apart(self, mixed_lobes: bool) -> bool {
        let m = self.normalized();
        m.merge && m.connect && !m.merge_all && !mixed_lobes
    }

    /// The value of `SPEC_VCM` in a scene with or without `mixed_lobes`.
    pub fn spec_value(self, mixed_lobes: bool) -> u32 {
        let m = self.normalized();
        (if m.merge { abi::VCM_MERGE } else { 0 })
            | (if m.connect { abi::VCM_CONNECT } else { 0 })
            | (if m.merge_all { abi::VCM_MERGE_ALL } else { 0 })
            | (if self.merges_apart(mixed_lobes) { abi::VCM_MERGE_APART } else { 0 })
    }
}

/// The first iteration's merge radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VcmRadius {
    /// A fraction of the scene's bounding-box diagonal (`--vcm-radius 0.001`).
    Relative(f32),
    /// In scene units (`--vcm-radius 0.02u`).
    Absolute(f32),
}

impl Default for VcmRadius {
    fn default() -> Self {
        VcmRadius::Relative(0.001)
    }
}

impl VcmRadius {
    /// The radius in scene units for a scene whose bounding box has diagonal `diagonal`.
    pub fn resolve(self, diagonal: f32) -> f32 {
        match self {
            VcmRadius::Relative(f) => f * diagonal,
            VcmRadius::Absolute(r) => r,
        }
    }
}

impl std::str::FromStr for VcmRadius {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let (num, absolute) = match s.strip_suffix('u') {
            Some(n) => (n, true),
            None => (s, false),
        };
        match num.parse::<f32>() {
            Ok(v) if v > 0.0 && v.is_finite() => Ok(if absolute { VcmRadius::Absolute(v) } else { VcmRadius::Relative(v) }),
            _ => Err(format!(
                "bad merge radius '{s}': a positive fraction of the scene's diagonal (0.001) or a length in scene units with the suffix u (0.02u)"
            )),
        }
    }
}

/// Checks the radius-reduction exponent (0 < alpha <= 1; 1 keeps the radius fixed).
pub fn check_alpha(alpha: f32) -> std::result::Result<f32, String> {
    if alpha > 0.0 && alpha <= 1.0 {
        Ok(alpha)
    } else {
        Err(format!("--vcm-alpha must lie in (0, 1], not {alpha}"))
    }
}

/// The specialisation constants of the BDPT kernels for VCM (`radius`: r_1 in scene units).
pub fn specs(mode: VcmMode, mixed_lobes: bool, radius: f32, alpha: f32, grid_bits: u32) -> [Spec; 4] {
    [
        Spec { id: abi::SPEC_VCM, value: mode.spec_value(mixed_lobes) },
        Spec { id: abi::SPEC_VCM_RADIUS, value: radius.to_bits() },
        Spec { id: abi::SPEC_VCM_ALPHA, value: alpha.to_bits() },
        Spec { id: abi::SPEC_MERGE_GRID_BITS, value: grid_bits },
    ]
}

/// log2 of the hash table's size for `capacity` light vertices: at least as many cells as
/// vertices (few collisions), between 2^10 and 2^24.
pub fn grid_bits(capacity: u32) -> u32 {
    capacity.max(1).next_power_of_two().trailing_zeros().clamp(10, 24)
}

/// The merge grid: per hash cell its entries' end (`cells`), the light vertices' positions and
/// slots sorted by cell (`items`, `abi::MergeItem`), and the kernels that build them from the
/// light vertex cache; where merging runs apart ([`VcmMode::merges_apart`]), the camera
/// vertices the camera pass leaves for it and the kernel that merges them.
pub struct MergeGrid {
    count: Kernel,
    scatter: Kernel,
    scan: crate::compute::Scan,
    plan: crate::compute::ScanPlan,
    cells: Buffer,
    items: Buffer,
    capacity: u32,
    apart: Option<MergeApart>,
    /// GPU bytes of the grid (cells, items, scan sums, queries).
    pub bytes: u64,
}

/// Merging in its own pass: one `abi::MergeQuery` per camera sample of an iteration.
struct MergeApart {
    merge: Kernel,
    queries: Buffer,
}

impl MergeGrid {
    /// A grid for up to `capacity` cached light vertices (`specs`: the BDPT kernels' constants);
    /// with `queries` > 0 also the merge pass over that many camera samples per iteration.
    pub fn new(ctx: &Context, specs: &[Spec], capacity: u32, grid_bits: u32, queries: u32) -> Result<MergeGrid> {
        let cells_n = 1u32 << grid_bits;
        let cells = ctx.create_buffer("vcm.merge_cells", cells_n as u64 * 4, Memory::Device)?;
        let item_bytes = std::mem::size_of::<abi::MergeItem>() as u64;
        let items = ctx.create_buffer("vcm.merge_items", capacity.max(1) as u64 * item_bytes, Memory::Device)?;
        let plan = crate::compute::ScanPlan::new(ctx, cells_n)?;
        let scan_sums = (cells_n as u64).div_ceil(abi::SCAN_WG_SIZE as u64) * 4;
        let apart = match queries {
            0 => None,
            n => Some(MergeApart {
                merge: ctx.create_kernel(&kernels::VCM_MERGE, specs)?,
                queries: ctx.create_buffer(
                    "vcm.merge_queries",
                    n as u64 * std::mem::size_of::<abi::MergeQuery>() as u64,
                    Memory::Device,
                )?,
            }),
        };
        Ok(MergeGrid {
            count: ctx.create_kernel(&kernels::MERGE_GRID_COUNT, specs)?,
            scatter: ctx.create_kernel(&kernels::MERGE_GRID_SCATTER, specs)?,
            scan: crate::compute::Scan::new(ctx)?,
            plan,
            bytes: cells.size() + items.size() + scan_sums + apart.as_ref().map_or(0, |a| a.queries.size()),
            apart,
            cells,
            items,
            capacity,
        })
    }

    /// The grid's kernels (for their compile statistics and timings).
    pub fn kernels(&self) -> Vec<&Kernel> {
        let mut k = vec![&self.count, &self.scatter];
        k.extend(self.apart.as_ref().map(|a| &a.merge));
        k
    }

    /// The grid's buffers for the camera kernel (the queries: the cells where merging does
    /// not run apart; the camera kernel then never touches them).
    pub fn binds(&self) -> [Bind<'_>; 3] {
        let queries = self.apart.as_ref().map_or(&self.cells, |a| &a.queries);
        [
            Bind::buffer(abi::BIND_MERGE_CELLS, &self.cells),
            Bind::buffer(abi::BIND_MERGE_ITEMS, &self.items),
            Bind::buffer(abi::BIND_MERGE_QUERIES, queries),
        ]
    }

    /// Records the merge pass over the `samples` camera samples the camera pass just ran (a
    /// no-op unless merging runs apart).
    pub fn record_merge(&self, rec: &mut Recorder, binds: &[Bind], push: &BdptPush, samples: u32) -> Result<()> {
        match &self.apart {
            Some(a) => rec.dispatch(&a.merge, binds, bytemuck::bytes_of(push), [a.merge.groups_for(samples), 1, 1]),
            None => Ok(()),
        }
    }

    /// Records the grid's build over the listed light vertex cache (`binds` hold the light
    /// vertices, the cache and [`MergeGrid::binds`]): clear, count per cell, exclusive scan,
    /// scatter.
    pub fn record(&self, rec: &mut Recorder, binds: &[Bind], push: &BdptPush) -> Result<()> {
        rec.fill_buffer(&self.cells, 0);
        rec.dispatch(&self.count, binds, bytemuck::bytes_of(push), [self.count.groups_for(self.capacity), 1, 1])?;
        self.scan.record(rec, &self.plan, &self.cells, self.plan.count())?;
        rec.dispatch(&self.scatter, binds, bytemuck::bytes_of(push), [self.scatter.groups_for(self.capacity), 1, 1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn radius_parses() {
        assert_eq!("0.005".parse::<VcmRadius>().unwrap(), VcmRadius::Relative(0.005));
        assert_eq!("0.02u".parse::<VcmRadius>().unwrap(), VcmRadius::Absolute(0.02));
        for bad in ["", "u", "0", "-1", "x", "nanu", "inf"] {
            assert!(bad.parse::<VcmRadius>().is_err(), "{bad}");
        }
        assert_eq!(VcmRadius::Relative(0.5).resolve(4.0), 2.0);
        assert!(check_alpha(0.0).is_err() && check_alpha(1.5).is_err() && check_alpha(0.75).is_ok());
        assert_eq!(grid_bits(1), 10);
        assert_eq!(grid_bits(5000), 13);
    }

    #[test]
    fn merging_runs_apart_only_where_a_sample_merges_once() {
        assert!(VcmMode::FULL.merges_apart(false));
        assert!(!VcmMode::FULL.merges_apart(true), "mixed materials: a path may merge at several vertices");
        for m in [VcmMode::MERGE_ALL, VcmMode::NO_CONNECT, VcmMode::NO_MERGE] {
            assert!(!m.merges_apart(false), "{m:?}");
        }
        assert_eq!(VcmMode::FULL.spec_value(false), abi::VCM_MERGE | abi::VCM_CONNECT | abi::VCM_MERGE_APART);
        assert_eq!(VcmMode::FULL.spec_value(true), abi::VCM_MERGE | abi::VCM_CONNECT);
        assert_eq!(VcmMode::MERGE_ALL.spec_value(false), abi::VCM_MERGE | abi::VCM_CONNECT | abi::VCM_MERGE_ALL);
        // merge_all means nothing without both strategies: one specialisation, one name.
        let ppm_all = VcmMode { merge_all: true, ..VcmMode::NO_CONNECT };
        assert_eq!(ppm_all.spec_value(false), VcmMode::NO_CONNECT.spec_value(false));
        assert_eq!(super::super::Integrator::Vcm(ppm_all).name(), "vcm:no-connect");
        assert_eq!(super::super::Integrator::Vcm(VcmMode::MERGE_ALL).name(), "vcm:merge-all");
        assert_eq!("vcm:merge-all".parse::<super::super::Integrator>().unwrap(), super::super::Integrator::Vcm(VcmMode::MERGE_ALL));
    }
}
