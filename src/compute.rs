//! Reusable GPU building blocks on subgroup operations: sum reduction and exclusive prefix
//! sum (stream compaction and light-path offsets build on them).

use crate::gpu::{abi, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Memory, Recorder, Result};

/// Sum and exclusive-scan kernels, built once.
pub struct Scan {
    reduce: Kernel,
    block: Kernel,
    add: Kernel,
}

impl Scan {
    pub fn new(ctx: &Context) -> Result<Self> {
        Ok(Scan {
            reduce: ctx.create_kernel(&kernels::REDUCE_SUM, &[])?,
            block: ctx.create_kernel(&kernels::SCAN_BLOCK, &[])?,
            add: ctx.create_kernel(&kernels::SCAN_ADD, &[])?,
        })
    }

    /// Sum of the first `count` u32s of `input` (wrapping modulo 2^32).
    pub fn sum(&self, ctx: &Context, input: &Buffer, count: u32) -> Result<u32> {
        let out = ctx.create_buffer("reduce.out", 4, Memory::Device)?;
        let push = abi::ScanPush { count, ..Default::default() };
        // Enough workgroups to fill a large GPU; each loops over a grid stride.
        let groups = self.reduce.groups_for(count).clamp(1, 1024);
        ctx.submit("reduce_sum", |rec| {
            rec.fill_buffer(&out, 0);
            rec.dispatch(
                &self.reduce,
                &[Bind::buffer(abi::REDUCE_BIND_INPUT, input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &out)],
                bytemuck::bytes_of(&push),
                [groups, 1, 1],
            )
        })?;
        Ok(ctx.read_buffer::<u32>(&out)?[0])
    }

    /// In-place exclusive prefix sum of the first `count` u32s of `data`.
    pub fn exclusive_scan(&self, ctx: &Context, data: &Buffer, count: u32) -> Result<()> {
        let plan = ScanPlan::new(ctx, count)?;
        ctx.submit("exclusive_scan", |rec| self.record(rec, &plan, data, count))
    }

    /// Records the in-place exclusive prefix sum of the first `count` (at most `plan.count`)
    /// u32s of `data` into `rec` (so a scan can sit between other passes of one submission).
    pub fn record(&self, rec: &mut Recorder, plan: &ScanPlan, data: &Buffer, count: u32) -> Result<()> {
        assert!(count <= plan.count, "scan of {count} elements with a plan for {}", plan.count);
        // Level sizes for this count; the plan's buffers (sized for plan.count) hold them.
        let mut levels: Vec<(u32, &Buffer)> = Vec::new();
        let mut n = count;
        for (_, sums) in &plan.levels {
            if n <= 1 {
                break;
            }
            levels.push((n, sums));
            n = n.div_ceil(abi::SCAN_WG_SIZE);
        }
        if levels.is_empty() {
            if count == 1 {
                rec.fill_buffer_range(data, 0, 4, 0);
            }
            return Ok(());
        }
        // Down: scan each level's blocks, writing block totals to the next level.
        for (i, (n, sums)) in levels.iter().enumerate() {
            let target = if i == 0 { data } else { levels[i - 1].1 };
            let push = abi::ScanPush { count: *n, ..Default::default() };
            rec.dispatch(
                &self.block,
                &[Bind::buffer(abi::SCAN_BIND_DATA, target), Bind::buffer(abi::SCAN_BIND_BLOCK_SUMS, sums)],
                bytemuck::bytes_of(&push),
                [self.block.groups_for(*n), 1, 1],
            )?;
        }
        // Up: add each level's scanned block offsets back into the level below.
        for i in (0..levels.len().saturating_sub(1)).rev() {
            let (n, sums) = levels[i];
            let target = if i == 0 { data } else { levels[i - 1].1 };
            let push = abi::ScanPush { count: n, ..Default::default() };
            rec.dispatch(
                &self.add,
                &[Bind::buffer(abi::SCAN_BIND_DATA, target), Bind::buffer(abi::SCAN_BIND_BLOCK_SUMS, sums)],
                bytemuck::bytes_of(&push),
                [self.add.groups_for(n), 1, 1],
            )?;
        }
        Ok(())
    }
}

/// The block-sum buffers a scan of `count` elements needs (count/256, count/256^2, ... down
/// to one block), allocated once so the scan can be recorded every frame.
pub struct ScanPlan {
    count: u32,
    levels: Vec<(u32, Buffer)>,
}

impl ScanPlan {
    pub fn new(ctx: &Context, count: u32) -> Result<Self> {
        let mut levels = Vec::new();
        let mut n = count;
        while n > 1 {
            let blocks = n.div_ceil(abi::SCAN_WG_SIZE);
            levels.push((n, ctx.create_buffer(&format!("scan.block_sums[{}]", levels.len()), blocks as u64 * 4, Memory::Device)?));
            if blocks == 1 {
                break;
            }
            n = blocks;
        }
        Ok(ScanPlan { count, levels })
    }

    /// Elements scanned.
    pub fn count(&self) -> u32 {
        self.count
    }
}
