//! `bidir render`: headless progressive rendering to EXR/PNG.

use super::scene_args::SceneArgs;
use anyhow::{bail, Context as _};
use bidir::bvh::TriTest;
use bidir::film::{self, metrics};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::vk::{Context, ContextOptions};
use std::path::PathBuf;
use std::time::{Duration, Instant};

#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// pt | pt-nee | bdpt | bdpt:full | bdpt:single | bdpt:k=N
    #[arg(long, default_value = "pt-nee")]
    pub integrator: Integrator,
    /// BDPT join (overrides the one in --integrator): full | single | k=N | lvc | lvc=N.
    #[arg(long)]
    pub join: Option<Join>,
    /// Samples per pixel (default 64 unless --time is given).
    #[arg(long, conflicts_with = "time")]
    pub spp: Option<u32>,
    /// Render passes until this many seconds have passed.
    #[arg(long)]
    pub time: Option<f64>,
    #[arg(long, default_value_t = 0)]
    pub seed: u32,
    /// Random numbers: sobol (Owen-scrambled Sobol', about half the RMSE at equal spp on the
    /// Cornell box) | independent.
    #[arg(long, default_value = "sobol")]
    pub sampler: bidir::render::Sampler,
    /// Most path segments (0: unbounded; Russian roulette ends paths).
    #[arg(long, default_value_t = 0)]
    pub max_depth: u32,
    /// BDPT: light vertices kept per light path (a reservoir over the whole path).
    #[arg(long, default_value_t = 8)]
    pub light_path_len: u32,
    /// Output image(s): .exr (linear float) or .png (sRGB); may repeat.
    #[arg(short = 'o', long = "output")]
    pub outputs: Vec<PathBuf>,
    /// Exposure in stops applied to PNG output.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub exposure: f32,
    /// Ray-triangle test: watertight | woop.
    #[arg(long, default_value = "watertight")]
    pub tri_test: TriTest,
    /// Compile the mirror/glass/texture/alpha code in even where the scene has none (measures
    /// what kernel specialisation buys).
    #[arg(long)]
    pub all_features: bool,
    /// Print RMSE / mean ratio against this reference EXR at the end.
    #[arg(long)]
    pub reference: Option<PathBuf>,
}

pub fn run(args: &RenderArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    let outputs = if args.outputs.is_empty() { vec![PathBuf::from("render.png")] } else { args.outputs.clone() };
    for o in &outputs {
        match o.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("exr") | Some("png") => {}
            _ => bail!("{}: output must end in .exr or .png", o.display()),
        }
    }
    if let Some(t) = args.time {
        if !(t > 0.0 && t.is_finite()) {
            bail!("--time must be a positive number of seconds");
        }
    }
    let reference = args.reference.as_ref().map(|p| film::read_exr(p)).transpose()?;
    let loaded = args.scene.load()?;
    for w in &loaded.warnings {
        eprintln!("warning: {w}");
    }
    let camera = loaded.camera.clone();
    let mut integrator = args.integrator;
    if let (Some(j), Integrator::Bdpt(_)) = (args.join, integrator) {
        integrator = Integrator::Bdpt(j);
    } else if args.join.is_some() {
        bail!("--join applies to --integrator bdpt only");
    }
    let ctx = Context::new(opts).context("cannot start Vulkan")?;
    let mut settings = RenderSettings::new(integrator);
    settings.seed = args.seed;
    settings.sampler = args.sampler;
    settings.all_material_code = args.all_features;
    settings.max_depth = args.max_depth;
    settings.light_path_len = args.light_path_len;
    settings.bvh.tri_test = args.tri_test;
    let t_setup = Instant::now();
    let mut r = Renderer::new(&ctx, &loaded.scene, &camera, settings)?;
    let setup = t_setup.elapsed();

    let pixels = camera.width as f64 * camera.height as f64;
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:32}] {pos}/{len} {msg} (eta {eta})")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    let start = Instant::now();
    let report = |p: bidir::render::Progress| {
        let msps = p.samples as f64 * pixels / p.elapsed.as_secs_f64().max(1e-9) / 1e6;
        bar.set_message(format!("spp, {msps:.1} Msamples/s"));
    };
    match args.time {
        Some(t) => {
            bar.set_length((t * 1000.0) as u64);
            r.render_time(Duration::from_secs_f64(t), |p| {
                bar.set_position(p.elapsed.as_millis() as u64);
                report(p)
            })?;
        }
        None => {
            let spp = args.spp.unwrap_or(64);
            if spp == 0 {
                bail!("--spp must be at least 1");
            }
            bar.set_length(spp as u64);
            r.render_spp(spp, |p| {
                bar.set_position(p.samples as u64);
                report(p)
            })?;
        }
    }
    bar.finish_and_clear();
    let elapsed = start.elapsed();
    let img = r.image()?;
    let nan = r.nan_samples()?;
    for o in &outputs {
        film::write_image(o, &img, args.exposure)?;
    }
    let spp = r.samples();
    println!(
        "{} {}x{} {}: {spp} spp in {:.3} s ({:.2} Msamples/s; setup {:.2} s), {} NaN/Inf samples dropped",
        ctx.info().name,
        camera.width,
        camera.height,
        integrator.name(),
        elapsed.as_secs_f64(),
        spp as f64 * pixels / elapsed.as_secs_f64() / 1e6,
        setup.as_secs_f64(),
        nan
    );
    println!(
        "GPU memory: scene {:.1} MiB, integrator {:.1} MiB",
        r.gpu_scene().bytes as f64 / (1u64 << 20) as f64,
        r.integrator_bytes() as f64 / (1u64 << 20) as f64
    );
    if let Some(reference) = reference {
        if reference.width != img.width || reference.height != img.height {
            bail!("reference is {}x{}, the render {}x{}", reference.width, reference.height, img.width, img.height);
        }
        let ratio = metrics::mean_ratio(&img, &reference);
        println!("RMSE {:.5}, relMSE {:.5}, mean ratio {:.4} {:.4} {:.4}", metrics::rmse(&img, &reference), metrics::rel_mse(&img, &reference), ratio[0], ratio[1], ratio[2]);
    }
    for o in &outputs {
        println!("wrote {}", o.display());
    }
    Ok(())
}
