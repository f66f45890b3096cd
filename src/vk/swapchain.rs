//! Showing images in a window: a surface on a window's native handles and a swapchain that
//! presents copies of an [`Image`].
//!
//! Presentation is a *copy*, not a render target: swapchain images are not guaranteed to
//! support storage use (most are B8G8R8A8), so kernels write an R8G8B8A8 storage image and
//! [`Swapchain::present`] copies its bytes into the acquired swapchain image. A copy never
//! converts, so the writer stores the bytes the swapchain format wants: sRGB-encoded values
//! (right for both `_UNORM` and `_SRGB` swapchains, which differ only in how *shaders* read
//! them) in B,G,R,A order when [`Swapchain::bgra`] says so.
//!
//! Each frame is synchronous, like [`Context::submit`]: acquire (semaphore), submit the
//! recorded work plus the copy (waiting on the acquire semaphore, signalling a per-image
//! semaphore, fence-waited on the host), present (waiting on that semaphore).

use super::{
    commands::Recorder,
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
    memory::{color_range, Image},
};
use ash::vk;
use raw_window_handle::{HasDisplayHandle, HasWindowHandle};
use std::{any::Any, ffi::CStr, sync::Arc};

/// The device extension a [`Swapchain`] needs; add it to `ContextOptions::device_extensions`.
pub const SWAPCHAIN_EXTENSION: &CStr = ash::khr::swapchain::NAME;

/// The instance extensions a surface on `display`'s window system needs; add them to
/// `ContextOptions::instance_extensions`.
pub fn surface_extensions(display: &impl HasDisplayHandle) -> Result<Vec<&'static CStr>> {
    let raw = display.display_handle().map_err(handle_error)?.as_raw();
    let exts = ash_window::enumerate_required_extensions(raw)
        .map_err(|result| VkError::Vk { what: format!("Vulkan surfaces on this window system ({raw:?}) are not supported"), result })?;
    // SAFETY: ash-window returns pointers to ash's static, NUL-terminated extension names.
    Ok(exts.iter().map(|&p| unsafe { CStr::from_ptr(p) }).collect())
}

fn handle_error(e: raw_window_handle::HandleError) -> VkError {
    VkError::Usage { name: "window".into(), msg: format!("no native window handle: {e}") }
}

/// Whether presentation waits for the display's vertical blank.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Vsync {
    /// FIFO: one image per refresh, never torn (always available).
    On,
    /// MAILBOX where available (newest image wins, no tearing), else IMMEDIATE, else FIFO.
    Off,
}

/// What [`Swapchain::present`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Presented {
    /// The image is on its way to the screen.
    Shown,
    /// Shown, but the swapchain no longer matches the window well: call
    /// [`Swapchain::resize`].
    Suboptimal,
    /// Nothing was shown (the window changed size or is minimised): call
    /// [`Swapchain::resize`] with the window's size and draw again.
    OutOfDate,
}

/// A window surface with its swapchain; destroys both (and the semaphores) on drop, and
/// keeps the window alive until then.
pub struct Swapchain {
    shared: Arc<Shared>,
    surface_fn: ash::khr::surface::Instance,
    swapchain_fn: ash::khr::swapchain::Device,
    surface: vk::SurfaceKHR,
    /// Null while the window has no area (minimised).
    raw: vk::SwapchainKHR,
    images: Vec<vk::Image>,
    /// Signalled by the frame's submission, waited on by its present; one per image, as an
    /// image's previous present has finished with it once that image is acquired again.
    present_done: Vec<vk::Semaphore>,
    /// Signalled by the acquire, waited on by the frame's submission (which the host waits
    /// for, so one suffices).
    acquired: vk::Semaphore,
    format: vk::SurfaceFormatKHR,
    extent: vk::Extent2D,
    mode: vk::PresentModeKHR,
    vsync: Vsync,
    generation: u32,
    /// The window whose handles the surface uses: dropped only after the surface (fields
    /// drop after `Drop::drop`), which is what makes creating the surface sound.
    _window: Arc<dyn Any + Send + Sync>,
}

impl Swapchain {
    /// Creates a surface for `window` and a swapchain of `size` (the window's inner size in
    /// pixels; the surface's own extent wins where it reports one). Fails with
    /// [`VkError::CannotPresent`] if the context's queue cannot present to the window.
    pub fn new<W>(ctx: &Context, window: Arc<W>, size: [u32; 2], vsync: Vsync) -> Result<Swapchain>
    where
        W: HasWindowHandle + HasDisplayHandle + Send + Sync + 'static,
    {
        let s = &ctx.shared;
        let display = window.display_handle().map_err(handle_error)?.as_raw();
        let handle = window.window_handle().map_err(handle_error)?.as_raw();
        // SAFETY: the handles come from a live window, which `_window` keeps alive until the
        // surface is destroyed in Drop.
        let surface = unsafe { ash_window::create_surface(&s.entry, &s.instance, display, handle, None) }
            .ctx(|| "vkCreate*SurfaceKHR for the window".into())?;
        // The surface stays unnamed: it is an instance-level object, and naming it through the
        // device crashes the Vulkan loader 1.3.239 (Debian 12) inside vkSetDebugUtilsObjectNameEXT.
        // From here on, Drop destroys whatever has been created (null handles are ignored).
        let mut sc = Swapchain {
            shared: s.clone(),
            surface_fn: ash::khr::surface::Instance::new(&s.entry, &s.instance),
            swapchain_fn: ash::khr::swapchain::Device::new(&s.instance, &s.device),
            surface,
            raw: vk::SwapchainKHR::null(),
            images: Vec::new(),
            present_done: Vec::new(),
            acquired: vk::Semaphore::null(),
            format: vk::SurfaceFormatKHR::default(),
            extent: vk::Extent2D::default(),
            mode: vk::PresentModeKHR::FIFO,
            vsync,
            generation: 0,
            _window: window,
        };
        // SAFETY: queries on live objects of this instance.
        let supported = unsafe { sc.surface_fn.get_physical_device_surface_support(s.physical, s.queue_family, surface) }
            .ctx(|| "vkGetPhysicalDeviceSurfaceSupportKHR".into())?;
        if !supported {
            return Err(VkError::CannotPresent {
                device: s.info.name.clone(),
                why: format!("its queue family {} has no present support for the window's surface", s.queue_family),
            });
        }
        sc.format = sc.choose_format()?;
        sc.acquired = sc.semaphore("viewer.acquired")?;
        sc.resize(size)?;
        Ok(sc)
    }

    /// Current size in pixels (zero while the window is minimised).
    pub fn extent(&self) -> [u32; 2] {
        [self.extent.width, self.extent.height]
    }

    /// The swapchain images' format.
    pub fn format(&self) -> vk::Format {
        self.format.format
    }

    /// Whether the swapchain stores bytes as B, G, R, A (else R, G, B, A).
    pub fn bgra(&self) -> bool {
        matches!(self.format.format, vk::Format::B8G8R8A8_UNORM | vk::Format::B8G8R8A8_SRGB)
    }

    /// The present mode in use: "fifo", "mailbox", "immediate" or "fifo-relaxed".
    pub fn present_mode(&self) -> &'static str {
        match self.mode {
            vk::PresentModeKHR::MAILBOX => "mailbox",
            vk::PresentModeKHR::IMMEDIATE => "immediate",
            vk::PresentModeKHR::FIFO_RELAXED => "fifo-relaxed",
            _ => "fifo",
        }
    }

    fn semaphore(&self, name: &str) -> Result<vk::Semaphore> {
        // SAFETY: live device; destroyed in Drop or `resize`.
        let sem = unsafe { self.shared.device.create_semaphore(&vk::SemaphoreCreateInfo::default(), None) }
            .ctx(|| format!("semaphore {name}"))?;
        self.shared.name(sem, name);
        Ok(sem)
    }

    /// An 8-bit RGBA or BGRA format in the sRGB colour space (what the copy can fill).
    fn choose_format(&self) -> Result<vk::SurfaceFormatKHR> {
        let s = &self.shared;
        // SAFETY: query on live objects.
        let formats = unsafe { self.surface_fn.get_physical_device_surface_formats(s.physical, self.surface) }
            .ctx(|| "vkGetPhysicalDeviceSurfaceFormatsKHR".into())?;
        let wanted = [vk::Format::B8G8R8A8_UNORM, vk::Format::R8G8B8A8_UNORM, vk::Format::B8G8R8A8_SRGB, vk::Format::R8G8B8A8_SRGB];
        for w in wanted {
            if let Some(f) = formats.iter().find(|f| f.format == w && f.color_space == vk::ColorSpaceKHR::SRGB_NONLINEAR) {
                return Ok(*f);
            }
        }
        Err(VkError::CannotPresent {
            device: s.info.name.clone(),
            why: format!(
                "the surface offers no 8-bit RGBA/BGRA sRGB format, only {:?}",
                formats.iter().map(|f| f.format).collect::<Vec<_>>()
            ),
        })
    }

    fn choose_mode(&self) -> Result<vk::PresentModeKHR> {
        // SAFETY: query on live objects.
        let modes = unsafe { self.surface_fn.get_physical_device_surface_present_modes(self.shared.physical, self.surface) }
            .ctx(|| "vkGetPhysicalDeviceSurfacePresentModesKHR".into())?;
        let order: &[vk::PresentModeKHR] = match self.vsync {
            Vsync::On => &[vk::PresentModeKHR::FIFO],
            Vsync::Off => &[vk::PresentModeKHR::MAILBOX, vk::PresentModeKHR::IMMEDIATE, vk::PresentModeKHR::FIFO],
        };
        Ok(order.iter().copied().find(|m| modes.contains(m)).unwrap_or(vk::PresentModeKHR::FIFO))
    }

    /// Waits until the queue is idle: a retired swapchain's images and semaphores may still be
    /// in use by the last frame otherwise.
    fn wait_idle(&self) -> Result<()> {
        let queue = self.shared.queue.lock().unwrap_or_else(|e| e.into_inner());
        // SAFETY: the queue is externally synchronised by its mutex.
        unsafe { self.shared.device.queue_wait_idle(*queue) }.ctx(|| "vkQueueWaitIdle".into())
    }

    /// Destroys the swapchain and its per-image semaphores (after the queue is idle).
    fn destroy_chain(&mut self, old: vk::SwapchainKHR, semaphores: Vec<vk::Semaphore>) {
        // SAFETY: the caller waited for the queue; null handles are ignored.
        unsafe {
            for sem in semaphores {
                self.shared.device.destroy_semaphore(sem, None);
            }
            self.swapchain_fn.destroy_swapchain(old, None);
        }
    }

    /// Recreates the swapchain for a window of `size` pixels (after a resize, or when
    /// [`Swapchain::present`] says so). A zero size (minimised) leaves no swapchain;
    /// `present` then reports [`Presented::OutOfDate`] until a resize to a real size.
    pub fn resize(&mut self, size: [u32; 2]) -> Result<()> {
        let s = self.shared.clone();
        // SAFETY: query on live objects.
        let caps = unsafe { self.surface_fn.get_physical_device_surface_capabilities(s.physical, self.surface) }
            .ctx(|| "vkGetPhysicalDeviceSurfaceCapabilitiesKHR".into())?;
        let extent = if caps.current_extent.width != u32::MAX {
            caps.current_extent
        } else {
            vk::Extent2D {
                width: size[0].clamp(caps.min_image_extent.width, caps.max_image_extent.width),
                height: size[1].clamp(caps.min_image_extent.height, caps.max_image_extent.height),
            }
        };
        let mode = self.choose_mode()?;
        self.wait_idle()?;
        let old = std::mem::replace(&mut self.raw, vk::SwapchainKHR::null());
        let old_semaphores = std::mem::take(&mut self.present_done);
        self.images.clear();
        self.extent = vk::Extent2D::default();
        if extent.width == 0 || extent.height == 0 {
            self.destroy_chain(old, old_semaphores);
            return Ok(());
        }
        if !caps.supported_usage_flags.contains(vk::ImageUsageFlags::TRANSFER_DST) {
            self.destroy_chain(old, old_semaphores);
            return Err(VkError::CannotPresent { device: s.info.name.clone(), why: "its swapchain images cannot be copied into".into() });
        }
        self.mode = mode;
        let mut count = caps.min_image_count + 1;
        if caps.max_image_count > 0 {
            count = count.min(caps.max_image_count);
        }
        let alpha = [
            vk::CompositeAlphaFlagsKHR::OPAQUE,
            vk::CompositeAlphaFlagsKHR::INHERIT,
            vk::CompositeAlphaFlagsKHR::PRE_MULTIPLIED,
            vk::CompositeAlphaFlagsKHR::POST_MULTIPLIED,
        ]
        .into_iter()
        .find(|a| caps.supported_composite_alpha.contains(*a))
        .unwrap_or(vk::CompositeAlphaFlagsKHR::OPAQUE);
        let info = vk::SwapchainCreateInfoKHR::default()
            .surface(self.surface)
            .min_image_count(count)
            .image_format(self.format.format)
            .image_color_space(self.format.color_space)
            .image_extent(extent)
            .image_array_layers(1)
            .image_usage(vk::ImageUsageFlags::TRANSFER_DST)
            .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
            .pre_transform(caps.current_transform)
            .composite_alpha(alpha)
            .present_mode(self.mode)
            .clipped(true)
            .old_swapchain(old);
        // SAFETY: live surface and device; `old` (retired by this call) is destroyed below,
        // after the queue went idle.
        let created = unsafe { self.swapchain_fn.create_swapchain(&info, None) };
        self.destroy_chain(old, old_semaphores);
        self.raw = created.ctx(|| format!("vkCreateSwapchainKHR {}x{}", extent.width, extent.height))?;
        self.generation += 1;
        let generation = self.generation;
        s.name(self.raw, &format!("viewer.swapchain#{generation}"));
        // SAFETY: live swapchain.
        self.images = unsafe { self.swapchain_fn.get_swapchain_images(self.raw) }.ctx(|| "vkGetSwapchainImagesKHR".into())?;
        for (i, &image) in self.images.iter().enumerate() {
            s.name(image, &format!("viewer.swapchain#{generation}.image[{i}]"));
        }
        for i in 0..self.images.len() {
            let sem = self.semaphore(&format!("viewer.swapchain#{generation}.present_done[{i}]"))?;
            self.present_done.push(sem);
        }
        self.extent = extent;
        Ok(())
    }

    /// One frame: acquires an image, submits what `record` records followed by a copy of
    /// `source` (an R8G8B8A8 image in bidir's `GENERAL` layout holding the bytes to show, see
    /// the module docs) into it, waits for that work, and presents. A `source` smaller than
    /// the swapchain is shown in the top-left corner on black; a larger one is cropped.
    pub fn present<F>(&mut self, ctx: &Context, source: &Image, record: F) -> Result<Presented>
    where
        F: FnOnce(&mut Recorder) -> Result<()>,
    {
        if !Arc::ptr_eq(&ctx.shared, &self.shared) {
            return Err(VkError::Usage { name: "swapchain".into(), msg: "present with a context other than the swapchain's".into() });
        }
        if self.raw == vk::SwapchainKHR::null() {
            return Ok(Presented::OutOfDate);
        }
        let s = &*self.shared;
        let timeout_ns = s.gpu_timeout.as_nanos().min(u64::MAX as u128) as u64;
        // SAFETY: live swapchain; `acquired` is unsignalled (the previous frame's submission,
        // which waited on it, has completed).
        let acquired = unsafe { self.swapchain_fn.acquire_next_image(self.raw, timeout_ns, self.acquired, vk::Fence::null()) };
        let (index, suboptimal) = match acquired {
            Ok(r) => r,
            Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => return Ok(Presented::OutOfDate),
            Err(vk::Result::TIMEOUT | vk::Result::NOT_READY) => {
                return Err(VkError::Timeout("acquire a swapchain image".into(), s.gpu_timeout))
            }
            Err(result) => return Err(VkError::Vk { what: "vkAcquireNextImageKHR".into(), result }),
        };
        let image = self.images[index as usize];
        let done = self.present_done[index as usize];
        let extent = self.extent;
        ctx.submit_synced("viewer frame", &[(self.acquired, vk::PipelineStageFlags::TRANSFER)], &[done], |rec| {
            record(rec)?;
            copy_to_swapchain(rec, source, image, extent);
            Ok(())
        })?;
        let (waits, chains, indices) = ([done], [self.raw], [index]);
        let info = vk::PresentInfoKHR::default().wait_semaphores(&waits).swapchains(&chains).image_indices(&indices);
        let queue = s.queue.lock().unwrap_or_else(|e| e.into_inner());
        // SAFETY: the queue is externally synchronised by its mutex; `index` was acquired.
        let presented = unsafe { self.swapchain_fn.queue_present(*queue, &info) };
        drop(queue);
        match presented {
            Ok(false) if !suboptimal => Ok(Presented::Shown),
            Ok(_) => Ok(Presented::Suboptimal),
            Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => Ok(Presented::OutOfDate),
            Err(result) => Err(VkError::Vk { what: "vkQueuePresentKHR".into(), result }),
        }
    }
}

/// Records: the acquired `target` to TRANSFER_DST (chained to the acquire semaphore's wait at
/// the transfer stage) and `source` to TRANSFER_SRC, black where `source` does not cover
/// `target`, the copy, then `target` to PRESENT_SRC and `source` back to GENERAL.
fn copy_to_swapchain(rec: &mut Recorder, source: &Image, target: vk::Image, extent: vk::Extent2D) {
    let d = &rec.shared.device;
    let barrier = |image, old, new, src_access, dst_access| {
        vk::ImageMemoryBarrier::default()
            .image(image)
            .old_layout(old)
            .new_layout(new)
            .src_access_mask(src_access)
            .dst_access_mask(dst_access)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .subresource_range(color_range())
    };
    let layout = |old, new, src_access, dst_access| barrier(target, old, new, src_access, dst_access);
    let transfer = vk::PipelineStageFlags::TRANSFER;
    let compute_or_transfer = vk::PipelineStageFlags::COMPUTE_SHADER | transfer;
    let dst = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
    let (general, src) = (vk::ImageLayout::GENERAL, vk::ImageLayout::TRANSFER_SRC_OPTIMAL);
    let written = vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE;
    let (w, h) = (source.width().min(extent.width), source.height().min(extent.height));
    let layers = vk::ImageSubresourceLayers { aspect_mask: vk::ImageAspectFlags::COLOR, mip_level: 0, base_array_layer: 0, layer_count: 1 };
    let region = [vk::ImageCopy {
        src_subresource: layers,
        src_offset: vk::Offset3D::default(),
        dst_subresource: layers,
        dst_offset: vk::Offset3D::default(),
        extent: vk::Extent3D { width: w, height: h, depth: 1 },
    }];
    // SAFETY: recording state; `target` was acquired for this submission, `source` is a live
    // image in GENERAL layout whose last writes are made visible by the preceding barrier.
    unsafe {
        let to_dst = [layout(vk::ImageLayout::UNDEFINED, dst, vk::AccessFlags::empty(), vk::AccessFlags::TRANSFER_WRITE)];
        d.cmd_pipeline_barrier(rec.cmd, transfer, transfer, vk::DependencyFlags::empty(), &[], &[], &to_dst);
        let to_src = [barrier(source.raw, general, src, written, vk::AccessFlags::TRANSFER_READ)];
        d.cmd_pipeline_barrier(rec.cmd, compute_or_transfer, transfer, vk::DependencyFlags::empty(), &[], &[], &to_src);
        if w < extent.width || h < extent.height {
            let black = vk::ClearColorValue { float32: [0.0, 0.0, 0.0, 1.0] };
            d.cmd_clear_color_image(rec.cmd, target, dst, &black, &[color_range()]);
            let after_clear = [layout(dst, dst, vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::TRANSFER_WRITE)];
            d.cmd_pipeline_barrier(rec.cmd, transfer, transfer, vk::DependencyFlags::empty(), &[], &[], &after_clear);
        }
        if w > 0 && h > 0 {
            d.cmd_copy_image(rec.cmd, source.raw, src, target, dst, &region);
        }
        let all =
            vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE;
        let to_general = [barrier(source.raw, src, general, vk::AccessFlags::empty(), all)];
        d.cmd_pipeline_barrier(rec.cmd, transfer, compute_or_transfer, vk::DependencyFlags::empty(), &[], &[], &to_general);
        let to_present = [layout(dst, vk::ImageLayout::PRESENT_SRC_KHR, vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::empty())];
        d.cmd_pipeline_barrier(
            rec.cmd,
            transfer,
            vk::PipelineStageFlags::BOTTOM_OF_PIPE,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &to_present,
        );
    }
}

impl Drop for Swapchain {
    fn drop(&mut self) {
        if self.shared.poisoned.load(std::sync::atomic::Ordering::SeqCst) {
            return;
        }
        let _ = self.wait_idle();
        let old = std::mem::replace(&mut self.raw, vk::SwapchainKHR::null());
        let semaphores = std::mem::take(&mut self.present_done);
        self.destroy_chain(old, semaphores);
        // SAFETY: the queue is idle; the swapchain using the surface is gone; the window
        // (`_window`) is dropped only after this.
        unsafe {
            self.shared.device.destroy_semaphore(self.acquired, None);
            self.surface_fn.destroy_surface(self.surface, None);
        }
    }
}
