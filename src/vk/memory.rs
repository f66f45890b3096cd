//! Buffers and images, allocated through gpu-allocator and freed on drop.

use super::{
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
};
use ash::vk;
use gpu_allocator::{
    vulkan::{Allocation, AllocationCreateDesc, AllocationScheme},
    MemoryLocation,
};
use std::sync::Arc;

/// Where a buffer's memory lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Memory {
    /// Device-local; filled and read through staging copies.
    Device,
    /// Host-visible, written by the CPU, read by the GPU (staging, per-frame data).
    Upload,
    /// Host-visible, written by the GPU, read by the CPU (readback).
    Readback,
}

impl Memory {
    fn location(self) -> MemoryLocation {
        match self {
            Memory::Device => MemoryLocation::GpuOnly,
            Memory::Upload => MemoryLocation::CpuToGpu,
            Memory::Readback => MemoryLocation::GpuToCpu,
        }
    }
}

/// A storage buffer (also usable as a transfer source and destination).
pub struct Buffer {
    shared: Arc<Shared>,
    pub(crate) raw: vk::Buffer,
    allocation: Option<Allocation>,
    size: u64,
    memory: Memory,
    name: String,
    /// Made with INDIRECT_BUFFER usage: may hold indirect dispatch arguments.
    pub(super) indirect: bool,
}

impl Buffer {
    pub fn size(&self) -> u64 {
        self.size
    }
    pub fn name(&self) -> &str {
        &self.name
    }
    pub fn memory(&self) -> Memory {
        self.memory
    }

    fn mapped(&self) -> Result<&[u8]> {
        self.allocation
            .as_ref()
            .and_then(|a| a.mapped_slice())
            .ok_or_else(|| VkError::Usage { name: self.name.clone(), msg: "buffer is not host-visible".into() })
    }

    /// Copies `data` into a host-visible buffer at byte `offset`.
    pub fn write<T: bytemuck::Pod>(&mut self, offset: u64, data: &[T]) -> Result<()> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let name = self.name.clone();
        let end = offset as usize + bytes.len();
        let slice = self
            .allocation
            .as_mut()
            .and_then(|a| a.mapped_slice_mut())
            .ok_or_else(|| VkError::Usage { name: name.clone(), msg: "buffer is not host-visible".into() })?;
        if end > slice.len() {
            return Err(VkError::Usage { name, msg: format!("write of {} bytes at {offset} overruns the buffer", bytes.len()) });
        }
        slice[offset as usize..end].copy_from_slice(bytes);
        Ok(())
    }

    /// Reads a host-visible buffer as `T`s (the first `size / size_of::<T>()` of them).
    pub fn read<T: bytemuck::Pod>(&self) -> Result<Vec<T>> {
        let bytes = &self.mapped()?[..self.size as usize];
        let n = bytes.len() / std::mem::size_of::<T>();
        Ok(bytemuck::pod_collect_to_vec(&bytes[..n * std::mem::size_of::<T>()]))
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        if self.shared.poisoned.load(std::sync::atomic::Ordering::SeqCst) {
            return;
        }
        if let Some(a) = self.allocation.take() {
            let _ = self.shared.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(a);
        }
        // SAFETY: submissions wait for completion before returning, so no GPU work uses it.
        unsafe { self.shared.device.destroy_buffer(self.raw, None) };
    }
}

/// A 2D image kept in `GENERAL` layout, usable as a storage image and a transfer
/// source/destination.
pub struct Image {
    shared: Arc<Shared>,
    pub(crate) raw: vk::Image,
    pub(crate) view: vk::ImageView,
    allocation: Option<Allocation>,
    width: u32,
    height: u32,
    format: vk::Format,
    name: String,
}

impl Image {
    pub fn width(&self) -> u32 {
        self.width
    }
    pub fn height(&self) -> u32 {
        self.height
    }
    pub fn format(&self) -> vk::Format {
        self.format
    }
    pub fn name(&self) -> &str {
        &self.name
    }
    /// Bytes of one texel for the formats bidir uses.
    pub fn texel_bytes(&self) -> u64 {
        texel_bytes(self.format)
    }
}

pub(crate) fn texel_bytes(format: vk::Format) -> u64 {
    match format {
        vk::Format::R32G32B32A32_SFLOAT | vk::Format::R32G32B32A32_UINT => 16,
        vk::Format::R16G16B16A16_SFLOAT => 8,
        vk::Format::R32_SFLOAT
        | vk::Format::R32_UINT
        | vk::Format::R8G8B8A8_UNORM
        | vk::Format::R8G8B8A8_SRGB
        | vk::Format::B8G8R8A8_UNORM => 4,
        _ => 16,
    }
}

impl Drop for Image {
    fn drop(&mut self) {
        if self.shared.poisoned.load(std::sync::atomic::Ordering::SeqCst) {
            return;
        }
        if let Some(a) = self.allocation.take() {
            let _ = self.shared.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(a);
        }
        // SAFETY: submissions wait for completion before returning, so no GPU work uses it.
        unsafe {
            self.shared.device.destroy_image_view(self.view, None);
            self.shared.device.destroy_image(self.raw, None);
        }
    }
}

impl Context {
    /// Creates a buffer of `bytes` bytes (at least 4: Vulkan has no empty buffers).
    pub fn create_buffer(&self, name: &str, bytes: u64, memory: Memory) -> Result<Buffer> {
        self.create_buffer_with_usage(name, bytes, memory, vk::BufferUsageFlags::empty())
    }

    /// A device buffer that may also hold indirect dispatch arguments
    /// (`Recorder::dispatch_indirect`).
    pub fn create_indirect_buffer(&self, name: &str, bytes: u64) -> Result<Buffer> {
        self.create_buffer_with_usage(name, bytes, Memory::Device, vk::BufferUsageFlags::INDIRECT_BUFFER)
    }

    /// `create_buffer` with `extra` usages (acceleration-structure storage and inputs, shader
    /// binding tables, device addresses: the ray-tracing yardstick, `rt.rs`).
    pub(crate) fn create_buffer_with_usage(&self, name: &str, bytes: u64, memory: Memory, extra: vk::BufferUsageFlags) -> Result<Buffer> {
        let s = &self.shared;
        let size = bytes.max(4).next_multiple_of(4);
        let usage = vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST | extra;
        if size > s.info.max_storage_buffer_range as u64 && memory == Memory::Device {
            return Err(VkError::Usage {
                name: name.into(),
                msg: format!(
                    "{size} bytes exceed the device's largest storage buffer ({} bytes on {}): the scene is too big for this GPU",
                    s.info.max_storage_buffer_range, s.info.name
                ),
            });
        }
        let info = vk::BufferCreateInfo::default().size(size).usage(usage).sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: live device, valid create info.
        let raw = unsafe { s.device.create_buffer(&info, None) }.ctx(|| format!("vkCreateBuffer '{name}'"))?;
        // SAFETY: `raw` is a live buffer.
        let requirements = unsafe { s.device.get_buffer_memory_requirements(raw) };
        let allocation = s.allocator.lock().unwrap_or_else(|e| e.into_inner()).allocate(&AllocationCreateDesc {
            name,
            requirements,
            location: memory.location(),
            linear: true,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        });
        let allocation = match allocation {
            Ok(a) => a,
            Err(source) => {
                // SAFETY: unbound, unused buffer.
                unsafe { s.device.destroy_buffer(raw, None) };
                return Err(VkError::Alloc { name: name.into(), bytes: size, source });
            }
        };
        let indirect = usage.contains(vk::BufferUsageFlags::INDIRECT_BUFFER);
        let buffer = Buffer { shared: s.clone(), raw, allocation: Some(allocation), size, memory, name: name.into(), indirect };
        let a = buffer.allocation.as_ref().expect("just set");
        // SAFETY: memory and offset come from an allocation made for these requirements.
        unsafe { s.device.bind_buffer_memory(raw, a.memory(), a.offset()) }.ctx(|| format!("vkBindBufferMemory '{name}'"))?;
        s.name(raw, name);
        Ok(buffer)
    }

    /// Creates a device-local buffer holding `data` (uploaded through a staging buffer).
    pub fn upload_buffer<T: bytemuck::Pod>(&self, name: &str, data: &[T]) -> Result<Buffer> {
        self.upload_buffer_with_usage(name, data, vk::BufferUsageFlags::empty())
    }

    /// `upload_buffer` with `extra` usages (see `create_buffer_with_usage`).
    pub(crate) fn upload_buffer_with_usage<T: bytemuck::Pod>(&self, name: &str, data: &[T], extra: vk::BufferUsageFlags) -> Result<Buffer> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let dst = self.create_buffer_with_usage(name, bytes.len() as u64, Memory::Device, extra)?;
        if !bytes.is_empty() {
            let mut staging = self.create_buffer(&format!("{name}.staging"), bytes.len() as u64, Memory::Upload)?;
            staging.write(0, bytes)?;
            self.submit(&format!("upload {name}"), |rec| {
                rec.copy_buffer(&staging, &dst, bytes.len() as u64);
                Ok(())
            })?;
        }
        Ok(dst)
    }

    /// Reads a whole buffer back to the host as `T`s.
    pub fn read_buffer<T: bytemuck::Pod>(&self, buffer: &Buffer) -> Result<Vec<T>> {
        if buffer.memory() == Memory::Readback {
            return buffer.read();
        }
        let staging = self.create_buffer(&format!("{}.readback", buffer.name()), buffer.size(), Memory::Readback)?;
        self.submit(&format!("read back {}", buffer.name()), |rec| {
            rec.copy_buffer(buffer, &staging, buffer.size());
            Ok(())
        })?;
        staging.read()
    }

    /// Creates a 2D image in `GENERAL` layout, zero-filled.
    pub fn create_image(&self, name: &str, width: u32, height: u32, format: vk::Format) -> Result<Image> {
        let s = &self.shared;
        if width == 0 || height == 0 {
            return Err(VkError::Usage { name: name.into(), msg: format!("image size {width}x{height} is empty") });
        }
        let usage = vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST;
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width, height, depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: live device, valid create info.
        let raw = unsafe { s.device.create_image(&info, None) }.ctx(|| format!("vkCreateImage '{name}' {width}x{height}"))?;
        // SAFETY: `raw` is a live image.
        let requirements = unsafe { s.device.get_image_memory_requirements(raw) };
        let allocation = s.allocator.lock().unwrap_or_else(|e| e.into_inner()).allocate(&AllocationCreateDesc {
            name,
            requirements,
            location: MemoryLocation::GpuOnly,
            linear: false,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        });
        let allocation = match allocation {
            Ok(a) => a,
            Err(source) => {
                // SAFETY: unbound, unused image.
                unsafe { s.device.destroy_image(raw, None) };
                return Err(VkError::Alloc { name: name.into(), bytes: requirements.size, source });
            }
        };
        // SAFETY: memory from an allocation made for this image's requirements.
        if let Err(result) = unsafe { s.device.bind_image_memory(raw, allocation.memory(), allocation.offset()) } {
            let _ = s.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(allocation);
            // SAFETY: the image was never used and no view of it exists; destroyed once, on this error path.
            unsafe { s.device.destroy_image(raw, None) };
            return Err(VkError::Vk { what: format!("vkBindImageMemory '{name}'"), result });
        }
        let view_info = vk::ImageViewCreateInfo::default()
            .image(raw)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format)
            .subresource_range(color_range());
        // SAFETY: `raw` is bound to memory.
        let view = match unsafe { s.device.create_image_view(&view_info, None) } {
            Ok(v) => v,
            Err(result) => {
                let _ = s.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(allocation);
                // SAFETY: the image was never used and no view of it exists; destroyed once, on this error path.
                unsafe { s.device.destroy_image(raw, None) };
                return Err(VkError::Vk { what: format!("vkCreateImageView '{name}'"), result });
            }
        };
        s.name(raw, name);
        s.name(view, &format!("{name}.view"));
        let image = Image { shared: s.clone(), raw, view, allocation: Some(allocation), width, height, format, name: name.into() };
        self.submit(&format!("init {name}"), |rec| {
            rec.init_image(&image);
            rec.clear_image(&image);
            Ok(())
        })?;
        Ok(image)
    }

    /// Uploads tightly packed texels (`width * height * texel_bytes` bytes) into `image`.
    pub fn write_image<T: bytemuck::Pod>(&self, image: &Image, texels: &[T]) -> Result<()> {
        let bytes: &[u8] = bytemuck::cast_slice(texels);
        let expect = image.width as u64 * image.height as u64 * image.texel_bytes();
        if bytes.len() as u64 != expect {
            return Err(VkError::Usage { name: image.name.clone(), msg: format!("{} bytes given, the image takes {expect}", bytes.len()) });
        }
        let mut staging = self.create_buffer(&format!("{}.staging", image.name), expect, Memory::Upload)?;
        staging.write(0, bytes)?;
        self.submit(&format!("upload {}", image.name), |rec| {
            rec.copy_buffer_to_image(&staging, image);
            Ok(())
        })
    }

    /// Reads an image back as tightly packed texels.
    pub fn read_image<T: bytemuck::Pod>(&self, image: &Image) -> Result<Vec<T>> {
        let bytes = image.width as u64 * image.height as u64 * image.texel_bytes();
        let staging = self.create_buffer(&format!("{}.readback", image.name), bytes, Memory::Readback)?;
        self.submit(&format!("read back {}", image.name), |rec| {
            rec.copy_image_to_buffer(image, &staging);
            Ok(())
        })?;
        staging.read()
    }
}

pub(crate) fn color_range() -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}
