//! Compute pipelines whose descriptor-set layout, push-constant range and workgroup size
//! are read from their own SPIR-V: a kernel's bindings are declared once, in GLSL, with the
//! indices from `gpu::abi`. Resources are bound with push descriptors, so no pools or sets
//! are managed per pass.

use super::{
    context::{Context, Shared},
    error::{Result, VkError, VkResultExt},
    reflect::{Module, ReflectedBinding},
};
use ash::vk;
use std::sync::Arc;

/// One compiled compute kernel: its SPIR-V, embedded by build.rs (`gpu::kernels` lists them).
#[derive(Clone, Copy, Debug)]
pub struct KernelSource {
    /// File stem, e.g. `reduce_sum`; also its debug name.
    pub name: &'static str,
    /// Source path relative to the crate root.
    pub file: &'static str,
    /// SPIR-V words as bytes (not necessarily 4-byte aligned; use `spirv_words`).
    pub spirv: &'static [u8],
}

impl KernelSource {
    /// The SPIR-V as aligned 32-bit words.
    pub fn spirv_words(&self) -> Vec<u32> {
        self.spirv.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
    }
}

/// A compiled compute pipeline. Clones share it: a [`Context`] compiles each kernel once
/// per specialisation and hands the same pipeline to every later `create_kernel` asking for it
/// (a renderer created again with the same settings compiles nothing; on lavapipe under the
/// validation layers a megakernel's pipeline takes 1-3 s to create).
#[derive(Clone)]
pub struct Kernel(pub(crate) Arc<Compiled>);

/// What a [`Kernel`] shares: the pipeline and what was read from its SPIR-V.
pub(crate) struct Compiled {
    shared: Arc<Shared>,
    name: String,
    pub(crate) set_layout: vk::DescriptorSetLayout,
    pub(crate) pipeline_layout: vk::PipelineLayout,
    pub(crate) pipeline: vk::Pipeline,
    bindings: Vec<ReflectedBinding>,
    push_size: u32,
    local_size: [u32; 3],
    /// How long the driver took to make the shader module and the pipeline.
    build_time: std::time::Duration,
}

/// One compile statistic of a kernel, as the driver names it (e.g. NVIDIA's "Register
/// Count", Mesa's "Private memory"), from VK_KHR_pipeline_executable_properties.
#[derive(Clone, Debug)]
pub struct KernelStatistic {
    /// The executable (shader stage) it belongs to.
    pub executable: String,
    pub name: String,
    pub value: String,
    pub description: String,
}

impl Kernel {
    /// The driver's compile statistics of this kernel (registers, spills, shared memory, ...);
    /// empty unless the context was created with `ContextOptions::kernel_statistics` on a
    /// device that offers them (`DeviceInfo::kernel_statistics`).
    pub fn statistics(&self) -> Result<Vec<KernelStatistic>> {
        let Some(pe) = &self.0.shared.pipeline_executables else { return Ok(Vec::new()) };
        let text = |c: &[std::ffi::c_char]| {
            // SAFETY: the driver writes NUL-terminated strings into these fixed-size arrays.
            unsafe { std::ffi::CStr::from_ptr(c.as_ptr()) }.to_string_lossy().into_owned()
        };
        let k = &self.0;
        let info = vk::PipelineInfoKHR::default().pipeline(k.pipeline);
        // SAFETY: a live pipeline of this device, created with CAPTURE_STATISTICS_KHR.
        let executables = unsafe { pe.get_pipeline_executable_properties(&info) }.ctx(|| format!("executables of kernel {}", k.name))?;
        let mut out = Vec::new();
        for (i, exe) in executables.iter().enumerate() {
            let ei = vk::PipelineExecutableInfoKHR::default().pipeline(k.pipeline).executable_index(i as u32);
            // SAFETY: as above; `i` is below the executable count just returned.
            let stats = unsafe { pe.get_pipeline_executable_statistics(&ei) }.ctx(|| format!("statistics of kernel {}", k.name))?;
            for st in &stats {
                // SAFETY: `format` says which member of the union the driver wrote.
                let value = unsafe {
                    match st.format {
                        vk::PipelineExecutableStatisticFormatKHR::BOOL32 => (st.value.b32 == vk::TRUE).to_string(),
                        vk::PipelineExecutableStatisticFormatKHR::INT64 => st.value.i64.to_string(),
                        vk::PipelineExecutableStatisticFormatKHR::UINT64 => st.value.u64.to_string(),
                        vk::PipelineExecutableStatisticFormatKHR::FLOAT64 => format!("{:.3}", st.value.f64),
                        _ => "?".into(),
                    }
                };
                out.push(KernelStatistic { executable: text(&exe.name), name: text(&st.name), value, description: text(&st.description) });
            }
        }
        Ok(out)
    }

    pub fn name(&self) -> &str {
        &self.0.name
    }
    /// Whether `self` and `other` are the same compiled pipeline (one `create_kernel` result
    /// and its clones, or a later call with the same source and constants).
    pub fn same_pipeline(&self, other: &Kernel) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
    /// Descriptor bindings the kernel uses (reflected from its SPIR-V).
    pub fn bindings(&self) -> &[ReflectedBinding] {
        &self.0.bindings
    }
    /// Push-constant bytes the kernel expects.
    pub fn push_size(&self) -> u32 {
        self.0.push_size
    }
    /// `local_size_{x,y,z}` of the kernel.
    pub fn local_size(&self) -> [u32; 3] {
        self.0.local_size
    }
    /// How long the driver took to build the pipeline (its shader module and pipeline
    /// creation), when this context first asked for this source and these constants: the
    /// part of a renderer's setup a kernel costs (`bidir bench render` prints it). A driver
    /// with a cache of its own (NVIDIA's, Mesa's for machine code) is faster the second time.
    pub fn build_time(&self) -> std::time::Duration {
        self.0.build_time
    }
    /// Workgroups needed to cover `n` invocations along x.
    pub fn groups_for(&self, n: u32) -> u32 {
        n.div_ceil(self.0.local_size[0].max(1))
    }
}

impl Drop for Compiled {
    fn drop(&mut self) {
        if self.shared.poisoned.load(std::sync::atomic::Ordering::SeqCst) {
            return;
        }
        // SAFETY: submissions complete before returning; nothing uses the pipeline now.
        unsafe {
            self.shared.device.destroy_pipeline(self.pipeline, None);
            self.shared.device.destroy_pipeline_layout(self.pipeline_layout, None);
            self.shared.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}

/// What identifies a compiled kernel in a [`Context`]'s cache: its source (name and
/// embedded SPIR-V) and specialisation constants.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub(crate) struct KernelKey {
    name: &'static str,
    spirv: (usize, usize),
    specs: Vec<(u32, u32)>,
}

/// A specialisation constant: `layout(constant_id = id) const uint NAME = default;`.
#[derive(Clone, Copy, Debug)]
pub struct Spec {
    pub id: u32,
    pub value: u32,
}

impl Context {
    /// The pipeline for an embedded kernel, with specialisation constants: built on the first
    /// call for this source and these constants (in this order), shared after.
    pub fn create_kernel(&self, source: &KernelSource, specs: &[Spec]) -> Result<Kernel> {
        let key = KernelKey {
            name: source.name,
            spirv: (source.spirv.as_ptr() as usize, source.spirv.len()),
            specs: specs.iter().map(|sp| (sp.id, sp.value)).collect(),
        };
        if let Some(k) = self.kernels.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return Ok(k.clone());
        }
        let kernel = Kernel(Arc::new(self.compile_kernel(source, specs)?));
        self.kernels.lock().unwrap_or_else(|e| e.into_inner()).insert(key, kernel.clone());
        Ok(kernel)
    }

    fn compile_kernel(&self, source: &KernelSource, specs: &[Spec]) -> Result<Compiled> {
        let s = &self.shared;
        let kerr = |msg: String| VkError::Kernel { kernel: source.name.into(), msg };
        let words = source.spirv_words();
        let module = Module::parse(&words).map_err(kerr)?;
        let bindings = module.bindings().map_err(kerr)?;
        let push_size = module.push_constant_size();
        let local_size = module.local_size().unwrap_or([1, 1, 1]);

        let descriptors: u32 = bindings.iter().map(|b| b.count).sum();
        if descriptors > s.info.max_kernel_descriptors {
            return Err(kerr(format!(
                "binds {descriptors} descriptors; {} binds at most {} in one kernel (maxPushDescriptors, maxPerStageDescriptorStorageBuffers): the kernel must use fewer buffers",
                s.info.name, s.info.max_kernel_descriptors
            )));
        }
        let layout_bindings: Vec<_> = bindings
            .iter()
            .map(|b| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(b.binding)
                    .descriptor_type(b.descriptor_type)
                    .descriptor_count(b.count)
                    .stage_flags(vk::ShaderStageFlags::COMPUTE)
            })
            .collect();
        let set_info = vk::DescriptorSetLayoutCreateInfo::default()
            .flags(vk::DescriptorSetLayoutCreateFlags::PUSH_DESCRIPTOR_KHR)
            .bindings(&layout_bindings);
        // SAFETY: live device, valid create infos; every object is destroyed by Kernel::drop
        // or on the error paths below.
        unsafe {
            let set_layout =
                s.device.create_descriptor_set_layout(&set_info, None).ctx(|| format!("descriptor set layout of {}", source.name))?;
            let ranges = [vk::PushConstantRange { stage_flags: vk::ShaderStageFlags::COMPUTE, offset: 0, size: push_size }];
            let set_layouts = [set_layout];
            let mut pl_info = vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts);
            if push_size > 0 {
                pl_info = pl_info.push_constant_ranges(&ranges);
            }
            let pipeline_layout = match s.device.create_pipeline_layout(&pl_info, None) {
                Ok(l) => l,
                Err(result) => {
                    s.device.destroy_descriptor_set_layout(set_layout, None);
                    return Err(VkError::Vk { what: format!("pipeline layout of {}", source.name), result });
                }
            };
            let t_build = std::time::Instant::now();
            let shader = match s.device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None) {
                Ok(m) => m,
                Err(result) => {
                    s.device.destroy_pipeline_layout(pipeline_layout, None);
                    s.device.destroy_descriptor_set_layout(set_layout, None);
                    return Err(VkError::Vk { what: format!("shader module of {}", source.name), result });
                }
            };
            let entries: Vec<vk::SpecializationMapEntry> = specs
                .iter()
                .enumerate()
                .map(|(i, sp)| vk::SpecializationMapEntry { constant_id: sp.id, offset: (i * 4) as u32, size: 4 })
                .collect();
            let data: Vec<u8> = specs.iter().flat_map(|sp| sp.value.to_le_bytes()).collect();
            let spec_info = vk::SpecializationInfo::default().map_entries(&entries).data(&data);
            let entry = c"main";
            let mut stage = vk::PipelineShaderStageCreateInfo::default().stage(vk::ShaderStageFlags::COMPUTE).module(shader).name(entry);
            if !specs.is_empty() {
                stage = stage.specialization_info(&spec_info);
            }
            let flags = if s.pipeline_executables.is_some() {
                vk::PipelineCreateFlags::CAPTURE_STATISTICS_KHR
            } else {
                vk::PipelineCreateFlags::empty()
            };
            let mut robustness = vk::PipelineRobustnessCreateInfoEXT::default()
                .storage_buffers(vk::PipelineRobustnessBufferBehaviorEXT::DISABLED)
                .uniform_buffers(vk::PipelineRobustnessBufferBehaviorEXT::DISABLED);
            let mut info = vk::ComputePipelineCreateInfo::default().stage(stage).layout(pipeline_layout).flags(flags);
            if super::context::unchecked_buffers(&s.info) {
                info = info.push_next(&mut robustness);
            }
            let info = [info];
            let result = s.device.create_compute_pipelines(vk::PipelineCache::null(), &info, None);
            let build_time = t_build.elapsed();
            s.device.destroy_shader_module(shader, None);
            let pipeline = match result {
                Ok(p) => p[0],
                Err((_, result)) => {
                    s.device.destroy_pipeline_layout(pipeline_layout, None);
                    s.device.destroy_descriptor_set_layout(set_layout, None);
                    return Err(VkError::Vk { what: format!("compute pipeline {}", source.name), result });
                }
            };
            s.name(pipeline, source.name);
            s.name(pipeline_layout, &format!("{}.layout", source.name));
            s.name(set_layout, &format!("{}.set_layout", source.name));
            Ok(Compiled {
                shared: s.clone(),
                name: source.name.into(),
                set_layout,
                pipeline_layout,
                pipeline,
                bindings,
                push_size,
                local_size,
                build_time,
            })
        }
    }
}
