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
            let line: Vec<String> = stats.iter().map(|s| format!("{} {}", s.name, s.value)).collect();
            let bvh = r.settings().bvh.layout.name();
            let wg = kernel.local_size()[0];
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
