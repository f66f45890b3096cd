//! The driver's own ray tracing: VK_KHR_ray_tracing_pipeline over VK_KHR_acceleration_structure,
//! the yardstick that `bidir bench traversal --driver-rt` measures bidir's traversal against.
//! A bottom-level acceleration structure over the scene's triangles (opaque, built for fast
//! tracing), a top-level one holding it once (identity transform, no culling), and a pipeline
//! of three stages (ray generation, miss, closest hit: `glsl/rt/`) that traces a buffer of
//! rays into hits as the trace kernels do. Nothing else in bidir uses it.

use super::{
    commands::Recorder,
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
    kernel::KernelSource,
    memory::{Buffer, Memory},
};
use ash::vk;
use std::sync::Arc;

/// The ray-tracing entry points and the limits the shader binding table and builds obey,
/// loaded when a context is created with `ContextOptions::ray_tracing`.
pub(crate) struct RtDevice {
    accel: ash::khr::acceleration_structure::Device,
    pipeline: ash::khr::ray_tracing_pipeline::Device,
    handle_size: u32,
    handle_alignment: u32,
    base_alignment: u32,
    scratch_alignment: u32,
    max_invocations: u32,
    max_primitives: u64,
}

impl RtDevice {
    pub(crate) fn new(instance: &ash::Instance, physical: vk::PhysicalDevice, device: &ash::Device) -> RtDevice {
        let mut rt = vk::PhysicalDeviceRayTracingPipelinePropertiesKHR::default();
        let mut accel = vk::PhysicalDeviceAccelerationStructurePropertiesKHR::default();
        {
            let mut props = vk::PhysicalDeviceProperties2::default().push_next(&mut rt).push_next(&mut accel);
            // SAFETY: property query on a live physical device that offers both extensions
            // (checked before the device was created with them).
            unsafe { instance.get_physical_device_properties2(physical, &mut props) };
        }
        RtDevice {
            accel: ash::khr::acceleration_structure::Device::new(instance, device),
            pipeline: ash::khr::ray_tracing_pipeline::Device::new(instance, device),
            handle_size: rt.shader_group_handle_size,
            handle_alignment: rt.shader_group_handle_alignment.max(1),
            base_alignment: rt.shader_group_base_alignment.max(1),
            scratch_alignment: accel.min_acceleration_structure_scratch_offset_alignment.max(1),
            max_invocations: rt.max_ray_dispatch_invocation_count,
            max_primitives: accel.max_primitive_count,
        }
    }
}

/// The three stages of the yardstick's pipeline and where its shaders expect their resources.
#[derive(Clone, Copy, Debug)]
pub struct RtShaders<'a> {
    pub raygen: &'a KernelSource,
    pub miss: &'a KernelSource,
    pub closest_hit: &'a KernelSource,
    /// Binding of the top-level acceleration structure.
    pub tlas_binding: u32,
    /// Bindings of the ray and hit storage buffers.
    pub rays_binding: u32,
    pub hits_binding: u32,
    /// Push-constant bytes of the ray-generation stage.
    pub push_size: u32,
}

/// Acceleration structures over one triangle mesh and the pipeline that traces them.
pub struct DriverTracer {
    shared: Arc<Shared>,
    blas: vk::AccelerationStructureKHR,
    tlas: vk::AccelerationStructureKHR,
    set_layout: vk::DescriptorSetLayout,
    pipeline_layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    /// Ray generation, miss, hit and (empty) callable regions of the shader binding table.
    regions: [vk::StridedDeviceAddressRegionKHR; 4],
    bindings: [u32; 3],
    push_size: u32,
    blas_build_ms: f64,
    blas_bytes: u64,
    /// Storage of the structures, the build inputs and the binding table (kept alive).
    buffers: Vec<Buffer>,
}

impl DriverTracer {
    /// GPU time of the bottom-level build (timestamps around it), milliseconds.
    pub fn blas_build_ms(&self) -> f64 {
        self.blas_build_ms
    }
    /// Bytes of the bottom-level acceleration structure as the driver sized it.
    pub fn blas_bytes(&self) -> u64 {
        self.blas_bytes
    }
}

impl Drop for DriverTracer {
    fn drop(&mut self) {
        let s = &self.shared;
        if s.poisoned.load(std::sync::atomic::Ordering::SeqCst) {
            return;
        }
        let Some(rt) = &s.ray_tracing else { return };
        // SAFETY: submissions complete before returning, so nothing in flight uses these; each
        // handle is destroyed once (null ones, left by a failed creation, are skipped).
        unsafe {
            if self.pipeline != vk::Pipeline::null() {
                s.device.destroy_pipeline(self.pipeline, None);
            }
            if self.pipeline_layout != vk::PipelineLayout::null() {
                s.device.destroy_pipeline_layout(self.pipeline_layout, None);
            }
            if self.set_layout != vk::DescriptorSetLayout::null() {
                s.device.destroy_descriptor_set_layout(self.set_layout, None);
            }
            for a in [self.tlas, self.blas] {
                if a != vk::AccelerationStructureKHR::null() {
                    rt.accel.destroy_acceleration_structure(a, None);
                }
            }
        }
        self.buffers.clear();
    }
}

fn align_up(x: u64, a: u64) -> u64 {
    x.div_ceil(a) * a
}

fn device_address(s: &Shared, buffer: &Buffer) -> u64 {
    // SAFETY: a live buffer created with SHADER_DEVICE_ADDRESS usage on a device with the
    // bufferDeviceAddress feature (every buffer of this module).
    unsafe { s.device.get_buffer_device_address(&vk::BufferDeviceAddressInfo::default().buffer(buffer.raw)) }
}

fn shader_module(s: &Shared, source: &KernelSource) -> Result<vk::ShaderModule> {
    let words = source.spirv_words();
    // SAFETY: live device; the words are SPIR-V compiled by build.rs.
    unsafe { s.device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None) }
        .ctx(|| format!("shader module of {}", source.name))
}

impl Context {
    /// Builds the driver's acceleration structures over `triangles` (indices into
    /// `positions`) and the pipeline of `shaders`. Needs a context created with
    /// `ContextOptions::ray_tracing`.
    pub fn create_driver_tracer(&self, shaders: &RtShaders, positions: &[[f32; 3]], triangles: &[[u32; 3]]) -> Result<DriverTracer> {
        let s = &self.shared;
        let usage = |msg: &str| VkError::Usage { name: "driver ray tracing".into(), msg: msg.into() };
        let rt = s.ray_tracing.as_ref().ok_or_else(|| usage("the context was created without ContextOptions::ray_tracing"))?;
        if triangles.is_empty() || positions.is_empty() {
            return Err(usage("the scene has no triangles"));
        }
        if triangles.len() as u64 > rt.max_primitives {
            return Err(usage(&format!(
                "{} triangles exceed the {} one acceleration structure of this driver holds",
                triangles.len(),
                rt.max_primitives
            )));
        }
        let mut t = DriverTracer {
            shared: s.clone(),
            blas: vk::AccelerationStructureKHR::null(),
            tlas: vk::AccelerationStructureKHR::null(),
            set_layout: vk::DescriptorSetLayout::null(),
            pipeline_layout: vk::PipelineLayout::null(),
            pipeline: vk::Pipeline::null(),
            regions: [vk::StridedDeviceAddressRegionKHR::default(); 4],
            bindings: [shaders.tlas_binding, shaders.rays_binding, shaders.hits_binding],
            push_size: shaders.push_size,
            blas_build_ms: 0.0,
            blas_bytes: 0,
            buffers: Vec::new(),
        };
        let sda = vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS;
        let input = vk::BufferUsageFlags::ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_KHR | sda;

        // Build inputs: vertices and indices on the device.
        let vertices = self.upload_buffer_with_usage("rt.vertices", positions, input)?;
        let indices = self.upload_buffer_with_usage("rt.indices", triangles, input)?;

        // Bottom level: the triangles, opaque (no any-hit shader), built for fast tracing.
        let tris = vk::AccelerationStructureGeometryTrianglesDataKHR::default()
            .vertex_format(vk::Format::R32G32B32_SFLOAT)
            .vertex_data(vk::DeviceOrHostAddressConstKHR { device_address: device_address(s, &vertices) })
            .vertex_stride(12)
            .max_vertex(positions.len() as u32 - 1)
            .index_type(vk::IndexType::UINT32)
            .index_data(vk::DeviceOrHostAddressConstKHR { device_address: device_address(s, &indices) });
        let blas_geometry = [vk::AccelerationStructureGeometryKHR::default()
            .geometry_type(vk::GeometryTypeKHR::TRIANGLES)
            .geometry(vk::AccelerationStructureGeometryDataKHR { triangles: tris })
            .flags(vk::GeometryFlagsKHR::OPAQUE)];
        let (blas, blas_buffer, blas_scratch) =
            create_structure(self, rt, vk::AccelerationStructureTypeKHR::BOTTOM_LEVEL, &blas_geometry, triangles.len() as u32, "rt.blas")?;
        t.blas = blas;
        t.blas_bytes = blas_buffer.size();
        let blas_address = {
            let info = vk::AccelerationStructureDeviceAddressInfoKHR::default().acceleration_structure(t.blas);
            // SAFETY: a live acceleration structure of this device.
            unsafe { rt.accel.get_acceleration_structure_device_address(&info) }
        };
        t.buffers.push(blas_buffer);

        // Top level: the bottom level once, identity transform, no face culling.
        let instance = vk::AccelerationStructureInstanceKHR {
            transform: vk::TransformMatrixKHR { matrix: [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0] },
            instance_custom_index_and_mask: vk::Packed24_8::new(0, 0xff),
            instance_shader_binding_table_record_offset_and_flags: vk::Packed24_8::new(
                0,
                vk::GeometryInstanceFlagsKHR::TRIANGLE_FACING_CULL_DISABLE.as_raw() as u8,
            ),
            acceleration_structure_reference: vk::AccelerationStructureReferenceKHR { device_handle: blas_address },
        };
        // SAFETY: a plain #[repr(C)] struct of floats and integers, read as its bytes.
        let instance_bytes = unsafe {
            std::slice::from_raw_parts(
                (&instance as *const vk::AccelerationStructureInstanceKHR).cast::<u8>(),
                std::mem::size_of::<vk::AccelerationStructureInstanceKHR>(),
            )
        };
        let mut instances = self.create_buffer_with_usage("rt.instances", instance_bytes.len() as u64, Memory::Upload, input)?;
        instances.write(0, instance_bytes)?;
        let inst_data = vk::AccelerationStructureGeometryInstancesDataKHR::default()
            .array_of_pointers(false)
            .data(vk::DeviceOrHostAddressConstKHR { device_address: device_address(s, &instances) });
        let tlas_geometry = [vk::AccelerationStructureGeometryKHR::default()
            .geometry_type(vk::GeometryTypeKHR::INSTANCES)
            .geometry(vk::AccelerationStructureGeometryDataKHR { instances: inst_data })];
        let (tlas, tlas_buffer, tlas_scratch) =
            create_structure(self, rt, vk::AccelerationStructureTypeKHR::TOP_LEVEL, &tlas_geometry, 1, "rt.tlas")?;
        t.tlas = tlas;
        t.buffers.push(tlas_buffer);

        // Both builds in one submission, the bottom level timed.
        let timer = self.create_timer("rt.build_timer", 2)?;
        self.submit("build acceleration structures", |rec| {
            rec.reset_timer(&timer);
            rec.timestamp(&timer, 0);
            record_build(
                rec,
                rt,
                &blas_geometry,
                t.blas,
                vk::AccelerationStructureTypeKHR::BOTTOM_LEVEL,
                &blas_scratch,
                triangles.len() as u32,
            );
            rec.timestamp(&timer, 1);
            record_build(rec, rt, &tlas_geometry, t.tlas, vk::AccelerationStructureTypeKHR::TOP_LEVEL, &tlas_scratch, 1);
            Ok(())
        })?;
        t.blas_build_ms = timer.elapsed_ns(0, 1)? * 1e-6;
        drop((vertices, indices, instances, blas_scratch, tlas_scratch));

        // The pipeline: ray generation reads the rays and writes the hits.
        let stages_flags = vk::ShaderStageFlags::RAYGEN_KHR;
        let layout_bindings = [
            vk::DescriptorSetLayoutBinding::default()
                .binding(shaders.tlas_binding)
                .descriptor_type(vk::DescriptorType::ACCELERATION_STRUCTURE_KHR)
                .descriptor_count(1)
                .stage_flags(stages_flags),
            vk::DescriptorSetLayoutBinding::default()
                .binding(shaders.rays_binding)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(1)
                .stage_flags(stages_flags),
            vk::DescriptorSetLayoutBinding::default()
                .binding(shaders.hits_binding)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(1)
                .stage_flags(stages_flags),
        ];
        let set_info = vk::DescriptorSetLayoutCreateInfo::default()
            .flags(vk::DescriptorSetLayoutCreateFlags::PUSH_DESCRIPTOR_KHR)
            .bindings(&layout_bindings);
        // SAFETY: live device, valid create info; destroyed by DriverTracer::drop.
        t.set_layout = unsafe { s.device.create_descriptor_set_layout(&set_info, None) }.ctx(|| "rt descriptor set layout".into())?;
        s.name(t.set_layout, "rt.set_layout");
        let ranges = [vk::PushConstantRange { stage_flags: stages_flags, offset: 0, size: shaders.push_size }];
        let set_layouts = [t.set_layout];
        let mut pl_info = vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts);
        if shaders.push_size > 0 {
            pl_info = pl_info.push_constant_ranges(&ranges);
        }
        // SAFETY: as above.
        t.pipeline_layout = unsafe { s.device.create_pipeline_layout(&pl_info, None) }.ctx(|| "rt pipeline layout".into())?;
        s.name(t.pipeline_layout, "rt.pipeline_layout");

        let sources = [shaders.raygen, shaders.miss, shaders.closest_hit];
        let mut modules = Vec::new();
        for src in sources {
            match shader_module(s, src) {
                Ok(m) => modules.push(m),
                Err(e) => {
                    // SAFETY: modules made above, used by nothing yet.
                    modules.iter().for_each(|&m| unsafe { s.device.destroy_shader_module(m, None) });
                    return Err(e);
                }
            }
        }
        let kinds = [vk::ShaderStageFlags::RAYGEN_KHR, vk::ShaderStageFlags::MISS_KHR, vk::ShaderStageFlags::CLOSEST_HIT_KHR];
        let stages: Vec<_> = modules
            .iter()
            .zip(kinds)
            .map(|(&m, k)| vk::PipelineShaderStageCreateInfo::default().stage(k).module(m).name(c"main"))
            .collect();
        let general = |i: u32| {
            vk::RayTracingShaderGroupCreateInfoKHR::default()
                .ty(vk::RayTracingShaderGroupTypeKHR::GENERAL)
                .general_shader(i)
                .closest_hit_shader(vk::SHADER_UNUSED_KHR)
                .any_hit_shader(vk::SHADER_UNUSED_KHR)
                .intersection_shader(vk::SHADER_UNUSED_KHR)
        };
        let groups = [
            general(0),
            general(1),
            vk::RayTracingShaderGroupCreateInfoKHR::default()
                .ty(vk::RayTracingShaderGroupTypeKHR::TRIANGLES_HIT_GROUP)
                .general_shader(vk::SHADER_UNUSED_KHR)
                .closest_hit_shader(2)
                .any_hit_shader(vk::SHADER_UNUSED_KHR)
                .intersection_shader(vk::SHADER_UNUSED_KHR),
        ];
        let info = [vk::RayTracingPipelineCreateInfoKHR::default()
            .stages(&stages)
            .groups(&groups)
            .max_pipeline_ray_recursion_depth(1)
            .layout(t.pipeline_layout)];
        // SAFETY: live device; stages, groups and layout are valid and outlive the call.
        let created =
            unsafe { rt.pipeline.create_ray_tracing_pipelines(vk::DeferredOperationKHR::null(), vk::PipelineCache::null(), &info, None) };
        // SAFETY: the modules are no longer needed once the pipeline is created (or failed).
        modules.iter().for_each(|&m| unsafe { s.device.destroy_shader_module(m, None) });
        t.pipeline = match created {
            Ok(p) => p[0],
            Err((_, result)) => return Err(VkError::Vk { what: "ray-tracing pipeline (glsl/rt/)".into(), result }),
        };
        s.name(t.pipeline, "rt.pipeline");

        // Shader binding table: one record per group, each region at the base alignment.
        let (hs, ha, ba) = (rt.handle_size as u64, rt.handle_alignment as u64, rt.base_alignment as u64);
        // SAFETY: a live ray-tracing pipeline with 3 groups.
        let handles = unsafe { rt.pipeline.get_ray_tracing_shader_group_handles(t.pipeline, 0, 3, (3 * hs) as usize) }
            .ctx(|| "shader group handles".into())?;
        let stride = align_up(hs, ha);
        let region = align_up(stride, ba);
        let mut sbt = self.create_buffer_with_usage(
            "rt.shader_binding_table",
            3 * region + ba,
            Memory::Upload,
            vk::BufferUsageFlags::SHADER_BINDING_TABLE_KHR | sda,
        )?;
        let base = device_address(s, &sbt);
        let first = align_up(base, ba);
        for g in 0..3u64 {
            sbt.write(first - base + g * region, &handles[(g * hs) as usize..((g + 1) * hs) as usize])?;
        }
        for g in 0..3 {
            t.regions[g] = vk::StridedDeviceAddressRegionKHR { device_address: first + g as u64 * region, stride, size: stride };
        }
        t.buffers.push(sbt);
        Ok(t)
    }
}

/// Sizes and creates an acceleration structure and its scratch buffer (aligned as the
/// driver asks); the build is recorded later by `record_build`.
fn create_structure(
    ctx: &Context,
    rt: &RtDevice,
    ty: vk::AccelerationStructureTypeKHR,
    geometry: &[vk::AccelerationStructureGeometryKHR],
    primitives: u32,
    name: &str,
) -> Result<(vk::AccelerationStructureKHR, Buffer, Buffer)> {
    let s = &ctx.shared;
    let build = vk::AccelerationStructureBuildGeometryInfoKHR::default()
        .ty(ty)
        .flags(vk::BuildAccelerationStructureFlagsKHR::PREFER_FAST_TRACE)
        .mode(vk::BuildAccelerationStructureModeKHR::BUILD)
        .geometries(geometry);
    let mut sizes = vk::AccelerationStructureBuildSizesInfoKHR::default();
    // SAFETY: live device; `build` describes valid geometry with one primitive count per geometry.
    unsafe {
        rt.accel.get_acceleration_structure_build_sizes(vk::AccelerationStructureBuildTypeKHR::DEVICE, &build, &[primitives], &mut sizes)
    };
    let sda = vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS;
    let buffer = ctx.create_buffer_with_usage(
        name,
        sizes.acceleration_structure_size,
        Memory::Device,
        vk::BufferUsageFlags::ACCELERATION_STRUCTURE_STORAGE_KHR | sda,
    )?;
    let scratch = ctx.create_buffer_with_usage(
        &format!("{name}.scratch"),
        sizes.build_scratch_size + rt.scratch_alignment as u64,
        Memory::Device,
        sda,
    )?;
    let info = vk::AccelerationStructureCreateInfoKHR::default().buffer(buffer.raw).size(sizes.acceleration_structure_size).ty(ty);
    // SAFETY: live device; the buffer is large enough and has acceleration-structure storage usage.
    let raw = unsafe { rt.accel.create_acceleration_structure(&info, None) }.ctx(|| format!("acceleration structure {name}"))?;
    s.name(raw, name);
    Ok((raw, buffer, scratch))
}

/// Records the build of `dst` from `geometry`, then a barrier that makes it visible to later
/// builds and to ray tracing.
fn record_build(
    rec: &mut Recorder,
    rt: &RtDevice,
    geometry: &[vk::AccelerationStructureGeometryKHR],
    dst: vk::AccelerationStructureKHR,
    ty: vk::AccelerationStructureTypeKHR,
    scratch: &Buffer,
    primitives: u32,
) {
    let scratch_address = align_up(device_address(rec.shared, scratch), rt.scratch_alignment as u64);
    let build = [vk::AccelerationStructureBuildGeometryInfoKHR::default()
        .ty(ty)
        .flags(vk::BuildAccelerationStructureFlagsKHR::PREFER_FAST_TRACE)
        .mode(vk::BuildAccelerationStructureModeKHR::BUILD)
        .geometries(geometry)
        .dst_acceleration_structure(dst)
        .scratch_data(vk::DeviceOrHostAddressKHR { device_address: scratch_address })];
    let range = [vk::AccelerationStructureBuildRangeInfoKHR { primitive_count: primitives, ..Default::default() }];
    let stage = vk::PipelineStageFlags::ACCELERATION_STRUCTURE_BUILD_KHR;
    let mb = [vk::MemoryBarrier::default()
        .src_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_WRITE_KHR)
        .dst_access_mask(vk::AccessFlags::ACCELERATION_STRUCTURE_READ_KHR)];
    // SAFETY: recording state; the structure, scratch and inputs live until the submission
    // completes (Context::submit waits).
    unsafe {
        rt.accel.cmd_build_acceleration_structures(rec.cmd, &build, &[&range]);
        rec.shared.device.cmd_pipeline_barrier(
            rec.cmd,
            stage,
            stage | vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR,
            vk::DependencyFlags::empty(),
            &mb,
            &[],
            &[],
        );
    }
}

impl Recorder<'_> {
    /// Traces `count` rays of `rays` (GpuRay) through the driver's pipeline into `hits`
    /// (GpuHit), with the ray-generation push constants `push`.
    pub fn trace_rays_driver(&mut self, t: &DriverTracer, rays: &Buffer, hits: &Buffer, push: &[u8], count: u32) -> Result<()> {
        let s = self.shared;
        let rt =
            s.ray_tracing.as_ref().ok_or_else(|| VkError::Usage { name: "driver ray tracing".into(), msg: "no ray tracing".into() })?;
        if push.len() as u32 != t.push_size {
            return Err(VkError::Usage {
                name: "driver ray tracing".into(),
                msg: format!("push constants of {} bytes given, the pipeline declares {}", push.len(), t.push_size),
            });
        }
        if count > rt.max_invocations {
            return Err(VkError::Usage {
                name: "driver ray tracing".into(),
                msg: format!("{count} rays exceed the driver's {} per launch", rt.max_invocations),
            });
        }
        let tlas = [t.tlas];
        let mut as_write = vk::WriteDescriptorSetAccelerationStructureKHR::default().acceleration_structures(&tlas);
        let ray_info = [vk::DescriptorBufferInfo { buffer: rays.raw, offset: 0, range: vk::WHOLE_SIZE }];
        let hit_info = [vk::DescriptorBufferInfo { buffer: hits.raw, offset: 0, range: vk::WHOLE_SIZE }];
        let writes = [
            vk::WriteDescriptorSet::default()
                .dst_binding(t.bindings[0])
                .descriptor_type(vk::DescriptorType::ACCELERATION_STRUCTURE_KHR)
                .descriptor_count(1)
                .push_next(&mut as_write),
            vk::WriteDescriptorSet::default()
                .dst_binding(t.bindings[1])
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&ray_info),
            vk::WriteDescriptorSet::default()
                .dst_binding(t.bindings[2])
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&hit_info),
        ];
        let compute = vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER;
        let trace = vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR;
        let rw = vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE;
        let before = [vk::MemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE | vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(rw | vk::AccessFlags::ACCELERATION_STRUCTURE_READ_KHR)];
        let after = [vk::MemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE)
            .dst_access_mask(rw | vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE)];
        let d = &s.device;
        // SAFETY: recording state; pipeline, layout, structures and buffers are live for the
        // submission (Context::submit waits for it).
        unsafe {
            d.cmd_pipeline_barrier(self.cmd, compute, trace, vk::DependencyFlags::empty(), &before, &[], &[]);
            d.cmd_bind_pipeline(self.cmd, vk::PipelineBindPoint::RAY_TRACING_KHR, t.pipeline);
            s.push_descriptor.cmd_push_descriptor_set(self.cmd, vk::PipelineBindPoint::RAY_TRACING_KHR, t.pipeline_layout, 0, &writes);
            if !push.is_empty() {
                d.cmd_push_constants(self.cmd, t.pipeline_layout, vk::ShaderStageFlags::RAYGEN_KHR, 0, push);
            }
            if count > 0 {
                rt.pipeline.cmd_trace_rays(self.cmd, &t.regions[0], &t.regions[1], &t.regions[2], &t.regions[3], count, 1, 1);
            }
            d.cmd_pipeline_barrier(self.cmd, trace, compute, vk::DependencyFlags::empty(), &after, &[], &[]);
        }
        self.mark("rt_trace", 1);
        Ok(())
    }
}
