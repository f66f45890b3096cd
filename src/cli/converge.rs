//! `bidir converge`: RMSE against a reference over render time (or samples) for several
//! integrators, with a CSV, charts and the final images (`bidir::bench::converge`).

use super::scene_args::SceneArgs;
use super::settings_args::SettingsArgs;
use anyhow::Context as _;
use bidir::bench::converge::{self, Options, Presentation, Schedule, XAxis};
use bidir::imaging;
use bidir::render::Integrator;
use bidir::vk::{Context, ContextOptions};
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
#[command(after_help = "Writes into DIR: convergence.csv (integrator,seconds,spp,rmse,relmse; with --seeds N the \
seeds' average), stability.csv (integrator,stability: the worst ratio of consecutive RMSEs), convergence.png and \
convergence.svg (log-log RMSE chart), INTEGRATOR.exr/.png (final images, ':' -> '_', '=' dropped: bdpt_k4) and \
side_by_side.png (final images beside the reference). Nothing is written when the input is bad; each file appears \
whole or not at all.

Example: bidir converge --reference ../shared/references/cornell-box/reference.exr --time 20 --out /tmp/cornell")]
pub struct ConvergeArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Converged image of the same scene, camera and size (EXR, linear RGB)
    #[arg(long, value_name = "REF.exr")]
    pub reference: PathBuf,
    /// Integrators, rendered one after the other: pt | pt-nee | bdpt:full | bdpt:single |
    /// bdpt:k=N | bdpt:lvc | bdpt:lvc=N | vcm | vcm:merge-all | vcm:no-merge | vcm:no-connect
    #[arg(long, value_delimiter = ',', default_value = "pt,pt-nee,bdpt:lvc,bdpt:full,bdpt:single,bdpt:k=4")]
    pub integrators: Vec<Integrator>,
    /// Render-time budget per integrator, in seconds. Render time is the sum of the
    /// integrator's pass times: set-up, read-backs and metrics do not count. Snapshots are
    /// taken at --points log-spaced times from 1 % of the budget to all of it, each after the
    /// first pass that reaches it, so the CSV's measured times are at or just past these.
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, required_unless_present = "spp_points", conflicts_with = "spp_points")]
    pub time: Option<f64>,
    /// Number of snapshots with --time
    #[arg(long, value_name = "N", default_value_t = 12, conflicts_with = "spp_points")]
    pub points: usize,
    /// Instead of --time: snapshot when the samples per pixel reach each of these ascending
    /// counts (e.g. 1,4,16,64), met exactly; the chart's x axis is then samples per pixel
    /// (the CSV still records render time)
    #[arg(long, value_name = "SPP,...", value_delimiter = ',')]
    pub spp_points: Option<Vec<u32>>,
    /// Independent runs per integrator (seeds --seed, --seed + 1, ...): curves averaged (root
    /// mean square of the RMSEs), and per integrator the worst stability figure, the largest
    /// ratio RMSE(t_{i+1}) / RMSE(t_i) between consecutive snapshots (1 or below: the curve
    /// only descends)
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub seeds: u32,
    /// Output directory (created if missing)
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Exposure in stops for the PNG images
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub exposure: f32,
    /// Chart title [default: scene, device]
    #[arg(long)]
    pub title: Option<String>,
}

pub fn run(args: &ConvergeArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!("--out {}: exists and is not a directory", args.out.display());
    }
    if !args.exposure.is_finite() {
        anyhow::bail!("--exposure {}: must be a finite number of stops", args.exposure);
    }
    let reference = imaging::read_exr(&args.reference).context("--reference")?;
    super::diff::warn_non_finite(&args.reference, &reference);
    let loaded = args.scene.load()?;
    super::print_warnings(&loaded.warnings);
    let schedule = match &args.spp_points {
        Some(spp) => Schedule::Spp(spp.clone()),
        None => Schedule::Time { budget_s: args.time.unwrap_or(0.0), points: args.points },
    };
    let settings = args.settings.settings(Integrator::Pt)?;
    let rr_depth = args.settings.rr_depth;
    let options = Options { integrators: args.integrators.clone(), schedule, settings, rr_depth, seeds: args.seeds };
    converge::check(&options, &loaded.camera, &reference)?;

    super::signals::on_interrupt(super::signals::FirstInterrupt::FinishPass)?;
    let ctx = Context::new(opts).context("cannot start Vulkan")?;
    let created = !args.out.exists();
    std::fs::create_dir_all(&args.out).with_context(|| format!("cannot create {}", args.out.display()))?;
    let result = render_and_write(args, &ctx, &loaded, &reference, &options);
    if result.is_err() && created {
        let _ = std::fs::remove_dir(&args.out); // only if still empty
    }
    result
}

fn render_and_write(
    args: &ConvergeArgs,
    ctx: &Context,
    loaded: &super::scene_args::LoadedScene,
    reference: &imaging::RgbImage,
    options: &Options,
) -> anyhow::Result<()> {
    let device = ctx.info().name.clone();
    let cam = &loaded.camera;
    println!("{device}, {} {}x{}: integrator, seconds, spp, RMSE, relMSE", loaded.scene.source, cam.width, cam.height);
    let curves = converge::run(ctx, &loaded.scene, cam, reference, options, |i, p| {
        println!("{:<12} {:>10.4} {:>8} {:>10.6} {:>10.6}", i.name(), p.seconds, p.spp, p.rmse, p.rel_mse);
    })?;
    for c in &curves {
        if c.nan_samples > 0 {
            eprintln!("warning: {}: {} NaN/Inf samples dropped", c.integrator.name(), c.nan_samples);
        }
    }
    let scene_name = match &args.scene.scene {
        Some(p) => p.file_stem().map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into_owned()),
        None => "Cornell box".to_owned(),
    };
    let how = Presentation {
        title: args.title.clone().unwrap_or_else(|| format!("{scene_name} {}x{}, {device}", cam.width, cam.height)),
        x_axis: if args.spp_points.is_some() { XAxis::Spp } else { XAxis::Seconds },
        exposure: args.exposure,
    };
    let written = converge::write_outputs(&args.out, &curves, reference, &how)?;
    println!(
        "final: integrator, spp, seconds, RMSE (set-up excluded), stability (worst RMSE(t_i+1) / RMSE(t_i) over {} seed(s))",
        args.seeds
    );
    for c in &curves {
        if let Some(p) = c.points.last() {
            println!(
                "{:<12} {:>8} {:>10.3} {:>10.6}   stability {:.3}   (set-up {:.2} s)",
                c.integrator.name(),
                p.spp,
                p.seconds,
                p.rmse,
                c.stability,
                c.setup_s
            );
        }
    }
    for p in written {
        println!("wrote {}", p.display());
    }
    Ok(())
}
