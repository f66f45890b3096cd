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

/// Timestamps one submission can hold; dispatches past it are not timed (counted apart).
const QUERIES: u32 = 4096;
/// Submissions whose timestamps the pool holds at once: recordings take its parts in turn, so
/// that one submission may be queued behind another before the other's timestamps are read
/// (`Context::start`: BDPT's passes), as long as no more than this many are in flight.
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
    /// Recordings begun under this profiler (which part of the pool the next one takes).
    recordings: std::sync::atomic::AtomicU32,
}

/// What a recording with profiling on writes: the pool and the name of each timestamp's dispatch.
pub(crate) struct RecordingProfile {
    pub pool: vk::QueryPool,
    /// Its part of the pool: queries `base..base + QUERIES`.
    base: u32,
    /// Each timestamp's interval: what ran in it, and how many commands.
    pub names: Vec<(String, u64)>,
    /// The profiler's generation when recorded.
    pub generation: u64,
}

impl RecordingProfile {
    /// The next timestamp's index for `commands` dispatches of `name`, or None when the pool is
    /// full.
    pub fn next(&mut self, name: &str, commands: u64) -> Option<u32> {
        if self.names.len() as u32 + 1 >= QUERIES {
            return None;
        }
        self.names.push((name.to_string(), commands));
        Some(self.base + self.names.len() as u32)
    }
}

impl Profiler {
    /// Starts a recording: resets its part of the pool and writes its timestamp 0.
    pub(crate) fn begin(&self, device: &ash::Device, cmd: vk::CommandBuffer) -> RecordingProfile {
        let base = self.recordings.fetch_add(1, std::sync::atomic::Ordering::Relaxed) % PARTS * QUERIES;
        // SAFETY: `cmd` is recording; the pool is live. The reset runs when `cmd` does, after
        // the submission that last used this part has completed and had its timestamps read
        // (at most PARTS submissions are in flight: each `Context::start` is waited for before
        // the one after the next is recorded), and only under this profiler (`is_current`).
        unsafe {
            device.cmd_reset_query_pool(cmd, self.pool, base, QUERIES);
            device.cmd_write_timestamp(cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, self.pool, base);
        }
        RecordingProfile { pool: self.pool, base, names: Vec::new(), generation: self.generation }
    }

    /// Whether `rec` was recorded under this profiler (its pool still live).
    pub(crate) fn is_current(&self, rec: &RecordingProfile) -> bool {
        rec.generation == self.generation
    }

    /// Adds a completed submission's dispatch times to the table.
    pub(crate) fn finish(&mut self, shared: &Shared, rec: RecordingProfile, untimed: u64) -> Result<()> {
        self.untimed += untimed;
        if rec.names.is_empty() {
            return Ok(());
        }
        let mut ticks = vec![0u64; rec.names.len() + 1];
        // SAFETY: the submission that wrote these queries has completed (its fence was waited on).
        unsafe {
            shared.device.get_query_pool_results(
                self.pool,
                rec.base,
                &mut ticks,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
            )
        }
        .ctx(|| "read profiling timestamps".into())?;
        let (bits, period) = (shared.info.timestamp_valid_bits, shared.info.timestamp_period_ns as f64);
        let log = std::env::var_os("BIDIR_PROFILE_LOG").is_some();
        for (i, (name, commands)) in rec.names.into_iter().enumerate() {
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
        *slot = Some(Profiler { pool, generation, totals: BTreeMap::new(), untimed: 0, recordings: Default::default() });
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
