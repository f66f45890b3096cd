//! One render on several devices (`render::multi`, `bidir render --device 0,0`): passes
//! taken from a shared counter, the devices' sums added on the host. Every pass uses the
//! random numbers a single-device render uses for its sample indices, so the result is the
//! single-device render pixel for pixel (within 1e-5 relative: float summation order), and
//! both devices must have taken passes.

use bidir::imaging::RgbImage;
use bidir::render::{multi, Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Scene};
use bidir::vk::{Context, ContextOptions};

/// The tests of this file one at a time: each checks that both devices took passes, which
/// a test running beside it on a 2-core machine could starve.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn opts() -> ContextOptions {
    let mut o = ContextOptions::from_env();
    o.validation = true;
    o
}

fn assert_same(what: &str, a: &RgbImage, b: &RgbImage) {
    assert_eq!((a.width, a.height), (b.width, b.height));
    for (i, (x, y)) in a.data.iter().zip(&b.data).enumerate() {
        let rel = (x - y).abs() as f64 / x.abs().max(y.abs()).max(1e-30) as f64;
        assert!(rel <= 1e-5, "{what}: pixel {} channel {}: {x} vs {y}", i / 3, i % 3);
    }
    assert!(a.mean()[0] > 0.0, "{what}: a black image proves nothing");
}

fn check(integrator: Integrator, spp: u32) {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let scene = Scene::builtin_cornell_box();
    let camera = Camera { width: 40, height: 32, ..scene.cameras[0].clone() };
    let mut settings = RenderSettings::new(integrator);
    settings.seed = 11;
    // Small passes, so that both devices take several from the counter.
    settings.pass_target = std::time::Duration::from_millis(20);
    let ctx = Context::new(&opts()).unwrap();
    let mut r = Renderer::new(&ctx, &scene, &camera, settings.clone()).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let single = r.image().unwrap();
    drop(r);
    assert!(ctx.close().unwrap().is_empty(), "validation messages (single device)");

    let devices = [opts(), opts()];
    let done = multi::render_on_devices(&devices, &scene, &camera, &settings, spp, None, &|_| {}).unwrap();
    assert!(done.validation.is_empty(), "validation messages: {:?}", done.validation);
    assert_eq!(done.sums.spp, spp as u64);
    assert_eq!(done.devices.iter().map(|d| d.samples).sum::<u64>(), spp as u64);
    for d in &done.devices {
        eprintln!("{}: {}: {} spp in {:.3} s", integrator.name(), d.name, d.samples, d.elapsed.as_secs_f64());
        assert!(d.samples > 0, "{} took no pass from the shared counter", d.name);
    }
    assert_eq!(done.nan_samples, 0);
    assert_same(&format!("{} on two devices", integrator.name()), &done.sums.resolve(), &single);
}

/// `--time` on several devices: they stop taking passes when the budget is spent, and what
/// they rendered is one contiguous range of samples, the same image a single device makes of
/// that many samples.
#[test]
fn two_devices_with_a_time_budget_equal_one_render_of_their_samples() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let scene = Scene::builtin_cornell_box();
    let camera = Camera { width: 40, height: 32, ..scene.cameras[0].clone() };
    let mut settings = RenderSettings::new(Integrator::PtNee);
    settings.seed = 12;
    settings.pass_target = std::time::Duration::from_millis(20);
    let devices = [opts(), opts()];
    let budget = std::time::Duration::from_millis(1500);
    let done = multi::render_on_devices(&devices, &scene, &camera, &settings, u32::MAX, Some(budget), &|_| {}).unwrap();
    assert!(done.validation.is_empty(), "validation messages: {:?}", done.validation);
    let spp = done.sums.spp as u32;
    assert!(spp > 0, "nothing rendered in {budget:?}");
    assert_eq!(done.devices.iter().map(|d| d.samples).sum::<u64>(), spp as u64);
    for d in &done.devices {
        eprintln!("time budget: {}: {} spp in {:.3} s", d.name, d.samples, d.elapsed.as_secs_f64());
        assert!(d.elapsed.as_secs_f64() < 3.0 * budget.as_secs_f64(), "{} ran {:?} on a {budget:?} budget", d.name, d.elapsed);
    }
    let ctx = Context::new(&opts()).unwrap();
    let mut r = Renderer::new(&ctx, &scene, &camera, settings).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let single = r.image().unwrap();
    drop(r);
    assert!(ctx.close().unwrap().is_empty(), "validation messages (single device)");
    assert_same("pt-nee on two devices with a time budget", &done.sums.resolve(), &single);
}

#[test]
fn two_devices_equal_one_pt_nee() {
    check(Integrator::PtNee, 48);
}

#[test]
fn two_devices_equal_one_bdpt_lvc() {
    check(Integrator::Bdpt(Join::Lvc(0)), 24);
}

/// `bidir render --device 0,0` through the binary: the multi-device path, each device's
/// rate reported, equal to the single-device render.
#[test]
fn cli_device_list() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let d = std::env::temp_dir().join(format!("bidir-devices-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let run = |dev: &str, out: &std::path::Path| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_bidir"))
            .args(["--device", dev, "render", "--width", "24", "--height", "16", "--spp", "16", "--seed", "5", "-o", out.to_str().unwrap()])
            .env("BIDIR_VALIDATION", "1")
            .output()
            .unwrap();
        let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        eprintln!("--device {dev}:\n{text}");
        assert!(o.status.success(), "{text}");
        assert!(!text.to_lowercase().contains("validation"), "{text}");
        text
    };
    let (one, two) = (d.join("one.exr"), d.join("two.exr"));
    run("0", &one);
    let text = run("0,0", &two);
    assert!(text.contains("2 devices") && text.contains("#0: ") && text.contains("#1: ") && text.contains("Msamples/s"), "{text}");
    assert_same("--device 0,0", &bidir::imaging::read_exr(&two).unwrap(), &bidir::imaging::read_exr(&one).unwrap());
    std::fs::remove_dir_all(&d).ok();
}
