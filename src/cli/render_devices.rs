//! `bidir render --device all` (or a list such as `--device 0,1`, `--device 0,0`): one render
//! on several devices at once (`render::multi`), with each device's rate on the progress bar.

use super::part_args;
use super::render::RenderArgs;
use super::scene_args::LoadedScene;
use anyhow::{bail, Context as _};
use bidir::imaging::{self, metrics, SampleRange};
use bidir::render::{multi, RenderSettings};
use bidir::vk::{self, ContextOptions};
use std::time::Instant;

/// The devices of `--device all` or a comma-separated list (None: one device, the usual
/// path). Each entry is an index or a name substring, as for a single device.
pub fn device_list(opts: &ContextOptions) -> anyhow::Result<Option<Vec<ContextOptions>>> {
    let Some(sel) = opts.device.as_deref() else {
        return Ok(None);
    };
    if sel != "all" && !sel.contains(',') {
        return Ok(None);
    }
    let devices = vk::list_devices().context("cannot list Vulkan devices")?;
    let picked: Vec<usize> = if sel == "all" {
        devices.iter().filter(|d| d.usable()).map(|d| d.index).collect()
    } else {
        sel.split(',').map(|s| vk::choose_device(&devices, Some(s)).map(|i| devices[i].index)).collect::<Result<_, _>>()?
    };
    if picked.is_empty() {
        bail!("--device {sel}: no usable Vulkan device");
    }
    Ok(Some(picked.into_iter().map(|i| ContextOptions { device: Some(i.to_string()), ..opts.clone() }).collect()))
}

/// Renders `spp` samples on `devices` and writes the outputs.
pub fn run(
    args: &RenderArgs,
    loaded: &LoadedScene,
    settings: &RenderSettings,
    devices: &[ContextOptions],
    outputs: &[std::path::PathBuf],
    reference: Option<imaging::RgbImage>,
) -> anyhow::Result<()> {
    let time = args.time.map(std::time::Duration::from_secs_f64);
    // With --time the devices render what they can in it (the sample count is known after).
    let cap = match time {
        Some(_) => u32::MAX - settings.sample_start,
        None => args.part.sample_range.map_or(args.spp.unwrap_or(64), |r| r.len()),
    };
    let spp = cap;
    if spp == 0 {
        bail!("--spp must be at least 1");
    }
    let camera = &loaded.camera;
    let pixels = settings.crop.map_or(camera.width as f64 * camera.height as f64, |c| c.pixels() as f64);
    let bar = indicatif::ProgressBar::new(if time.is_some() { 0 } else { spp as u64 });
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:32}] {pos}/{len} spp {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    let rates = |p: &[multi::DeviceProgress]| {
        p.iter()
            .map(|d| {
                format!(
                    "{}: {} spp, {:.1} Msamples/s",
                    d.name,
                    d.samples,
                    d.samples as f64 * pixels / d.elapsed.as_secs_f64().max(1e-9) / 1e6
                )
            })
            .collect::<Vec<_>>()
            .join("; ")
    };
    let start = Instant::now();
    let done = multi::render_on_devices(devices, &loaded.scene, camera, settings, cap, time, &|p| {
        bar.set_position(p.iter().map(|d| d.samples).sum());
        bar.set_message(rates(p));
    })?;
    bar.finish_and_clear();
    let elapsed = start.elapsed();
    let spp = done.sums.spp as u32;
    if spp == 0 {
        bail!("no device rendered a sample in the time given");
    }
    for m in &done.validation {
        eprintln!("validation: {m}");
    }
    let range = SampleRange { start: settings.sample_start, end: settings.sample_start + spp };
    let names: Vec<&str> = done.devices.iter().map(|d| d.name.as_str()).collect();
    let info = part_args::render_info(loaded, settings, range, elapsed.as_secs_f64(), &names.join(", "));
    let img = done.sums.resolve();
    let crop = settings.crop.unwrap_or(imaging::Crop::full(camera.width, camera.height));
    part_args::write_outputs(outputs, &done.sums, &img, &info, crop, args.exposure)?;
    println!(
        "{} devices, {}x{} {}: {spp} spp in {:.3} s ({:.2} Msamples/s), {} NaN/Inf samples dropped",
        devices.len(),
        img.width,
        img.height,
        settings.integrator.name(),
        elapsed.as_secs_f64(),
        spp as f64 * pixels / elapsed.as_secs_f64() / 1e6,
        done.nan_samples
    );
    println!("{}", rates(&done.devices));
    if let Some(reference) = reference {
        if reference.width != img.width || reference.height != img.height {
            bail!("reference is {}x{}, the render {}x{}", reference.width, reference.height, img.width, img.height);
        }
        println!("RMSE {:.5}, relMSE {:.5}", metrics::rmse(&img, &reference), metrics::rel_mse(&img, &reference));
    }
    for o in outputs {
        println!("wrote {}", o.display());
    }
    Ok(())
}
