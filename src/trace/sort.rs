//! Ray reordering before tracing: a counting sort of rays by a key of direction octant (high
//! bits) and the Morton code of the origin's cell on a 16^3 grid over the scene bounds, so that
//! a subgroup traces rays that start near each other and head the same way (secondary rays
//! come out of the generator in pixel order, their directions scattered). Three passes on the
//! GPU: keys and ranks (`ray_sort_keys.comp`, atomic counts per key), the existing exclusive
//! scan over the 32,768 keys, and a scatter (`ray_sort_scatter.comp`), which also writes each
//! sorted ray's input index so hits can be mapped back.
//!
//! The local sort (`RaySorter::record_local`, `ray_sort_local.comp`) keeps the rays' order
//! between blocks of consecutive rays and sorts each block by the ray direction's cell on an
//! octahedral grid: one pass, a workgroup per block, no global atomics. Secondary rays come
//! in 8x8-tile pixel order, so a block's origins lie close together and its subgroups then
//! trace rays that also head the same way.

use crate::compute::{Scan, ScanPlan};
use crate::gpu::{
    abi::{self, GpuRay, RaySortLocalPush, RaySortPush},
    kernels,
};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result};
use glam::Vec3;

/// Sorts up to `capacity` rays at a time.
pub struct RaySorter {
    keys_kernel: Kernel,
    scatter: Kernel,
    local: Kernel,
    scan: Scan,
    plan: ScanPlan,
    keys: Buffer,
    bins: Buffer,
    capacity: u32,
}

/// The sort key of a ray with origin `o` and direction `d` on the grid of `push`, as
/// `ray_sort_keys.comp` computes it (same f32 operations).
pub fn sort_key(push: &RaySortPush, o: Vec3, d: Vec3) -> u32 {
    let cells = 1u32 << abi::RAY_SORT_CELL_BITS;
    let c = ((o - push.bounds_lo) * push.cells_per_unit).clamp(Vec3::ZERO, Vec3::splat((cells - 1) as f32));
    let cell = c.to_array().map(|x| (x as u32).min(cells - 1));
    let spread = |v: u32| (0..abi::RAY_SORT_CELL_BITS).fold(0, |r, b| r | ((v >> b) & 1) << (3 * b));
    let octant = (d.x < 0.0) as u32 | ((d.y < 0.0) as u32) << 1 | ((d.z < 0.0) as u32) << 2;
    octant << (3 * abi::RAY_SORT_CELL_BITS) | spread(cell[0]) | spread(cell[1]) << 1 | spread(cell[2]) << 2
}

/// The sort's grid over the bounds [lo, hi] for `count` rays.
pub fn sort_push(lo: Vec3, hi: Vec3, count: u32) -> RaySortPush {
    let cells = (1u32 << abi::RAY_SORT_CELL_BITS) as f32;
    RaySortPush { bounds_lo: lo, count, cells_per_unit: Vec3::splat(cells) / (hi - lo).max(Vec3::splat(1e-30)), pad0: 0 }
}

/// How rays are reordered before tracing (`bench traversal --sort`, `--sort-local`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SortKind {
    /// The global counting sort by direction octant and origin cell.
    Cells,
    /// Blocks of `block` consecutive rays, each sorted by direction cell on a `grid` x `grid`
    /// octahedral grid.
    Local { grid: u32, block: u32 },
}

impl SortKind {
    /// Checks a local sort's parameters against the kernel's shared arrays.
    pub fn local(grid: u32, block: u32) -> std::result::Result<SortKind, String> {
        if !(1..=abi::RAY_SORT_LOCAL_MAX_GRID).contains(&grid) || !(1..=abi::RAY_SORT_LOCAL_MAX_BLOCK).contains(&block) {
            return Err(format!(
                "local ray sort over a {grid} x {grid} grid in blocks of {block}: the grid takes 1 to {} cells a side, a block 1 to {} rays",
                abi::RAY_SORT_LOCAL_MAX_GRID,
                abi::RAY_SORT_LOCAL_MAX_BLOCK
            ));
        }
        Ok(SortKind::Local { grid, block })
    }

    /// The kind as reports name it: `cells`, or `local GRIDxGRID/BLOCK`.
    pub fn name(&self) -> String {
        match self {
            SortKind::Cells => "cells".to_string(),
            SortKind::Local { grid, block } => format!("local {grid}x{grid}/{block}"),
        }
    }

    /// A short description for reports.
    pub fn describe(&self) -> String {
        match self {
            SortKind::Cells => "sorted (octant, origin cell)".to_string(),
            SortKind::Local { grid, block } => format!("sorted by direction ({grid}x{grid} octahedral cells) within blocks of {block}"),
        }
    }
}

/// The cell of direction `d` on a `grid` x `grid` grid over the octahedral map of the sphere,
/// as `ray_sort_local.comp` computes it (same f32 operations; its division may round
/// differently by an ulp, so a direction on a cell's border may land in the next).
pub fn direction_cell(grid: u32, d: Vec3) -> u32 {
    let s = d.x.abs() + d.y.abs() + d.z.abs();
    let mut p = glam::Vec2::new(d.x / s, d.y / s);
    if d.z < 0.0 {
        let folded = glam::Vec2::ONE - glam::Vec2::new(p.y.abs(), p.x.abs());
        p = glam::Vec2::new(if p.x >= 0.0 { folded.x } else { -folded.x }, if p.y >= 0.0 { folded.y } else { -folded.y });
    }
    let u = (p + glam::Vec2::ONE) * (0.5 * grid as f32);
    let c = |x: f32| (x.max(0.0) as u32).min(grid - 1);
    c(u.y) * grid + c(u.x)
}

impl RaySorter {
    pub fn new(ctx: &Context, capacity: u32) -> Result<RaySorter> {
        Ok(RaySorter {
            keys_kernel: ctx.create_kernel(&kernels::RAY_SORT_KEYS, &[])?,
            scatter: ctx.create_kernel(&kernels::RAY_SORT_SCATTER, &[])?,
            local: ctx.create_kernel(&kernels::RAY_SORT_LOCAL, &[])?,
            scan: Scan::new(ctx)?,
            plan: ScanPlan::new(ctx, abi::RAY_SORT_KEYS)?,
            keys: ctx.create_buffer("ray_sort.keys", capacity.max(1) as u64 * 8, Memory::Device)?,
            bins: ctx.create_buffer("ray_sort.bins", abi::RAY_SORT_KEYS as u64 * 4, Memory::Device)?,
            capacity,
        })
    }

    /// Records the sort of the first `count` rays of `rays` into `out`, and each sorted ray's
    /// input index into `order` (`count` u32s), on the grid over the bounds [lo, hi].
    #[allow(clippy::too_many_arguments)]
    pub fn record(&self, rec: &mut Recorder, rays: &Buffer, out: &Buffer, order: &Buffer, count: u32, lo: Vec3, hi: Vec3) -> Result<()> {
        assert!(count <= self.capacity, "sorting {count} rays with room for {}", self.capacity);
        let push = sort_push(lo, hi, count);
        let groups = [self.keys_kernel.groups_for(count), 1, 1];
        rec.fill_buffer(&self.bins, 0);
        rec.dispatch(
            &self.keys_kernel,
            &[
                Bind::buffer(abi::RAY_SORT_BIND_RAYS, rays),
                Bind::buffer(abi::RAY_SORT_BIND_KEYS, &self.keys),
                Bind::buffer(abi::RAY_SORT_BIND_BINS, &self.bins),
            ],
            bytemuck::bytes_of(&push),
            groups,
        )?;
        self.scan.record(rec, &self.plan, &self.bins, abi::RAY_SORT_KEYS)?;
        rec.dispatch(
            &self.scatter,
            &[
                Bind::buffer(abi::RAY_SORT_BIND_RAYS, rays),
                Bind::buffer(abi::RAY_SORT_BIND_KEYS, &self.keys),
                Bind::buffer(abi::RAY_SORT_BIND_BINS, &self.bins),
                Bind::buffer(abi::RAY_SORT_BIND_OUT, out),
                Bind::buffer(abi::RAY_SORT_BIND_ORDER, order),
            ],
            bytemuck::bytes_of(&push),
            groups,
        )
    }

    /// Records the local sort of the first `count` rays of `rays` into `out` (blocks of
    /// `block` consecutive rays, each in the order of its rays' direction cells on a `grid` x
    /// `grid` octahedral grid), each sorted ray's input index into `order`; the cells go to
    /// the sorter's key buffer.
    #[allow(clippy::too_many_arguments)]
    pub fn record_local(
        &self,
        rec: &mut Recorder,
        rays: &Buffer,
        out: &Buffer,
        order: &Buffer,
        count: u32,
        grid: u32,
        block: u32,
    ) -> Result<()> {
        assert!(count <= self.capacity, "sorting {count} rays with room for {}", self.capacity);
        assert!(SortKind::local(grid, block).is_ok(), "local sort: grid {grid}, block {block}");
        let push = RaySortLocalPush { count, block, grid, pad0: 0 };
        rec.dispatch(
            &self.local,
            &[
                Bind::buffer(abi::RAY_SORT_BIND_RAYS, rays),
                Bind::buffer(abi::RAY_SORT_BIND_KEYS, &self.keys),
                Bind::buffer(abi::RAY_SORT_BIND_OUT, out),
                Bind::buffer(abi::RAY_SORT_BIND_ORDER, order),
            ],
            bytemuck::bytes_of(&push),
            [count.div_ceil(block).max(1), 1, 1],
        )
    }

    /// Records the sort `kind` (see `record` and `record_local`; `lo`, `hi` are the bounds of
    /// the global sort's grid).
    #[allow(clippy::too_many_arguments)]
    pub fn record_kind(
        &self,
        rec: &mut Recorder,
        kind: SortKind,
        rays: &Buffer,
        out: &Buffer,
        order: &Buffer,
        count: u32,
        lo: Vec3,
        hi: Vec3,
    ) -> Result<()> {
        match kind {
            SortKind::Cells => self.record(rec, rays, out, order, count, lo, hi),
            SortKind::Local { grid, block } => self.record_local(rec, rays, out, order, count, grid, block),
        }
    }

    /// Sorts host rays locally (for tests and tools): the sorted rays, each one's input index
    /// and its direction cell.
    pub fn sort_local(&self, ctx: &Context, rays: &[GpuRay], grid: u32, block: u32) -> Result<(Vec<GpuRay>, Vec<u32>, Vec<u32>)> {
        let (sorted, order) =
            self.sort_on_host(ctx, rays, |rec, input, out, order, count| self.record_local(rec, input, out, order, count, grid, block))?;
        let cells: Vec<u32> = ctx.read_buffer(&self.keys)?;
        Ok((sorted, order, cells[..rays.len()].to_vec()))
    }

    /// Sorts host rays (for tests and tools): the sorted rays and each one's input index.
    pub fn sort(&self, ctx: &Context, rays: &[GpuRay], lo: Vec3, hi: Vec3) -> Result<(Vec<GpuRay>, Vec<u32>)> {
        self.sort_on_host(ctx, rays, |rec, input, out, order, count| self.record(rec, input, out, order, count, lo, hi))
    }

    /// Uploads `rays`, runs `record` (input, output, order, count) on them, reads back the
    /// sorted rays and their input indices.
    fn sort_on_host(
        &self,
        ctx: &Context,
        rays: &[GpuRay],
        record: impl FnOnce(&mut Recorder, &Buffer, &Buffer, &Buffer, u32) -> Result<()>,
    ) -> Result<(Vec<GpuRay>, Vec<u32>)> {
        let count = rays.len() as u32;
        let input = ctx.upload_buffer("ray_sort.input", rays)?;
        let out = ctx.create_buffer("ray_sort.out", count.max(1) as u64 * 32, Memory::Device)?;
        let order = ctx.create_buffer("ray_sort.order", count.max(1) as u64 * 4, Memory::Device)?;
        ctx.submit("ray sort", |rec| record(rec, &input, &out, &order, count))?;
        let sorted: Vec<GpuRay> = ctx.read_buffer(&out)?;
        let order: Vec<u32> = ctx.read_buffer(&order)?;
        Ok((sorted[..rays.len()].to_vec(), order[..rays.len()].to_vec()))
    }
}
