//! `bidir view`: the progressive film live in a window (see `bidir::viewer`).

use super::scene_args::SceneArgs;
use super::settings_args::{IntegratorArgs, SettingsArgs};
use anyhow::{bail, Context as _};
use bidir::viewer::{self, ViewOptions};
use bidir::vk::{ContextOptions, Vsync};
use std::path::PathBuf;
use std::time::Duration;

#[derive(clap::Args, Debug)]
pub struct ViewArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub integrator: IntegratorArgs,
    #[command(flatten)]
    pub settings: SettingsArgs,
    /// Exposure in stops (+/- change it by half a stop).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub exposure: f32,
    /// Present without waiting for vertical blank (MAILBOX, else IMMEDIATE).
    #[arg(long)]
    pub no_vsync: bool,
    /// Frame time to size each frame's batch of samples to, in milliseconds.
    #[arg(long, default_value_t = 16.0)]
    pub frame_ms: f64,
    /// Quit after this many frames.
    #[arg(long)]
    pub frames: Option<u32>,
    /// Write the film to this file (.exr or .png) when quitting; may repeat.
    #[arg(long)]
    pub screenshot: Vec<PathBuf>,
    /// Testing: after frame F, resize the window to WxH (e.g. 3:320x200).
    #[arg(long, value_name = "F:WxH", value_parser = parse_resize, hide = true)]
    pub resize_at: Option<(u32, u32, u32)>,
}

fn parse_resize(s: &str) -> Result<(u32, u32, u32), String> {
    let err = || format!("expected FRAME:WIDTHxHEIGHT like 3:320x200, got '{s}'");
    let (f, size) = s.split_once(':').ok_or_else(err)?;
    let (w, h) = size.split_once('x').ok_or_else(err)?;
    let n = |x: &str| x.trim().parse::<u32>().ok().filter(|&v| v > 0).ok_or_else(err);
    Ok((n(f)?, n(w)?, n(h)?))
}

pub fn run(args: &ViewArgs, opts: &ContextOptions) -> anyhow::Result<()> {
    if !(args.frame_ms > 0.0 && args.frame_ms.is_finite()) {
        bail!("--frame-ms must be a positive number of milliseconds");
    }
    if !args.exposure.is_finite() {
        bail!("--exposure {}: must be a finite number of stops", args.exposure);
    }
    let settings = args.settings.settings(args.integrator.integrator()?)?;
    let loaded = args.scene.load()?;
    super::print_warnings(&loaded.warnings);
    // Ctrl-C in the terminal: quit at once, without a half-written screenshot.
    super::signals::on_interrupt(super::signals::FirstInterrupt::Abort)?;
    let mut v = ViewOptions::new(loaded.scene, loaded.camera, settings);
    v.exposure = args.exposure;
    v.vsync = if args.no_vsync { Vsync::Off } else { Vsync::On };
    v.frames = args.frames;
    v.screenshots = args.screenshot.clone();
    v.frame_budget = Duration::from_secs_f64(args.frame_ms / 1e3);
    v.context = opts.clone();
    v.resize_at = args.resize_at;
    let summary = viewer::run(&v).context("bidir view")?;

    let mut ms: Vec<f64> = summary.frame_times.iter().map(|t| t.as_secs_f64() * 1e3).collect();
    ms.sort_by(f64::total_cmp);
    let median = ms.get(ms.len() / 2).copied().unwrap_or(0.0);
    println!(
        "{} {}x{} {}: {} frames, {} spp in the film, median {:.1} ms/frame, present mode {}",
        summary.device,
        summary.camera.width,
        summary.camera.height,
        summary.integrator.name(),
        summary.frames,
        summary.samples,
        median,
        summary.present_mode
    );
    for s in &summary.screenshots {
        println!("wrote {}", s.display());
    }
    if !summary.validation_messages.is_empty() {
        bail!("the validation layer reported {} message(s) (printed above)", summary.validation_messages.len());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn resize_spec_parses() {
        assert_eq!(parse_resize("3:320x200").unwrap(), (3, 320, 200));
        assert!(parse_resize("3:320").is_err());
        assert!(parse_resize("0:320x200").is_err());
        assert!(parse_resize("x").unwrap_err().contains("FRAME:WIDTHxHEIGHT"));
    }
}
