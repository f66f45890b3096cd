//! One render on several Vulkan devices at once (`--device all` or a list): every device
//! takes passes — runs of sample indices — from a shared counter, so a faster device renders
//! more of them (once all are set up), and the host adds the devices' film sums. Each pass is rendered with the
//! random numbers a single-device render uses for its sample indices, so the sum is the
//! single-device image (up to float summation order).

use super::{RenderError, RenderSettings, Renderer};
use crate::imaging::part::Accumulation;
use crate::scene::{Camera, Scene};
use crate::vk::{Context, ContextOptions};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Barrier, Mutex};
use std::time::{Duration, Instant};

/// How far one device has got.
#[derive(Clone, Debug, Default)]
pub struct DeviceProgress {
    pub name: String,
    /// Samples per pixel this device has rendered.
    pub samples: u64,
    pub elapsed: Duration,
}

/// The devices' summed film and what each did.
pub struct MultiRender {
    pub sums: Accumulation,
    pub nan_samples: u64,
    pub devices: Vec<DeviceProgress>,
    /// Validation messages of every device's context (empty without validation).
    pub validation: Vec<String>,
}

/// One device's film sums, dropped NaN/Inf samples and validation messages.
type DeviceResult = Result<(Accumulation, u64, Vec<String>), RenderError>;

/// Renders samples `settings.sample_start ..` `+ spp` of every pixel on the devices of
/// `devices` (one context each; the same device may appear twice). With `time`, devices stop
/// taking passes once it has passed (their last passes sized to end near it), and the render
/// holds the samples handed out by then (`sums.spp`, at most `spp`): always a contiguous
/// range from `sample_start`, since every pass taken is finished. `progress` is called after
/// every pass of any device with all devices' progress.
pub fn render_on_devices(
    devices: &[ContextOptions],
    scene: &Scene,
    camera: &Camera,
    settings: &RenderSettings,
    spp: u32,
    time: Option<Duration>,
    progress: &(dyn Fn(&[DeviceProgress]) + Sync),
) -> Result<MultiRender, RenderError> {
    let next = AtomicU64::new(0);
    let status = Mutex::new(vec![DeviceProgress::default(); devices.len()]);
    let stop = || next.store(u64::MAX / 2, Ordering::SeqCst);
    // Passes start once every device is set up (or has failed), so that a device whose
    // kernels compile first does not take the whole render before the others can start.
    let ready = Barrier::new(devices.len());
    // Set-up (instance, device, pipelines) runs one device at a time: on the H200 one
    // `--device 0,0` render hung once with set-ups in parallel (not reproduced; see
    // docs/scale-out.md), and drivers need not make concurrent instance creation safe.
    let setup_lock = Mutex::new(());
    let run = |i: usize, opts: &ContextOptions| -> DeviceResult {
        let setup = {
            let _one_at_a_time = setup_lock.lock().unwrap_or_else(|e| e.into_inner());
            Context::new(opts)
                .map_err(RenderError::from)
                .and_then(|ctx| Renderer::new(&ctx, scene, camera, settings.clone()).map(|r| (ctx, r)))
        };
        ready.wait();
        let (ctx, mut r) = setup?;
        status.lock().unwrap_or_else(|e| e.into_inner())[i].name = format!("{} #{i}", ctx.info().name);
        // Whole BDPT iterations where the counter allows (see `Renderer::pass_at`).
        let align = r.sample_slices().max(1);
        let start = Instant::now();
        loop {
            let mut want = r.next_pass_spp();
            if let Some(t) = time {
                let left = t.as_secs_f64() - start.elapsed().as_secs_f64();
                if left <= 0.0 {
                    break;
                }
                want = want.min(r.pass_spp_within(left).max(1));
            }
            let want = want.div_ceil(align) * align;
            let first = next.fetch_add(want as u64, Ordering::SeqCst);
            if first >= spp as u64 {
                break;
            }
            let n = (want as u64).min(spp as u64 - first) as u32;
            r.adaptive_pass_at(settings.sample_start + first as u32, n)?;
            let snapshot = {
                let mut s = status.lock().unwrap_or_else(|e| e.into_inner());
                s[i].samples += n as u64;
                s[i].elapsed = start.elapsed();
                s.clone()
            };
            progress(&snapshot);
        }
        let sums = r.sums()?;
        let nan = r.nan_samples()? as u64;
        drop(r);
        Ok((sums, nan, ctx.close()?))
    };
    let results: Vec<DeviceResult> = std::thread::scope(|sc| {
        let handles: Vec<_> = devices
            .iter()
            .enumerate()
            .map(|(i, opts)| {
                let run = &run;
                sc.spawn(move || {
                    let r = run(i, opts);
                    if r.is_err() {
                        stop();
                    }
                    r
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|_| Err(RenderError::Unsupported("a device's render thread panicked".into()))))
            .collect()
    });
    let mut total: Option<Accumulation> = None;
    let (mut nan_samples, mut validation) = (0, Vec::new());
    for r in results {
        let (sums, nan, messages) = r?;
        nan_samples += nan;
        validation.extend(messages);
        match &mut total {
            None => total = Some(sums),
            Some(t) => {
                t.add_at(&sums, (0, 0));
                t.spp += sums.spp;
            }
        }
    }
    let sums = total.ok_or_else(|| RenderError::Unsupported("no device to render on".into()))?;
    Ok(MultiRender { sums, nan_samples, devices: status.into_inner().unwrap_or_else(|e| e.into_inner()), validation })
}
