use ash::vk;
use std::time::Duration;

/// Everything that can go wrong in the Vulkan backend, each with what to do about it.
#[derive(Debug, thiserror::Error)]
pub enum VkError {
    #[error(
        "the Vulkan loader (libvulkan.so.1) could not be loaded ({0}). Install it with a driver, \
         e.g. on Debian/Ubuntu: apt-get install libvulkan1 mesa-vulkan-drivers (lavapipe, a CPU \
         Vulkan) or your GPU vendor's driver"
    )]
    Loader(String),
    #[error(
        "no Vulkan device found. Install a Vulkan driver, e.g. on Debian/Ubuntu: apt-get install \
         mesa-vulkan-drivers (lavapipe, a CPU Vulkan), or your GPU vendor's driver"
    )]
    NoDevice,
    #[error("no usable Vulkan device: {0}")]
    NoSuitableDevice(String),
    #[error("no Vulkan device matches '{0}'; `bidir info` lists the devices and their indices")]
    DeviceNotFound(String),
    #[error("device '{0}' cannot be used: {1}")]
    Unsuitable(String, String),
    #[error(
        "validation was requested (BIDIR_VALIDATION=1 or a test) but VK_LAYER_KHRONOS_validation \
         is not installed: apt-get install vulkan-validationlayers"
    )]
    NoValidationLayer,
    #[error("{what}: {result}")]
    Vk { what: String, result: vk::Result },
    #[error("GPU memory for '{name}' ({bytes} bytes) could not be allocated: {source}")]
    Alloc {
        name: String,
        bytes: u64,
        #[source]
        source: gpu_allocator::AllocationError,
    },
    #[error(
        "the GPU did not finish '{0}' within {1:?}: it hung or the work was too large; the \
         device cannot be used further (raise BIDIR_GPU_TIMEOUT_S if the work is legitimately long)"
    )]
    Timeout(String, Duration),
    #[error("kernel '{kernel}': {msg}")]
    Kernel { kernel: String, msg: String },
    #[error("'{name}': {msg}")]
    Usage { name: String, msg: String },
    #[error("{on} does not offer {extension}: {hint}")]
    MissingExtension { extension: String, on: String, hint: String },
    #[error(
        "device '{device}' cannot present to this window ({why}); choose another device with \
         --device (`bidir info` lists them), or render headless with `bidir render`"
    )]
    CannotPresent { device: String, why: String },
    #[error("{0} GPU object(s) still alive when the context was closed (a leak in the caller)")]
    LiveObjects(usize),
}

pub type Result<T, E = VkError> = std::result::Result<T, E>;

/// Attaches what was being done to a raw `vk::Result`.
pub(crate) trait VkResultExt<T> {
    fn ctx(self, what: impl FnOnce() -> String) -> Result<T>;
}

impl<T> VkResultExt<T> for Result<T, vk::Result> {
    fn ctx(self, what: impl FnOnce() -> String) -> Result<T> {
        self.map_err(|result| VkError::Vk { what: what(), result })
    }
}
