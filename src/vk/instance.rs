//! Loader, instance, validation messenger and the description of every physical device.

use super::error::{Result, VkError, VkResultExt};
use ash::vk;
use std::{
    ffi::{c_void, CStr, CString},
    sync::Mutex,
};

pub(crate) const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Warnings and errors reported by the validation layer (and drivers) through the debug
/// messenger. Tests fail when it is not empty.
#[derive(Debug, Default)]
pub struct ValidationLog {
    messages: Mutex<Vec<String>>,
}

impl ValidationLog {
    pub fn messages(&self) -> Vec<String> {
        self.messages.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }
    fn push(&self, msg: String) {
        self.messages.lock().unwrap_or_else(|e| e.into_inner()).push(msg);
    }
}

unsafe extern "system" fn debug_callback(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    kind: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes a valid callback-data pointer; `user` is the `ValidationLog`
    // kept alive (in an Arc) until after the messenger is destroyed.
    let (msg, log) = unsafe {
        let msg = if data.is_null() || (*data).p_message.is_null() {
            String::from("(no message)")
        } else {
            CStr::from_ptr((*data).p_message).to_string_lossy().into_owned()
        };
        (msg, &*(user as *const ValidationLog))
    };
    let line = format!("[vulkan {severity:?} {kind:?}] {msg}");
    eprintln!("{line}");
    log.push(line);
    vk::FALSE
}

/// The loader and an instance, with the debug messenger when validation is on.
pub(crate) struct InstanceParts {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    pub debug_utils: Option<ash::ext::debug_utils::Instance>,
    pub messenger: vk::DebugUtilsMessengerEXT,
}

pub(crate) fn load_entry() -> Result<ash::Entry> {
    // SAFETY: loading the system Vulkan loader library; it is only used through ash.
    unsafe { ash::Entry::load() }.map_err(|e| VkError::Loader(e.to_string()))
}

pub(crate) fn create_instance(validation: bool, extra_extensions: &[&CStr], log: &std::sync::Arc<ValidationLog>) -> Result<InstanceParts> {
    let entry = load_entry()?;
    // SAFETY: plain queries on a loaded entry.
    let (loader_version, layers, exts) = unsafe {
        (
            entry.try_enumerate_instance_version().ctx(|| "vkEnumerateInstanceVersion".into())?.unwrap_or(vk::API_VERSION_1_0),
            entry.enumerate_instance_layer_properties().ctx(|| "vkEnumerateInstanceLayerProperties".into())?,
            entry.enumerate_instance_extension_properties(None).ctx(|| "vkEnumerateInstanceExtensionProperties".into())?,
        )
    };
    if validation && !layers.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)) {
        return Err(VkError::NoValidationLayer);
    }
    for want in extra_extensions {
        if !exts.iter().any(|e| e.extension_name_as_c_str() == Ok(*want)) {
            return Err(VkError::MissingExtension {
                extension: want.to_string_lossy().into_owned(),
                on: "the Vulkan loader".into(),
                hint: "a window needs it; install a driver with window-system support (on Debian/Ubuntu: \
                       apt-get install libvulkan1 mesa-vulkan-drivers), or render headless with `bidir render`"
                    .into(),
            });
        }
    }
    let has_debug_utils = validation || exts.iter().any(|e| e.extension_name_as_c_str() == Ok(ash::ext::debug_utils::NAME));
    let api_version = loader_version.min(vk::API_VERSION_1_3);
    if api_version < vk::API_VERSION_1_2 {
        return Err(VkError::NoSuitableDevice(format!(
            "the Vulkan loader offers API {}.{}, bidir needs 1.2 or newer: update libvulkan1",
            vk::api_version_major(loader_version),
            vk::api_version_minor(loader_version)
        )));
    }

    let app_name = CString::new("bidir").unwrap();
    let app =
        vk::ApplicationInfo::default().application_name(&app_name).application_version(1).engine_name(&app_name).api_version(api_version);
    let mut ext_ptrs: Vec<*const i8> = extra_extensions.iter().map(|e| e.as_ptr()).collect();
    if has_debug_utils {
        ext_ptrs.push(ash::ext::debug_utils::NAME.as_ptr());
    }
    let layer_ptrs: Vec<*const i8> = if validation { vec![VALIDATION_LAYER.as_ptr()] } else { vec![] };

    let severity = vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR;
    let kinds = vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
        | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE;
    let log_ptr = std::sync::Arc::as_ptr(log) as *mut c_void;
    let mut messenger_info = vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(severity)
        .message_type(kinds)
        .pfn_user_callback(Some(debug_callback))
        .user_data(log_ptr);
    let enables = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
    let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&enables);
    let mut info =
        vk::InstanceCreateInfo::default().application_info(&app).enabled_extension_names(&ext_ptrs).enabled_layer_names(&layer_ptrs);
    if validation {
        info = info.push_next(&mut messenger_info).push_next(&mut features);
    }
    // SAFETY: every pointer in `info` outlives this call.
    let instance = unsafe { entry.create_instance(&info, None) }.map_err(|result| match result {
        vk::Result::ERROR_INCOMPATIBLE_DRIVER => VkError::NoDevice,
        result => VkError::Vk { what: "vkCreateInstance".into(), result },
    })?;
    let debug_utils = has_debug_utils.then(|| ash::ext::debug_utils::Instance::new(&entry, &instance));
    let messenger = match (&debug_utils, validation) {
        (Some(du), true) => {
            // SAFETY: the messenger is destroyed before the instance (Shared::drop).
            match unsafe { du.create_debug_utils_messenger(&messenger_info, None) } {
                Ok(m) => m,
                Err(result) => {
                    // SAFETY: nothing else was created from this instance yet.
                    unsafe { instance.destroy_instance(None) };
                    return Err(VkError::Vk { what: "vkCreateDebugUtilsMessengerEXT".into(), result });
                }
            }
        }
        _ => vk::DebugUtilsMessengerEXT::null(),
    };
    Ok(InstanceParts { entry, instance, debug_utils, messenger })
}

/// Subgroup operations a device supports in compute shaders.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SubgroupOps {
    pub basic: bool,
    pub vote: bool,
    pub arithmetic: bool,
    pub ballot: bool,
    pub shuffle: bool,
    pub shuffle_relative: bool,
    pub clustered: bool,
    pub quad: bool,
}

impl SubgroupOps {
    fn from_flags(f: vk::SubgroupFeatureFlags) -> Self {
        SubgroupOps {
            basic: f.contains(vk::SubgroupFeatureFlags::BASIC),
            vote: f.contains(vk::SubgroupFeatureFlags::VOTE),
            arithmetic: f.contains(vk::SubgroupFeatureFlags::ARITHMETIC),
            ballot: f.contains(vk::SubgroupFeatureFlags::BALLOT),
            shuffle: f.contains(vk::SubgroupFeatureFlags::SHUFFLE),
            shuffle_relative: f.contains(vk::SubgroupFeatureFlags::SHUFFLE_RELATIVE),
            clustered: f.contains(vk::SubgroupFeatureFlags::CLUSTERED),
            quad: f.contains(vk::SubgroupFeatureFlags::QUAD),
        }
    }
    /// The supported operations, by name.
    pub fn names(&self) -> Vec<&'static str> {
        let all = [
            (self.basic, "basic"),
            (self.vote, "vote"),
            (self.arithmetic, "arithmetic"),
            (self.ballot, "ballot"),
            (self.shuffle, "shuffle"),
            (self.shuffle_relative, "shuffle_relative"),
            (self.clustered, "clustered"),
            (self.quad, "quad"),
        ];
        all.iter().filter(|(on, _)| *on).map(|(_, n)| *n).collect()
    }
}

/// One memory heap of a device.
#[derive(Clone, Copy, Debug)]
pub struct MemoryHeap {
    pub bytes: u64,
    pub device_local: bool,
}

/// The device extensions the driver's ray-tracing pipeline needs (`ContextOptions::ray_tracing`).
pub(crate) const RAY_TRACING_EXTENSIONS: [&CStr; 3] =
    [ash::khr::acceleration_structure::NAME, ash::khr::ray_tracing_pipeline::NAME, ash::khr::deferred_host_operations::NAME];

/// What bidir knows about a physical device.
#[derive(Clone, Debug)]
pub struct DeviceInfo {
    /// Position in the loader's enumeration (what `--device INDEX` refers to).
    pub index: usize,
    pub name: String,
    pub device_type: vk::PhysicalDeviceType,
    pub driver_name: String,
    pub driver_info: String,
    pub api_version: u32,
    pub vendor_id: u32,
    pub subgroup_size: u32,
    pub min_subgroup_size: u32,
    pub max_subgroup_size: u32,
    pub subgroup_ops: SubgroupOps,
    pub subgroup_in_compute: bool,
    pub memory_heaps: Vec<MemoryHeap>,
    pub max_storage_buffer_range: u32,
    /// The most descriptors one kernel may bind: its set is pushed (VK_KHR_push_descriptor's
    /// `maxPushDescriptors`), and all its storage buffers are in it
    /// (`maxPerStageDescriptorStorageBuffers`); 32 on lavapipe and NVIDIA's driver.
    pub max_kernel_descriptors: u32,
    pub max_shared_memory: u32,
    pub max_workgroup_invocations: u32,
    /// The most workgroups one dispatch may launch on each axis
    /// (`maxComputeWorkGroupCount`; 65,535 is the least a device may offer).
    pub max_workgroup_count: [u32; 3],
    pub timestamp_period_ns: f32,
    pub timestamp_valid_bits: u32,
    pub queue_family: Option<u32>,
    pub push_descriptor: bool,
    pub shader_int64: bool,
    /// VK_EXT_shader_atomic_float with atomic float add on storage buffers (light-tracing
    /// splats of BDPT need it).
    pub atomic_float_add: bool,
    /// Streaming multiprocessors and the most warps each keeps resident (VK_NV_shader_sm_builtins;
    /// 0 where the device does not report them).
    pub sm_count: u32,
    pub warps_per_sm: u32,
    /// VK_KHR_pipeline_executable_properties: the driver reports each kernel's registers,
    /// spills, shared memory and the like (`ContextOptions::kernel_statistics`).
    pub kernel_statistics: bool,
    /// VK_EXT_pipeline_robustness (its `pipelineRobustness` feature): kernels may be created
    /// without the driver's bounds checks on storage and uniform buffers.
    pub pipeline_robustness: bool,
    /// VK_KHR_ray_tracing_pipeline with VK_KHR_acceleration_structure (and the deferred host
    /// operations it needs): the driver's own ray tracing, which `bench traversal --driver-rt`
    /// measures bidir's traversal against.
    pub ray_tracing_pipeline: bool,
    /// Why bidir cannot use this device; empty when it can.
    pub missing: Vec<String>,
}

impl DeviceInfo {
    pub fn type_name(&self) -> &'static str {
        match self.device_type {
            vk::PhysicalDeviceType::DISCRETE_GPU => "discrete GPU",
            vk::PhysicalDeviceType::INTEGRATED_GPU => "integrated GPU",
            vk::PhysicalDeviceType::VIRTUAL_GPU => "virtual GPU",
            vk::PhysicalDeviceType::CPU => "CPU",
            _ => "other",
        }
    }
    /// A CPU device (llvmpipe and the like), where several defaults differ from a GPU's.
    pub fn is_cpu(&self) -> bool {
        self.device_type == vk::PhysicalDeviceType::CPU
    }

    /// Preference order for automatic choice: discrete > integrated > virtual > CPU.
    pub fn rank(&self) -> u32 {
        match self.device_type {
            vk::PhysicalDeviceType::DISCRETE_GPU => 0,
            vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
            vk::PhysicalDeviceType::VIRTUAL_GPU => 2,
            vk::PhysicalDeviceType::CPU => 3,
            _ => 4,
        }
    }
    pub fn usable(&self) -> bool {
        self.missing.is_empty()
    }
    pub fn api_string(&self) -> String {
        format!(
            "{}.{}.{}",
            vk::api_version_major(self.api_version),
            vk::api_version_minor(self.api_version),
            vk::api_version_patch(self.api_version)
        )
    }
    pub fn device_local_bytes(&self) -> u64 {
        self.memory_heaps.iter().filter(|h| h.device_local).map(|h| h.bytes).max().unwrap_or(0)
    }
}

pub(crate) fn describe_devices(instance: &ash::Instance) -> Result<Vec<(vk::PhysicalDevice, DeviceInfo)>> {
    // SAFETY: queries on a live instance.
    let physicals = unsafe { instance.enumerate_physical_devices() }.ctx(|| "vkEnumeratePhysicalDevices".into())?;
    physicals.into_iter().enumerate().map(|(index, pd)| Ok((pd, describe(instance, pd, index)?))).collect()
}

fn describe(instance: &ash::Instance, pd: vk::PhysicalDevice, index: usize) -> Result<DeviceInfo> {
    // SAFETY: queries on a live physical device; every chained struct outlives the call.
    unsafe {
        let base = instance.get_physical_device_properties(pd);
        let api = base.api_version;
        let mut subgroup = vk::PhysicalDeviceSubgroupProperties::default();
        let mut driver = vk::PhysicalDeviceDriverProperties::default();
        let mut size_control = vk::PhysicalDeviceSubgroupSizeControlProperties::default();
        let mut sm = vk::PhysicalDeviceShaderSMBuiltinsPropertiesNV::default();
        let mut push = vk::PhysicalDevicePushDescriptorPropertiesKHR::default();
        let exts = instance.enumerate_device_extension_properties(pd).ctx(|| "vkEnumerateDeviceExtensionProperties".into())?;
        let has_ext = |n: &CStr| exts.iter().any(|e| e.extension_name_as_c_str() == Ok(n));
        {
            let mut props2 = vk::PhysicalDeviceProperties2::default().push_next(&mut subgroup);
            if api >= vk::API_VERSION_1_2 {
                props2 = props2.push_next(&mut driver);
            }
            if api >= vk::API_VERSION_1_3 {
                props2 = props2.push_next(&mut size_control);
            }
            // Only queried (never enabled): how many SMs, and warps each keeps resident.
            if has_ext(ash::nv::shader_sm_builtins::NAME) {
                props2 = props2.push_next(&mut sm);
            }
            if has_ext(ash::khr::push_descriptor::NAME) {
                props2 = props2.push_next(&mut push);
            }
            instance.get_physical_device_properties2(pd, &mut props2);
        }
        let features = instance.get_physical_device_features(pd);
        let mem = instance.get_physical_device_memory_properties(pd);
        let queues = instance.get_physical_device_queue_family_properties(pd);
        // Prefer a queue family with graphics + compute (the viewer presents from it), then any
        // compute family.
        let family = queues
            .iter()
            .position(|q| q.queue_flags.contains(vk::QueueFlags::COMPUTE | vk::QueueFlags::GRAPHICS))
            .or_else(|| queues.iter().position(|q| q.queue_flags.contains(vk::QueueFlags::COMPUTE)))
            .map(|i| i as u32);
        let timestamp_valid_bits = family.map(|f| queues[f as usize].timestamp_valid_bits).unwrap_or(0);

        let name = base.device_name_as_c_str().map(|c| c.to_string_lossy().into_owned()).unwrap_or_default();
        let subgroup_in_compute = subgroup.supported_stages.contains(vk::ShaderStageFlags::COMPUTE);
        let ops = SubgroupOps::from_flags(subgroup.supported_operations);
        let push_descriptor = has_ext(ash::khr::push_descriptor::NAME);
        let mut atomic_float = vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT::default();
        if has_ext(ash::ext::shader_atomic_float::NAME) {
            let mut f2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut atomic_float);
            instance.get_physical_device_features2(pd, &mut f2);
        }
        let atomic_float_add = atomic_float.shader_buffer_float32_atomic_add == vk::TRUE;
        let mut robustness = vk::PhysicalDevicePipelineRobustnessFeaturesEXT::default();
        if has_ext(ash::ext::pipeline_robustness::NAME) {
            let mut f2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut robustness);
            instance.get_physical_device_features2(pd, &mut f2);
        }

        let mut missing = Vec::new();
        if api < vk::API_VERSION_1_2 {
            missing.push(format!("Vulkan {} < 1.2", vk::api_version_minor(api)));
        }
        if family.is_none() {
            missing.push("no compute queue".into());
        }
        if !push_descriptor {
            missing.push("VK_KHR_push_descriptor".into());
        }
        if !(subgroup_in_compute && ops.basic && ops.vote && ops.arithmetic && ops.ballot && ops.shuffle) {
            missing.push("subgroup basic/vote/arithmetic/ballot/shuffle operations in compute".into());
        }
        let (min_sg, max_sg) = if api >= vk::API_VERSION_1_3 && size_control.max_subgroup_size > 0 {
            (size_control.min_subgroup_size, size_control.max_subgroup_size)
        } else {
            (subgroup.subgroup_size, subgroup.subgroup_size)
        };
        Ok(DeviceInfo {
            index,
            name,
            device_type: base.device_type,
            driver_name: driver.driver_name_as_c_str().map(|c| c.to_string_lossy().into_owned()).unwrap_or_default(),
            driver_info: driver.driver_info_as_c_str().map(|c| c.to_string_lossy().into_owned()).unwrap_or_default(),
            api_version: api,
            vendor_id: base.vendor_id,
            subgroup_size: subgroup.subgroup_size,
            min_subgroup_size: min_sg,
            max_subgroup_size: max_sg,
            subgroup_ops: ops,
            subgroup_in_compute,
            memory_heaps: mem
                .memory_heaps_as_slice()
                .iter()
                .map(|h| MemoryHeap { bytes: h.size, device_local: h.flags.contains(vk::MemoryHeapFlags::DEVICE_LOCAL) })
                .collect(),
            max_storage_buffer_range: base.limits.max_storage_buffer_range,
            max_kernel_descriptors: push.max_push_descriptors.min(base.limits.max_per_stage_descriptor_storage_buffers),
            max_shared_memory: base.limits.max_compute_shared_memory_size,
            max_workgroup_invocations: base.limits.max_compute_work_group_invocations,
            max_workgroup_count: base.limits.max_compute_work_group_count,
            timestamp_period_ns: base.limits.timestamp_period,
            timestamp_valid_bits,
            queue_family: family,
            push_descriptor,
            shader_int64: features.shader_int64 == vk::TRUE,
            atomic_float_add,
            sm_count: sm.shader_sm_count,
            warps_per_sm: sm.shader_warps_per_sm,
            kernel_statistics: has_ext(ash::khr::pipeline_executable_properties::NAME),
            pipeline_robustness: robustness.pipeline_robustness == vk::TRUE,
            ray_tracing_pipeline: RAY_TRACING_EXTENSIONS.iter().all(|e| has_ext(e)),
            missing,
        })
    }
}

/// Picks a device: `selector` is an index or a case-insensitive name substring; without
/// one, the usable device of best rank (discrete > integrated > virtual > CPU).
pub fn choose_device(devices: &[DeviceInfo], selector: Option<&str>) -> Result<usize> {
    if devices.is_empty() {
        return Err(VkError::NoDevice);
    }
    let pos = match selector {
        Some(sel) => {
            let found = match sel.trim().parse::<usize>() {
                Ok(i) => devices.iter().position(|d| d.index == i),
                Err(_) => {
                    let needle = sel.to_lowercase();
                    devices.iter().position(|d| d.name.to_lowercase().contains(&needle))
                }
            };
            let pos = found.ok_or_else(|| VkError::DeviceNotFound(sel.to_string()))?;
            if !devices[pos].usable() {
                return Err(VkError::Unsuitable(devices[pos].name.clone(), devices[pos].missing.join(", ")));
            }
            pos
        }
        None => {
            devices.iter().enumerate().filter(|(_, d)| d.usable()).min_by_key(|(_, d)| (d.rank(), d.index)).map(|(i, _)| i).ok_or_else(
                || {
                    VkError::NoSuitableDevice(
                        devices.iter().map(|d| format!("{}: lacks {}", d.name, d.missing.join(", "))).collect::<Vec<_>>().join("; "),
                    )
                },
            )?
        }
    };
    Ok(pos)
}

/// Lists every Vulkan device without creating a logical device (for `bidir info`).
pub fn list_devices() -> Result<Vec<DeviceInfo>> {
    let log = std::sync::Arc::new(ValidationLog::default());
    let parts = create_instance(false, &[], &log)?;
    let result = describe_devices(&parts.instance);
    // SAFETY: no child objects were created.
    unsafe { parts.instance.destroy_instance(None) };
    Ok(result?.into_iter().map(|(_, d)| d).collect())
}
