//! Submitting recorded work: one-shot command buffers with a fence and a timeout
//! (`Context::submit`), or recorded now and run later while the GPU runs something else
//! (`Context::record`, `Context::run`), or submitted and waited for later, so that the next
//! submission can queue behind it (`Context::start`, `InFlight`). Finished submissions leave
//! their fence and command buffer for the next (`Shared::spare`).

use super::commands::Recorder;
use super::{
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
    profile::RecordingProfile,
};
use ash::vk;
use std::sync::{atomic::Ordering, Arc};

impl Context {
    /// Records commands with `record`, submits them and waits (up to the context's GPU
    /// timeout). Resources borrowed by the recording stay valid because this waits.
    pub fn submit<F>(&self, what: &str, record: F) -> Result<()>
    where
        F: FnOnce(&mut Recorder) -> Result<()>,
    {
        self.submit_synced(what, &[], &[], record)
    }

    /// [`Context::submit`] that also waits for the semaphores `wait` (each at its stage) before
    /// the recorded work and signals `signal` after it (swapchain acquire and present).
    pub(super) fn submit_synced<F>(
        &self,
        what: &str,
        wait: &[(vk::Semaphore, vk::PipelineStageFlags)],
        signal: &[vk::Semaphore],
        record: F,
    ) -> Result<()>
    where
        F: FnOnce(&mut Recorder) -> Result<()>,
    {
        let recorded = self.record_commands(what, record)?;
        self.execute(recorded, wait, signal, || ())
    }

    /// Records commands with `record` for a later [`Context::run`], which submits them: the
    /// recording of one submission may then overlap the GPU's work on another. The resources
    /// the recording borrows stay borrowed (`'a`) until the commands are dropped or have run.
    /// Commands recorded with profiling on do not run once it has been switched
    /// (`set_profiling`): `run` returns an error.
    pub fn record<'a, F>(&self, what: &str, record: F) -> Result<Recorded<'a>>
    where
        F: FnOnce(&mut Recorder) -> Result<()> + 'a,
    {
        let inner = self.record_commands(what, record)?;
        Ok(Recorded { inner: Some(inner), _borrows: std::marker::PhantomData })
    }

    /// Submits `recorded`, calls `meanwhile` while the GPU runs it (to record the next
    /// submission, say), then waits for it (up to the context's GPU timeout); returns what
    /// `meanwhile` returned.
    pub fn run<T>(&self, mut recorded: Recorded, meanwhile: impl FnOnce() -> T) -> Result<T> {
        let inner = recorded.inner.take().expect("recorded commands run once");
        let mut out = None;
        self.execute(inner, &[], &[], || out = Some(meanwhile()))?;
        Ok(out.expect("called before the wait"))
    }

    /// Submits `recorded` and returns at once: the commands run while the host goes on, and
    /// more may be submitted behind them (the queue runs them in order; each recorded command
    /// ends with a full barrier, so later submissions see all their writes). [`InFlight::wait`]
    /// waits for them; dropped unwaited, it waits too, so nothing they use is released early.
    pub fn start<'a>(&'a self, mut recorded: Recorded<'a>) -> Result<InFlight<'a>> {
        let inner = recorded.inner.take().expect("recorded commands run once");
        self.launch(inner, &[], &[])
    }

    /// Allocates a command buffer and records into it.
    fn record_commands<F>(&self, what: &str, record: F) -> Result<RecordedInner>
    where
        F: FnOnce(&mut Recorder) -> Result<()>,
    {
        let s = &*self.shared;
        let pool = s.command_pool.lock().unwrap_or_else(|e| e.into_inner());
        let spare = s.spare.lock().unwrap_or_else(|e| e.into_inner()).commands.pop();
        let cmd = match spare {
            // Reset when begun (the pool has RESET_COMMAND_BUFFER); its submission has finished.
            Some(cmd) => cmd,
            None => {
                let alloc = vk::CommandBufferAllocateInfo::default()
                    .command_pool(*pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(1);
                // SAFETY: the pool is externally synchronised by its mutex, held through recording.
                unsafe { s.device.allocate_command_buffers(&alloc) }.ctx(|| format!("allocate command buffer for {what}"))?[0]
            }
        };
        s.name(cmd, what);
        // SAFETY: the pool mutex is held; the buffer is not pending (never submitted, or a
        // spare whose submission finished).
        let free = |cmd| unsafe { s.device.free_command_buffers(*pool, &[cmd]) };
        // SAFETY: fresh command buffer.
        if let Err(result) = unsafe {
            s.device.begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT))
        } {
            free(cmd);
            return Err(VkError::Vk { what: format!("begin {what}"), result });
        }
        let profile = s.profiler.lock().unwrap_or_else(|e| e.into_inner()).as_ref().map(|p| p.begin(&s.device, cmd));
        let mut rec = Recorder::new(s, cmd, profile);
        let recorded = record(&mut rec);
        let (profile, untimed) = rec.finish();
        // SAFETY: recording state.
        let ended = unsafe { s.device.end_command_buffer(cmd) };
        if let Err(e) = recorded {
            free(cmd);
            return Err(e);
        }
        if let Err(result) = ended {
            free(cmd);
            return Err(VkError::Vk { what: format!("end {what}"), result });
        }
        Ok(RecordedInner { shared: self.shared.clone(), cmd, what: what.into(), profile, untimed })
    }

    /// Submits recorded commands, calls `meanwhile`, waits for them, frees them and reads
    /// their profile.
    fn execute(
        &self,
        r: RecordedInner,
        wait: &[(vk::Semaphore, vk::PipelineStageFlags)],
        signal: &[vk::Semaphore],
        meanwhile: impl FnOnce(),
    ) -> Result<()> {
        let flight = self.launch(r, wait, signal)?;
        meanwhile();
        flight.wait()
    }

    /// Submits recorded commands: the GPU's until the returned `InFlight` has waited for them.
    fn launch<'a>(
        &'a self,
        mut r: RecordedInner,
        wait: &[(vk::Semaphore, vk::PipelineStageFlags)],
        signal: &[vk::Semaphore],
    ) -> Result<InFlight<'a>> {
        let s = &*self.shared;
        let what = r.what.clone();
        if let Some(rp) = &r.profile {
            // Its timestamps go to the pool of the profiler it was recorded under.
            let current = s.profiler.lock().unwrap_or_else(|e| e.into_inner()).as_ref().is_some_and(|p| p.is_current(rp));
            if !current {
                return Err(VkError::Usage {
                    name: what,
                    msg: "profiling was switched between recording these commands and running them: record them again".into(),
                });
            }
        }
        let fence = s.take_fence().ctx(|| format!("fence for {what}"))?;
        let cmds = [r.cmd];
        let wait_semaphores: Vec<vk::Semaphore> = wait.iter().map(|w| w.0).collect();
        let wait_stages: Vec<vk::PipelineStageFlags> = wait.iter().map(|w| w.1).collect();
        let submit = [vk::SubmitInfo::default()
            .command_buffers(&cmds)
            .wait_semaphores(&wait_semaphores)
            .wait_dst_stage_mask(&wait_stages)
            .signal_semaphores(signal)];
        let queue = s.queue.lock().unwrap_or_else(|e| e.into_inner());
        // SAFETY: the queue is externally synchronised by its mutex.
        let submitted = unsafe { s.device.queue_submit(*queue, &submit, fence) };
        drop(queue);
        if let Err(result) = submitted {
            // The fence is not in use: the submission failed.
            s.return_fence(fence);
            return Err(VkError::Vk { what: format!("submit {what}"), result });
        }
        s.submissions.fetch_add(1, Ordering::Relaxed);
        // From here the commands are the GPU's until the fence signals: not freed on drop.
        let cmd = std::mem::replace(&mut r.cmd, vk::CommandBuffer::null());
        // The wait must happen whatever the caller does next (it may unwind).
        let waiter = WaitOnDrop { shared: s, fence, cmd };
        Ok(InFlight { waiter: Some(waiter), profile: r.profile.take(), untimed: r.untimed, what, _borrows: std::marker::PhantomData })
    }
}

/// Commands submitted by [`Context::start`] that may still run on the GPU, with the resources
/// their recording borrowed (`'a`).
pub struct InFlight<'a> {
    // (Fields drop in order: an unwaited submission is waited for before its profile gives its
    // part of the timestamp pool back.)
    waiter: Option<WaitOnDrop<'a>>,
    profile: Option<RecordingProfile>,
    untimed: u64,
    what: String,
    _borrows: std::marker::PhantomData<&'a ()>,
}

impl InFlight<'_> {
    /// Waits for the commands (up to the context's GPU timeout), frees them and reads their
    /// profile.
    pub fn wait(mut self) -> Result<()> {
        let waiter = self.waiter.take().expect("waited once");
        let s = waiter.shared;
        let timeout_ns = s.gpu_timeout.as_nanos().min(u64::MAX as u128) as u64;
        let what = std::mem::take(&mut self.what);
        match waiter.wait(timeout_ns) {
            Ok(()) => match (self.profile.take(), s.profiler.lock().unwrap_or_else(|e| e.into_inner()).as_mut()) {
                (Some(rp), Some(p)) => p.finish(s, rp, self.untimed),
                _ => Ok(()),
            },
            Err(vk::Result::TIMEOUT) => Err(VkError::Timeout(what, s.gpu_timeout)),
            Err(result) => Err(VkError::Vk { what: format!("wait for {what}"), result }),
        }
    }
}

/// Commands recorded by [`Context::record`], not yet run; they keep the resources they use
/// borrowed (`'a`). Dropped unrun, they are freed.
pub struct Recorded<'a> {
    inner: Option<RecordedInner>,
    _borrows: std::marker::PhantomData<&'a ()>,
}

/// A recorded command buffer (null once submitted) with its profile.
struct RecordedInner {
    shared: Arc<Shared>,
    cmd: vk::CommandBuffer,
    what: String,
    profile: Option<RecordingProfile>,
    untimed: u64,
}

impl Drop for RecordedInner {
    fn drop(&mut self) {
        if self.cmd != vk::CommandBuffer::null() {
            let pool = self.shared.command_pool.lock().unwrap_or_else(|e| e.into_inner());
            // SAFETY: never submitted (a submitted buffer's handle is taken out); pool locked.
            unsafe { self.shared.device.free_command_buffers(*pool, &[self.cmd]) };
        }
    }
}

/// A submitted command buffer and its fence: `wait` (or a drop, as when unwinding) waits for
/// the fence before freeing both, so that nothing the GPU still uses is released. On a timeout
/// or a lost device it leaks them and marks the context poisoned.
struct WaitOnDrop<'s> {
    shared: &'s Shared,
    fence: vk::Fence,
    cmd: vk::CommandBuffer,
}

impl WaitOnDrop<'_> {
    fn wait(self, timeout_ns: u64) -> std::result::Result<(), vk::Result> {
        let s = self.shared;
        // SAFETY: waiting on a fence of this device.
        let r = unsafe { s.device.wait_for_fences(&[self.fence], true, timeout_ns) };
        match r {
            Ok(()) => self.release(),
            // The GPU may still run this work: leak rather than destroy in-flight objects.
            Err(_) => s.poisoned.store(true, Ordering::SeqCst),
        }
        std::mem::forget(self);
        r
    }

    /// The fence signalled: the fence and the command buffer are kept for later submissions
    /// (`Shared::spare`), or freed.
    fn release(&self) {
        let s = self.shared;
        s.return_fence(self.fence);
        let mut spare = s.spare.lock().unwrap_or_else(|e| e.into_inner());
        if spare.commands.len() < super::context::SPARE_SUBMISSIONS {
            spare.commands.push(self.cmd);
        } else {
            drop(spare);
            let pool = s.command_pool.lock().unwrap_or_else(|e| e.into_inner());
            // SAFETY: the submission finished; the pool is externally synchronised by its mutex.
            unsafe { s.device.free_command_buffers(*pool, &[self.cmd]) };
        }
    }
}

impl Drop for WaitOnDrop<'_> {
    fn drop(&mut self) {
        let s = self.shared;
        let timeout_ns = s.gpu_timeout.as_nanos().min(u64::MAX as u128) as u64;
        // SAFETY: waiting on a fence of this device.
        match unsafe { s.device.wait_for_fences(&[self.fence], true, timeout_ns) } {
            Ok(()) => self.release(),
            Err(_) => s.poisoned.store(true, Ordering::SeqCst),
        }
    }
}
