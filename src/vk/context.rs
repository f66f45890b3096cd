//! The logical device and everything that lives as long as it: queue, command pool,
//! allocator. `Context` is the safe handle the rest of bidir holds.

use super::{
    error::{Result, VkError, VkResultExt},
    instance::{self, DeviceInfo, ValidationLog},
};
use ash::vk;
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};
use std::{
    ffi::{CStr, CString},
    mem::ManuallyDrop,
    sync::{
        atomic::{AtomicBool, AtomicU64, Ordering},
        Arc, Mutex,
    },
    time::Duration,
};

/// How to create a [`Context`].
#[derive(Clone, Debug)]
pub struct ContextOptions {
    /// Enable VK_LAYER_KHRONOS_validation (with synchronisation validation) and collect its
    /// messages; an error if the layer is not installed.
    pub validation: bool,
    /// `--device`: an index from `bidir info` or a name substring.
    pub device: Option<String>,
    /// How long one submission may run before it is reported as a hung GPU.
    pub gpu_timeout: Duration,
    /// Extra instance extensions (surface extensions for the viewer).
    pub instance_extensions: Vec<&'static CStr>,
    /// Extra device extensions (the swapchain for the viewer).
    pub device_extensions: Vec<&'static CStr>,
    /// Ask the driver to keep each kernel's compile statistics (registers, spills, ...:
    /// `Kernel::statistics`), where it offers VK_KHR_pipeline_executable_properties.
    pub kernel_statistics: bool,
    /// Enable the driver's ray-tracing pipeline (acceleration structures, buffer device
    /// addresses): `bench traversal --driver-rt`. An error naming the extension where the
    /// device has none (`DeviceInfo::ray_tracing_pipeline`).
    pub ray_tracing: bool,
    /// Environment variables [`ContextOptions::from_env`] could not use, for the caller to
    /// print.
    pub env_warnings: Vec<String>,
}

impl Default for ContextOptions {
    fn default() -> Self {
        ContextOptions {
            validation: false,
            device: None,
            gpu_timeout: Duration::from_secs(60),
            instance_extensions: vec![],
            device_extensions: vec![],
            kernel_statistics: false,
            ray_tracing: false,
            env_warnings: vec![],
        }
    }
}

impl ContextOptions {
    /// Defaults, with `BIDIR_VALIDATION=1` turning validation on, `BIDIR_DEVICE` choosing the
    /// device and `BIDIR_GPU_TIMEOUT_S` the submission timeout.
    pub fn from_env() -> Self {
        let mut o = ContextOptions {
            validation: std::env::var("BIDIR_VALIDATION").is_ok_and(|v| v == "1" || v.eq_ignore_ascii_case("true")),
            device: std::env::var("BIDIR_DEVICE").ok().filter(|s| !s.is_empty()),
            ..ContextOptions::default()
        };
        if let Ok(v) = std::env::var("BIDIR_GPU_TIMEOUT_S") {
            match v.trim().parse::<f64>() {
                Ok(s) if s > 0.0 && s <= 1e6 => o.gpu_timeout = Duration::from_secs_f64(s.max(0.001)),
                _ => o.env_warnings.push(format!(
                    "BIDIR_GPU_TIMEOUT_S={} is not a number of seconds in (0, 1000000]; using {} s",
                    crate::text::quote(&v),
                    o.gpu_timeout.as_secs_f64()
                )),
            }
        }
        o
    }
}

/// Whether kernels are created without the driver's bounds checks on storage and uniform
/// buffers (VK_EXT_pipeline_robustness, `DISABLED`): wherever the device allows it, unless
/// BIDIR_BUFFER_CHECKS=1 asks for the checks (a debugging aid: the driver's default handling
/// of out-of-bounds accesses instead of undefined behaviour). NVIDIA's driver otherwise
/// compares every storage-buffer access's offset with the buffer's size: two instructions per
/// load, 4-7 % of the trace kernels' time on the H200 (docs/traversal.md, session 12).
/// Every kernel must index its buffers within bounds: out of bounds is undefined without the
/// checks (lavapipe under Mesa 22 lacks the extension, so CI runs with them).
pub(crate) fn unchecked_buffers(info: &DeviceInfo) -> bool {
    info.pipeline_robustness && !std::env::var("BIDIR_BUFFER_CHECKS").is_ok_and(|v| v == "1")
}

/// The device-wide state shared (through `Arc`) by every GPU object, so that each object
/// can free itself on drop and the device is destroyed only after the last of them.
pub(crate) struct Shared {
    /// The loader (keeps its library loaded while the instance lives; surfaces need it).
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    /// The chosen physical device and the queue family of `queue` (graphics + compute when
    /// the device has one): what a surface's present support is checked against.
    pub physical: vk::PhysicalDevice,
    pub queue_family: u32,
    debug_utils: Option<ash::ext::debug_utils::Instance>,
    messenger: vk::DebugUtilsMessengerEXT,
    pub device: ash::Device,
    debug_device: Option<ash::ext::debug_utils::Device>,
    pub push_descriptor: ash::khr::push_descriptor::Device,
    /// Present when kernels are created with their statistics captured.
    pub pipeline_executables: Option<ash::khr::pipeline_executable_properties::Device>,
    /// Present when the context was created with `ContextOptions::ray_tracing`.
    pub ray_tracing: Option<super::rt::RtDevice>,
    pub allocator: ManuallyDrop<Mutex<Allocator>>,
    pub queue: Mutex<vk::Queue>,
    pub command_pool: Mutex<vk::CommandPool>,
    /// Command buffers and fences of finished submissions, kept for the next ones: creating
    /// and destroying a fence and freeing a command buffer cost the NVIDIA driver about 0.7
    /// ms a submission, with the GPU idle (docs/results.md, "Launches of three dispatches").
    /// The command buffers are `command_pool`'s (reset when begun again); at most
    /// `SPARE_SUBMISSIONS` of each are kept.
    pub spare: Mutex<Spare>,
    pub info: DeviceInfo,
    pub gpu_timeout: Duration,
    /// Set when a submission timed out: the device may still be executing, so nothing is
    /// destroyed (destroying in-flight objects is undefined behaviour).
    pub poisoned: AtomicBool,
    /// Submissions made so far (`Context::submissions`).
    pub submissions: AtomicU64,
    /// Per-kernel GPU timing, when on (`Context::set_profiling`).
    pub profiler: Mutex<Option<super::profile::Profiler>>,
    _log: Arc<ValidationLog>,
}

/// Reusable submission objects (`Shared::spare`).
#[derive(Default)]
pub struct Spare {
    pub commands: Vec<vk::CommandBuffer>,
    pub fences: Vec<vk::Fence>,
}

/// The most command buffers and fences `Shared::spare` keeps (submissions in flight at once are
/// fewer: one runs while the next is recorded).
pub const SPARE_SUBMISSIONS: usize = 8;

impl Shared {
    /// An unsignalled fence: a spare one, or a new one.
    pub fn take_fence(&self) -> std::result::Result<vk::Fence, vk::Result> {
        if let Some(f) = self.spare.lock().unwrap_or_else(|e| e.into_inner()).fences.pop() {
            return Ok(f);
        }
        // SAFETY: live device.
        let fence = unsafe { self.device.create_fence(&vk::FenceCreateInfo::default(), None) }?;
        self.name(fence, "bidir.submission_fence");
        Ok(fence)
    }

    /// Takes back `fence` of a finished submission (signalled, no longer waited on): reset and
    /// kept, or destroyed.
    pub fn return_fence(&self, fence: vk::Fence) {
        let mut spare = self.spare.lock().unwrap_or_else(|e| e.into_inner());
        // SAFETY: the fence signalled and nothing waits on it.
        if spare.fences.len() < SPARE_SUBMISSIONS && unsafe { self.device.reset_fences(&[fence]) }.is_ok() {
            spare.fences.push(fence);
        } else {
            // SAFETY: as above.
            unsafe { self.device.destroy_fence(fence, None) };
        }
    }

    /// Gives a Vulkan object a debug name (shown by validation messages and GPU debuggers).
    pub fn name<H: vk::Handle>(&self, handle: H, name: &str) {
        if let Some(du) = &self.debug_device {
            let cname = CString::new(name.replace('\0', " ")).unwrap_or_default();
            let info = vk::DebugUtilsObjectNameInfoEXT::default().object_handle(handle).object_name(&cname);
            // SAFETY: `handle` is a live object of this device; naming is advisory.
            let _ = unsafe { du.set_debug_utils_object_name(&info) };
        }
    }
}

impl Drop for Shared {
    fn drop(&mut self) {
        if self.poisoned.load(Ordering::SeqCst) {
            return; // see `poisoned`
        }
        // SAFETY: this is the last reference; every child object has been dropped (each holds
        // an Arc<Shared>), so destroying in reverse creation order is sound.
        unsafe {
            let _ = self.device.device_wait_idle();
            if let Some(p) = self.profiler.get_mut().unwrap_or_else(|e| e.into_inner()).take() {
                p.destroy(&self.device);
            }
            ManuallyDrop::drop(&mut self.allocator);
            // (The spare command buffers go with their pool.)
            for f in self.spare.get_mut().unwrap_or_else(|e| e.into_inner()).fences.drain(..) {
                self.device.destroy_fence(f, None);
            }
            self.device.destroy_command_pool(*self.command_pool.get_mut().unwrap_or_else(|e| e.into_inner()), None);
            self.device.destroy_device(None);
            if let Some(du) = &self.debug_utils {
                if self.messenger != vk::DebugUtilsMessengerEXT::null() {
                    du.destroy_debug_utils_messenger(self.messenger, None);
                }
            }
            self.instance.destroy_instance(None);
        }
    }
}

/// A Vulkan device ready for compute work. Cheap to clone (an `Arc`).
#[derive(Clone)]
pub struct Context {
    pub(crate) shared: Arc<Shared>,
    log: Arc<ValidationLog>,
    devices: Arc<Vec<DeviceInfo>>,
    /// Every kernel built on this device, by source and specialisation (`create_kernel`).
    pub(crate) kernels: Arc<std::sync::Mutex<std::collections::HashMap<super::kernel::KernelKey, super::kernel::Kernel>>>,
}

impl Context {
    /// Creates an instance and a device as `opts` says.
    pub fn new(opts: &ContextOptions) -> Result<Context> {
        let log = Arc::new(ValidationLog::default());
        let parts = instance::create_instance(opts.validation, &opts.instance_extensions, &log)?;
        let destroy_instance = |parts: &instance::InstanceParts| unsafe {
            // SAFETY: only called on early-error paths, before any device exists.
            if let Some(du) = &parts.debug_utils {
                if parts.messenger != vk::DebugUtilsMessengerEXT::null() {
                    du.destroy_debug_utils_messenger(parts.messenger, None);
                }
            }
            parts.instance.destroy_instance(None);
        };
        let described = match instance::describe_devices(&parts.instance) {
            Ok(d) => d,
            Err(e) => {
                destroy_instance(&parts);
                return Err(e);
            }
        };
        let infos: Vec<DeviceInfo> = described.iter().map(|(_, d)| d.clone()).collect();
        let chosen = match instance::choose_device(&infos, opts.device.as_deref()) {
            Ok(c) => c,
            Err(e) => {
                destroy_instance(&parts);
                return Err(e);
            }
        };
        let (physical, info) = described[chosen].clone();
        match create_device(&parts, physical, &info, opts) {
            Ok((device, queue, pool, allocator)) => {
                let debug_device = parts.debug_utils.as_ref().map(|_| ash::ext::debug_utils::Device::new(&parts.instance, &device));
                let push_descriptor = ash::khr::push_descriptor::Device::new(&parts.instance, &device);
                let pipeline_executables = (opts.kernel_statistics && info.kernel_statistics)
                    .then(|| ash::khr::pipeline_executable_properties::Device::new(&parts.instance, &device));
                let queue_family = info.queue_family.expect("usable devices have a compute queue");
                let ray_tracing = opts.ray_tracing.then(|| super::rt::RtDevice::new(&parts.instance, physical, &device));
                let shared = Shared {
                    entry: parts.entry,
                    instance: parts.instance,
                    physical,
                    queue_family,
                    debug_utils: parts.debug_utils,
                    messenger: parts.messenger,
                    device,
                    debug_device,
                    push_descriptor,
                    pipeline_executables,
                    ray_tracing,
                    allocator: ManuallyDrop::new(Mutex::new(allocator)),
                    queue: Mutex::new(queue),
                    command_pool: Mutex::new(pool),
                    spare: Mutex::new(Spare::default()),
                    info,
                    gpu_timeout: opts.gpu_timeout,
                    poisoned: AtomicBool::new(false),
                    submissions: AtomicU64::new(0),
                    profiler: Mutex::new(None),
                    _log: log.clone(),
                };
                shared.name(queue, "bidir.queue");
                shared.name(pool, "bidir.command_pool");
                Ok(Context { shared: Arc::new(shared), log, devices: Arc::new(infos), kernels: Default::default() })
            }
            Err(e) => {
                destroy_instance(&parts);
                Err(e)
            }
        }
    }

    /// Submissions made through this context so far (each one waited for): what a pass's
    /// host round trips are (`BIDIR_PASS_LOG`).
    pub fn submissions(&self) -> u64 {
        self.shared.submissions.load(Ordering::Relaxed)
    }

    /// The chosen device.
    pub fn info(&self) -> &DeviceInfo {
        &self.shared.info
    }

    /// Every device the instance saw (the chosen one is `info().index`).
    pub fn devices(&self) -> &[DeviceInfo] {
        &self.devices
    }

    /// Validation-layer warnings and errors so far (empty without validation).
    pub fn validation_messages(&self) -> Vec<String> {
        self.log.messages()
    }

    /// Destroys the device and instance now and returns every validation message, including
    /// those emitted during destruction (leaked objects). Fails if GPU objects made from this
    /// context are still alive.
    pub fn close(self) -> Result<Vec<String>> {
        let Context { shared, log, kernels, .. } = self;
        // The cached kernels hold the device: drop them first (those still in use elsewhere
        // keep it alive, and are reported below).
        kernels.lock().unwrap_or_else(|e| e.into_inner()).clear();
        drop(kernels);
        match Arc::try_unwrap(shared) {
            Ok(shared) => drop(shared),
            Err(shared) => return Err(VkError::LiveObjects(Arc::strong_count(&shared) - 1)),
        }
        Ok(log.messages())
    }
}

type DeviceParts = (ash::Device, vk::Queue, vk::CommandPool, Allocator);

fn create_device(
    parts: &instance::InstanceParts,
    physical: vk::PhysicalDevice,
    info: &DeviceInfo,
    opts: &ContextOptions,
) -> Result<DeviceParts> {
    let instance = &parts.instance;
    let family = info.queue_family.expect("usable devices have a compute queue");
    let priorities = [1.0f32];
    let queue_info = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
    // Extensions the caller asked for (the viewer's swapchain) must exist: say which is missing
    // rather than fail inside vkCreateDevice.
    if !opts.device_extensions.is_empty() {
        // SAFETY: query on a live physical device.
        let available =
            unsafe { instance.enumerate_device_extension_properties(physical) }.ctx(|| "vkEnumerateDeviceExtensionProperties".into())?;
        for want in &opts.device_extensions {
            if !available.iter().any(|e| e.extension_name_as_c_str() == Ok(*want)) {
                return Err(VkError::MissingExtension {
                    extension: want.to_string_lossy().into_owned(),
                    on: format!("device '{}'", info.name),
                    hint: "a window needs it; choose another device with --device (`bidir info` lists them)".into(),
                });
            }
        }
    }
    let mut ext_ptrs: Vec<*const i8> = vec![ash::khr::push_descriptor::NAME.as_ptr()];
    if info.atomic_float_add {
        ext_ptrs.push(ash::ext::shader_atomic_float::NAME.as_ptr());
    }
    ext_ptrs.extend(opts.device_extensions.iter().map(|e| e.as_ptr()));
    if opts.ray_tracing {
        if !info.ray_tracing_pipeline {
            return Err(VkError::MissingExtension {
                extension: instance::RAY_TRACING_EXTENSIONS.iter().map(|e| e.to_string_lossy()).collect::<Vec<_>>().join(" + "),
                on: format!("device '{}'", info.name),
                hint: "the driver's ray-tracing pipeline (--driver-rt) needs it; run without --driver-rt, or choose a device that has it with --device".into(),
            });
        }
        ext_ptrs.extend(instance::RAY_TRACING_EXTENSIONS.iter().map(|e| e.as_ptr()));
    }
    let statistics = opts.kernel_statistics && info.kernel_statistics;
    if statistics {
        ext_ptrs.push(ash::khr::pipeline_executable_properties::NAME.as_ptr());
    }
    let unchecked = unchecked_buffers(info);
    if unchecked {
        ext_ptrs.push(ash::ext::pipeline_robustness::NAME.as_ptr());
    }

    // Enable the optional features bidir's kernels use where the device has them.
    let mut f13 = vk::PhysicalDeviceVulkan13Features::default();
    let mut f12 = vk::PhysicalDeviceVulkan12Features::default();
    // SAFETY: feature query on a live physical device.
    let supported = unsafe {
        let mut q = vk::PhysicalDeviceFeatures2::default().push_next(&mut f12);
        if info.api_version >= vk::API_VERSION_1_3 {
            q = q.push_next(&mut f13);
        }
        instance.get_physical_device_features2(physical, &mut q);
        q.features
    };
    let core = vk::PhysicalDeviceFeatures::default().shader_int64(supported.shader_int64 == vk::TRUE);
    let mut e12 = vk::PhysicalDeviceVulkan12Features::default()
        .scalar_block_layout(f12.scalar_block_layout == vk::TRUE)
        .host_query_reset(f12.host_query_reset == vk::TRUE)
        .shader_float16(f12.shader_float16 == vk::TRUE)
        .storage_buffer8_bit_access(f12.storage_buffer8_bit_access == vk::TRUE)
        .shader_int8(f12.shader_int8 == vk::TRUE)
        .buffer_device_address(opts.ray_tracing);
    let mut e13 = vk::PhysicalDeviceVulkan13Features::default()
        .subgroup_size_control(f13.subgroup_size_control == vk::TRUE)
        .compute_full_subgroups(f13.compute_full_subgroups == vk::TRUE);
    let mut create = vk::DeviceCreateInfo::default()
        .queue_create_infos(&queue_info)
        .enabled_extension_names(&ext_ptrs)
        .enabled_features(&core)
        .push_next(&mut e12);
    if info.api_version >= vk::API_VERSION_1_3 {
        create = create.push_next(&mut e13);
    }
    let mut executable_info = vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default().pipeline_executable_info(true);
    if statistics {
        create = create.push_next(&mut executable_info);
    }
    let mut robustness = vk::PhysicalDevicePipelineRobustnessFeaturesEXT::default().pipeline_robustness(true);
    if unchecked {
        create = create.push_next(&mut robustness);
    }
    let mut atomic_float = vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT::default().shader_buffer_float32_atomic_add(true);
    if info.atomic_float_add {
        create = create.push_next(&mut atomic_float);
    }
    let mut accel = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
    let mut rt_pipeline = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
    if opts.ray_tracing {
        create = create.push_next(&mut accel).push_next(&mut rt_pipeline);
    }
    // SAFETY: every pointer in `create` outlives the call.
    let device = unsafe { instance.create_device(physical, &create, None) }.ctx(|| format!("vkCreateDevice ({})", info.name))?;
    // SAFETY: the queue family and index were requested above.
    let queue = unsafe { device.get_device_queue(family, 0) };
    let pool_info = vk::CommandPoolCreateInfo::default()
        .queue_family_index(family)
        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER | vk::CommandPoolCreateFlags::TRANSIENT);
    // SAFETY: live device.
    let pool = match unsafe { device.create_command_pool(&pool_info, None) } {
        Ok(p) => p,
        Err(result) => {
            // SAFETY: nothing was created from the device yet; it is destroyed once, on this error path.
            unsafe { device.destroy_device(None) };
            return Err(VkError::Vk { what: "vkCreateCommandPool".into(), result });
        }
    };
    let allocator = match Allocator::new(&AllocatorCreateDesc {
        instance: instance.clone(),
        device: device.clone(),
        physical_device: physical,
        debug_settings: Default::default(),
        buffer_device_address: opts.ray_tracing,
        allocation_sizes: Default::default(),
    }) {
        Ok(a) => a,
        Err(e) => {
            // SAFETY: nothing else was created from this device.
            unsafe {
                device.destroy_command_pool(pool, None);
                device.destroy_device(None);
            }
            return Err(VkError::Usage { name: "gpu-allocator".into(), msg: e.to_string() });
        }
    };
    Ok((device, queue, pool, allocator))
}
