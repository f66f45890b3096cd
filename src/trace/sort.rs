//! Ray reordering before tracing: a counting sort of rays by a key of direction octant (high
//! bits) and the Morton code of the origin's cell on a 16^3 grid over the scene bounds, so that
//! a subgroup traces rays that start near each other and head the same way (secondary rays
//! come out of the generator in pixel order, their directions scattered). Three passes on the
//! GPU: keys and ranks (`ray_sort_keys.comp`, atomic counts per key), the existing exclusive
//! scan over the 32,768 keys, and a scatter (`ray_sort_scatter.comp`), which also writes each
//! sorted ray's input index so hits can be mapped back.

use crate::compute::{Scan, ScanPlan};
use crate::gpu::{
    abi::{self, GpuRay, RaySortPush},
    kernels,
};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result};
use glam::Vec3;

/// Sorts up to `capacity` rays at a time.
pub struct RaySorter {
    keys_kernel: Kernel,
    scatter: Kernel,
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

impl RaySorter {
    pub fn new(ctx: &Context, capacity: u32) -> Result<RaySorter> {
        Ok(RaySorter {
            keys_kernel: ctx.create_kernel(&kernels::RAY_SORT_KEYS, &[])?,
            scatter: ctx.create_kernel(&kernels::RAY_SORT_SCATTER, &[])?,
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

    /// Sorts host rays (for tests and tools): the sorted rays and each one's input index.
    pub fn sort(&self, ctx: &Context, rays: &[GpuRay], lo: Vec3, hi: Vec3) -> Result<(Vec<GpuRay>, Vec<u32>)> {
        let count = rays.len() as u32;
        let input = ctx.upload_buffer("ray_sort.input", rays)?;
        let out = ctx.create_buffer("ray_sort.out", count.max(1) as u64 * 32, Memory::Device)?;
        let order = ctx.create_buffer("ray_sort.order", count.max(1) as u64 * 4, Memory::Device)?;
        ctx.submit("ray sort", |rec| self.record(rec, &input, &out, &order, count, lo, hi))?;
        let sorted: Vec<GpuRay> = ctx.read_buffer(&out)?;
        let order: Vec<u32> = ctx.read_buffer(&order)?;
        Ok((sorted[..rays.len()].to_vec(), order[..rays.len()].to_vec()))
    }
}
