//! `bidir render`: headless progressive rendering to EXR/PNG.

use super::scene_args::SceneArgs;
use super::settings_args::{IntegratorArgs, SettingsArgs};
use anyhow::{bail, Context as _};
use bidir::imaging::{self, metrics};
use bidir::render::Renderer;
use bidir::vk::{Context, ContextOptions};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
    /// Samples per pixel (default 64 unless --time is given).
    #[arg(long, conflicts_with = "time")]
    pub spp: Option<u32>,
    /// Render passes until this many seconds have passed.
    #[arg(long, allow_hyphen_values = true)]
    pub time: Option<f64>,
    #[command(flatten)]
    pub settings: SettingsArgs,
    #[command(flatten)]
    pub part: super::part_args::PartArgs,
    /// Output image(s): .exr (linear float) or .png (sRGB); may repeat.
    #[arg(short = 'o', long = "output")]
    pub outputs: Vec<PathBuf>,
    /// Exposure in stops applied to PNG output.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub exposure: f32,
    /// Extra EXR layers for denoisers, any of albedo,normal,depth (comma-separated): written as
    /// albedo.R/G/B, normal.X/Y/Z, depth.Z beside the colour and its alpha A.
    #[arg(long, value_name = "LIST")]
    pub aov: Option<bidir::imaging::aov::Aovs>,
    /// Print RMSE / mean ratio against this reference EXR at the end.
    #[arg(long)]
    pub reference: Option<PathBuf>,
}

/// Checks an output path before any work: `.exr` or `.png`, and writable (see
/// [`imaging::check_writable`]).
pub(super) fn check_output(path: &Path) -> anyhow::Result<()> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("exr") | Some("png") => {}
        _ => bail!("{}: output must end in .exr or .png", path.display()),
    }
    Ok(imaging::check_writable(path)?)
}

pub fn run(args: &RenderArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    let outputs = if args.outputs.is_empty() { vec![PathBuf::from("render.png")] } else { args.outputs.clone() };
    for (i, o) in outputs.iter().enumerate() {
        check_output(o)?;
        if outputs[..i].contains(o) {
            bail!("{}: given twice with -o", o.display());
        }
    }
    if let Some(t) = args.time {
        if !(t > 0.0 && t.is_finite()) {
            bail!("--time {t}: must be a positive number of seconds");
        }
    }
    if args.spp == Some(0) {
        bail!("--spp must be at least 1");
    }
    if !args.exposure.is_finite() {
        bail!("--exposure {}: must be a finite number of stops", args.exposure);
    }
    let reference = args.reference.as_ref().map(|p| imaging::read_exr(p)).transpose()?;
    let loaded = args.scene.load()?;
    super::print_warnings(&loaded.warnings);
    let camera = loaded.camera.clone();
    if let (Some(path), Some(reference)) = (&args.reference, &reference) {
        if (reference.width, reference.height) != (camera.width, camera.height) {
            bail!(
                "--reference {} is {}x{} but the camera renders {}x{} (match them with --width/--height)",
                path.display(),
                reference.width,
                reference.height,
                camera.width,
                camera.height
            );
        }
        super::diff::warn_non_finite(path, reference);
    }
    let integrator = args.integrator.integrator()?;
    let mut settings = args.settings.settings(integrator)?;
    settings.first_hit = first_hit_request(args.aov, &outputs)?;
    args.part.apply(&mut settings, &camera)?;
    let info_settings = settings.clone();
    super::signals::on_interrupt(super::signals::FirstInterrupt::FinishPass)?;
    if let Some(devices) = super::render_devices::device_list(opts)? {
        return super::render_devices::run(args, &loaded, &settings, &devices, &outputs, reference);
    }
    let ctx = Context::new(opts).context("cannot start Vulkan")?;
    let t_setup = Instant::now();
    let mut r = Renderer::new(&ctx, &loaded.scene, &camera, settings)?;
    let setup = t_setup.elapsed();
    super::part_args::warn_unaligned(&args.part, &info_settings, r.sample_slices());
    eprintln!(
        "rendering {}x{} with {} over {} (Ctrl-C: stop after this pass and write what was rendered)",
        camera.width,
        camera.height,
        integrator.name(),
        r.kernel_form()
    );

    let pixels = settings_window_pixels(&info_settings, &camera);
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
            let spp = args.part.sample_range.map_or(args.spp.unwrap_or(64), |r| r.len());
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
    if bidir::render::stop_requested() {
        eprintln!("interrupted: writing the {} spp rendered so far", r.samples());
    }
    let img = r.image()?;
    let nan = r.nan_samples()?;
    let spp = r.samples();
    let range = bidir::imaging::SampleRange { start: info_settings.sample_start, end: info_settings.sample_start + spp };
    let mut info = super::part_args::render_info(&loaded, &info_settings, range, elapsed.as_secs_f64(), &ctx.info().name);
    info.set(bidir::imaging::part::keys::KERNELS, r.kernel_form());
    let crop = info_settings.crop.unwrap_or(imaging::Crop::full(camera.width, camera.height));
    super::part_args::write_outputs(&outputs, &r.sums()?, &img, &info, crop, args.exposure)?;
    println!(
        "{} {}x{} {}: {spp} spp in {:.3} s ({:.2} Msamples/s; setup {:.2} s), {} NaN/Inf samples dropped",
        ctx.info().name,
        img.width,
        img.height,
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
        let ratio = metrics::mean_ratio(&img, &reference);
        println!(
            "RMSE {:.5}, relMSE {:.5}, mean ratio {:.4} {:.4} {:.4}",
            metrics::rmse(&img, &reference),
            metrics::rel_mse(&img, &reference),
            ratio[0],
            ratio[1],
            ratio[2]
        );
    }
    for o in &outputs {
        println!("wrote {}", o.display());
    }
    Ok(())
}

/// What the first-hit pass must compute: alpha wherever an output is EXR, with the AOV layers
/// of `--aov` (which needs an EXR output: PNG keeps RGB).
fn first_hit_request(aov: Option<bidir::imaging::aov::Aovs>, outputs: &[PathBuf]) -> anyhow::Result<Option<bidir::imaging::aov::Aovs>> {
    let exr = outputs.iter().any(|o| o.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr")));
    if aov.is_some() && !exr {
        bail!("--aov writes EXR layers: give an .exr output (-o FILE.exr)");
    }
    Ok(exr.then(|| aov.unwrap_or_default()))
}

/// Pixels rendered: the crop window's, or the whole image's.
fn settings_window_pixels(settings: &bidir::render::RenderSettings, camera: &bidir::scene::Camera) -> f64 {
    settings.crop.map_or(camera.width as f64 * camera.height as f64, |c| c.pixels() as f64)
}
