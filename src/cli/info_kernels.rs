//! `bidir info --kernels`: every integrator's kernels compiled for a scene on the chosen
//! device, with the driver's compile statistics (registers, spills, shared memory, ...), the
//! first thing to read when a kernel is slower than its work explains.

use super::scene_args::SceneArgs;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::vk::{Context, ContextOptions};

pub fn run(
    scene_args: &SceneArgs,
    layout: Option<bidir::bvh::BvhLayout>,
    shadow_queue: Option<Option<bidir::render::ShadowQueue>>,
    opts: &ContextOptions,
) -> anyhow::Result<()> {
    let loaded = scene_args.load()?;
    let mut opts = opts.clone();
    opts.kernel_statistics = true;
    let ctx = Context::new(&opts)?;
    println!("device: {}", ctx.info().name);
    if !ctx.info().kernel_statistics {
        println!("  the driver does not offer VK_KHR_pipeline_executable_properties: no kernel statistics");
        return Ok(());
    }
    // Each integrator over `layout`, or the BVH layout it renders with by default (`--bvh
    // auto`); the BVH is rebuilt only where that layout changes.
    let integrators = [
        Integrator::Pt,
        Integrator::PtNee,
        Integrator::Bdpt(Join::DEFAULT),
        Integrator::Bdpt(Join::Full),
        Integrator::Vcm(bidir::render::vcm::VcmMode::FULL),
        Integrator::Vcm(bidir::render::vcm::VcmMode::MERGE_ALL),
    ];
    let mut settings = RenderSettings::new(integrators[0]);
    settings.bvh_layout = layout;
    settings.shadow_queue = shadow_queue;
    let mut r = Renderer::new(&ctx, &loaded.scene, &loaded.camera, settings)?;
    for integrator in integrators {
        r.switch_integrator(&loaded.scene, &loaded.camera, integrator)?;
        for kernel in r.kernels() {
            let stats = kernel.statistics()?;
            let mut line: Vec<String> = stats.iter().map(|s| format!("{} {}", s.name, s.value)).collect();
            let bvh = r.settings().bvh.layout.name();
            let wg = kernel.local_size()[0];
            let registers = stats.iter().find(|s| s.name == "Register Count").and_then(|s| s.value.parse::<u32>().ok());
            if let (Some(regs), true) = (registers, ctx.info().warps_per_sm > 0) {
                let warps = resident_warps_by_registers(regs, wg.div_ceil(32), ctx.info().warps_per_sm);
                line.push(format!("resident warps by registers {warps} of {}", ctx.info().warps_per_sm));
            }
            println!(
                "{} / {} over {bvh}, workgroups of {wg} ({} statistics): {}",
                integrator.name(),
                kernel.name(),
                stats.len(),
                line.join("; ")
            );
        }
    }
    Ok(())
}

/// Warps a streaming multiprocessor keeps resident by its register file alone, for a kernel of
/// `registers` registers a lane in workgroups of `group_warps` warps, at most `max_warps` (the
/// device's, VK_NV_shader_sm_builtins): NVIDIA's SMs hold 65,536 32-bit registers and give
/// each warp a multiple of 256, and a workgroup is resident whole. Shared memory may allow
/// fewer. On a Hopper SM (64 warps) 56 registers keep 36 warps, 72 keep 28, 96 keep 20.
fn resident_warps_by_registers(registers: u32, group_warps: u32, max_warps: u32) -> u32 {
    const REGISTER_FILE: u32 = 65_536;
    const WARP_UNIT: u32 = 256;
    let per_warp = (registers.max(1) * 32).div_ceil(WARP_UNIT) * WARP_UNIT;
    let group = group_warps.max(1);
    (REGISTER_FILE / per_warp).min(max_warps) / group * group
}

#[cfg(test)]
mod tests {
    use super::resident_warps_by_registers;

    #[test]
    fn registers_bound_the_resident_warps() {
        // Hopper, workgroups of 64 lanes (2 warps): bidir's kernels as the driver compiled them.
        assert_eq!(resident_warps_by_registers(56, 2, 64), 36);
        assert_eq!(resident_warps_by_registers(72, 2, 64), 28);
        assert_eq!(resident_warps_by_registers(96, 2, 64), 20);
        // Few registers: the SM's own limit; whole workgroups of 16 warps only.
        assert_eq!(resident_warps_by_registers(16, 2, 64), 64);
        assert_eq!(resident_warps_by_registers(72, 16, 64), 16);
        // Registers rounded to the warp's unit of 256: 57 take what 64 take.
        assert_eq!(resident_warps_by_registers(57, 1, 64), 32);
    }
}
