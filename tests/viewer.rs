//! The viewer (`bidir view`): the tonemap kernel against the CPU's film resolve and PNG
//! encoding, the renderer's integrator and size switches against fresh renderers, and the
//! real window (spawned binary, on an X display: `$DISPLAY`, else an Xvfb this test starts)
//! against headless renders, through a resize, validation-clean.

mod common;

use bidir::imaging::{linear_to_srgb, read_exr, RgbImage};
use bidir::render::{Integrator, Join, RenderSettings, Renderer, Tonemap, TonemapSettings};
use bidir::scene::{Camera, Scene};
use common::{finish, gpu};
use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn camera(width: u32, height: u32) -> Camera {
    Camera { width, height, ..Camera::cornell_box() }
}

/// The PNG writer's byte for a linear value (imaging::write_image).
fn png_byte(v: f32, scale: f32) -> u8 {
    let v = if v.is_finite() { v * scale } else { 0.0 };
    (linear_to_srgb(v.clamp(0.0, 1.0)) * 255.0 + 0.5) as u8
}

#[test]
fn tonemap_matches_film_resolve_and_png_bytes() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    let tonemap = Tonemap::new(&ctx).unwrap();
    // pt-nee films have no splats; BDPT's light tracing adds them (divided by iterations).
    for integrator in [Integrator::PtNee, Integrator::Bdpt(Join::Full)] {
        let cam = camera(40, 24);
        let mut r = Renderer::new(&ctx, &scene, &cam, RenderSettings::new(integrator)).unwrap();
        r.pass(1).unwrap();
        r.pass(2).unwrap();
        let film = r.image().unwrap();
        for (exposure, bgra) in [(0.0, false), (1.5, true), (-2.0, false)] {
            let target = ctx.create_image("tonemap.target", cam.width, cam.height, Tonemap::FORMAT).unwrap();
            let settings = TonemapSettings { exposure, bgra };
            ctx.submit("tonemap", |rec| r.record_tonemap(rec, &tonemap, &target, settings)).unwrap();
            let bytes: Vec<u8> = ctx.read_image(&target).unwrap();
            let scale = 2f32.powf(exposure);
            let mut worst = 0i32;
            for (i, px) in bytes.chunks_exact(4).enumerate() {
                let rgb = [0, 1, 2].map(|c| png_byte(film.data[3 * i + c], scale));
                let want = if bgra { [rgb[2], rgb[1], rgb[0], 255] } else { [rgb[0], rgb[1], rgb[2], 255] };
                for c in 0..4 {
                    worst = worst.max((px[c] as i32 - want[c] as i32).abs());
                }
            }
            // Float-to-UNORM conversion may round differently from the CPU's +0.5 truncation.
            assert!(worst <= 1, "{} exposure {exposure} bgra {bgra}: a byte differs by {worst}", integrator.name());
        }
        // A target of the wrong size is refused, not written out of bounds.
        let wrong = ctx.create_image("tonemap.wrong", 8, 8, Tonemap::FORMAT).unwrap();
        let e = ctx.submit("tonemap", |rec| r.record_tonemap(rec, &tonemap, &wrong, TonemapSettings { exposure: 0.0, bgra: false }));
        assert!(e.unwrap_err().to_string().contains("the film needs 40x24"));
    }
    drop(tonemap);
    finish(ctx);
}

fn passes(r: &mut Renderer, n: u32) -> RgbImage {
    for _ in 0..n {
        r.pass(1).unwrap();
    }
    r.image().unwrap()
}

fn max_rel_diff(a: &RgbImage, b: &RgbImage) -> f32 {
    assert_eq!((a.width, a.height), (b.width, b.height));
    a.data.iter().zip(&b.data).map(|(x, y)| (x - y).abs() / y.abs().max(1e-3)).fold(0.0, f32::max)
}

#[test]
fn switching_integrator_and_size_matches_fresh_renderers() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    let fresh = |integrator, cam: &Camera| {
        let mut r = Renderer::new(&ctx, &scene, cam, RenderSettings::new(integrator)).unwrap();
        passes(&mut r, 2)
    };
    let (small, wide) = (camera(32, 24), camera(48, 20));
    let mut r = Renderer::new(&ctx, &scene, &small, RenderSettings::new(Integrator::PtNee)).unwrap();
    passes(&mut r, 1);
    // Same size, another integrator: the film restarts; the same passes give the same image.
    r.set_integrator(Integrator::Pt).unwrap();
    assert_eq!(r.samples(), 0);
    assert_eq!(passes(&mut r, 2), fresh(Integrator::Pt, &small));
    // Another size: a new film (and for BDPT a new light-vertex store).
    r.set_integrator(Integrator::Bdpt(Join::Full)).unwrap();
    r.set_camera(&wide).unwrap();
    let got = passes(&mut r, 2);
    assert_eq!((got.width, got.height), (48, 20));
    // Splats are atomic float adds: their order, hence the last bits, may differ.
    let d = max_rel_diff(&got, &fresh(Integrator::Bdpt(Join::Full), &wide));
    assert!(d < 1e-4, "bdpt after set_camera differs from a fresh renderer by {d}");
    assert!(r.set_camera(&camera(0, 10)).is_err());
    assert_eq!((r.film().width, r.film().height), (48, 20), "a failed set_camera leaves the renderer as it was");
    drop(r);
    finish(ctx);
}

/// An X display for the spawned viewer: `$DISPLAY`, else an Xvfb started here (killed on
/// drop).
struct Display {
    name: String,
    server: Option<Child>,
}

impl Drop for Display {
    fn drop(&mut self) {
        if let Some(c) = &mut self.server {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

fn display() -> Option<Display> {
    if let Some(name) = std::env::var("DISPLAY").ok().filter(|d| !d.is_empty()) {
        return Some(Display { name, server: None });
    }
    // -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
    let spawned = Command::new("Xvfb")
        .args(["-displayfd", "1", "-screen", "0", "1280x1024x24", "-nolisten", "tcp"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn();
    let mut child = match spawned {
        Ok(c) => c,
        Err(e) => {
            eprintln!(
                "SKIPPED: no X display (DISPLAY is unset) and Xvfb cannot be started ({e}); install xvfb (scripts/setup.sh does) or run scripts/test"
            );
            return None;
        }
    };
    let mut line = String::new();
    let _ = BufReader::new(child.stdout.take().expect("piped")).read_line(&mut line);
    match line.trim().parse::<u32>() {
        Ok(n) => Some(Display { name: format!(":{n}"), server: Some(child) }),
        Err(_) => {
            let _ = child.kill();
            let _ = child.wait();
            eprintln!("SKIPPED: no X display (DISPLAY is unset) and Xvfb did not start");
            None
        }
    }
}

/// Runs `bidir ARGS` with `env`, killing it after `limit`; (success, stdout, stderr).
fn bidir(args: &[&str], env: &[(&str, Option<&str>)], limit: Duration) -> (bool, String, String) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_bidir"));
    cmd.args(args).stdout(Stdio::piped()).stderr(Stdio::piped());
    for (k, v) in env {
        match v {
            Some(v) => cmd.env(k, v),
            None => cmd.env_remove(k),
        };
    }
    let mut child = cmd.spawn().expect("the bidir binary starts");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            let _ = child.kill();
            panic!("bidir {args:?} did not finish within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let out = child.wait_with_output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into_owned(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn viewer_without_a_display_fails_clearly() {
    let (ok, _, err) = bidir(
        &["view", "--frames", "1"],
        &[("DISPLAY", None), ("WAYLAND_DISPLAY", None), ("WAYLAND_SOCKET", None)],
        Duration::from_secs(60),
    );
    assert!(!ok, "the viewer must fail without a display");
    assert!(err.contains("cannot open a window") && err.contains("xvfb-run"), "unclear error: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// `N spp in the film` and `WxH` from the viewer's summary line.
fn parse_summary(stdout: &str) -> (u32, u32, u32) {
    let line = stdout.lines().find(|l| l.contains("spp in the film")).unwrap_or_else(|| panic!("no summary in: {stdout}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    let spp = words.iter().position(|w| *w == "spp").map(|i| words[i - 1].parse().unwrap()).unwrap();
    let size =
        words.iter().find_map(|w| w.split_once('x').and_then(|(a, b)| Some((a.parse().ok()?, b.trim_end_matches(':').parse().ok()?))));
    let (w, h) = size.unwrap_or_else(|| panic!("no size in: {line}"));
    (w, h, spp)
}

/// Over the region (x, y, w, h), per channel: the viewer's mean minus the references'
/// average, the standard deviation of that difference, and the references' average.
fn compare(viewer: &RgbImage, a: &RgbImage, b: &RgbImage, (x0, y0, w, h): (u32, u32, u32, u32)) -> [(f64, f64, f64); 3] {
    let n = (w * h) as f64;
    [0, 1, 2].map(|c| {
        let (mut sv, mut sr, mut var) = (0.0, 0.0, 0.0);
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                let (v, pa, pb) = (viewer.pixel(x, y)[c] as f64, a.pixel(x, y)[c] as f64, b.pixel(x, y)[c] as f64);
                sv += v;
                sr += 0.5 * (pa + pb);
                var += (pa - pb).powi(2) / 2.0;
            }
        }
        ((sv - sr) / n, (1.5 * var).sqrt() / n, sr / n)
    })
}

#[test]
fn viewer_window_matches_headless_render_through_a_resize() {
    let Some(display) = display() else { return };
    let dir = std::env::temp_dir().join(format!("bidir-viewer-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (exr, png) = (dir.join("view.exr"), dir.join("view.png"));
    let (exr_s, png_s) = (exr.to_str().unwrap(), png.to_str().unwrap());
    // 256x256 for three frames, then the window is resized to 200x150: the film follows it.
    let args = ["view", "--frames", "12", "--resize-at", "3:200x150", "--screenshot", exr_s, "--screenshot", png_s];
    let env = [("DISPLAY", Some(display.name.as_str())), ("WAYLAND_DISPLAY", None), ("BIDIR_VALIDATION", Some("1"))];
    let (ok, out, err) = bidir(&args, &env, Duration::from_secs(600));
    eprintln!("{out}{err}");
    assert!(ok, "bidir view failed:\n{err}");
    assert!(!err.contains("[vulkan"), "validation messages:\n{err}");
    let (w, h, spp) = parse_summary(&out);
    assert_eq!((w, h), (200, 150), "the film did not follow the resized window");
    assert!(spp >= 1);
    let shot = read_exr(&exr).unwrap();
    assert_eq!((shot.width, shot.height), (200, 150));
    assert!(png.exists());

    // Two independent headless renders of the same camera and spp (other seeds) give the
    // reference and the noise: pixels are independent, so over a region sum((a_i - b_i)^2) / 2
    // estimates the sum of its pixel variances, and the variance of one image's region mean
    // is that over pixels^2. The viewer's mean minus the references' average has 1.5 times
    // that variance; allow 5 standard deviations, for the whole image (the mean) and for
    // each of 4x3 blocks (which a camera off by a degree or two would fail).
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    let render = |seed| {
        let mut s = RenderSettings::new(Integrator::PtNee);
        s.seed = seed;
        let mut r = Renderer::new(&ctx, &scene, &camera(200, 150), s).unwrap();
        r.render_spp(spp, |_| {}).unwrap();
        r.image().unwrap()
    };
    let (a, b) = (render(1), render(2));
    let whole = compare(&shot, &a, &b, (0, 0, w, h));
    for (c, (off, sigma, reference)) in whole.iter().enumerate() {
        eprintln!(
            "mean, channel {c}: viewer {:.5}, headless {reference:.5} ({spp} spp), off {:+.3} %, tolerance {:.3} %",
            reference + off,
            100.0 * off / reference,
            500.0 * sigma / reference
        );
        assert!(5.0 * sigma < 0.05 * reference, "too few samples for a meaningful comparison");
        assert!(off.abs() <= 5.0 * sigma, "channel {c}: the viewer's mean is {:.2} standard deviations from the headless one", off / sigma);
    }
    let (bw, bh) = (w / 4, h / 3);
    let mut worst = 0.0f64;
    for (bx, by) in (0..3).flat_map(|y| (0..4).map(move |x| (x, y))) {
        for (c, (off, sigma, reference)) in compare(&shot, &a, &b, (bx * bw, by * bh, bw, bh)).iter().enumerate() {
            worst = worst.max(off.abs() / sigma);
            assert!(
                off.abs() <= 5.0 * sigma,
                "block ({bx}, {by}) channel {c}: viewer {:.5} vs headless {reference:.5}, {:.2} standard deviations",
                reference + off,
                off / sigma
            );
        }
    }
    eprintln!("4x3 blocks: worst {worst:.2} standard deviations");
    finish(ctx);
    drop(display);
    let _ = std::fs::remove_dir_all(PathBuf::from(&dir));
}
