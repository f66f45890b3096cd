//! GPU time per kernel. With profiling on ([`Context::set_profiling`]) every submission writes
//! a timestamp before its first command and after each dispatch (each dispatch is followed by
//! a full barrier, so consecutive timestamps bracket exactly one dispatch), and the time is
//! added to a table by kernel name that [`Context::take_profile`] returns. Off by default:
//! renders pay nothing for it. With `BIDIR_PROFILE_LOG` set, each interval is also printed to
//! stderr as it is read back: its index in the submission, kernel, dispatches and microseconds.

use super::{
    context::{Context, Shared},
    error::{Result, VkResultExt},
};
use ash::vk;
use std::collections::BTreeMap;
use std::sync::{
    atomic::{AtomicU32, Ordering},
    Arc,
};

/// Timestamps one submission can hold; dispatches past it are not timed (counted apart).
const QUERIES: u32 = 4096;
/// Recordings whose timestamps the pool holds at once: each takes a part of it that no other
/// recording holds (from its recording until its timestamps are read, or it is dropped), so
/// that one submission may be queued behind another before the other's timestamps are read
/// (`Context::start`: BDPT's passes). A recording begun while every part is held is not timed
/// (its dispatches are counted apart, as those past QUERIES are).
const PARTS: u32 = 2;

/// GPU time of one kernel over the submissions since profiling started.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelTime {
    /// The kernel's name (its SPIR-V module, e.g. `bdpt_camera`).
    pub name: String,
    /// Nanoseconds, summed over its dispatches.
    pub ns: f64,
    pub dispatches: u64,
}

/// The query pool and the table (in `Shared`, behind a mutex).
pub(crate) struct Profiler {
    pool: vk::QueryPool,
    /// Which turning-on this is (`set_profiling`): a recording made under another may not run.
    generation: u64,
    totals: BTreeMap<String, (f64, u64)>,
    /// Dispatches a submission recorded beyond `QUERIES`.
    pub untimed: u64,
    /// The parts of the pool recordings hold, a bit each.
    held: Arc<AtomicU32>,
}

/// What a recording with profiling on writes: the pool and the name of each timestamp's dispatch.
pub(crate) struct RecordingProfile {
    pub pool: vk::QueryPool,
    /// Its part of the pool (queries `part * QUERIES..(part + 1) * QUERIES`), held until this is
    /// dropped; None where every part was held (nothing is timed).
    part: Option<u32>,
    held: Arc<AtomicU32>,
    /// Each timestamp's interval: what ran in it, and how many commands.
    pub names: Vec<(String, u64)>,
    /// The profiler's generation when recorded.
    pub generation: u64,
}

impl RecordingProfile {
    /// The next timestamp's index for `commands` dispatches of `name`, or None when the pool is
    /// full.
    pub fn next(&mut self, name: &str, commands: u64) -> Option<u32> {
        let part = self.part?;
        if self.names.len() as u32 + 1 >= QUERIES {
            return None;
        }
        self.names.push((name.to_string(), commands));
        Some(part * QUERIES + self.names.len() as u32)
    }
}

impl Drop for RecordingProfile {
    /// Gives the part back: its timestamps have been read, or its commands never ran, or ran and
    /// were waited for (a submission's wait comes before its profile is dropped).
    fn drop(&mut self) {
        if let Some(part) = self.part {
            self.held.fetch_and(!(1 << part), Ordering::AcqRel);
        }
    }
}

impl Profiler {
    /// Starts a recording: takes a free part of the pool, resets it and writes its timestamp 0.
    pub(crate) fn begin(&self, device: &ash::Device, cmd: vk::CommandBuffer) -> RecordingProfile {
        let mut held = self.held.load(Ordering::Acquire);
        let part = loop {
            let Some(free) = (0..PARTS).find(|p| held & (1 << p) == 0) else { break None };
            match self.held.compare_exchange(held, held | (1 << free), Ordering::AcqRel, Ordering::Acquire) {
                Ok(_) => break Some(free),
                Err(now) => held = now,
            }
        };
        if let Some(part) = part {
            // SAFETY: `cmd` is recording; the pool is live. No other recording holds this part:
            // the last one that did has had its timestamps read, or never ran, or ran and was
            // waited for; and only under this profiler (`is_current`).
            unsafe {
                device.cmd_reset_query_pool(cmd, self.pool, part * QUERIES, QUERIES);
                device.cmd_write_timestamp(cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, self.pool, part * QUERIES);
            }
        }
        RecordingProfile { pool: self.pool, part, held: self.held.clone(), names: Vec::new(), generation: self.generation }
    }

    /// Whether `rec` was recorded under this profiler (its pool still live).
    pub(crate) fn is_current(&self, rec: &RecordingProfile) -> bool {
        rec.generation == self.generation
    }

    /// Adds a completed submission's dispatch times to the table.
    pub(crate) fn finish(&mut self, shared: &Shared, mut rec: RecordingProfile, untimed: u64) -> Result<()> {
        self.untimed += untimed;
        let Some(part) = rec.part.filter(|_| !rec.names.is_empty()) else { return Ok(()) };
        let mut ticks = vec![0u64; rec.names.len() + 1];
        // SAFETY: the submission that wrote these queries has completed (its fence was waited on).
        unsafe {
            shared.device.get_query_pool_results(
                self.pool,
                part * QUERIES,
                &mut ticks,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
            )
        }
        .ctx(|| "read profiling timestamps".into())?;
        let (bits, period) = (shared.info.timestamp_valid_bits, shared.info.timestamp_period_ns as f64);
        let log = std::env::var_os("BIDIR_PROFILE_LOG").is_some();
        for (i, (name, commands)) in std::mem::take(&mut rec.names).into_iter().enumerate() {
            let dt = super::commands::ticks_between(ticks[i], ticks[i + 1], bits);
            if log {
                // One line per timed interval, in submission order (what a pass's launches cost one by one).
                eprintln!("profile {i} {name} x{commands} {:.1} us", dt as f64 * period / 1000.0);
            }
            let e = self.totals.entry(name).or_insert((0.0, 0));
            e.0 += dt as f64 * period;
            e.1 += commands;
        }
        Ok(())
    }

    /// Frees the pool (the device is idle or being destroyed).
    pub(crate) fn destroy(&self, device: &ash::Device) {
        // SAFETY: no submission in flight uses the pool.
        unsafe { device.destroy_query_pool(self.pool, None) };
    }
}

impl Context {
    /// Turns per-kernel GPU timing on (a fresh, empty table) or off. Needs timestamps on the
    /// compute queue (`DeviceInfo::timestamp_valid_bits` > 0).
    pub fn set_profiling(&self, on: bool) -> Result<()> {
        let s = &self.shared;
        let mut slot = s.profiler.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(old) = slot.take() {
            old.destroy(&s.device);
        }
        if !on {
            return Ok(());
        }
        if s.info.timestamp_valid_bits == 0 {
            return Err(super::VkError::Usage {
                name: "profiling".into(),
                msg: format!("{} has no timestamps on its compute queue", s.info.name),
            });
        }
        let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(PARTS * QUERIES);
        // SAFETY: live device.
        let pool = unsafe { s.device.create_query_pool(&info, None) }.ctx(|| "profiling query pool".into())?;
        s.name(pool, "bidir.profiling");
        static GENERATION: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        let generation = GENERATION.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        *slot = Some(Profiler { pool, generation, totals: BTreeMap::new(), untimed: 0, held: Default::default() });
        Ok(())
    }

    /// The table since profiling was turned on (most time first), and empties it; plus the
    /// dispatches that were not timed (more than a submission's timestamps).
    pub fn take_profile(&self) -> (Vec<KernelTime>, u64) {
        let mut slot = self.shared.profiler.lock().unwrap_or_else(|e| e.into_inner());
        let Some(p) = slot.as_mut() else { return (Vec::new(), 0) };
        let mut out: Vec<KernelTime> =
            std::mem::take(&mut p.totals).into_iter().map(|(name, (ns, dispatches))| KernelTime { name, ns, dispatches }).collect();
        out.sort_by(|a, b| b.ns.total_cmp(&a.ns));
        (out, std::mem::take(&mut p.untimed))
    }
}
