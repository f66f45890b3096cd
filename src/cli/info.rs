use anyhow::Context as _;
use bidir::vk::{self, ContextOptions};

use super::scene_args::SceneArgs;

#[derive(clap::Args, Debug)]
pub struct InfoArgs {
    /// Report on the built-in Cornell box
    #[arg(long, conflicts_with = "scene")]
    pub builtin: bool,
    /// Compile every integrator's kernels for the scene (or the built-in Cornell box) on the
    /// chosen device and print the driver's statistics of each: registers, spills, shared
    /// memory (VK_KHR_pipeline_executable_properties, where the driver offers it)
    #[arg(long)]
    pub kernels: bool,
    /// With --kernels: the BVH layout to compile them for, bvh2 | cwbvh | bvh4 [default: each
    /// integrator's own, as `render --bvh auto` picks it]
    #[arg(long, requires = "kernels")]
    pub bvh: Option<bidir::bvh::BvhLayout>,
    /// With --kernels: the shadow-ray queue as `render --shadow-queue` takes it
    #[arg(long, requires = "kernels", default_value = "auto", value_name = "auto|off|SLOTS[/SAMPLES][/pause]")]
    pub shadow_queue: String,
    #[command(flatten)]
    pub scene: SceneArgs,
}

fn gib(bytes: u64) -> String {
    format!("{:.1} GiB", bytes as f64 / (1u64 << 30) as f64)
}

pub fn run(args: &InfoArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    if args.kernels {
        return super::info_kernels::run(&args.scene, args.bvh, super::settings_args::parse_shadow_queue(&args.shadow_queue)?, opts);
    }
    if let Some(p) = args.scene.scene.as_ref().filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr"))) {
        return super::merge::info(p);
    }
    if args.builtin || args.scene.scene.is_some() {
        return super::info_scene::run(&args.scene);
    }
    if args.scene.has_camera_flags() || args.scene.strict || !args.scene.added_lights().is_empty() {
        anyhow::bail!("camera flags, light flags and --strict need a scene: give a scene file or --builtin");
    }
    devices(opts)
}

fn devices(opts: &ContextOptions) -> anyhow::Result<()> {
    let devices = vk::list_devices().context("cannot list Vulkan devices")?;
    if devices.is_empty() {
        return Err(vk::VkError::NoDevice.into());
    }
    let chosen = vk::choose_device(&devices, opts.device.as_deref());
    for d in &devices {
        let mark = match &chosen {
            Ok(i) if devices[*i].index == d.index => "  <- bidir uses this one",
            _ => "",
        };
        println!("device {}: {} ({}){mark}", d.index, d.name, d.type_name());
        println!("  driver:        {} {}", d.driver_name, d.driver_info);
        println!("  Vulkan:        {}", d.api_string());
        let sg_range = if d.min_subgroup_size != d.max_subgroup_size {
            format!(" (size control {}..{})", d.min_subgroup_size, d.max_subgroup_size)
        } else {
            String::new()
        };
        println!("  subgroup:      size {}{sg_range}; ops: {}", d.subgroup_size, d.subgroup_ops.names().join(" "));
        let heaps: Vec<String> =
            d.memory_heaps.iter().map(|h| format!("{}{}", gib(h.bytes), if h.device_local { " device-local" } else { " host" })).collect();
        println!("  memory heaps:  {}", heaps.join(", "));
        if d.sm_count > 0 {
            // The persistent trace kernels' default launch fills these (`trace::default_persistent_groups`).
            println!("  processors:    {} streaming multiprocessors, up to {} resident warps each", d.sm_count, d.warps_per_sm);
        }
        println!(
            "  limits:        storage buffer {} MiB, shared memory {} KiB, workgroup {} invocations, timestamps {} bits @ {} ns",
            d.max_storage_buffer_range / (1 << 20),
            d.max_shared_memory / 1024,
            d.max_workgroup_invocations,
            d.timestamp_valid_bits,
            d.timestamp_period_ns
        );
        println!(
            "  features:      atomic float add {}, int64 {}, driver ray tracing {}, kernels without buffer bounds checks {}",
            if d.atomic_float_add { "yes" } else { "no" },
            if d.shader_int64 { "yes" } else { "no" },
            if d.ray_tracing_pipeline { "yes (bench traversal --driver-rt)" } else { "no" },
            if d.pipeline_robustness { "yes (BIDIR_BUFFER_CHECKS=1 keeps them)" } else { "no" }
        );
        if !d.usable() {
            println!("  not usable:    lacks {}", d.missing.join(", "));
        }
    }
    chosen.context("no device can be used")?;
    Ok(())
}
