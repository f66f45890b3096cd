//! The GPU ABI: every struct declared in `src/gpu/abi.rs` must have, in the SPIR-V the GLSL
//! compiler produced, the same member names, offsets and array stride as in Rust. This
//! catches std430 surprises (a vec3 followed by a vec3, a vec4 after a scalar) before they
//! become wrong pixels.

use bidir::gpu::{abi, kernels};
use bidir::vk::reflect::Module;

#[test]
fn rust_structs_match_their_glsl_layout() {
    let module = Module::parse(&kernels::ABI_LAYOUT.spirv_words()).expect("abi_layout.spv parses");
    let layouts = abi::struct_layouts();
    assert!(!layouts.is_empty());
    for (name, size, fields) in layouts {
        let (members, stride) = module.struct_layout(name).unwrap_or_else(|| panic!("struct {name} missing from abi_layout.spv"));
        assert_eq!(members.len(), fields.len(), "{name}: member count");
        for (m, f) in members.iter().zip(fields) {
            assert_eq!(m.name, f.name, "{name}: member order");
            assert_eq!(m.offset as usize, f.offset, "{name}.{}: GLSL std430 offset {} but Rust offset {}", f.name, m.offset, f.offset);
        }
        assert_eq!(stride, Some(size as u32), "{name}: GLSL array stride vs Rust size_of");
    }
}

#[test]
fn every_kernel_reflects() {
    for k in kernels::ALL {
        let m = Module::parse(&k.spirv_words()).unwrap_or_else(|e| panic!("{}: {e}", k.file));
        m.bindings().unwrap_or_else(|e| panic!("{}: {e}", k.file));
        assert!(m.local_size().is_some(), "{}: workgroup size must be literal", k.file);
    }
    let reduce = Module::parse(&kernels::REDUCE_SUM.spirv_words()).unwrap();
    let b: Vec<u32> = reduce.bindings().unwrap().iter().map(|b| b.binding).collect();
    assert_eq!(b, vec![abi::REDUCE_BIND_INPUT, abi::REDUCE_BIND_OUTPUT]);
    assert_eq!(reduce.push_constant_size() as usize, std::mem::size_of::<abi::ScanPush>());
    assert_eq!(reduce.local_size(), Some([abi::SCAN_WG_SIZE, 1, 1]));
}

/// Every kernel's descriptors fit one pushed set on every device bidir runs on: a device with
/// VK_KHR_push_descriptor pushes at least 32 (its `maxPushDescriptors`; lavapipe and NVIDIA's
/// driver push exactly 32, and `maxPerStageDescriptorStorageBuffers` is also 32 on lavapipe).
/// A kernel past it is refused when created (`DeviceInfo::max_kernel_descriptors`); lavapipe
/// crashed on one before that check (session 21, a BDPT wavefront kernel at 33).
#[test]
fn every_kernel_fits_the_push_descriptor_minimum() {
    const MIN_PUSH_DESCRIPTORS: u32 = 32;
    let mut most = (0, "");
    // (glsl/tests/ holds layout probes that are reflected, never made into pipelines.)
    for k in kernels::ALL.iter().filter(|k| !k.file.starts_with("glsl/tests/")) {
        let m = Module::parse(&k.spirv_words()).unwrap();
        let n: u32 = m.bindings().unwrap().iter().map(|b| b.count).sum();
        assert!(n <= MIN_PUSH_DESCRIPTORS, "{} binds {n} descriptors, more than the {MIN_PUSH_DESCRIPTORS} every device pushes", k.file);
        most = most.max((n, k.file));
    }
    eprintln!("most descriptors in one kernel: {} ({})", most.0, most.1);
}

#[test]
fn generated_header_carries_every_constant() {
    let h = abi::header_glsl();
    assert!(h.contains(&format!("#define SCAN_WG_SIZE {}u", abi::SCAN_WG_SIZE)));
    assert!(h.contains("struct ImageAffinePush {"));
}

/// The integrator kernels share one binding space and one specialisation-constant space:
/// two `BIND_*` (or two `SPEC_*`) constants with the same number would bind one resource in
/// the place of another. (Bindings of standalone kernels carry their own prefix, such as
/// `REDUCE_BIND_*`.)
#[test]
fn binding_and_spec_ids_are_unique() {
    let glsl = abi::consts_glsl();
    for prefix in ["BIND_", "SPEC_"] {
        let mut seen = std::collections::BTreeMap::new();
        for line in glsl.lines() {
            let mut parts = line.split_whitespace().skip(1);
            let (Some(name), Some(value)) = (parts.next(), parts.next()) else { continue };
            if !name.starts_with(prefix) {
                continue;
            }
            if let Some(other) = seen.insert(value.to_string(), name.to_string()) {
                panic!("{name} and {other} are both {value}");
            }
        }
        assert!(seen.len() > 5, "{prefix}: too few constants found: {seen:?}");
    }
}

/// `gl_WorkGroupSize` is used only after the file itself declares `layout(local_size_x ...)`:
/// glslang takes it as (1, 1, 1) in code compiled before that declaration, and kernels include
/// their headers before theirs, so a header that reads it sizes with 1 (session 22: a launch's
/// successor got 64x its workgroups, which no image shows). Headers take the includer's size
/// as a macro instead (`WF_WG_SIZE` in glsl/common/wf_active.glsl).
#[test]
fn work_group_size_is_read_only_after_the_layout() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("glsl");
    let mut checked = 0;
    for dir in ["common", "kernels"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap();
            let mut declared = false;
            for (n, line) in text.lines().enumerate() {
                let code = line.split("//").next().unwrap_or("");
                declared |= code.contains("layout(local_size_x");
                if code.contains("gl_WorkGroupSize") {
                    assert!(declared, "{}:{}: gl_WorkGroupSize before this file's layout(local_size_x ...)", path.display(), n + 1);
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 0, "no use of gl_WorkGroupSize found: is the glsl/ tree where it was?");
}
