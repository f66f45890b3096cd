//! Recording GPU work: dispatches with push descriptors and automatic barriers (or, inside
//! `Recorder::concurrent`, one barrier after a group), copies, fills, image transitions and
//! timestamp queries. Submitting it is `submit.rs`'s.

use super::profile::RecordingProfile;
use super::{
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
    kernel::Kernel,
    memory::{color_range, Buffer, Image},
};
use ash::vk;
use std::sync::{atomic::Ordering, Arc};

/// A resource bound to a kernel binding index (an index from `gpu::abi`).
#[derive(Clone, Copy)]
pub struct Bind<'a> {
    pub index: u32,
    pub resource: Resource<'a>,
}

#[derive(Clone, Copy)]
pub enum Resource<'a> {
    Buffer(&'a Buffer),
    StorageImage(&'a Image),
}

impl<'a> Bind<'a> {
    pub fn buffer(index: u32, buffer: &'a Buffer) -> Self {
        Bind { index, resource: Resource::Buffer(buffer) }
    }
    pub fn image(index: u32, image: &'a Image) -> Self {
        Bind { index, resource: Resource::StorageImage(image) }
    }
}

/// Records commands into one command buffer. Every dispatch, copy and fill is followed by a
/// full compute/transfer memory barrier, so consecutive commands see each other's writes.
pub struct Recorder<'a> {
    pub(super) shared: &'a Shared,
    pub(super) cmd: vk::CommandBuffer,
    /// With profiling on: the timestamps written so far (one after each command).
    profile: Option<RecordingProfile>,
    /// Commands recorded after the profile's timestamps ran out.
    untimed: u64,
    /// Inside `concurrent`: the names of the commands recorded so far (no barriers yet).
    group: Option<Vec<String>>,
}

impl<'a> Recorder<'a> {
    /// A recorder into `cmd` (begun), profiled into `profile` where profiling is on.
    pub(super) fn new(shared: &'a Shared, cmd: vk::CommandBuffer, profile: Option<RecordingProfile>) -> Self {
        Recorder { shared, cmd, profile, untimed: 0, group: None }
    }

    /// The recording's profile and the commands recorded past its timestamps.
    pub(super) fn finish(mut self) -> (Option<RecordingProfile>, u64) {
        assert!(self.group.is_none(), "a recording ended inside Recorder::concurrent");
        (self.profile.take(), self.untimed)
    }

    /// With profiling on, writes a timestamp that closes the command `name` just recorded
    /// (after its barrier, so it brackets that command alone).
    pub(super) fn mark(&mut self, name: &str, commands: u64) {
        let Some(p) = &mut self.profile else { return };
        match p.next(name, commands) {
            // SAFETY: recording state; the profile's pool was reset at the start of this buffer.
            Some(i) => unsafe { self.shared.device.cmd_write_timestamp(self.cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, p.pool, i) },
            None => self.untimed += commands,
        }
    }

    /// After a command `name`: a barrier and its timestamp, or inside `concurrent` neither yet.
    fn end_command(&mut self, name: &str) {
        match &mut self.group {
            Some(names) => names.push(name.to_string()),
            None => {
                self.barrier();
                self.mark(name, 1);
            }
        }
    }

    /// Records `f`'s commands without barriers between them, so that the GPU may run them at
    /// once (one kernel's tail beside the next one's start), then one barrier after them all.
    /// The commands must not depend on each other: none may read or write what another one
    /// writes. Profiled as one interval, named after its commands (`a+b`, or `a` where all are
    /// `a`) and counting each. Groups do not nest.
    pub fn concurrent<T>(&mut self, f: impl FnOnce(&mut Self) -> Result<T>) -> Result<T> {
        assert!(self.group.is_none(), "Recorder::concurrent does not nest");
        self.group = Some(Vec::new());
        let out = f(self);
        let mut names = self.group.take().unwrap_or_default();
        if !names.is_empty() {
            self.barrier();
            let n = names.len() as u64;
            names.dedup();
            self.mark(&names.join("+"), n);
        }
        out
    }

    fn barrier(&mut self) {
        let src = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER;
        // Writes also reach the next indirect dispatch's read of its group counts.
        let dst = src | vk::PipelineStageFlags::DRAW_INDIRECT;
        let mb = [vk::MemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(
                vk::AccessFlags::SHADER_READ
                    | vk::AccessFlags::SHADER_WRITE
                    | vk::AccessFlags::TRANSFER_READ
                    | vk::AccessFlags::TRANSFER_WRITE
                    | vk::AccessFlags::INDIRECT_COMMAND_READ,
            )];
        // SAFETY: recording into a command buffer in the recording state.
        unsafe { self.shared.device.cmd_pipeline_barrier(self.cmd, src, dst, vk::DependencyFlags::empty(), &mb, &[], &[]) };
    }

    /// Dispatches `kernel` over `groups` workgroups with `binds` and push constants `push`.
    /// Every binding the kernel uses must be given; extra ones (optimised away) are ignored.
    /// More workgroups on an axis than the device allows (`DeviceInfo::max_workgroup_count`)
    /// is an error, not undefined behaviour.
    pub fn dispatch(&mut self, kernel: &Kernel, binds: &[Bind], push: &[u8], groups: [u32; 3]) -> Result<()> {
        let limit = self.shared.info.max_workgroup_count;
        if groups.iter().zip(limit).any(|(&g, l)| g > l) {
            return Err(VkError::Kernel {
                kernel: kernel.name().into(),
                msg: format!("{groups:?} workgroups in one dispatch, more than the device allows ({limit:?}); launch fewer or larger ones"),
            });
        }
        self.bind(kernel, binds, push)?;
        // SAFETY: recording state; `bind` bound the kernel's pipeline and descriptors.
        unsafe { self.shared.device.cmd_dispatch(self.cmd, groups[0], groups[1], groups[2]) };
        self.end_command(kernel.name());
        Ok(())
    }

    /// `dispatch` with the group counts read on the GPU from `args` at byte `offset` (three
    /// u32, written by earlier commands; a buffer made by `Context::create_indirect_buffer`).
    pub fn dispatch_indirect(&mut self, kernel: &Kernel, binds: &[Bind], push: &[u8], args: &Buffer, offset: u64) -> Result<()> {
        assert!(
            args.indirect && offset % 4 == 0 && offset + 12 <= args.size(),
            "indirect dispatch arguments at {offset} of {}",
            args.name()
        );
        self.bind(kernel, binds, push)?;
        // SAFETY: recording state; `bind` bound the kernel's pipeline and descriptors; `args`
        // has INDIRECT_BUFFER usage and holds the arguments at `offset` (checked above).
        unsafe { self.shared.device.cmd_dispatch_indirect(self.cmd, args.raw, offset) };
        self.end_command(kernel.name());
        Ok(())
    }

    /// Binds `kernel`'s pipeline, its descriptors from `binds` and its push constants.
    fn bind(&mut self, kernel: &Kernel, binds: &[Bind], push: &[u8]) -> Result<()> {
        let kerr = |msg: String| VkError::Kernel { kernel: kernel.name().into(), msg };
        if push.len() as u32 != kernel.push_size() {
            return Err(kerr(format!("push constants of {} bytes given, the kernel declares {}", push.len(), kernel.push_size())));
        }
        let mut buffer_infos = Vec::with_capacity(binds.len());
        let mut image_infos = Vec::with_capacity(binds.len());
        for b in kernel.bindings() {
            let given: Vec<&Bind> = binds.iter().filter(|x| x.index == b.binding).collect();
            let bind = match given.as_slice() {
                [one] => *one,
                [] => return Err(kerr(format!("binding {} ({:?}) was not given", b.binding, b.descriptor_type))),
                _ => return Err(kerr(format!("binding {} was given more than once", b.binding))),
            };
            match (bind.resource, b.descriptor_type) {
                (Resource::Buffer(buf), vk::DescriptorType::STORAGE_BUFFER) => {
                    buffer_infos.push((b.binding, vk::DescriptorBufferInfo { buffer: buf.raw, offset: 0, range: vk::WHOLE_SIZE }));
                }
                (Resource::StorageImage(img), vk::DescriptorType::STORAGE_IMAGE) => {
                    image_infos.push((
                        b.binding,
                        vk::DescriptorImageInfo {
                            sampler: vk::Sampler::null(),
                            image_view: img.view,
                            image_layout: vk::ImageLayout::GENERAL,
                        },
                    ));
                }
                (_, ty) => return Err(kerr(format!("binding {} expects {ty:?}, a different resource was given", b.binding))),
            }
        }
        let mut writes = Vec::with_capacity(buffer_infos.len() + image_infos.len());
        for (binding, info) in &buffer_infos {
            writes.push(
                vk::WriteDescriptorSet::default()
                    .dst_binding(*binding)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(std::slice::from_ref(info)),
            );
        }
        for (binding, info) in &image_infos {
            writes.push(
                vk::WriteDescriptorSet::default()
                    .dst_binding(*binding)
                    .descriptor_type(vk::DescriptorType::STORAGE_IMAGE)
                    .image_info(std::slice::from_ref(info)),
            );
        }
        let d = &self.shared.device;
        // SAFETY: recording state; every handle is live for the submission (the caller's
        // borrows outlive `Context::submit`, which waits for completion).
        unsafe {
            d.cmd_bind_pipeline(self.cmd, vk::PipelineBindPoint::COMPUTE, kernel.0.pipeline);
            if !writes.is_empty() {
                self.shared.push_descriptor.cmd_push_descriptor_set(
                    self.cmd,
                    vk::PipelineBindPoint::COMPUTE,
                    kernel.0.pipeline_layout,
                    0,
                    &writes,
                );
            }
            if !push.is_empty() {
                d.cmd_push_constants(self.cmd, kernel.0.pipeline_layout, vk::ShaderStageFlags::COMPUTE, 0, push);
            }
        }
        Ok(())
    }

    /// Copies `bytes` from the start of `src` to the start of `dst`.
    pub fn copy_buffer(&mut self, src: &Buffer, dst: &Buffer, bytes: u64) {
        self.copy_buffer_range(src, 0, dst, 0, bytes);
    }

    /// Copies `bytes` from byte `src_offset` of `src` to byte `dst_offset` of `dst` (the same
    /// buffer if the ranges do not overlap).
    pub fn copy_buffer_range(&mut self, src: &Buffer, src_offset: u64, dst: &Buffer, dst_offset: u64, bytes: u64) {
        let region = [vk::BufferCopy { src_offset, dst_offset, size: bytes }];
        // SAFETY: recording state, live buffers.
        unsafe { self.shared.device.cmd_copy_buffer(self.cmd, src.raw, dst.raw, &region) };
        self.end_command("copy");
    }

    /// Fills a whole buffer with a repeated u32.
    pub fn fill_buffer(&mut self, buffer: &Buffer, value: u32) {
        // SAFETY: recording state, live buffer.
        unsafe { self.shared.device.cmd_fill_buffer(self.cmd, buffer.raw, 0, vk::WHOLE_SIZE, value) };
        self.end_command("fill");
    }

    /// Fills `bytes` bytes of `buffer` from byte `offset` with a repeated u32.
    pub fn fill_buffer_range(&mut self, buffer: &Buffer, offset: u64, bytes: u64, value: u32) {
        // SAFETY: recording state, live buffer.
        unsafe { self.shared.device.cmd_fill_buffer(self.cmd, buffer.raw, offset, bytes, value) };
        self.end_command("fill");
    }

    /// Moves `image` from layout `old` to `new`, ordering all compute and transfer work
    /// before against all after.
    fn transition(&mut self, image: &Image, old: vk::ImageLayout, new: vk::ImageLayout) {
        let all =
            vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE;
        let src_access = if old == vk::ImageLayout::UNDEFINED { vk::AccessFlags::empty() } else { all };
        let b = [vk::ImageMemoryBarrier::default()
            .image(image.raw)
            .old_layout(old)
            .new_layout(new)
            .src_access_mask(src_access)
            .dst_access_mask(all)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .subresource_range(color_range())];
        let stages = vk::PipelineStageFlags::TRANSFER | vk::PipelineStageFlags::COMPUTE_SHADER;
        // SAFETY: recording state, live image currently in layout `old`.
        unsafe { self.shared.device.cmd_pipeline_barrier(self.cmd, stages, stages, vk::DependencyFlags::empty(), &[], &[], &b) };
    }

    pub(crate) fn init_image(&mut self, image: &Image) {
        self.transition(image, vk::ImageLayout::UNDEFINED, vk::ImageLayout::GENERAL);
    }

    /// Sets every texel of `image` to zero.
    pub fn clear_image(&mut self, image: &Image) {
        let zero = vk::ClearColorValue { float32: [0.0; 4] };
        // SAFETY: recording state; the image is in GENERAL layout.
        unsafe { self.shared.device.cmd_clear_color_image(self.cmd, image.raw, vk::ImageLayout::GENERAL, &zero, &[color_range()]) };
        self.barrier();
    }

    fn image_copy(image: &Image) -> [vk::BufferImageCopy; 1] {
        [vk::BufferImageCopy {
            buffer_offset: 0,
            buffer_row_length: 0,
            buffer_image_height: 0,
            image_subresource: vk::ImageSubresourceLayers {
                aspect_mask: vk::ImageAspectFlags::COLOR,
                mip_level: 0,
                base_array_layer: 0,
                layer_count: 1,
            },
            image_offset: vk::Offset3D::default(),
            image_extent: vk::Extent3D { width: image.width(), height: image.height(), depth: 1 },
        }]
    }

    /// Copies tightly packed texels from `src` into the whole image.
    pub fn copy_buffer_to_image(&mut self, src: &Buffer, image: &Image) {
        let dst_layout = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
        self.transition(image, vk::ImageLayout::GENERAL, dst_layout);
        // SAFETY: recording state; the image is in TRANSFER_DST layout and the buffer large enough.
        unsafe { self.shared.device.cmd_copy_buffer_to_image(self.cmd, src.raw, image.raw, dst_layout, &Self::image_copy(image)) };
        self.transition(image, dst_layout, vk::ImageLayout::GENERAL);
    }

    /// Copies the whole image into `dst` as tightly packed texels.
    pub fn copy_image_to_buffer(&mut self, image: &Image, dst: &Buffer) {
        let src_layout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
        self.transition(image, vk::ImageLayout::GENERAL, src_layout);
        // SAFETY: recording state; the image is in TRANSFER_SRC layout and the buffer holds it.
        unsafe { self.shared.device.cmd_copy_image_to_buffer(self.cmd, image.raw, src_layout, dst.raw, &Self::image_copy(image)) };
        self.transition(image, src_layout, vk::ImageLayout::GENERAL);
    }

    /// Writes a GPU timestamp into query `index` of `timer` once all previous commands finish.
    pub fn timestamp(&mut self, timer: &Timer, index: u32) {
        assert!(index < timer.count, "timestamp index {index} out of range (timer has {})", timer.count);
        // SAFETY: recording state; the query was reset by `reset_timer` in this buffer.
        unsafe { self.shared.device.cmd_write_timestamp(self.cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, timer.pool, index) };
    }

    /// Resets every query of `timer`; record before the timestamps.
    pub fn reset_timer(&mut self, timer: &Timer) {
        // SAFETY: recording state, live query pool.
        unsafe { self.shared.device.cmd_reset_query_pool(self.cmd, timer.pool, 0, timer.count) };
    }
}

impl Context {
    /// Creates `count` timestamp queries.
    pub fn create_timer(&self, name: &str, count: u32) -> Result<Timer> {
        let s = &self.shared;
        if s.info.timestamp_valid_bits == 0 {
            return Err(VkError::Usage { name: name.into(), msg: format!("{} has no timestamps on its compute queue", s.info.name) });
        }
        let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(count);
        // SAFETY: live device.
        let pool = unsafe { s.device.create_query_pool(&info, None) }.ctx(|| format!("query pool {name}"))?;
        s.name(pool, name);
        Ok(Timer { shared: s.clone(), pool, count, period_ns: s.info.timestamp_period_ns as f64, valid_bits: s.info.timestamp_valid_bits })
    }
}

/// Ticks from timestamp `a` to `b`, of which only `valid_bits` are written (they wrap).
pub(super) fn ticks_between(a: u64, b: u64, valid_bits: u32) -> u64 {
    let mask = if valid_bits >= 64 { u64::MAX } else { (1u64 << valid_bits) - 1 };
    (b & mask).wrapping_sub(a & mask) & mask
}

/// GPU timestamps (a query pool).
pub struct Timer {
    shared: Arc<Shared>,
    pool: vk::QueryPool,
    count: u32,
    period_ns: f64,
    valid_bits: u32,
}

impl Timer {
    /// Nanoseconds between timestamps `a` and `b` of the last completed submission. Only the
    /// queries from the lower to the higher index are read, and waited for: each of them
    /// must have been written since the timer's reset (an unwritten one would wait forever).
    pub fn elapsed_ns(&self, a: u32, b: u32) -> Result<f64> {
        let (lo, hi) = (a.min(b), a.max(b));
        if hi >= self.count {
            return Err(VkError::Usage { name: "timer".into(), msg: format!("timestamp {hi} of a timer of {}", self.count) });
        }
        let mut data = vec![0u64; (hi - lo + 1) as usize];
        // SAFETY: the submission that wrote them has completed (submit waits); the range is
        // inside the pool.
        unsafe {
            self.shared.device.get_query_pool_results(self.pool, lo, &mut data, vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT)
        }
        .ctx(|| "read timestamps".into())?;
        Ok(ticks_between(data[(a - lo) as usize], data[(b - lo) as usize], self.valid_bits) as f64 * self.period_ns)
    }
}

impl Drop for Timer {
    fn drop(&mut self) {
        if self.shared.poisoned.load(Ordering::SeqCst) {
            return;
        }
        // SAFETY: no pending submission uses it (submit waits).
        unsafe { self.shared.device.destroy_query_pool(self.pool, None) };
    }
}
